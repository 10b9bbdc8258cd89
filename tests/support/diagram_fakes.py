"""A synchronous stand-in for prm9tool.online.connection.ValveConnection backed by an EmulatedValve.

The diagram and CANopen-window tests drive the real emulated firmware through the same
signals the GUI gets from the real connection, without its worker thread.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from types import SimpleNamespace

from PySide6.QtCore import QObject, Signal

from prm9tool.catalogue import CATALOGUE
from prm9tool.device.emulator import EmulatedValve


class EmulatorConnection(QObject):
    """Online/offline, writes, reads, store and restart straight on an emulated valve."""

    online_changed = Signal(bool)
    signal_values_changed = Signal(dict)
    live_values_changed = Signal(dict)
    operation_finished = Signal(str, object)
    failed = Signal(str)

    def __init__(self, valve: EmulatedValve) -> None:
        super().__init__()
        self.valve = valve
        self.is_online = False
        self.watched: list[str] = []
        self.writes: list[tuple[str, int | str]] = []
        self.stores = 0

    @property
    def device(self) -> object | None:
        """What the valve reports of itself, as ValveConnection.device (None offline)."""
        return SimpleNamespace(type_key=str(self.valve.type_key)) if self.is_online else None

    def go_online(self) -> None:
        self.is_online = True
        self.online_changed.emit(True)

    def go_offline(self) -> None:
        self.is_online = False
        self.online_changed.emit(False)

    def write(self, mnemonic: str, raw: int | str) -> None:
        param = CATALOGUE[mnemonic]
        self.valve.write(param.index, param.subindex, raw)
        self.writes.append((mnemonic, raw))

    def write_many(self, values: Mapping[str, int | str]) -> None:
        for mnemonic, raw in values.items():
            self.write(mnemonic, raw)

    def store(self) -> None:
        self.valve.store()
        self.stores += 1

    def read_many(self, mnemonics: Sequence[str], tag: str = "read") -> None:
        values = {mn: self.valve.read(*CATALOGUE[mn].key) for mn in mnemonics}
        self.operation_finished.emit(tag, values)

    def restart(self) -> None:
        self.valve.restart()
        self.operation_finished.emit("restart", None)

    def watch_signals(self, keys: Sequence[str]) -> None:
        self.watched = list(keys)

    def poll_signals(self) -> None:
        """What the real connection does about four times a second."""
        self.signal_values_changed.emit({key: self.valve.signal(key) for key in self.watched})

"""A stand-in for prm9tool.online.connection.ValveConnection with the same signals (scope tests)."""

from __future__ import annotations

from PySide6.QtCore import QObject, QTimer, Signal


class FakeConnection(QObject):
    """Records what the scope asks of the valve; tests push samples and link events in."""

    online_changed = Signal(bool)
    lost = Signal(str)
    samples_received = Signal(object)
    stream_started = Signal(list)
    stream_stopped = Signal()
    failed = Signal(str)
    write_failed = Signal(list)
    status_changed = Signal(object)

    def __init__(self, online: bool = True) -> None:
        super().__init__()
        self.is_online = online
        self.streams: list[tuple[list[str], int]] = []
        self.stream_stops = 0
        self.writes: list[tuple[str, int | str]] = []
        self.refuse: set[str] = set()  # mnemonics whose writes the valve refuses
        self.samples_lost = 0

    def start_stream(self, keys, rate_hz: int) -> None:
        self.streams.append((list(keys), rate_hz))
        self.stream_started.emit(list(keys))

    def stop_stream(self) -> None:
        self.stream_stops += 1
        self.stream_stopped.emit()

    def write(self, mnemonic: str, raw: int | str) -> None:
        if not self.is_online:
            raise AssertionError(f"write of {mnemonic} while offline")
        if mnemonic in self.refuse:  # reported later from the worker, as the real one does
            QTimer.singleShot(0, lambda: self._refused(mnemonic))
            return
        self.writes.append((mnemonic, raw))

    def _refused(self, mnemonic: str) -> None:
        self.failed.emit(f"{mnemonic}: access denied (0601 0000h)")
        self.write_failed.emit([mnemonic])

    def go_online(self) -> None:
        self.is_online = True
        self.online_changed.emit(True)

    def drop_link(self) -> None:
        self.is_online = False
        self.lost.emit("The USB cable was unplugged.")
        self.online_changed.emit(False)

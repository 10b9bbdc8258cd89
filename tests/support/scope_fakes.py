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
    stream_silent = Signal(str)
    failed = Signal(str)
    write_failed = Signal(list)
    status_changed = Signal(object)
    busy_changed = Signal(bool)
    reconnect_ended = Signal()

    def __init__(self, online: bool = True) -> None:
        super().__init__()
        self.is_online = online
        self.is_busy = False
        self.is_reconnecting = False
        self.streams: list[tuple[list[str], int]] = []
        self.stream_stops = 0
        self.writes: list[tuple[str, int | str]] = []
        self.refuse: set[str] = set()  # mnemonics whose writes the valve refuses
        self.samples_lost = 0
        self.generators: list[object] = []  # the waveforms started

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

    def start_generator(self, settings) -> None:
        """As the real connection: the first value, then the override on (the waveform's
        timing is the driver's: tests/test_setpoint_driver.py)."""
        self.generators.append(settings)
        self.write("SETPOVR", settings.raw_at(0.0))
        self.write("SETPOVRON", 1)

    def stop_generator(self) -> None:
        self.write("SETPOVRON", 0)

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

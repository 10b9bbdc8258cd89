"""Runs tuning and characterization procedures off the GUI thread (QtCore only).

:class:`ValveRunner` runs them on the connected valve, as a long job of the valve connection's
worker thread (the oscilloscope's stream is stopped first: the procedure streams itself).
:class:`SimulationRunner` runs them on an emulated copy of the document's valve in a thread of
its own, stepped as fast as the CPU allows (offline, and for trying before touching a valve).
Both report ``finished(kind, result)`` or ``failed(kind, message)`` on the GUI thread; ``stop()``
ends a running procedure at its next check, and the procedure puts the valve back as it was.
"""

from __future__ import annotations

import threading
from collections.abc import Callable, Mapping
from typing import TYPE_CHECKING

from PySide6.QtCore import QObject, Signal
from shiboken6 import Shiboken

from prm9tool.characterize.canrig import LinkTooSlowError, rig_for_session
from prm9tool.characterize.rig import Rig
from prm9tool.errors import CommunicationError, Prm9Error
from prm9tool.service.motion import claim
from prm9tool.translate import error_text

if TYPE_CHECKING:
    from prm9tool.device.records import ValveStatus
    from prm9tool.device.session import ValveSession
    from prm9tool.online.connection import ValveConnection
    from prm9tool.online.connection_protocol import ValveIdentity
    from prm9tool.online.twins import TwinPlant

Procedure = Callable[[Rig], object]


class _Failure:
    def __init__(self, message: str) -> None:
        self.message = message


class TuningRunner(QObject):
    """The interface the Tuning window uses (one procedure at a time)."""

    finished = Signal(str, object)  # kind, result
    failed = Signal(str, str)  # kind, message
    busy_changed = Signal(bool)

    def __init__(self, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self._rig: Rig | None = None
        self._kind = ""
        self._lock = threading.Lock()
        self.stop_requested = threading.Event()

    @property
    def busy(self) -> bool:
        """True while a procedure runs."""
        return bool(self._kind)

    @property
    def simulated(self) -> bool:
        """True when the procedures run on an emulated copy, not on a valve."""
        return False

    def run(self, kind: str, procedure: Procedure) -> None:
        """Start ``procedure`` (ignored while another one runs)."""
        if self._kind:
            return
        self._kind = kind
        self.stop_requested.clear()
        self.busy_changed.emit(True)
        self._start(kind, procedure)

    def played_s(self) -> float:
        """Valve seconds the running procedure has played so far (0 when none runs)."""
        with self._lock:
            rig = self._rig
        return rig.played_s if rig is not None else 0.0

    def stop(self) -> None:
        """Ask the running procedure to stop (it restores the valve)."""
        self.stop_requested.set()
        with self._lock:
            if self._rig is not None:
                self._rig.stop.set()

    def _start(self, kind: str, procedure: Procedure) -> None:
        raise NotImplementedError

    def _execute(self, rig: Rig, procedure: Procedure) -> object:
        """Run ``procedure`` on ``rig`` (worker thread); a Prm9Error becomes a _Failure."""
        with self._lock:
            self._rig = rig
            if self.stop_requested.is_set():
                rig.stop.set()
        try:
            return procedure(rig)
        except LinkTooSlowError as exc:  # the test cannot run at this rate; the link is fine
            return _Failure(error_text(exc))
        except CommunicationError:
            raise
        except Prm9Error as exc:
            return _Failure(error_text(exc))
        except ValueError as exc:
            return _Failure(str(exc))
        finally:
            with self._lock:
                self._rig = None

    def _deliver(self, result: object) -> None:
        kind, self._kind = self._kind, ""
        self.busy_changed.emit(False)
        if isinstance(result, _Failure):
            self.failed.emit(kind, result.message)
        else:
            self.finished.emit(kind, result)


class ValveRunner(TuningRunner):
    """Procedures on the connected valve (a long job of :class:`ValveConnection`).

    The values a procedure writes are read first and kept: a procedure puts them back itself,
    but when the link breaks in the middle it cannot. Then, once the same valve is back
    (the connection's ``reconnected``, before its comparison), the runner writes those values
    back and gives the setpoint back; ``restored(message)`` says so."""

    restored = Signal(str)

    def __init__(self, connection: ValveConnection, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self.connection = connection
        self.to_restore: dict[str, int] | None = None  # a broken test's changes (GUI thread)
        self._originals: dict[str, int] = {}  # worker thread, while a procedure runs
        connection.operation_finished.connect(self._on_operation_finished)
        connection.failed.connect(self._on_connection_failed)
        connection.lost.connect(self._on_connection_lost)
        connection.reconnected.connect(self._on_connection_reconnected)

    def _start(self, kind: str, procedure: Procedure) -> None:
        if self.connection.streaming_keys:
            self.connection.stop_stream()
        link = _link_name(self.connection.device)
        self._originals = {}
        signal = getattr(self.connection, "status_changed", None)  # the job holds the link:
        publish = signal.emit if signal is not None else None  # the status the test reads
        motion = {"report": "characterization", "autotune": "autotune",
                  "signature": "signature"}.get(kind, "tuning")  # fmt: skip

        def job(session: ValveSession) -> object:
            # one owner of the valve's motion (MotionBusyError while a generator runs on it);
            # the status the test reads goes to the main window's status bar (not polled)
            with claim(session, motion):
                rig = _recording(rig_for_session(session, link), self._originals, publish)
                return self._execute(rig, procedure)

        self.connection.run_job(f"tuning:{kind}", job)

    def _on_connection_lost(self, message: str) -> None:
        if self._kind:  # cut off: what it changed goes back when the valve is back
            self.to_restore = dict(self._originals)
        self._on_connection_failed(message)

    def _on_connection_reconnected(self, _info: object) -> None:
        values, self.to_restore = self.to_restore, None
        if values is None:
            return

        def restore(session: ValveSession) -> None:
            if values:
                session.write_many(values)
            session.setpoint_link().end()  # the override off, as the test's own end does

        names = ", ".join(values)

        def done(_result: object) -> None:
            if Shiboken.isValid(self):  # the window may have been closed meanwhile
                self.restored.emit(_restored_text(names))

        self.connection.run("tuning-restore", restore, done)

    def _on_operation_finished(self, name: str, result: object) -> None:
        if self._kind and name == f"tuning:{self._kind}":
            self._deliver(result)

    def _on_connection_failed(self, message: str) -> None:
        if self._kind:
            self._deliver(_Failure(message))


def _recording(
    rig: Rig, originals: dict[str, int], publish: Callable[[ValveStatus], None] | None = None
) -> Rig:
    """``rig`` whose writes first read and keep (in ``originals``) the values they replace,
    and whose every status read is passed to ``publish``: while a test holds the link the
    connection polls no status, so the status bar would go on showing the one from before the
    test (e.g. "waiting for a CANopen master" on a valve enabled just before it)."""
    write, status = rig.write, rig.status
    if publish is not None:

        def publishing_status() -> ValveStatus:
            found = status()
            publish(found)
            return found

        setattr(rig, "status", publishing_status)  # noqa: B010 (this instance only)

    def recording_write(values: Mapping[str, int]) -> None:
        new = [m for m in values if m not in originals]
        if new:
            originals.update(rig.read(new))
        write(values)

    setattr(rig, "write", recording_write)  # noqa: B010 (this instance only)
    return rig


def _restored_text(names: str) -> str:
    from PySide6.QtCore import QCoreApplication

    return QCoreApplication.translate(
        "TuningRunner",
        "The valve is back: what the broken test had changed is restored ({0}) and the "
        "setpoint is the valve's own again.",
    ).format(names or "—")


def _link_name(device: ValveIdentity | None) -> str:
    device_id = device.device_id if device is not None else ""
    if device_id.startswith("emulator:"):
        return "emulator over its USB link (real time)"
    return "USB"


class _Relay(QObject):
    done = Signal(object)


class SimulationRunner(TuningRunner):
    """Procedures on an emulated valve holding the document's values (no valve touched)."""

    def __init__(
        self,
        type_key: str,
        values: Mapping[str, int | str],
        parent: QObject | None = None,
        twin: TwinPlant | None = None,
    ) -> None:
        super().__init__(parent)
        self.type_key, self.values = type_key, dict(values)
        self.twin = twin  # the plant the tests run on: this twin's, else (None) the emulator's
        self._relay = _Relay()
        self._relay.done.connect(self._deliver)
        self._thread: threading.Thread | None = None

    @property
    def simulated(self) -> bool:
        """Always True."""
        return True

    def _start(self, kind: str, procedure: Procedure) -> None:
        relay = self._relay

        def work() -> None:
            try:
                result = self._execute(self._rig_factory(), procedure)
            except Prm9Error as exc:
                result = _Failure(error_text(exc))
            relay.done.emit(result)

        self._thread = threading.Thread(target=work, name="tuning-simulation", daemon=True)
        self._thread.start()

    def _rig_factory(self) -> Rig:
        from prm9tool.catalogue import CATALOGUE
        from prm9tool.characterize.rig import EmulatorRig
        from prm9tool.device.emulator import EmulatedValve
        from prm9tool.online.tuning import analog_type_key

        plant = self.twin.plant if self.twin is not None else None
        key = analog_type_key(self.type_key)
        valve = EmulatedValve(key) if plant is None else EmulatedValve(key, plant=plant)
        for mnemonic, raw in self.values.items():
            param = CATALOGUE.get(mnemonic)
            if param is not None and param.writable and param.applies(valve.variant):
                valve.write(param.index, param.subindex, raw)
        return EmulatorRig(valve)

    def wait(self, timeout: float = 10.0) -> None:
        """Wait for the running procedure's thread (tests, closing the window)."""
        if self._thread is not None:
            self._thread.join(timeout)

"""The valve connection: runs a valve session in a worker thread and reports through Qt signals.

One worker thread owns the session; the GUI thread only queues jobs (go online, write, upload,
…) and receives results as signals, so the GUI never blocks on the valve. Between jobs the
worker polls the valve on its own schedule, whether or not jobs keep arriving: the
oscilloscope stream (every 20 ms), status and read-only live values (≈ 2 Hz) and watched
measuring points (≈ 7 Hz); those live commands, their signals and their state are the part
the connection holds, :class:`LiveData` (connection_live.py). A communication error ends the
session: the connection reports ``lost``, is offline afterwards and looks for the same valve
again (connection_reconnect.py). QtCore only; the device layer is imported lazily.
"""

from __future__ import annotations

import logging
from collections.abc import Callable, Mapping, Sequence
from typing import TYPE_CHECKING, cast

from PySide6.QtCore import QObject, Qt, Signal, SignalInstance

from prm9tool.online.connection_live import LiveData
from prm9tool.online.connection_reconnect import ReconnectLink
from prm9tool.online.connection_worker import ConnectionWorker, Job
from prm9tool.service.reconnect import LostValve
from prm9tool.service.valve_listing import default_lister, default_opener, list_in_thread

if TYPE_CHECKING:
    from pathlib import Path

    from prm9tool.device.session import ValveSession
    from prm9tool.history.recorder import Details, Recorder
    from prm9tool.online.connection_protocol import ListedValves, ValveIdentity, ValveListing
    from prm9tool.scope import GeneratorSettings  # not at run time: numpy, at start-up
    from prm9tool.service.history import HistoryHook
    from prm9tool.service.valve import ValveService

log = logging.getLogger(__name__)

Opener = Callable[[object], "ValveSession"]  # entry -> the open session
Lister = Callable[..., "Sequence[ValveListing]"]  # (emulator specs[, CAN bus dict]) -> entries


class ValveConnection(QObject):
    """Online/offline state and asynchronous operations on one valve (docs/ARCHITECTURE.md);
    its stream, generator and polled values are its part :attr:`live`, a
    :class:`LiveData` (connection_live.py), whose signals and commands it shows as its own."""

    online_changed = Signal(bool)
    device_changed = Signal(object)  # DeviceInfo or None
    status_changed = Signal(object)  # ValveStatus
    failed = Signal(str)
    lost = Signal(str)
    progress = Signal(int, int, str)
    operation_finished = Signal(str, object)
    busy_changed = Signal(bool)
    write_failed = Signal(list)  # mnemonics whose write failed (the valve state is unknown)
    backup_written = Signal(str)  # path of the backup taken before the first upload
    history_problem = Signal(str)  # a record went to the local queue, or was lost (why)
    # a CANopen valve without 0x2041 whose type key is not known: (device ID, serial, "E02"/"E04")
    type_key_needed = Signal(str, int, str)
    # the lost valve is looked for (service/reconnect.py): seconds since it was lost
    reconnecting = Signal(float)
    reconnected = Signal(object)  # DeviceInfo: the same valve is back (online_changed follows)
    reconnect_ended = Signal()  # no longer looking (back, another valve, or the user decided)
    other_valve = Signal(int, int, str)  # (lost serial, serial found, device ID): a new valve
    _posted = Signal(object)  # a callable the GUI thread runs (results of the worker)

    def __init__(
        self,
        opener: Opener | None = None,
        lister: Lister | None = None,
        parent: QObject | None = None,
        after_open: Callable[[ValveSession], object] | None = None,
    ) -> None:
        """``after_open(session)`` runs in a thread of its own once a session is open, while
        the connection already reports online (the GUI puts an emulated -CA valve on its CAN
        bus there); a Prm9Error it raises arrives as ``failed``, the session stays open."""
        super().__init__(parent)
        self._lister = lister or default_lister
        self._worker = ConnectionWorker(self, opener or default_opener, after_open)
        self._online = False
        self._device: ValveIdentity | None = None
        self._busy = 0
        self._ended = False  # shutdown(): the worker's late results are dropped
        self.live = LiveData(self._worker, self._submit, self.write_failed.emit, self)
        self.live.stream_silent.connect(self.failed)  # a dead stream, in the capture's words
        self._posted.connect(self._on_posted, Qt.ConnectionType.QueuedConnection)
        self.history: HistoryHook | None = None  # set_recorder(); used by the worker only
        self.auto_reconnect = True  # look for a lost valve until it is back (service/reconnect.py)
        self.lost_during_operation = False  # the last loss cut a long operation off
        self._reconnect = ReconnectLink(self)

    def set_recorder(self, recorder: Recorder) -> None:
        """Record every operation on the valve's parameter set into this history."""
        from prm9tool.service.history import HistoryHook

        report = lambda text: self._post(lambda: self.history_problem.emit(text))  # noqa: E731
        self.history = HistoryHook(recorder, report)

    def service(self, session: ValveSession) -> ValveService:
        """The valve service of the worker's session, recording into this connection's
        history (worker thread only: the jobs call it with their session)."""
        from prm9tool.service.valve import service_for

        service = service_for(session)
        service.history = self.history
        return service

    def check_history(self, on_done: Callable[[object], None]) -> None:
        """Ask whether the history can take records; ``on_done(None or the HistoryError)`` runs
        on the GUI thread. Runs in the worker (a remote database may be slow)."""
        hook = self.history
        run = lambda _s: hook.problem() if hook else None  # noqa: E731
        self._submit(Job("history_check", run, on_done, report=False))

    def record(self, operation: str, outcome: str, values: Mapping[str, int | str] | None,
               details: Details | None = None) -> None:  # fmt: skip
        """Record an operation the GUI ran as its own job (e.g. restore factory values)."""
        if self.history is not None:
            hook = self.history
            run = lambda s: hook.add(s, operation, outcome, values, details)  # noqa: E731
            self._submit(Job("record", run, None, False))

    # --- state --------------------------------------------------------------------------------
    @property
    def is_online(self) -> bool:
        """True while a session is open."""
        return self._online

    @property
    def device(self) -> ValveIdentity | None:
        """The DeviceInfo of the connected valve, or None."""
        return self._device

    @property
    def is_busy(self) -> bool:
        """True while a long operation (upload, download, …) runs."""
        return self._busy > 0

    def list_devices(self, emulators: Sequence[str] = ()) -> list[ValveListing]:
        """Connected valves plus the emulated valves ``emulators`` ("TYPEKEY[:SERIAL]").

        Blocks while each USB valve identifies itself (up to 0.6 s for one that does not
        answer): the GUI uses :meth:`list_devices_async`.
        """
        return list(self._lister(emulators))

    def list_devices_async(
        self,
        emulators: Sequence[str],
        deliver: Callable[[ListedValves], None],
        can: Mapping[str, object] | None = None,
    ) -> None:
        """:meth:`list_devices` in a thread of its own; ``deliver(entries)`` — or
        ``deliver(exception)`` if listing failed — runs on the GUI thread. ``can``: also scan
        that CAN bus (``interface``, ``channel``, ``bitrate``) for its nodes."""
        list_in_thread(
            self._lister, emulators, can, lambda found: self._post(lambda: deliver(found))
        )

    # --- commands (GUI thread) ------------------------------------------------------------------
    def go_online(self, entry: object) -> None:
        """Open a session to ``entry`` (a DeviceEntry or device-id string)."""
        self.stop_reconnecting()
        if self._online or self.is_busy:
            busy = self.tr("The valve connection is busy; wait until it is done.")
            self.failed.emit(busy if self.is_busy else self.tr("Already online; go offline first."))
            return
        self._ended = False  # started again after a shutdown
        self._worker.start()
        self._set_busy(+1)  # connecting: no second session may be opened meanwhile
        done = lambda: self._set_busy(-1)  # noqa: E731
        self._submit(Job("online", lambda _s: self._worker.open(entry), self._on_opened, False, done,
                          needs_session=False))  # fmt: skip

    def go_offline(self) -> None:
        """Close the session (the stream stops); online_changed(False) follows. Also stops
        looking for a lost valve."""
        self.stop_reconnecting()
        if self._online:
            self._worker.cancel.set()
            self._submit(Job("offline", lambda _s: self._worker.close(), self._on_closed, False))

    def write(self, mnemonic: str, raw: int | str) -> None:
        """Write one value to the valve; failures arrive as ``failed`` and ``write_failed``."""
        self.write_many({mnemonic: raw})

    def write_many(self, values: Mapping[str, int | str]) -> None:
        """Write values to the valve; failures arrive as ``failed`` and ``write_failed``."""
        values, names = dict(values), list(values)
        failed = lambda: self.write_failed.emit(names)  # noqa: E731
        # checked as every door checks (read-only, range: the same words), then written
        self._submit(Job("write", lambda s: self.service(s).write_raw(values), None, False, failed))

    def store(self, values: Mapping[str, int | str] | None = None) -> None:
        """Copy the valve's working values to its non-volatile memory; ``values`` (the whole
        set as the GUI knows it) goes into the history as the stored online edits."""
        known = None if values is None else dict(values)

        def run(session: ValveSession) -> None:
            session.store()
            if self.history is not None:
                self.history.add(session, "online-edits", "ok", known, {"stored": True})

        self._long_job("store", run)

    def store_valve(self) -> None:
        """Valve → Store: what the valve works with becomes its stored set (the link's store),
        read back and recorded in the history; result: operation_finished("store", values)."""
        self._long_job("store", lambda s: self.service(s).store(self._worker.progress))

    def read_many(self, mnemonics: Sequence[str], tag: str = "read") -> None:
        """Read values; the result arrives as operation_finished(tag, {mnemonic: raw})."""
        names = list(mnemonics)
        self._submit(Job(tag, lambda s: s.read_many(names)))

    def upload(
        self, values: Mapping[str, int | str], backup: bool = True, purpose: str = ""
    ) -> None:
        """Write → read back and compare → store; result: operation_finished("upload", …).

        With ``backup``, a valve that has no backup yet is downloaded into one first
        (``backup_written`` reports the file). ``purpose``: what the user did, for the history.
        """
        values = dict(values)

        def backed_up(path: Path | None) -> None:
            if path is not None:
                self._post(lambda: self.backup_written.emit(str(path)))

        def run(session: ValveSession) -> object:
            # the one upload sequence (prm9tool.service.upload): rules, backup, upload, history
            return self.service(session).upload(
                values,
                backup=backup,
                progress=self._worker.progress,
                cancel=self._worker.cancel,
                purpose=purpose,
                on_backup=backed_up,
            )

        self._long_job("upload", run)

    def download(self, tag: str = "download") -> None:
        """Read the valve's file parameters; result: operation_finished(tag, {mnemonic: raw})."""

        def run(session: ValveSession) -> object:
            # the values first: the history database may take ~0.3 s to open, so the record
            # is made now and written by a job queued right behind (even when the link is lost
            # meanwhile: needs_session False)
            values = self.service(session).download(
                self._worker.progress, self._worker.cancel, tag, record_later=True
            )
            hook = self.history
            if hook is not None:
                self._worker.jobs.put(Job("history", lambda _s: hook.write_later(), None, False,
                                          needs_session=False))  # fmt: skip
            return values

        self._long_job(tag, run)

    def verify_by_restart(
        self, expected: Mapping[str, int | str], upload_store: str | None
    ) -> None:
        """Restart the valve and read back that it kept ``expected`` (service/restart_verify.py;
        only after the hydraulics confirmation); result: operation_finished("verify_restart",
        RestartVerification), a valve that does not come back arrives as ``lost``."""
        from prm9tool.service.restart_verify import verify_by_restart

        values, progress = dict(expected), self._worker.progress
        work = lambda s: verify_by_restart(s, values, upload_store, self.history, progress)  # noqa: E731
        self._long_job("verify_restart", work)

    def read_each(self, mnemonics: Sequence[str], tag: str) -> None:
        """Read values one by one; result: operation_finished(tag, {mnemonic: raw or the
        Prm9Error that refused it})."""
        names = list(mnemonics)
        self._long_job(tag, lambda s: self.service(s).read_each(names))

    def restart_valve(self, tag: str) -> None:
        """Restart (hydraulics confirmed off) and read the stored set; result:
        operation_finished(tag, {mnemonic: raw})."""
        work = lambda s: self.service(s).restart_and_read("Valve → Restart valve")  # noqa: E731
        self._long_job(tag, work)

    def factory_reset(self, tag: str) -> None:
        """Backup, restore the factory values, restart (hydraulics confirmed off), read back;
        result: operation_finished(tag, (values, backup path or None))."""
        self._long_job(tag, lambda s: self.service(s).restore_factory())

    def run_job(self, name: str, work: Callable[[ValveSession], object]) -> None:
        """Run ``work(session)`` as a long operation; result: operation_finished(name, …)."""
        self._long_job(name, work)

    def run(
        self,
        name: str,
        work: Callable[[ValveSession], object],
        on_done: Callable[[object], None] | None = None,
    ) -> None:
        """Run ``work(session)`` in the worker between its polls (a short job: the connection
        does not become busy); ``on_done(result)`` runs on the GUI thread, a failure arrives
        as ``failed`` (or ``lost``)."""
        self._submit(Job(name, work, on_done, report=False))

    def cancel(self) -> None:
        """Ask the running long operation to stop at the next safe point."""
        self._worker.cancel.set()

    def restart(self) -> None:
        """Restart the valve electronics; result: operation_finished("restart", None)."""
        self._long_job("restart", lambda s: self.service(s).restart())

    def shutdown(self, timeout_s: float = 3.0) -> None:
        """Close the session and end the worker thread (application exit)."""
        self.stop_reconnecting()
        self._ended = True  # what the worker still posts reaches no one: the window closed
        self._worker.stop(timeout_s)

    # --- the live part's signals and commands (connection_live.py) ---------------------------
    @property
    def live_values_changed(self) -> SignalInstance:
        """{mnemonic: raw} of the polled read-only values."""
        return self.live.live_values_changed

    @property
    def signal_values_changed(self) -> SignalInstance:
        """{measuring-point key: raw} of the watched measuring points."""
        return self.live.signal_values_changed

    @property
    def samples_received(self) -> SignalInstance:
        """A numpy (n, k) raw block of the running stream, in its key order."""
        return self.live.samples_received

    @property
    def stream_started(self) -> SignalInstance:
        """The stream runs (its keys)."""
        return self.live.stream_started

    @property
    def stream_stopped(self) -> SignalInstance:
        """The stream stopped (asked for, or with the link)."""
        return self.live.stream_stopped

    @property
    def stream_silent(self) -> SignalInstance:
        """A dead stream was stopped: the capture's words (``failed`` says them too)."""
        return self.live.stream_silent

    @property
    def samples_lost_changed(self) -> SignalInstance:
        """Samples the running stream lost since it started."""
        return self.live.samples_lost_changed

    @property
    def generator_undone(self) -> SignalInstance:
        """What a generator cut off with its session had changed, written back (mnemonics)."""
        return self.live.generator_undone

    @property
    def streaming_keys(self) -> list[str]:
        """:attr:`LiveData.streaming_keys`."""
        return self.live.streaming_keys

    @property
    def samples_lost(self) -> int:
        """:attr:`LiveData.samples_lost`."""
        return self.live.samples_lost

    @property
    def generator_running(self) -> bool:
        """:attr:`LiveData.generator_running`."""
        return self.live.generator_running

    def start_stream(self, keys: Sequence[str], rate_hz: int) -> None:
        """:meth:`LiveData.start_stream`."""
        self.live.start_stream(keys, rate_hz)

    def stop_stream(self) -> None:
        """:meth:`LiveData.stop_stream`."""
        self.live.stop_stream()

    def start_generator(self, settings: GeneratorSettings) -> None:
        """:meth:`LiveData.start_generator`."""
        self.live.start_generator(settings)

    def stop_generator(self) -> None:
        """:meth:`LiveData.stop_generator`."""
        self.live.stop_generator()

    def watch_signals(self, keys: Sequence[str]) -> None:
        """:meth:`LiveData.watch_signals`."""
        self.live.watch_signals(keys)

    def watch_live(self, mnemonics: Sequence[str]) -> None:
        """:meth:`LiveData.watch_live`."""
        self.live.watch_live(mnemonics)

    # --- GUI-thread helpers --------------------------------------------------------------------
    def _submit(self, job: Job) -> None:
        if job.needs_session and not self._online:
            self.failed.emit(self.tr("Not connected to a valve."))
            return
        self._worker.jobs.put(job)

    def _long_job(self, name: str, run: Callable[[ValveSession], object]) -> None:
        if not self._online:
            self.failed.emit(self.tr("Not connected to a valve."))
            return
        self._worker.cancel.clear()
        self._set_busy(+1)
        done = lambda: self._set_busy(-1)  # noqa: E731
        self._worker.jobs.put(Job(name, self._noting_moves(run), lambda _r: done(), on_error=done))

    def _noting_moves(
        self, run: Callable[[ValveSession], object]
    ) -> Callable[[ValveSession], object]:
        """``run``, after which a changed identity of the valve (a restart that moved it to
        another node ID or bit rate, which the session followed) is announced on the GUI
        thread as ``device_changed``."""

        def work(session: ValveSession) -> object:
            before = session.info
            try:
                return run(session)
            finally:
                after = session.info
                if after is not before:
                    self._post(lambda: self._on_identity_changed(after))

        return work

    def _on_identity_changed(self, info: object) -> None:
        if self._online:
            self._device = cast("ValveIdentity", info)
            self.device_changed.emit(info)

    def _set_busy(self, delta: int) -> None:
        was = self.is_busy
        self._busy = max(0, self._busy + delta)
        if was != self.is_busy:
            self.busy_changed.emit(self.is_busy)

    def _post(self, action: Callable[[], None]) -> None:
        self._posted.emit(action)

    def _on_posted(self, action: object) -> None:
        assert callable(action)
        if not self._ended:
            action()

    def _on_opened(self, info: object) -> None:
        self._set_busy(-1)
        self._online = True
        self._device = cast("ValveIdentity", info)  # what the session's identify() returned
        self.device_changed.emit(info)
        self.online_changed.emit(True)

    def _on_closed(self, _result: object = None) -> None:
        if not self._online:
            return
        self._online = False
        self._device = None
        self._busy = 0
        self.busy_changed.emit(False)
        self.live.forget()
        self.device_changed.emit(None)
        self.online_changed.emit(False)

    def _finish(self, job: Job, result: object) -> None:
        if job.on_done is not None:
            job.on_done(result)
        if job.report:
            self.operation_finished.emit(job.name, result)

    def _report_lost(self, message: str) -> None:
        if self._online:
            device = self._device
            self.lost_during_operation = self.is_busy  # an upload, download, … was cut off
            if self.auto_reconnect and device is not None and device.serial:
                bus = getattr(device, "can_bus", None)  # known looking before going offline
                self._reconnect.prepare(LostValve(device.serial, device.device_id, bus))
            self._on_closed()
            self.lost.emit(message)
            self._reconnect.go()
        else:
            self.failed.emit(message)

    # --- finding a lost valve again (connection_reconnect.py) ---------------------------------
    @property
    def is_reconnecting(self) -> bool:
        """True while a lost valve is looked for."""
        return self._reconnect.looking is not None

    @property
    def lost_valve(self) -> LostValve | None:
        """The valve looked for (None when none is)."""
        looking = self._reconnect.looking
        return None if looking is None else looking.lost

    def stop_reconnecting(self) -> None:
        """Stop looking for the lost valve (``reconnect_ended`` follows if it was looked for)."""
        self._reconnect.stop()

    def _on_reopened(self, info: object) -> None:
        """The lost valve is open again (its serial checked): online, as after go_online."""
        self._online = True
        self._device = cast("ValveIdentity", info)
        self.reconnect_ended.emit()
        self.device_changed.emit(info)
        self.reconnected.emit(info)
        self.online_changed.emit(True)

"""The worker thread of :class:`~prm9tool.online.connection.ValveConnection`: it owns the
valve session, runs the queued jobs one after another, polls the valve between them (the
oscilloscope stream, status, live values, watched measuring points) and drives the setpoint
generator. Everything it reports goes to the GUI thread through the connection's ``_post``,
which emits the connection's signals there; a communication error closes the session and is
reported as ``lost``. QtCore only through the connection; the device layer is imported lazily.
"""

from __future__ import annotations

import functools
import logging
import queue
import threading
import time
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Protocol, cast

from prm9tool.errors import CommunicationError, Prm9Error
from prm9tool.service.motion import MotionOwner, owner_of
from prm9tool.service.polling import Poller, Schedule
from prm9tool.service.setpoint_driver import SetpointDriver, StreamClock, setpoint_link
from prm9tool.translate import error_text

if TYPE_CHECKING:
    from PySide6.QtCore import SignalInstance

    from prm9tool.device.session import ValveSession
    from prm9tool.scope import GeneratorSettings  # not at run time: numpy, at start-up

log = logging.getLogger("prm9tool.online.connection")

PROGRESS_PERIOD_S = 0.05


@dataclass
class Job:
    """One operation for the worker: ``run(session)`` in the worker thread, the rest on the GUI
    thread."""

    name: str
    run: Callable[[ValveSession], object]  # session -> result (runs in the worker)
    on_done: Callable[[object], None] | None = None  # result -> None (runs in the GUI thread)
    report: bool = True  # emit operation_finished(name, result)
    on_error: Callable[[], None] | None = None  # runs in the GUI thread after a failure
    needs_session: bool = True


IDLE = Job("idle", lambda _s: None)


class LiveReports(Protocol):
    """What the worker reports the live data through: the connection's ``live`` part
    (online/connection_live.py ``LiveData`` fits it: online/conformance.py)."""

    @property
    def samples_received(self) -> SignalInstance: ...
    @property
    def live_values_changed(self) -> SignalInstance: ...
    @property
    def signal_values_changed(self) -> SignalInstance: ...
    @property
    def generator_undone(self) -> SignalInstance: ...

    def samples_lost_counted(self, count: int) -> None: ...
    def stream_went_silent(self, text: str) -> None: ...


class WorkerHost(Protocol):
    """What the worker needs of its connection: the signals it reports through, its live
    part and the GUI thread's side of a job (``ValveConnection`` fits it:
    online/conformance.py)."""

    @property
    def live(self) -> LiveReports: ...
    @property
    def failed(self) -> SignalInstance: ...
    @property
    def write_failed(self) -> SignalInstance: ...
    @property
    def progress(self) -> SignalInstance: ...
    @property
    def status_changed(self) -> SignalInstance: ...
    @property
    def type_key_needed(self) -> SignalInstance: ...

    def _post(self, action: Callable[[], None]) -> None: ...
    def _finish(self, job: Job, result: object) -> None: ...
    def _report_lost(self, message: str) -> None: ...


class ConnectionWorker:
    """The worker side of one ValveConnection (``host``); ``opener(entry)`` opens a session,
    ``after_open(session)`` runs in a thread of its own once it is open."""

    def __init__(
        self,
        host: WorkerHost,
        opener: Callable[[object], ValveSession],
        after_open: Callable[[ValveSession], object] | None,
    ) -> None:
        self._host = host
        self._opener = opener
        self._after_open = after_open
        self.jobs: queue.Queue[Job | None] = queue.Queue()
        self.cancel = threading.Event()  # set: the running long operation stops
        self.session: ValveSession | None = None  # touched by the worker thread only
        self.poller = Poller()  # worker-side state of the periodic reads
        self.clock = StreamClock()  # the valve's time from its stream (the generator's)
        self._driver: SetpointDriver | None = None  # the running generator
        self._driver_motion = MotionOwner()  # whose motion it owns (its session's)
        # (serial, {mnemonic: value}): what a generator cut off with its session had changed
        self._left_on: tuple[int, dict[str, int]] | None = None
        self._thread: threading.Thread | None = None
        self._last_progress = 0.0

    def start(self) -> None:
        """Start the worker thread (once)."""
        if self._thread is None:
            self._thread = threading.Thread(target=self._main, name="valve", daemon=True)
            self._thread.start()

    def stop(self, timeout_s: float) -> None:
        """Close the session and end the thread (waits up to ``timeout_s``)."""
        if self._thread is None:
            return
        self.cancel.set()
        self.jobs.put(None)
        self._thread.join(timeout_s)
        self._thread = None

    def _main(self) -> None:
        schedule = Schedule()
        while True:
            streaming = bool(self.poller.stream_keys)
            # offline there is nothing to read: wait for the next job
            wait = (
                schedule.wait_s(time.monotonic(), streaming) if self.session is not None else None
            )
            try:
                job = self.jobs.get(timeout=wait)
            except queue.Empty:
                job = IDLE
            if job is None:
                self.close()
                return
            if job is not IDLE:
                self._execute(job)
            if self.session is not None:
                due = schedule.take_due(time.monotonic(), bool(self.poller.stream_keys))
                if any(due):
                    self.guarded(functools.partial(self._poll, *due))

    def _execute(self, job: Job) -> None:
        if job.needs_session and self.session is None:
            # queued while online (the connection refuses it offline), its session closed
            # since: by a lost link, already reported, or going offline. Said again it was a
            # second error after "the valve did not come back" (issue 34)
            if job.on_error is not None:
                self._host._post(job.on_error)
            return

        def run() -> None:
            # a job that needs no session (going online) ignores its argument
            result = job.run(cast("ValveSession", self.session))
            self._host._post(lambda: self._host._finish(job, result))

        if not self.guarded(run) and job.on_error is not None:
            self._host._post(job.on_error)

    def guarded(self, work: Callable[[], None]) -> bool:
        """Run ``work``; turn errors into signals. Returns False if it failed."""
        try:
            work()
        except CommunicationError as exc:
            self.close()
            lost = exc  # texts are translated on the GUI thread, where the translators live
            self._host._post(lambda: self._host._report_lost(error_text(lost)))
            return False
        except Prm9Error as exc:
            failure = exc
            self._host._post(lambda: self._host.failed.emit(error_text(failure)))
            return False
        except Exception as exc:  # a bug must not kill the worker thread
            log.exception("valve worker")
            message = f"{type(exc).__name__}: {exc}"
            self._host._post(lambda: self._host.failed.emit(message))
            return False
        return True

    def open(self, entry: object) -> object:
        """Open a session to ``entry``; returns what the valve says it is (``identify()``)."""
        from prm9tool.device.canlink.typekeys import TypeKeyNeededError

        self.cancel.clear()
        try:
            self.session = self._opener(entry)
        except TypeKeyNeededError as exc:  # the GUI asks for the key on the label, then again
            device_id, serial = str(getattr(entry, "device_id", entry)), exc.serial
            told = exc.derived.config.value if exc.derived.config else ""
            self._host._post(lambda: self._host.type_key_needed.emit(device_id, serial, told))
            raise
        info = self.session.identify()
        self.poller.reset(info)
        self._put_back_left_on(self.session, getattr(info, "serial", 0))
        if self._after_open is not None:
            session = self.session
            threading.Thread(
                target=self._run_after_open, args=(session,), name="valve-after-open", daemon=True
            ).start()
        return info

    def _run_after_open(self, session: ValveSession) -> None:
        assert self._after_open is not None
        try:
            self._after_open(session)
        except Prm9Error as exc:
            failure = exc
            self._host._post(lambda: self._host.failed.emit(error_text(failure)))
        except Exception:  # a bug must not pass silently
            log.exception("after opening the session")

    def start_driver(self, session: ValveSession, settings: GeneratorSettings) -> None:
        """Run the setpoint generator's waveform (a running one is replaced); it owns the
        valve's motion (prm9tool.service.motion: MotionBusyError while another runs)."""
        self.stop_driver(session, switch_off=False)
        motion = owner_of(session)
        motion.take("generator")
        try:
            driver = SetpointDriver(session, settings, self._on_driver_refused, self.clock)
            driver.start()
        except BaseException:
            motion.release("generator")
            raise
        self._driver, self._driver_motion = driver, motion

    def stop_driver(self, session: ValveSession | None, switch_off: bool) -> None:
        """End the waveform; ``switch_off``: give the valve its own setpoint back."""
        driver, self._driver = self._driver, None
        if driver is not None:
            try:
                driver.stop(switch_off)
            finally:
                self._driver_motion.release("generator")
        elif switch_off and session is not None:
            setpoint_link(session).release()  # what a previous session may have left on

    def _on_driver_refused(self, mnemonic: str, exc: Prm9Error) -> None:
        """The driver's thread: the valve refused one of its writes; the driver has ended."""
        text = error_text(exc)

        def report() -> None:
            self._host.failed.emit(text)
            self._host.write_failed.emit([mnemonic])

        self._host._post(report)

    def _put_back_left_on(self, session: ValveSession, serial: int) -> None:
        """The same valve again: write back what a generator cut off with its last session
        had changed (over CANopen the RPDO1 deadline it armed) and say so."""
        left_on = self._left_on
        if left_on is None or left_on[0] != serial:
            return
        self._left_on = None
        values = left_on[1]
        try:
            session.write_many(values)
        except Prm9Error as exc:  # said; the session stays open
            text = error_text(exc)
            self._host._post(lambda: self._host.failed.emit(text))
            return
        names = sorted(values)
        self._host._post(lambda: self._host.live.generator_undone.emit(names))

    def close(self) -> None:
        """Stop the generator and close the session (a broken link closes quietly)."""
        if self._driver is not None and self.session is not None:
            left_on = self._driver.leftovers()  # its end cannot run: put back when it is back
            if left_on:
                serial = self.session.info.serial
                self._left_on = (serial, left_on)
        self.stop_driver(None, switch_off=False)  # the link may be gone: nothing to write
        session, self.session = self.session, None
        self.poller.forget_streams()
        if session is not None:
            try:
                session.close()
            except Prm9Error as exc:  # closing a broken link must not raise
                log.debug("closing the session failed: %s", exc)

    def progress(self, done: int, total: int, step: str) -> None:
        """A long operation's progress, passed on at most every ``PROGRESS_PERIOD_S``."""
        now = time.monotonic()
        if done < total and now - self._last_progress < PROGRESS_PERIOD_S:
            return
        self._last_progress = now
        self._host._post(lambda: self._host.progress.emit(done, total, step))

    def _poll(self, stream: bool, status: bool, signals: bool) -> None:
        if self.session is None:  # closed since the poll was due
            return
        result = self.poller.poll(self.session, status, signals, stream)
        if result.samples is not None:
            samples = result.samples
            self.clock.samples_arrived(len(samples))
            self._host._post(lambda: self._host.live.samples_received.emit(samples))
        if result.samples_lost is not None:
            lost = result.samples_lost
            self._host._post(lambda: self._host.live.samples_lost_counted(lost))
        if result.stream_silent is not None:  # the poller stopped it; the link still answers
            silent = error_text(result.stream_silent)
            self._host._post(lambda: self._host.live.stream_went_silent(silent))
        if result.status is not None:
            valve_status = result.status
            self._host._post(lambda: self._host.status_changed.emit(valve_status))
        if result.live:
            live = result.live
            self._host._post(lambda: self._host.live.live_values_changed.emit(live))
        if result.signals:
            values = result.signals
            self._host._post(lambda: self._host.live.signal_values_changed.emit(values))

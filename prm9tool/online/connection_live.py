"""The live side of the valve connection: the oscilloscope stream, the setpoint generator and
the measuring points and read-only values the worker polls between jobs.

:class:`LiveData` is a part :class:`~prm9tool.online.connection.ValveConnection` holds (its
``live``), a QObject of its own: its signals, its GUI-side state (the running stream's keys,
its lost samples, whether a generator runs) and its commands, which queue jobs on the
connection's worker like every other command (``submit``). The connection shows its signals
and commands as its own. They end with the link: :meth:`LiveData.forget` when the session
closes or breaks (the oscilloscope restarts its own stream once a lost valve is back; the
generator writes setpoints, so only the user starts it again). QtCore only.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING

from PySide6.QtCore import QObject, Signal

from prm9tool.online.connection_worker import ConnectionWorker, Job
from prm9tool.service.setpoint_driver import GENERATOR_OBJECTS

if TYPE_CHECKING:
    from prm9tool.device.session import ValveSession
    from prm9tool.scope import GeneratorSettings  # not at run time: numpy, at start-up

OVERRIDE_OBJECTS = tuple(sorted(GENERATOR_OBJECTS))  # a refused generator start names these


class LiveData(QObject):
    """Stream, generator and polled values of one connection (its ``live`` part):
    ``submit(job)`` queues a job on the connection's ``worker``, ``write_refused(mnemonics)``
    reports objects whose write failed (the connection's ``write_failed``)."""

    live_values_changed = Signal(dict)  # {mnemonic: raw}
    signal_values_changed = Signal(dict)  # {measuring-point key: raw}
    samples_received = Signal(object)  # numpy (n, k) raw block, in stream key order
    stream_started = Signal(list)
    stream_stopped = Signal()
    samples_lost_changed = Signal(int)  # samples the oscilloscope stream lost since it started
    stream_silent = Signal(str)  # the stream sent nothing for its bound and was stopped: why
    # a generator cut off with its session had changed these; the same valve open again, they
    # were written back (over CANopen: the RPDO1 deadline 0x1400/5 it armed)
    generator_undone = Signal(list)

    def __init__(
        self,
        worker: ConnectionWorker,
        submit: Callable[[Job], None],
        write_refused: Callable[[list[str]], None],
        parent: QObject | None = None,
    ) -> None:
        super().__init__(parent)
        self._worker, self._submit, self._write_refused = worker, submit, write_refused
        self._stream_keys: list[str] = []  # GUI-side: keys of the running stream
        self._generator = False  # GUI-side: a setpoint generator was started and not stopped
        self._samples_lost = 0  # GUI-side: lost samples of the running stream

    @property
    def streaming_keys(self) -> list[str]:
        """The measuring points of the running stream ([] when none runs)."""
        return list(self._stream_keys)

    @property
    def samples_lost(self) -> int:
        """Samples the running oscilloscope stream lost since it started (gaps in its sequence
        numbers: the link or the host could not keep up); 0 when no stream runs."""
        return self._samples_lost

    def start_stream(self, keys: Sequence[str], rate_hz: int) -> None:
        """Stream up to three measuring points; samples arrive as ``samples_received``."""
        names = list(keys)

        def run(session: ValveSession) -> list[str]:
            started = self._worker.poller.start_stream(session, names, rate_hz)
            self._worker.clock.restart(rate_hz)
            return started

        self._submit(Job("stream_start", run, self._on_stream_started, False))

    def stop_stream(self) -> None:
        """Stop the stream (``stream_stopped`` follows)."""
        self._submit(
            Job("stream_stop", self._worker.poller.stop_stream, self._on_stream_stopped, False)
        )

    def start_generator(self, settings: GeneratorSettings) -> None:
        """Run the setpoint generator's waveform on the valve's setpoint, off the GUI thread
        and on the valve's time base (:mod:`prm9tool.service.setpoint_driver`): the override
        over USB, RPDO1 over CANopen. A refused write arrives as the connection's ``failed``
        and ``write_failed``."""

        def refused() -> None:
            self._generator = False
            self._write_refused(list(OVERRIDE_OBJECTS))

        run = lambda s: self._worker.start_driver(s, settings)  # noqa: E731
        self._generator = True
        self._submit(Job("generator", run, None, False, refused))

    @property
    def generator_running(self) -> bool:
        """True from start_generator until stop_generator, a refusal or the link's end (what
        the Tuning window tells the user a test will stop)."""
        return self._generator

    def stop_generator(self) -> None:
        """End the waveform and give the setpoint back (SETPOVRON = 0; over CANopen the
        RPDO1 setpoint from before the generator)."""
        refused = lambda: self._write_refused(["SETPOVRON"])  # noqa: E731
        run = lambda s: self._worker.stop_driver(s, switch_off=True)  # noqa: E731
        self._generator = False
        self._submit(Job("generator_stop", run, None, False, refused))

    def watch_signals(self, keys: Sequence[str]) -> None:
        """Measuring points whose values ``signal_values_changed`` carries (≈ 4 Hz)."""
        self._worker.poller.watched = list(keys)

    def watch_live(self, mnemonics: Sequence[str]) -> None:
        """Read-only values polled for ``live_values_changed`` (default: the variant's)."""
        self._worker.poller.live = list(mnemonics)
        self._worker.poller.live_explicit = True

    def samples_lost_counted(self, count: int) -> None:
        """The worker counted ``count`` lost samples of the stream (none runs: ignored)."""
        if self._stream_keys:
            self._set_samples_lost(count)

    def stream_went_silent(self, text: str) -> None:
        """The worker stopped a stream that sent nothing for its silence bound: said as the
        connection's ``failed`` (the API's capture raises the same words), then stopped."""
        if self._stream_keys:
            self.stream_silent.emit(text)  # the connection's failed too
            self._on_stream_stopped(None)

    def forget(self) -> None:
        """The session ended (closed or broken): no generator runs, the stream has stopped."""
        self._generator = False
        if self._stream_keys:
            self._stream_keys = []
            self._set_samples_lost(0)
            self.stream_stopped.emit()

    def _on_stream_started(self, keys: object) -> None:
        self._stream_keys = list(keys)  # type: ignore[call-overload]
        self._set_samples_lost(0)
        self.stream_started.emit(self._stream_keys)

    def _on_stream_stopped(self, _result: object) -> None:
        self._stream_keys = []
        self._set_samples_lost(0)
        self.stream_stopped.emit()

    def _set_samples_lost(self, count: int) -> None:
        if count != self._samples_lost:
            self._samples_lost = count
            self.samples_lost_changed.emit(count)

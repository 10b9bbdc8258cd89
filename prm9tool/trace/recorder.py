"""Recording a CAN bus into a trace file: a listener on the bus the session already uses (the
shared master of :mod:`prm9tool.device.canlink.bus`, never a second bus), every frame received
and sent with its time stamp, written by python-can's own ``can.Logger`` in a thread of its
own so that a slow disk never delays the bus's Notifier. No Qt."""

from __future__ import annotations

import copy
import queue
import threading
import time
from pathlib import Path
from types import TracebackType
from typing import TYPE_CHECKING, Any

from prm9tool.device.canlink.bus import CanOptions, acquire, release
from prm9tool.errors import FileFormatError, FileProblem
from prm9tool.trace.frames import FORMATS

if TYPE_CHECKING:
    import can

    from prm9tool.device.canlink.bus import CanNetwork


class Recorder:
    """Writes every frame of the bus ``options`` to ``path`` (.asc, .blf, .trc, .log, .csv)
    from :meth:`start` to :meth:`stop`; also a context manager.

    ``frames`` counts the frames taken from the bus, ``written`` those in the file, and
    ``most_waiting`` the longest queue the writer had to catch up with.
    """

    def __init__(self, path: str | Path, options: CanOptions) -> None:
        suffix = Path(path).suffix.lower()
        if suffix not in FORMATS:
            raise FileFormatError(
                str(path),
                [
                    FileProblem(
                        0,
                        f"cannot record into {suffix or 'a file without suffix'!r}: use {', '.join(FORMATS)}",
                    )
                ],
            )
        self.path = Path(path)
        self.options = options
        self.frames = 0  # counted under _count_lock: the Notifier and senders call in at once
        self._count_lock = threading.Lock()
        self.written = 0
        self.most_waiting = 0
        self._queue: queue.SimpleQueue[can.Message | None] = queue.SimpleQueue()
        self._shared: CanNetwork | None = None
        self._writer: threading.Thread | None = None
        self._logger: Any = None
        self._failure: BaseException | None = None
        self.started_at: float | None = None

    # --- a python-can listener ----------------------------------------------------------
    def on_message_received(self, msg: can.Message) -> None:
        """A frame of the bus (the Notifier's thread, or the sender's): queued for the file."""
        with self._count_lock:
            self.frames += 1
        self._queue.put(msg)

    def __call__(self, msg: can.Message) -> None:
        self.on_message_received(msg)

    def on_error(self, exc: Exception) -> None:
        """The Notifier's error: kept, recording goes on."""

    def stop_listening(self) -> None:
        """Nothing: :meth:`stop` ends it."""

    # --- start and stop --------------------------------------------------------------------
    def start(self) -> Recorder:
        """Open the bus (shared with every session on it), then the file, and start recording;
        a bus that cannot be opened leaves the file as it was (no empty trace, nothing lost)."""
        import can

        shared = acquire(self.options)
        try:
            self._logger = can.Logger(str(self.path))
        except (OSError, ValueError) as exc:
            release(shared)
            raise FileFormatError(
                str(self.path), [FileProblem(0, f"cannot write the trace: {exc}")]
            ) from exc
        except BaseException:
            release(shared)
            raise
        self._shared = shared
        self._writer = threading.Thread(target=self._write, name="trace recorder", daemon=True)
        self._writer.start()
        self.started_at = time.monotonic()
        self._shared.add_listener(self)
        return self

    def stop(self) -> None:
        """Stop recording: every frame taken so far is written and the file closed."""
        shared, self._shared = self._shared, None
        if shared is not None:
            shared.remove_listener(self)
            release(shared)
        if self._writer is not None:
            self._queue.put(None)
            self._writer.join()
            self._writer = None
        if self._logger is not None:
            self._logger.stop()
            self._logger = None
        if self._failure is not None:
            failure, self._failure = self._failure, None
            raise FileFormatError(
                str(self.path), [FileProblem(0, f"writing the trace failed: {failure}")]
            )

    def __enter__(self) -> Recorder:
        return self.start()

    def __exit__(
        self, kind: type[BaseException] | None, exc: BaseException | None, tb: TracebackType | None
    ) -> None:
        self.stop()

    def _write(self) -> None:
        get, logger = self._queue.get, self._logger
        while True:
            msg = get()
            if msg is None:
                return
            waiting = self._queue.qsize()
            if waiting > self.most_waiting:
                self.most_waiting = waiting
            if self._failure is not None:
                continue
            if msg.channel is not None:  # one bus per file: the writer's own channel number
                msg = copy.copy(msg)
                msg.channel = None
            try:
                logger.on_message_received(msg)
                self.written += 1
            except Exception as exc:  # a full disk: the rest is counted, not written
                self._failure = exc


def record(path: str | Path, options: CanOptions | None = None) -> Recorder:
    """A :class:`Recorder` of the bus ``options`` (default: the virtual bus) into ``path``;
    use it as a context manager: ``with prm9tool.trace.record("run.asc", options): ...``."""
    return Recorder(path, options or CanOptions())

"""Recording the CAN bus from the GUI: one :class:`BusRecording` per window, started from the
CAN bus dialog or the trace window (Record… / Stop) and running on while the GUI goes online,
characterizes or uploads over the same bus — the recorder is a listener on the bus the session
uses (:mod:`prm9tool.trace.recorder`). Opening the bus may block, so it starts in a thread of its
own; stopping writes what is queued and closes the file. QtCore only.
"""

from __future__ import annotations

import contextlib
import logging
import threading
from collections.abc import Mapping
from typing import TYPE_CHECKING

from PySide6.QtCore import QObject, Signal

from prm9tool.errors import Prm9Error
from prm9tool.translate import error_text

if TYPE_CHECKING:
    from prm9tool.trace.recorder import Recorder

log = logging.getLogger(__name__)


class BusRecording(QObject):
    """The recording of one bus into one trace file, or none."""

    started = Signal(str)  # the file recorded into
    stopped = Signal(str, int)  # the file, frames written
    failed = Signal(str)  # why recording could not start or stopped (the program language)
    _deliver = Signal(object)

    def __init__(self, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self._recorder: Recorder | None = None
        self._starting = False
        self._deliver.connect(self._on_delivered)  # queued: from the opening thread

    @property
    def active(self) -> bool:
        """True while recording (or starting to)."""
        return self._recorder is not None or self._starting

    @property
    def path(self) -> str:
        """The file being recorded into ("" when none)."""
        return str(self._recorder.path) if self._recorder is not None else ""

    @property
    def frames(self) -> int:
        """Frames written so far."""
        return self._recorder.written if self._recorder is not None else 0

    def start(self, bus: Mapping[str, object], path: str) -> None:
        """Record ``bus`` (``interface``, ``channel``, ``bitrate``) into ``path``."""
        if self.active:
            return
        self._starting = True
        thread = threading.Thread(
            target=self._open, args=(dict(bus), path), name="can-trace-start", daemon=True
        )
        thread.start()

    def stop(self) -> None:
        """Stop recording: every frame received so far is written, the file closed."""
        recorder, self._recorder = self._recorder, None
        if recorder is None:
            return
        try:
            recorder.stop()
        except Prm9Error as exc:
            self.failed.emit(error_text(exc))
        self.stopped.emit(str(recorder.path), recorder.written)

    def _open(self, bus: dict[str, object], path: str) -> None:
        from prm9tool.device.canlink.bus import CanOptions
        from prm9tool.trace.recorder import Recorder

        rate = bus.get("bitrate")
        options = CanOptions(
            str(bus["interface"]), str(bus["channel"]), int(str(rate)) if rate else None
        )
        try:
            recorder: Recorder | Exception = Recorder(path, options).start()
        except Prm9Error as exc:
            recorder = exc.with_traceback(None)  # its frames would hold this object in a cycle
        with contextlib.suppress(RuntimeError):  # the window was closed meanwhile
            self._deliver.emit(recorder)

    def _on_delivered(self, payload: object) -> None:
        self._starting = False
        if isinstance(payload, Exception):
            self.failed.emit(error_text(payload))
            return
        self._recorder = payload  # type: ignore[assignment]
        self.started.emit(self.path)

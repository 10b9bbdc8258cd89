"""Record… / Stop for the CAN bus: the controls of a :class:`BusRecording`, shown in the CAN bus
dialog and the trace window (the same recording in both)."""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtCore import QTimer
from PySide6.QtWidgets import (
    QHBoxLayout,
    QLabel,
    QPushButton,
    QSizePolicy,
    QWidget,
)

from prm9tool.online.trace_recording import BusRecording
from prm9tool.views.files import dialogs as file_dialogs

TRACE_FILTER = "*.asc *.blf *.trc *.log"
REFRESH_MS = 500


class RecordControls(QWidget):
    """``Record…`` asks for the file and starts recording the bus ``bus()`` names; ``Stop``
    ends it; a line tells the file and the frames written."""

    def __init__(
        self,
        recording: BusRecording,
        bus: Callable[[], dict[str, object]],
        parent: QWidget | None = None,
    ) -> None:
        super().__init__(parent)
        self._recording, self._bus = recording, bus
        self.record = QPushButton(self.tr("Record…"))
        self.record.setToolTip(self.tr("Record every frame of the CAN bus into a trace file"))
        self.stop = QPushButton(self.tr("Stop recording"))
        self.state = QLabel()  # wraps: a failure's reason is long, and widened the window
        self.state.setWordWrap(True)
        self.state.setSizePolicy(QSizePolicy.Policy.Ignored, QSizePolicy.Policy.Preferred)
        self.record.clicked.connect(self._on_record_clicked)
        self.stop.clicked.connect(recording.stop)
        recording.started.connect(lambda _p: self._show())
        recording.stopped.connect(self._on_recording_stopped)
        recording.failed.connect(self._on_recording_failed)
        layout = QHBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addWidget(self.record)
        layout.addWidget(self.stop)
        layout.addWidget(self.state, 1)
        self._timer = QTimer(self)
        self._timer.setInterval(REFRESH_MS)
        self._timer.timeout.connect(self._show)
        self._timer.start()
        self._show()

    def start(self, path: str) -> None:
        """Start recording into ``path`` (what Record… does after asking)."""
        self.state.setText(self.tr("Opening the CAN bus…"))
        self._recording.start(self._bus(), path)
        self._show_buttons()

    def _on_record_clicked(self) -> None:
        path, _filter = file_dialogs.save_file_name(
            self, self.tr("Record the CAN bus"), "trace.asc",
            self.tr("CAN traces ({0})").format(TRACE_FILTER),
        )  # fmt: skip
        if path:
            self.start(path)

    def _show(self) -> None:
        self._show_buttons()
        if self._recording.path:
            self.state.setText(
                self.tr("Recording into {0}: {1} frames").format(
                    self._recording.path, self._recording.frames
                )
            )

    def _show_buttons(self) -> None:
        active = self._recording.active
        self.record.setEnabled(not active)
        self.stop.setEnabled(active)

    def _on_recording_stopped(self, path: str, frames: int) -> None:
        self.state.setText(self.tr("{0} frames recorded into {1}").format(frames, path))
        self._show_buttons()

    def _on_recording_failed(self, reason: str) -> None:
        message = self.tr("Not recording: {0}").format(reason)
        self.state.setText(message)
        self.state.setToolTip(message)
        self._show_buttons()

"""The oscilloscope (manual §8.7.2, figure 8-20): plot, measuring points on the right, controls below.

Data path: ``connection.start_stream(keys, rate)`` → ``connection.samples_received`` (raw numpy
blocks, queued from the connection's worker thread) → :class:`prm9tool.scope.Capture` ring
buffer. A QTimer redraws at ~30 Hz: the trigger engine picks the frame, the plot draws a view of
the ring buffer (clip-to-view, peak downsampling). Pausing, stopping or a completed single
capture freeze a copy of the whole buffer, which the user can zoom and pan while recording goes
on. Online only, like PRM9.exe.
"""

from __future__ import annotations

import time
from collections import deque
from pathlib import Path
from typing import Any

import numpy as np
from PySide6.QtCore import QEvent, Qt, QTimer
from PySide6.QtGui import QCloseEvent, QHideEvent, QShowEvent
from PySide6.QtWidgets import (
    QFileDialog,
    QGridLayout,
    QLabel,
    QMessageBox,
    QVBoxLayout,
    QWidget,
)

from prm9tool.errors import ValueRangeError
from prm9tool.scope import (
    Capture,
    Frame,
    GeneratorSettings,
    StepFigures,
    TriggerEngine,
    TriggerMode,
    TriggerSettings,
    cursor_readout,
    step_figures,
    write_csv,
)
from prm9tool.signals import BY_KEY, signals_for
from prm9tool.views.scope_generator import GeneratorPanel, SetpointGenerator
from prm9tool.views.scope_panels import ChannelPanel, ControlPanel
from prm9tool.views.scope_plot import ScopePlot
from prm9tool.views.scope_readout import CursorPanel, StepPanel

REDRAW_MS = 33  # ~30 Hz
FIGURES_EVERY = 8  # live step figures every 8th redraw (~4 Hz)


class ScopeWidget(QWidget):
    """Three-channel oscilloscope on the valve's measuring points."""

    def __init__(self, connection: Any, document: Any, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._connection = connection
        self._document = document
        self._capture: Capture | None = None
        self._engine = TriggerEngine(TriggerSettings(), 1)
        self._running = False
        self._accepting = False  # False between a (re)start request and stream_started
        self._frozen: tuple[np.ndarray, np.ndarray] | None = None
        self._shown: tuple[np.ndarray, np.ndarray] = (np.empty(0), np.empty((0, 0)))
        self._frame: Frame | None = None
        self._drawn_total = -1
        self._redraws = 0
        self._generator_note = ""
        self.redraw_durations: deque[float] = deque(maxlen=100_000)
        self.generator = SetpointGenerator(connection, self)
        self._build()
        self._connect()
        self._on_type_key_changed()
        self._on_online_changed(bool(connection.is_online))

    def _build(self) -> None:
        self.plot = ScopePlot()
        self.channels = ChannelPanel()
        self.cursor_panel = CursorPanel()
        self.step_panel = StepPanel()
        self.controls = ControlPanel()
        self.generator_panel = GeneratorPanel()
        self.status = QLabel()
        self.status.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
        self._timer = QTimer(self)
        self._timer.setInterval(REDRAW_MS)
        self._timer.timeout.connect(self._redraw)
        right = QVBoxLayout()
        right.addWidget(self.channels, 1)
        right.addWidget(self.cursor_panel)
        right.addWidget(self.step_panel)
        grid = QGridLayout(self)
        grid.addWidget(self.plot, 0, 0)
        grid.addLayout(right, 0, 1)
        bottom = QVBoxLayout()
        bottom.addWidget(self.controls)
        bottom.addWidget(self.status)
        grid.addLayout(bottom, 1, 0)
        grid.addWidget(self.generator_panel, 1, 1)
        grid.setColumnStretch(0, 1)
        grid.setRowStretch(0, 1)

    def _connect(self) -> None:
        conn = self._connection
        conn.online_changed.connect(self._on_online_changed)
        conn.lost.connect(self._on_link_lost)
        conn.samples_received.connect(self._on_samples_received)
        conn.stream_started.connect(self._on_stream_started)
        self._document.type_key_changed.connect(self._on_type_key_changed)
        self.channels.selection_changed.connect(self._on_selection_changed)
        c = self.controls
        c.start_requested.connect(self.start)
        c.stop_requested.connect(self.stop)
        c.pause_toggled.connect(self._on_pause_toggled)
        c.rate_changed.connect(self._on_rate_changed)
        c.window_changed.connect(self._on_trigger_changed)
        c.trigger_changed.connect(self._on_trigger_changed)
        c.cursors_toggled.connect(self.plot.set_cursors_visible)
        c.csv_requested.connect(self._on_csv_requested)
        c.png_requested.connect(self._on_png_requested)
        self.plot.cursors_moved.connect(self._update_readouts)
        self.plot.x_range_changed.connect(self._update_readouts)
        self.step_panel.channels_changed.connect(self._update_readouts)
        self.generator_panel.start_requested.connect(self._on_generator_start_requested)
        self.generator_panel.stop_requested.connect(self.generator.stop)
        self.generator.running_changed.connect(self.generator_panel.set_running)
        self.generator.stopped_by_link.connect(self._on_generator_stopped_by_link)

    # --- public API --------------------------------------------------------------------------
    @property
    def running(self) -> bool:
        """True while a capture streams."""
        return self._running

    @property
    def capture(self) -> Capture | None:
        """The current (or last) recording."""
        return self._capture

    def preselect(self, key: str) -> None:
        """Activate measuring point ``key`` (a red dot of the diagram was clicked)."""
        self.channels.preselect(key)

    def start(self) -> None:
        """Start recording the active measuring points."""
        keys = self.channels.selected()
        if not keys:
            self._say(self.tr("Select at least one measuring point on the right."))
            return
        if not self._connection.is_online:
            self._say(" ".join(filter(None, (self._generator_note, self._offline_text()))))
            return
        self._running = True
        self._start_capture(keys)

    def stop(self) -> None:
        """Stop the generator and the recording; the display holds the recorded data."""
        self.generator.stop()
        if self._running:
            self._running = False
            self._accepting = False
            if self._connection.is_online:
                self._connection.stop_stream()
            self._freeze()
        self._timer.stop()
        self._update_controls()

    # --- capture lifecycle -------------------------------------------------------------------
    def _start_capture(self, keys: list[str]) -> None:
        """(Re)start the stream cleanly: samples of the old stream are dropped."""
        self._accepting = False
        self._connection.stop_stream()
        self._capture = Capture([BY_KEY[k] for k in keys], self.controls.rate_hz())
        self._frozen = None
        self.controls.set_paused(False)
        self._new_engine()
        self._connection.start_stream(keys, self.controls.rate_hz())
        self.plot.set_time_interactive(False)
        self._timer.start()
        self._update_controls()

    def _on_stream_started(self, keys: list[str]) -> None:
        if self._capture is not None and self._running and list(keys) == self._capture.keys:
            self._capture.buffer.clear()
            self._engine.rearm()
            self._accepting = True

    def _on_samples_received(self, block: np.ndarray) -> None:
        if not self._accepting or self._capture is None:
            return
        if block.ndim != 2 or block.shape[1] != len(self._capture.signals):
            return
        self._capture.feed(block)

    def _new_engine(self) -> None:
        rate = self._capture.rate_hz if self._capture else self.controls.rate_hz()
        window = round(self.controls.window_s() * rate)
        settings = self.controls.trigger_settings()
        self._engine = TriggerEngine(settings, window)
        if self._capture is not None:
            self._engine.rearm(self._capture.buffer.total)
        roll = settings.mode is TriggerMode.ROLL
        self.plot.set_time_label(self.tr("Time [s]") if roll else self.tr("Time from trigger [s]"))
        self._drawn_total = -1

    # --- drawing -----------------------------------------------------------------------------
    def _redraw(self) -> None:
        capture = self._capture
        if capture is None or self._frozen is not None:
            return
        if capture.buffer.total == self._drawn_total:
            return
        started = time.perf_counter()
        self._drawn_total = capture.buffer.total
        frame = self._engine.update(capture.buffer)
        if frame is not None:
            self._draw_frame(capture, frame)
        if self._engine.done:
            self._freeze()
            self.controls.set_paused(True)
        self._redraws += 1
        if self.plot.cursors_visible or self._redraws % FIGURES_EVERY == 0:
            self._update_readouts()
        self._update_status()
        self.redraw_durations.append(time.perf_counter() - started)

    def _draw_frame(self, capture: Capture, frame: Frame) -> None:
        start, values = capture.buffer.window(frame.start, frame.stop)
        t = capture.times(start, len(values), frame.origin)
        self._frame = frame
        self._shown = (t, values)
        self.plot.show_data(t, values)
        rate = capture.rate_hz
        self.plot.set_x_range(
            (frame.start - frame.origin) / rate, (frame.stop - frame.origin) / rate
        )
        _, latest = capture.buffer.latest(1)
        if len(latest):
            self.plot.show_latest(latest[0])

    def _freeze(self) -> None:
        """Hold the display on a copy of everything recorded (zoom and pan with the mouse)."""
        capture = self._capture
        if capture is None or self._frozen is not None:
            return
        origin = self._frame.origin if self._frame is not None else 0
        start, values = capture.buffer.window(capture.buffer.first, capture.buffer.total)
        self._frozen = (capture.times(start, len(values), origin), values.copy())
        self.plot.show_data(*self._frozen)
        self.plot.set_time_interactive(True)
        self._update_readouts()
        self._update_status()

    def _thaw(self) -> None:
        self._frozen = None
        self._drawn_total = -1
        self.plot.set_time_interactive(False)
        if self._engine.done and self._capture is not None:
            self._engine.rearm(self._capture.buffer.total)

    def _view_data(self) -> tuple[np.ndarray, np.ndarray]:
        """Times and values of what the plot holds."""
        return self._frozen if self._frozen is not None else self._shown

    def _update_readouts(self) -> None:
        t, values = self._view_data()
        if not len(t):
            self.cursor_panel.show_readout(None)
            self.step_panel.show_figures(None, "")
            return
        if self.plot.cursors_visible:
            self.cursor_panel.show_readout(cursor_readout(t, values, *self.plot.cursor_times()))
            x0, x1 = sorted(self.plot.cursor_times())
            region = self.tr("the samples between cursors A and B")
        else:
            self.cursor_panel.show_readout(None)
            x0, x1 = self.plot.x_range()
            region = self.tr("the visible window")
        self.step_panel.show_figures(self._figures(t, values, x0, x1), region)

    def _figures(
        self, t: np.ndarray, values: np.ndarray, x0: float, x1: float
    ) -> StepFigures | None:
        response, reference = self.step_panel.response_slot(), self.step_panel.reference_slot()
        if response is None or response >= values.shape[1]:
            return None
        inside = (t >= x0) & (t <= x1)
        ref = values[inside, reference] if reference is not None else None
        return step_figures(t[inside], values[inside, response], ref)

    # --- controls ----------------------------------------------------------------------------
    def _on_selection_changed(self, keys: list[str]) -> None:
        signals = [BY_KEY[k] for k in keys]
        self.plot.set_channels(signals)
        self.controls.set_channels(signals)
        self.cursor_panel.set_channels(signals)
        self.step_panel.set_channels(signals)
        if self._running:
            if keys:
                self._start_capture(keys)
            else:
                self.stop()
        self._update_controls()

    def _on_rate_changed(self, _rate: int) -> None:
        if self._running and self._capture is not None:
            self._start_capture(self._capture.keys)

    def _on_trigger_changed(self, *_: object) -> None:
        self._new_engine()
        if self._frozen is not None and self._running and not self.controls.pause.isChecked():
            self._thaw()

    def _on_pause_toggled(self, paused: bool) -> None:
        if paused:
            self._freeze()
        else:
            self._thaw()

    def _on_type_key_changed(self, *_: object) -> None:
        self.channels.set_signals(signals_for(self._document.variant))
        self._on_selection_changed(self.channels.selected())

    def _on_online_changed(self, online: bool) -> None:
        if online:
            self._generator_note = ""
        else:
            self._on_link_lost()
        self._update_controls()
        self._update_status()

    def _on_link_lost(self, *_: object) -> None:
        if self._running:
            self._running = False
            self._accepting = False
            self._freeze()
            self._timer.stop()
        self._update_controls()

    def _update_controls(self) -> None:
        online = bool(self._connection.is_online)
        self.controls.set_running(self._running, online and bool(self.channels.selected()))
        if self._frozen is not None and self._running:
            self.controls.set_paused(True)
        self.generator_panel.setEnabled(online)
        self._update_status()

    def _update_status(self) -> None:
        if not self._connection.is_online:
            self._say(" ".join(filter(None, (self._generator_note, self._offline_text()))))
        elif not self._running:
            self._say(self.tr("Stopped. Choose up to three measuring points and press Start."))
        elif self._engine.done:
            self._say(self.tr("Single capture complete. Resume arms the trigger again."))
        elif self._frozen is not None:
            self._say(self.tr("Paused: zoom and pan with the mouse; recording continues."))
        elif self._engine.waiting and self._frame is None:
            self._say(self.tr("Waiting for the trigger…"))
        else:
            self._say(self._recording_text())

    def _recording_text(self) -> str:
        rate = self._capture.rate_hz if self._capture else 0
        lost = getattr(self._connection, "samples_lost", 0) or 0
        text = self.tr("Recording at {0} Hz.").format(rate)
        if lost:
            text += " " + self.tr("{0} samples lost on the link.").format(lost)
        return text

    def _offline_text(self) -> str:
        return self.tr(
            "The oscilloscope needs a connected valve: go online (Communication → Online)."
        )

    def _say(self, message: str) -> None:
        self.status.setText(message)

    # --- generator ---------------------------------------------------------------------------
    def _on_generator_start_requested(self, settings: GeneratorSettings) -> None:
        try:
            settings.check()
        except ValueRangeError as exc:
            QMessageBox.warning(self, self.tr("Setpoint generator"), str(exc))
            return
        answer = QMessageBox.question(
            self,
            self.tr("Setpoint generator"),
            self.tr(
                "The generator will drive the valve's setpoint and the valve will move.\n"
                "Make sure the machine is safe to move. Start the generator?"
            ),
            QMessageBox.StandardButton.Yes | QMessageBox.StandardButton.No,
            QMessageBox.StandardButton.No,
        )
        if answer != QMessageBox.StandardButton.Yes:
            return
        try:
            self.generator.start(settings)
        except RuntimeError as exc:
            self._say(str(exc))

    def _on_generator_stopped_by_link(self) -> None:
        self._generator_note = self.tr("The link dropped: the setpoint generator has stopped.")
        self._update_status()

    # --- export ------------------------------------------------------------------------------
    def export_csv(self, path: str | Path, whole: bool) -> int:
        """Write the visible window (or the whole recording) as CSV; returns the row count."""
        if self._capture is None:
            raise ValueError(self.tr("Nothing recorded yet."))
        t, values = self._view_data()
        if whole and self._frozen is None:
            origin = self._frame.origin if self._frame is not None else 0
            start, values = self._capture.buffer.window(0, self._capture.buffer.total)
            t = self._capture.times(start, len(values), origin)
        elif not whole:
            x0, x1 = self.plot.x_range()
            inside = (t >= x0) & (t <= x1)
            t, values = t[inside], values[inside]
        with open(path, "w", encoding="utf-8", newline="") as out:
            return write_csv(out, t, values, self._capture.signals)

    def export_png(self, path: str | Path) -> None:
        """Save the plot with its legend as a PNG image."""
        if not self.plot.render_image().save(str(path), "PNG"):
            raise OSError(self.tr("Could not write {0}.").format(path))

    def _on_csv_requested(self, whole: bool) -> None:
        path, _ = QFileDialog.getSaveFileName(
            self, self.tr("Export CSV"), "scope.csv", self.tr("CSV files (*.csv)")
        )
        if path:
            self._report_export(lambda: self.export_csv(path, whole), path)

    def _on_png_requested(self) -> None:
        path, _ = QFileDialog.getSaveFileName(
            self, self.tr("Export PNG"), "scope.png", self.tr("PNG images (*.png)")
        )
        if path:
            self._report_export(lambda: self.export_png(path), path)

    def _report_export(self, action: Any, path: str) -> None:
        try:
            action()
        except (OSError, ValueError) as exc:
            QMessageBox.warning(self, self.tr("Export"), str(exc))
        else:
            self._say(self.tr("Saved {0}.").format(path))

    # --- Qt events ---------------------------------------------------------------------------
    def closeEvent(self, event: QCloseEvent) -> None:
        """Closing the scope stops the generator and the recording."""
        self.stop()
        super().closeEvent(event)

    def hideEvent(self, event: QHideEvent) -> None:
        """Hidden (another view is shown): stop redrawing; recording goes on."""
        self._timer.stop()
        super().hideEvent(event)

    def showEvent(self, event: QShowEvent) -> None:
        """Shown again: resume redrawing."""
        if self._running:
            self._timer.start()
        super().showEvent(event)

    def changeEvent(self, event: QEvent) -> None:
        """Retranslate after a language change."""
        if event.type() == QEvent.Type.LanguageChange:
            for panel in (self.plot, self.channels, self.controls, self.cursor_panel):
                panel.retranslate()
            self.step_panel.retranslate()
            self.generator_panel.retranslate()
            self._update_status()
        super().changeEvent(event)

"""The oscilloscope (manual §8.7.2, figure 8-20): plot, measuring points on the right, controls below.

Layout for a 1024 × 768 screen: the plot with its legend; on the right the measuring points
and a tab each for the cursor read-out and the step-response figures; below, one row each for
recording, trigger and the setpoint generator (always visible, so is its Stop), and the status.

Data path: ``connection.start_stream(keys, rate)`` → ``connection.samples_received`` (raw numpy
blocks, queued from the connection's worker thread) → :class:`prm9tool.scope.Capture` ring
buffer. A QTimer redraws at ~30 Hz: the trigger engine picks the frame, the plot draws a view of
the ring buffer (clip-to-view, peak downsampling). Pausing, stopping or a completed single
capture freeze a copy of the whole buffer, which the user can zoom and pan while recording goes
on. Online only, like PRM9.exe.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import numpy as np
from PySide6.QtCore import QEvent, Qt, QTimer, Signal
from PySide6.QtGui import QCloseEvent, QHideEvent, QShowEvent
from PySide6.QtWidgets import (
    QGridLayout,
    QPushButton,
    QTabWidget,
    QVBoxLayout,
    QWidget,
)

from prm9tool.catalogue.signals import BY_KEY, signals_for
from prm9tool.errors import ValueRangeError
from prm9tool.model.document import ParameterDocument
from prm9tool.online.connection_protocol import ScopeConnection, StatusView
from prm9tool.online.valve_control import ValveControl, status_blocker
from prm9tool.scope import Capture, GeneratorSettings
from prm9tool.translate import error_text
from prm9tool.views.fixed_lines import FixedLinesLabel
from prm9tool.views.scope.display import ScopeDisplay
from prm9tool.views.scope.export import ScopeExport
from prm9tool.views.scope.generator import GeneratorPanel, SetpointGenerator
from prm9tool.views.scope.panels import ChannelPanel, ControlPanel
from prm9tool.views.scope.plot import ScopePlot
from prm9tool.views.scope.readout import CursorPanel, StepPanel
from prm9tool.views.scope.start import GeneratorStart, measure_against_demand
from prm9tool.views.scope.status import ScopeStatusText

REDRAW_MS = 33  # ~30 Hz
STATUS_LINES = 2  # the status line's height: its messages wrap in it (the whole one in its tip)


class ScopeWidget(QWidget):
    """Three-channel oscilloscope on the valve's measuring points."""

    tuning_requested = Signal()  # "Tuning and characterization…" (the main window opens it)

    def __init__(
        self,
        connection: ScopeConnection,
        document: ParameterDocument,
        parent: QWidget | None = None,
        control: ValveControl | None = None,
    ) -> None:
        super().__init__(parent)
        self._connection = connection
        self._document = document
        self._status: StatusView | None = None  # the valve's latest status
        self._running = False
        self._resume = False  # recording when the link broke: again when the valve is back
        self._accepting = False  # False between a (re)start request and stream_started
        self._silent = ""  # why the stream that stops next went dead (stream_silent)
        # why the generator or the recording stopped without the user: in the language of the
        # moment it is shown (a text made at the time stayed English after a switch)
        self._generator_note: Callable[[], str] | None = None
        self._recording_note: Callable[[], str] | None = None
        self.generator = SetpointGenerator(connection, self)
        self._starter = GeneratorStart(control, self)  # the questions before it starts
        self._build()
        self._connect()
        self._on_type_key_changed()
        self._on_online_changed(bool(connection.is_online))

    def _build(self) -> None:
        self.plot = ScopePlot()
        self.channels = ChannelPanel()
        self.cursor_panel = CursorPanel()
        self.step_panel = StepPanel()
        self.readouts = QTabWidget()
        for panel in (self.cursor_panel, self.step_panel):
            self.readouts.addTab(panel, panel.windowTitle())
        self.controls = ControlPanel()
        self.generator_panel = GeneratorPanel()
        self.display = ScopeDisplay(self.plot, self.cursor_panel, self.step_panel, self)
        self.exporter = ScopeExport(self.display, self.plot, self._say, self)
        self._texts = ScopeStatusText(self._connection, self.display, self)
        self.status = FixedLinesLabel(STATUS_LINES)  # a longer message moves no button
        self.status.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
        self._timer = QTimer(self)
        self._timer.setInterval(REDRAW_MS)
        self._timer.timeout.connect(self._redraw)
        right = QVBoxLayout()
        right.addWidget(self.channels, 1)
        right.addWidget(self.readouts)
        self.tuning_button = QPushButton(self.tr("Tuning and characterization…"))
        self.tuning_button.clicked.connect(self.tuning_requested)
        right.addWidget(self.tuning_button)
        grid = QGridLayout(self)
        grid.addWidget(self.plot, 0, 0)
        grid.addLayout(right, 0, 1)
        for row, widget in enumerate((self.controls, self.generator_panel, self.status), 1):
            grid.addWidget(widget, row, 0, 1, 2)
        grid.setColumnStretch(0, 1)
        grid.setRowStretch(0, 1)
        self._align_sections()

    def _align_sections(self) -> None:
        """The row names under the plot (Recording, Trigger, Setpoint generator) in one column."""
        labels = (
            self.controls.recording_label,
            self.controls.trigger_label,
            self.generator_panel.title,
        )
        width = max(label.sizeHint().width() for label in labels)
        for label in labels:
            label.setMinimumWidth(width)

    def _connect(self) -> None:
        conn = self._connection
        conn.online_changed.connect(self._on_online_changed)
        conn.lost.connect(self._on_link_lost)
        conn.reconnect_ended.connect(self._on_reconnect_ended)
        conn.samples_received.connect(self._on_samples_received)
        conn.stream_started.connect(self._on_stream_started)
        conn.stream_stopped.connect(self._on_stream_stopped)
        conn.stream_silent.connect(self._on_stream_silent)
        conn.failed.connect(self._on_failed)
        conn.status_changed.connect(self._on_status_changed)
        self._document.type_key_changed.connect(self._on_type_key_changed)
        self.channels.selection_changed.connect(self._on_selection_changed)
        self.channels.same_scale_toggled.connect(self.plot.set_same_scale)
        c = self.controls
        c.start_requested.connect(self.start)
        c.stop_requested.connect(self.stop)
        c.pause_toggled.connect(self._on_pause_toggled)
        c.rate_changed.connect(self._on_rate_changed)
        c.window_changed.connect(self._on_window_changed)
        c.trigger_changed.connect(self._on_trigger_changed)
        c.csv_requested.connect(self.exporter.ask_csv)
        c.png_requested.connect(self.exporter.ask_png)
        self.display.held.connect(self._on_display_held)
        self.cursor_panel.cursors_toggled.connect(self.plot.set_cursors_visible)
        self.generator_panel.start_requested.connect(self._on_generator_start_requested)
        self.generator_panel.stop_requested.connect(self.generator.stop)
        self.generator.running_changed.connect(self.generator_panel.set_running)
        self.generator.stopped_by_link.connect(self._on_generator_stopped_by_link)
        self.generator.refused.connect(self._on_generator_refused)
        self.generator.stopped_by_operation.connect(self._on_generator_stopped_by_operation)

    # --- public API --------------------------------------------------------------------------
    @property
    def running(self) -> bool:
        """True while a capture streams."""
        return self._running

    @property
    def receiving(self) -> bool:
        """True once the valve confirmed the stream and samples are taken in."""
        return self._accepting

    @property
    def capture(self) -> Capture | None:
        """The current (or last) recording."""
        return self.display.capture

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
            self._update_status()
            return
        self._running = True
        self._recording_note = None
        self._start_capture(keys)

    def stop(self) -> None:
        """Stop the generator and the recording; the display holds the recorded data."""
        self._resume = False  # also a recording the valve's return would have resumed
        self.generator.stop()
        if self._running:
            self._running = False
            self._accepting = False
            if self._connection.is_online:
                self._connection.stop_stream()
            self.display.hold_all()
        self._timer.stop()
        self._update_controls()

    # --- capture lifecycle -------------------------------------------------------------------
    def _start_capture(self, keys: list[str]) -> None:
        """(Re)start the stream cleanly: samples of the old stream are dropped."""
        self._accepting = False
        self._connection.stop_stream()
        self.display.set_capture(Capture([BY_KEY[k] for k in keys], self.controls.rate_hz()))
        self.controls.set_paused(False)
        self._new_engine()
        self._timer.start()
        self._update_controls()
        self._connection.start_stream(keys, self.controls.rate_hz())  # may fail: _on_failed

    def _on_stream_started(self, keys: list[str]) -> None:
        capture = self.display.capture
        if capture is not None and self._running and list(keys) == capture.keys:
            capture.buffer.clear()
            self.display.engine.rearm()
            self._accepting = True

    def _on_stream_silent(self, text: str) -> None:
        """The valve stopped sending: the stop that follows says so, not "another operation"."""
        self._silent = text

    def _on_stream_stopped(self) -> None:
        """The stream ended while samples flowed, and not by the scope (a tuning test streams
        itself): the recording stops, the display holds what came, the status says so."""
        if not (self._running and self._accepting):
            return  # the scope's own stop, or the restart of its stream
        if self._connection.is_reconnecting:  # the link broke: recording on when it is back
            self._on_link_lost()
            return
        self._running = False
        self._accepting = False
        self.display.hold_all()
        self._timer.stop()
        silent, self._silent = self._silent, ""
        texts = self._texts
        self._recording_note = (
            (lambda: texts.stream_silent(silent)) if silent else texts.stream_taken
        )
        self._update_controls()
        self._update_status()

    def _on_failed(self, message: str) -> None:
        """An operation failed; if it was the stream start we wait for, stop and say why."""
        if self._running and not self._accepting:
            self._running = False
            self._timer.stop()
            self._update_controls()
            self._say(self.tr("The recording could not start: {0}").format(message))

    def _on_samples_received(self, block: np.ndarray) -> None:
        capture = self.display.capture
        if not self._accepting or capture is None:
            return
        if block.ndim != 2 or block.shape[1] != len(capture.signals):
            return
        capture.feed(block)

    def _new_engine(self) -> None:
        self.display.set_trigger(self.controls.trigger_settings(), self.controls.window_s())

    def _redraw(self) -> None:
        if self.display.redraw():
            self._update_status()

    def _on_display_held(self) -> None:
        self.controls.set_paused(True)
        self._update_status()

    # --- controls ----------------------------------------------------------------------------
    def _on_selection_changed(self, keys: list[str]) -> None:
        signals = [BY_KEY[k] for k in keys]
        self.plot.set_channels(signals)
        self.controls.set_channels(signals)
        self.cursor_panel.set_channels(signals)
        self.step_panel.set_channels(signals)
        if self._running and keys:
            self._start_capture(keys)
        else:  # the plot dropped the held trace: its data and values at Stop go with it
            if self._running:
                self.stop()
            self.display.clear()
        self._update_controls()

    def _on_rate_changed(self, _rate: int) -> None:
        if self._running and self.display.capture is not None:
            self._start_capture(self.display.capture.keys)

    def _on_window_changed(self, _window_s: float) -> None:
        """A new time window: a running capture restarts cleanly, like a new rate."""
        if self._running and self.display.capture is not None:
            self._start_capture(self.display.capture.keys)
        else:
            self._on_trigger_changed()

    def _on_trigger_changed(self, *_: object) -> None:
        self._new_engine()
        if self.display.frozen and self._running and not self.controls.pause.isChecked():
            self.display.thaw()
        self._update_status()

    def _on_pause_toggled(self, paused: bool) -> None:
        if paused:
            self.display.freeze()
        else:
            self.display.thaw()
        self._update_status()

    def _on_type_key_changed(self, *_: object) -> None:
        self.channels.set_signals(signals_for(self._document.variant))
        self._on_selection_changed(self.channels.selected())

    def _on_online_changed(self, online: bool) -> None:
        if online:
            self._generator_note = None
            device = getattr(self._connection, "device", None)
            limit = getattr(device, "stream_rate_limit_hz", 0.0)
            self.controls.limit_rates(float(limit or 0.0))  # over CANopen: what the bus delivers
        else:
            self._on_link_lost()
        self._update_controls()
        self._update_status()
        if online and self._resume:  # the same valve is back: record on
            self._resume = False
            self.start()

    def _on_reconnect_ended(self) -> None:
        if not self._connection.is_online:  # not back: the user decides
            self._resume = False

    def _on_link_lost(self, *_: object) -> None:
        if self._running and self._connection.is_reconnecting:
            self._resume = True
        if self._running:
            self._running = False
            self._accepting = False
            self.display.hold_all()
            self._timer.stop()
        self._update_controls()

    def _update_controls(self) -> None:
        online = bool(self._connection.is_online)
        self.controls.set_running(self._running, online and bool(self.channels.selected()))
        if self.display.frozen and self._running:
            self.controls.set_paused(True)
        self.generator_panel.setEnabled(online)
        self._update_status()

    def _update_status(self) -> None:
        parts = (
            self._generator_note() if self._generator_note else "",
            self._recording_note() if self._recording_note else "",
            self._texts.blocked(self._status),
            self._texts.state(self._running),
        )
        self._say(" ".join(filter(None, parts)))

    def _on_status_changed(self, status: StatusView) -> None:
        before = status_blocker(self._status)
        self._status = status
        if status_blocker(status) != before:
            self._update_status()

    def _say(self, message: str) -> None:
        self.status.setText(message)

    # --- generator ---------------------------------------------------------------------------
    def _on_generator_start_requested(self, settings: GeneratorSettings) -> None:
        if not self._starter.confirmed(settings, self._status):
            return
        self._generator_note = None
        try:
            self.generator.start(settings)
        except (RuntimeError, ValueRangeError) as exc:
            self._say(error_text(exc))
            return
        measure_against_demand(self.channels, self.step_panel)

    def _on_generator_stopped_by_link(self) -> None:
        self._generator_note = self._texts.generator_link_dropped
        self._update_status()

    def _on_generator_stopped_by_operation(self) -> None:
        self._generator_note = self._texts.generator_displaced
        self._update_status()

    def _on_generator_refused(self, reason: str) -> None:
        self._generator_note = lambda: self._texts.generator_refused(reason)
        self._update_status()

    # --- export ------------------------------------------------------------------------------
    def export_csv(self, path: str | Path, whole: bool) -> int:
        """Write the visible window (or the whole recording) as CSV; returns the row count."""
        return self.exporter.csv(path, whole)

    def export_png(self, path: str | Path) -> None:
        """Save the plot with its legend as a PNG image."""
        self.exporter.png(path)

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
            self.tuning_button.setText(self.tr("Tuning and characterization…"))
            for tab, readout in enumerate((self.cursor_panel, self.step_panel)):
                self.readouts.setTabText(tab, readout.windowTitle())
            self._align_sections()
            signals = [BY_KEY[k] for k in self.channels.selected()]  # catalogue texts
            self.plot.relabel(signals)
            self.controls.set_channels(signals)
            self.cursor_panel.set_channels(signals)
            self.step_panel.set_channels(signals)
            self.display.update_readouts()
            self._update_status()
        super().changeEvent(event)

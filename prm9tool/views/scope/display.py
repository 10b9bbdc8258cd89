"""What the oscilloscope plot shows: live frames chosen by the trigger engine, or a frozen copy.

Live, each redraw hands the plot a *view* of the ring buffer (no copy); clip-to-view and peak
downsampling in the plot keep the drawing cost independent of the window length. Freezing
(pause, stop, a completed single capture, link loss) copies everything recorded once, so the
user can zoom and pan through it while the ring buffer goes on filling.
"""

from __future__ import annotations

import time
from collections import deque

import numpy as np
from PySide6.QtCore import QObject, Signal

from prm9tool.scope import (
    Capture,
    Frame,
    StepMeasurement,
    TriggerEngine,
    TriggerMode,
    TriggerSettings,
    Verdict,
    cursor_readout,
    measure_step,
)
from prm9tool.views.scope.plot import ScopePlot
from prm9tool.views.scope.readout import CursorPanel, StepPanel

FIGURES_EVERY = 8  # live step figures every 8th redraw (~4 Hz)
LEGEND_LOOKBACK = 100  # the legend shows a channel's newest sample among the last 100
EMPTY = (np.empty(0), np.empty((0, 0)))


class ScopeDisplay(QObject):
    """Feeds the plot and the read-out panels from a capture."""

    held = Signal()  # a single capture completed; the display now holds it

    def __init__(
        self, plot: ScopePlot, cursors: CursorPanel, steps: StepPanel, parent: QObject | None = None
    ) -> None:
        super().__init__(parent)
        self.plot, self.cursors, self.steps = plot, cursors, steps
        self.capture: Capture | None = None
        self.engine = TriggerEngine(TriggerSettings(), 1)
        self._frame: Frame | None = None
        self._shown: tuple[np.ndarray, np.ndarray] = EMPTY
        self._frozen: tuple[np.ndarray, np.ndarray] | None = None
        self._drawn_total = -1
        self._redraws = 0
        self._legend_ticks = 0
        self._legend_held = False  # the legend marks its values as newer than the plot
        self.redraw_durations: deque[float] = deque(maxlen=100_000)  # seconds, for benchmarks
        plot.cursors_moved.connect(self.update_readouts)
        plot.x_range_changed.connect(self.update_readouts)
        steps.channels_changed.connect(self.update_readouts)

    @property
    def frozen(self) -> bool:
        """True while the display holds a copy instead of following the stream."""
        return self._frozen is not None

    @property
    def waiting(self) -> bool:
        """True while a triggered mode waits for its first edge."""
        return self.engine.waiting and self._frame is None

    def set_capture(self, capture: Capture) -> None:
        """Follow a new recording (the previous display is dropped)."""
        self.capture = capture
        self._frame = None
        self._shown = EMPTY
        self._frozen = None
        self._legend_ticks = 0  # the first values of the new recording at once (not "at stop")
        self.plot.set_time_interactive(False)

    def clear(self) -> None:
        """Drop the held recording: the plot no longer shows it (its channels were set anew,
        a file was opened, another valve is online), so neither do the read-outs, the
        export or the legend's values at Stop."""
        self.capture = None
        self._frame = None
        self._shown = EMPTY
        self._frozen = None
        self._drawn_total = -1
        self._legend_held = False
        self.plot.set_time_interactive(False)
        self.update_readouts()

    def set_trigger(self, settings: TriggerSettings, window_s: float) -> None:
        """New trigger set-up or time window; searching starts at the newest sample."""
        rate = self.capture.rate_hz if self.capture is not None else 1
        self.engine = TriggerEngine(settings, round(window_s * rate))
        if self.capture is not None:
            self.engine.rearm(self.capture.buffer.total)
        self._frame = None
        self._drawn_total = -1
        self.plot.set_time_axis(settings.mode is not TriggerMode.ROLL, window_s)

    # --- live ------------------------------------------------------------------------------------
    def redraw(self) -> bool:
        """Draw what the trigger engine selects; False when nothing new arrived."""
        capture = self.capture
        if capture is None or capture.buffer.total == self._drawn_total:
            return False
        if self._frozen is not None:
            self._show_latest(capture)  # the legend stays live (marked so) while the plot holds
            return False
        started = time.perf_counter()
        self._drawn_total = capture.buffer.total
        frame = self.engine.update(capture.buffer)
        if frame is not None:
            self._draw_frame(capture, frame)
        if self.engine.done:
            self.freeze()
            self.held.emit()
        self._redraws += 1
        if self.plot.cursors_visible or self._redraws % FIGURES_EVERY == 0:
            self.update_readouts()
        self.redraw_durations.append(time.perf_counter() - started)
        return True

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
        self._show_latest(capture)

    def _show_latest(self, capture: Capture, force: bool = False, stopped: bool = False) -> None:
        """The newest values in the legend, ~8 Hz (readable, no relayout every frame); at
        once when they become, or stop being, newer than a held trace (``stopped``: the
        recording ended, they are the values at Stop)."""
        held = self._frozen is not None and not force
        self._legend_ticks += 1
        if force or held != self._legend_held or self._legend_ticks % 4 == 1:
            _, recent = capture.buffer.latest(LEGEND_LOOKBACK)
            if len(recent):
                self.plot.show_latest(newest_arrived(recent), held, stopped)
                self._legend_held = held

    # --- hold ------------------------------------------------------------------------------------
    def freeze(self) -> None:
        """Hold the display on a copy of everything recorded (zoom and pan with the mouse)."""
        capture = self.capture
        if capture is None or self._frozen is not None:
            return
        self._frozen = self.whole_data()  # what was recorded up to now
        self.plot.show_all(*self._frozen)
        self.plot.set_time_interactive(True)
        self.update_readouts()

    def hold_all(self) -> None:
        """Hold everything recorded (the recording ended): also what arrived after a pause;
        the legend then shows the last recorded values."""
        if self.capture is None:
            return
        self._frozen = None
        self.freeze()
        self._show_latest(self.capture, force=True, stopped=True)

    def thaw(self) -> None:
        """Follow the stream again (a completed single capture re-arms)."""
        self._frozen = None
        self._drawn_total = -1
        self.plot.set_time_interactive(False)
        if self.engine.done and self.capture is not None:
            self.engine.rearm(self.capture.buffer.total)
            self._frame = None

    # --- data for read-outs and export -------------------------------------------------------
    def data(self) -> tuple[np.ndarray, np.ndarray]:
        """Times and values the plot holds."""
        return self._frozen if self._frozen is not None else self._shown

    def whole_data(self) -> tuple[np.ndarray, np.ndarray]:
        """Everything recorded (a copy), on the time axis of the current frame.

        Also while the display holds a paused picture: the recording goes on behind it, and
        "whole recording" means all of it, not what the held picture shows.
        """
        if self.capture is None:
            return EMPTY
        buffer = self.capture.buffer
        origin = self._frame.origin if self._frame is not None else 0
        start, values = buffer.window(buffer.first, buffer.total)
        return self.capture.times(start, len(values), origin), values.copy()

    def visible_data(self) -> tuple[np.ndarray, np.ndarray]:
        """The samples inside the plot's visible time range."""
        t, values = self.data()
        x0, x1 = self.plot.x_range()
        inside = (t >= x0) & (t <= x1)
        return t[inside], values[inside]

    def update_readouts(self) -> None:
        """Recompute the cursor read-out and the step figures."""
        t, values = self.data()
        if not len(t):
            self.cursors.show_readout(None)
            self.steps.show_figures(None, "")
            return
        cursors = self.plot.cursors_visible
        readout = cursor_readout(t, values, *self.plot.cursor_times()) if cursors else None
        self.cursors.show_readout(readout)
        self.steps.between_cursors.setEnabled(cursors)
        if cursors and self.steps.between_cursors.isChecked():
            x0, x1 = sorted(self.plot.cursor_times())
            region = self.tr("the samples between cursors A and B")
        else:
            x0, x1 = self.plot.x_range()
            region = self.tr("the visible window")
        self.steps.show_figures(self.measure(x0, x1), region)

    def measure(self, x0: float, x1: float) -> StepMeasurement:
        """Step-response measurement of the samples between times ``x0`` and ``x1``: the
        reference's first complete step (see :func:`prm9tool.scope.measure_step`)."""
        t, values = self.data()
        response, reference = self.steps.response_slot(), self.steps.reference_slot()
        if response is None or response >= values.shape[1]:
            return StepMeasurement(Verdict.NO_STEP)
        if reference is not None and reference >= values.shape[1]:
            reference = None
        inside = (t >= x0) & (t <= x1)
        ref = values[inside, reference] if reference is not None else None
        same_unit = self.steps.units_match()
        return measure_step(t[inside], values[inside, response], ref, comparable=same_unit)


def newest_arrived(rows: np.ndarray) -> np.ndarray:
    """Per channel the newest sample of ``rows`` that arrived (NaN only when none did): a lost
    sample over CANopen does not blank the legend."""
    finite = np.isfinite(rows)
    last = rows.shape[0] - 1 - np.argmax(finite[::-1], axis=0)
    values = rows[last, np.arange(rows.shape[1])]
    return np.where(finite.any(axis=0), values, np.nan)

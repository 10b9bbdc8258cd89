"""The oscilloscope's plot: one ViewBox and axis per channel, A/B cursors, a live legend
(``legend.py``).

Channel 1 uses the plot's own ViewBox and left axis; channels 2 and 3 get their own ViewBoxes
(x-linked, stacked below the main one so the mouse and the cursors stay on it) with axes on the
right. Each channel therefore has its own colour, unit and scale; dragging or wheeling on an
axis zooms that channel alone (and stops its autoscale until "Auto" is pressed).

Live frames are peak-decimated to twice the plot's pixel width before they reach pyqtgraph
(the window is the clip), so a 10 s window at 5 kHz draws as ~2000 points per channel; a held
recording is handed over whole, with pyqtgraph's clip-to-view and peak downsampling on. The
grid is an opaque item of its own under all three views, the y axes are cached pixmaps
(benchmarks/bench_scope_paint.py: a repaint costs half of what pyqtgraph's own grid costs).
"""

from __future__ import annotations

import math
import re
from collections.abc import Sequence

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import Qt, Signal
from PySide6.QtGui import QFontMetrics, QImage
from PySide6.QtWidgets import (
    QGraphicsItem,
    QHBoxLayout,
    QVBoxLayout,
    QWidget,
)

from prm9tool.catalogue.signals import MAX_CHANNELS
from prm9tool.catalogue.signals import Signal as MeasuringPoint
from prm9tool.i18n import text
from prm9tool.scope import axis_ranges, curve_points, peak_decimate
from prm9tool.views.localized_axis import LocalizedAxis
from prm9tool.views.scope.items import CursorLine, PlotGrid
from prm9tool.views.scope.legend import COLOURS, LegendEntry

CURSOR_COLOUR = "#e0e0e0"
SHARED_AXIS_COLOUR = "#c8c8c8"  # tick labels of an axis two channels share
OBJECT_NUMBER = re.compile(r"\s*\(0x[0-9A-Fa-f]+\)")  # "(0x6301)" in a measuring point's name


class ScopePlot(QWidget):
    """Plot area of the oscilloscope (no data logic: the owner pushes arrays in)."""

    cursors_moved = Signal()
    x_range_changed = Signal()  # the user zoomed or panned the time axis

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.graphics = pg.GraphicsLayoutWidget()
        self.graphics.setBackground("#111418")
        axes = {name: LocalizedAxis(name) for name in ("left", "bottom", "right")}
        self.item = self.graphics.addPlot(row=0, col=0, axisItems=axes)
        for name in ("left", "bottom"):  # major ticks only, as the grid (minor lines cost ~15 ms)
            self.item.getAxis(name).setStyle(maxTickLevel=0)
        self.item.hideButtons()
        self.views = [self.item.getViewBox(), pg.ViewBox(), pg.ViewBox()]
        self.axes = [self.item.getAxis("left"), self.item.getAxis("right"), LocalizedAxis("right")]
        self.item.showAxis("right")
        self.item.layout.addItem(self.axes[2], 2, 3)
        for axis in (*self.axes, self.item.getAxis("bottom")):
            axis.enableAutoSIPrefix(False)  # no label re-render on every range change
        for axis in self.axes:  # y axes change rarely (autoscale hysteresis): keep them as pixmaps
            axis.setCacheMode(QGraphicsItem.CacheMode.DeviceCoordinateCache)
        for view, axis in zip(self.views[1:], self.axes[1:], strict=True):
            self.item.scene().addItem(view)
            axis.linkToView(view)
            view.setXLink(self.item)
            view.setZValue(-10)  # below the main plot: mouse and cursors act on channel 1's view
        self.views[0].sigResized.connect(self._sync_geometry)
        self.views[0].sigResized.connect(self._on_resized)
        self._label_room = 0  # the axis length the labels were last fitted to (pixels)
        self.grid = PlotGrid(self.views[0], self.item.getAxis("bottom"), self.axes[0])
        self.item.scene().addItem(self.grid)
        self.grid.follow_view()
        self._auto = [True] * MAX_CHANNELS
        self._clipping = True
        for slot, view in enumerate(self.views):
            view.disableAutoRange()  # our own autoscale with hysteresis (see _rescale)
            view.sigRangeChangedManually.connect(lambda *_, s=slot: self._on_manual_range(s))
        self.curves = [self._make_curve(slot) for slot in range(MAX_CHANNELS)]
        self.cursors = [self._make_cursor(name) for name in ("A", "B")]
        self.legend = [LegendEntry(slot) for slot in range(MAX_CHANNELS)]
        self._same_scale = True
        self._units: list[str] = []
        self._signals: list[MeasuringPoint] = []
        self._shared: dict[int, int] = {}  # channel → the earlier channel whose axis it uses
        self._channels = 0
        self._time_axis = (False, 1.0)
        for slot, entry in enumerate(self.legend):
            entry.autoscale.clicked.connect(lambda _=False, s=slot: self.autoscale(s))
        self._build_layout()
        self.set_channels([])
        self.set_cursors_visible(False)
        self.retranslate()

    def _make_curve(self, slot: int) -> pg.PlotDataItem:
        curve = pg.PlotDataItem(pen=pg.mkPen(COLOURS[slot], width=1))  # cosmetic: fast path
        curve.setClipToView(True)
        curve.setDownsampling(auto=True, method="peak")
        curve.setSkipFiniteCheck(True)
        self.views[slot].addItem(curve)
        return curve

    def _make_cursor(self, name: str) -> pg.InfiniteLine:
        pen = pg.mkPen(CURSOR_COLOUR, width=1, style=Qt.PenStyle.DashLine)
        line = CursorLine(angle=90, movable=True, pen=pen, label=name)
        line.label.setColor(CURSOR_COLOUR)
        line.label.setPosition(0.96)
        line.sigPositionChanged.connect(lambda *_: self.cursors_moved.emit())
        self.item.addItem(line, ignoreBounds=True)
        return line

    def _build_layout(self) -> None:
        strip = QHBoxLayout()
        for entry in self.legend:
            strip.addWidget(entry)
        strip.addStretch(1)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addLayout(strip)
        layout.addWidget(self.graphics, 1)

    def _sync_geometry(self) -> None:
        for view in self.views[1:]:
            view.setGeometry(self.views[0].sceneBoundingRect())
            view.linkedViewChanged(self.views[0], view.XAxis)

    def retranslate(self) -> None:
        """Re-read user-visible texts (after a language change)."""
        self.set_time_axis(*self._time_axis)
        for entry in self.legend:
            entry.autoscale.setText(self.tr("Auto"))
            entry.autoscale.setToolTip(self.tr("Scale this channel to its data again"))
            entry.set_live_texts(
                self.tr("live:"),
                self.tr(
                    "The valve's newest value. The plot holds an earlier recording; read it "
                    "with the cursors."
                ),
                self.tr("at stop:"),
                self.tr("The last value recorded before Stop; the valve may hold another now."),
            )

    # --- channels and data ---------------------------------------------------------------------
    def set_channels(self, signals: Sequence[MeasuringPoint]) -> None:
        """Show one axis, curve and legend entry per signal (at most three), nothing drawn
        yet: a trace's legend values leave with it (no "at stop:" above an empty plot)."""
        for slot in range(MAX_CHANNELS):
            self.legend[slot].setVisible(slot < len(signals))
            self.legend[slot].set_value(math.nan)
            self.curves[slot].setData([], [])
            self._auto[slot] = True
        self._channels = len(signals)
        self._units = [s.unit for s in signals]
        self._shared = self._sharing()
        self.relabel(signals)

    def relabel(self, signals: Sequence[MeasuringPoint]) -> None:
        """Axis and legend names of the channels (also after a language change)."""
        self._signals = list(signals)
        for slot, signal in enumerate(signals):
            self.legend[slot].set_signal(signal)
        self._label_axes()

    def _label_axes(self) -> None:
        """One axis per channel, named in the channel's colour; channels that share an axis
        (same unit, same scale) are named on it together, and the later one's is hidden."""
        signals = self._signals
        for slot, axis in enumerate(self.axes):
            if slot == 0 or (slot < len(signals) and slot not in self._shared):
                axis.show()  # show/hide, not setVisible: they also give or free its width
            else:
                axis.hide()
        for slot, signal in enumerate(signals):
            members = [slot] + [k for k, owner in self._shared.items() if owner == slot]
            axis = self.axes[slot]
            if slot in self._shared:
                continue
            if len(members) == 1:
                axis.setToolTip("")
                axis.setLabel(f"{text(signal.text)} [{signal.unit}]", color=COLOURS[slot])
                axis.setTextPen(COLOURS[slot])
                continue
            names = [text(signals[k].text) for k in members]
            axis.setLabel(self._shared_label(members, names, signal.unit), color=SHARED_AXIS_COLOUR)
            axis.setToolTip(f"{', '.join(names)} [{signal.unit}]")
            axis.setTextPen(SHARED_AXIS_COLOUR)
        if not signals:
            self.axes[0].setLabel("")

    def _shared_label(self, members: Sequence[int], names: Sequence[str], unit: str) -> str:
        """The label of an axis several channels share: their names in their colours if they
        fit along the axis (without object numbers if need be), else the legend's colour
        squares ("■ ■ [%]"): the legend above the plot names the channels, the axis's tooltip
        too. A cut "Demand value…, Spool position actual (…" named nothing readable."""
        label = self.axes[0].label
        # pyqtgraph draws the text with a space after it (its empty units) inside the margins
        # of the label's text document: "… (0x630" was cut at the top by those few pixels
        room = self._label_room - 2 * label.document().documentMargin()
        metrics = QFontMetrics(label.font())
        for candidate in (names, [OBJECT_NUMBER.sub("", name) for name in names]):
            if metrics.horizontalAdvance(f"{', '.join(candidate)} [{unit}] ") <= room:
                break
        else:
            candidate = ["■"] * len(members)
        spans = (
            f'<span style="color:{COLOURS[k]}">{name}</span>'
            for k, name in zip(members, candidate, strict=True)
        )
        joint = " " if candidate[0] == "■" else ", "
        return f"{joint.join(spans)} [{unit}]"

    def _on_resized(self) -> None:
        room = int(self.views[0].height())
        if room != self._label_room:
            self._label_room = room
            if self._shared:
                self._label_axes()

    def _sharing(self) -> dict[int, int]:
        """Channels whose axis would repeat an earlier channel's: same unit, both autoscaled
        on one scale (see :func:`axis_ranges`)."""
        shared: dict[int, int] = {}
        if not self._same_scale:
            return shared
        for slot in range(1, self._channels):
            for owner in range(slot):
                same = self._units[owner] == self._units[slot]
                if same and self._auto[owner] and self._auto[slot] and owner not in shared:
                    shared[slot] = owner
                    break
        return shared

    def _update_sharing(self) -> None:
        shared = self._sharing()
        if shared != self._shared:
            self._shared = shared
            self._label_axes()

    def shared_axes(self) -> dict[int, int]:
        """Channels drawn on an earlier channel's axis: ``{channel: owner}`` (0-based)."""
        return dict(self._shared)

    def set_time_axis(self, from_trigger: bool, window_s: float) -> None:
        """Label the time axis; windows under a second are labelled in milliseconds."""
        self._time_axis = (from_trigger, window_s)
        ms = window_s < 1.0
        axis = self.item.getAxis("bottom")
        axis.setScale(1000.0 if ms else 1.0)
        if from_trigger:
            label = self.tr("Time from trigger [ms]") if ms else self.tr("Time from trigger [s]")
        else:
            label = self.tr("Time [ms]") if ms else self.tr("Time [s]")
        axis.setLabel(label)

    def show_data(self, t: np.ndarray, values: np.ndarray) -> None:
        """Draw a live frame: peak-decimated here to the plot's width (no re-clipping)."""
        self._set_clipping(False)
        width = max(100, int(self.views[0].width()))
        t, values = peak_decimate(t, values, 2 * width)
        for slot in range(self._channels):
            self._set_curve(slot, t, values[:, slot])
        self._rescale()

    def show_all(self, t: np.ndarray, values: np.ndarray) -> None:
        """Draw a held recording: pyqtgraph clips and decimates to whatever the user zooms to."""
        self._set_clipping(True)
        for slot in range(self._channels):
            self._set_curve(slot, t, values[:, slot])
        self._rescale(force=True)

    def _set_curve(self, slot: int, t: np.ndarray, y: np.ndarray) -> None:
        """The samples that arrived; a run of lost ones (NaN, over CANopen) longer than a few
        samples is a gap in the line at its time (:func:`curve_points`)."""
        x, v, connect = curve_points(t, y)
        self.curves[slot].setData(x, v, connect="all" if connect.all() else connect)

    def _set_clipping(self, on: bool) -> None:
        if self._clipping != on:
            self._clipping = on
            for curve in self.curves:
                curve.setClipToView(on)
                curve.setDownsampling(ds=1, auto=on, method="peak")

    def _rescale(self, force: bool = False) -> None:
        """Autoscale the channels that follow their data (see :func:`axis_ranges`)."""
        slots = range(self._channels)
        bounds = [self._bounds(slot) if self._auto[slot] else None for slot in slots]
        current = [self.y_range(slot) for slot in slots]
        ranges = axis_ranges(bounds, current, self._units, self._same_scale, force, self._auto)
        for slot, new in enumerate(ranges):
            if new is not None:
                self.views[slot].setYRange(*new, padding=0)

    def _bounds(self, slot: int) -> tuple[float, float] | None:
        y = self.curves[slot].yData
        if y is None or not len(y):
            return None
        finite = y[np.isfinite(y)]  # a channel without data (NaN) has no bounds, no warning
        if not len(finite):
            return None
        return float(finite.min()), float(finite.max())

    def show_latest(self, values: np.ndarray, held: bool = False, stopped: bool = False) -> None:
        """The newest values in the legend (one per channel, NaN when unknown); ``held``:
        the plot holds an earlier recording, so they are marked as live; ``stopped``: the
        recording ended, so they are marked as the values at Stop."""
        for slot in range(self._channels):
            self.legend[slot].set_value(float(values[slot]), held, stopped and not held)

    def set_x_range(self, x0: float, x1: float) -> None:
        """Show times ``x0`` … ``x1`` (new data: a new frame or capture).

        The cursors keep their place on the screen, like a bench oscilloscope's: a new capture
        or a rolling frame does not leave them behind at old times, off the plot. Panning and
        zooming a held picture with the mouse moves the view, not this, so there the cursors
        stay on the samples they mark.
        """
        old0, old1 = self.x_range()
        shares = (
            [(line.value() - old0) / (old1 - old0) for line in self.cursors] if old1 > old0 else []
        )
        self.views[0].setXRange(x0, x1, padding=0)
        if (old0, old1) != (x0, x1) and shares and self.cursors_visible:
            for line, share in zip(self.cursors, shares, strict=True):
                line.setValue(x0 + min(1.0, max(0.0, share)) * (x1 - x0))

    def x_range(self) -> tuple[float, float]:
        """The time range on screen."""
        x0, x1 = self.views[0].viewRange()[0]
        return float(x0), float(x1)

    def set_time_interactive(self, interactive: bool) -> None:
        """Allow zooming and panning the time axis with the mouse (when the display holds)."""
        self.views[0].setMouseEnabled(x=interactive, y=True)

    def autoscale(self, slot: int) -> None:
        """Scale channel ``slot``'s axis to its data, and keep doing so as data arrives."""
        self._auto[slot] = True
        self._rescale(force=True)
        self._update_sharing()

    def set_same_scale(self, on: bool) -> None:
        """Autoscaled channels with the same unit share one scale (on by default)."""
        self._same_scale = on
        self._rescale(force=True)
        self._update_sharing()

    def is_autoscaled(self, slot: int) -> bool:
        """True while channel ``slot``'s axis follows its data."""
        return self._auto[slot]

    def _on_manual_range(self, slot: int) -> None:
        self._auto[slot] = False
        self._update_sharing()
        if slot == 0:
            self.x_range_changed.emit()

    def y_range(self, slot: int) -> tuple[float, float]:
        """The value range shown on channel ``slot``'s axis."""
        y0, y1 = self.views[slot].viewRange()[1]
        return float(y0), float(y1)

    # --- cursors -------------------------------------------------------------------------------
    def set_cursors_visible(self, visible: bool) -> None:
        """Show the A/B cursors; they appear at ¼ and ¾ of the visible time range."""
        if visible:
            x0, x1 = self.x_range()
            apart = self.cursors[0].value() != self.cursors[1].value()
            for line, share in zip(self.cursors, (0.25, 0.75), strict=True):
                if not (x0 <= line.value() <= x1 and apart):
                    line.setValue(x0 + share * (x1 - x0))
        for line in self.cursors:
            line.setVisible(visible)
        self.cursors_moved.emit()

    @property
    def cursors_visible(self) -> bool:
        """True while the A/B cursors are shown."""
        return self.cursors[0].isVisible()

    def cursor_times(self) -> tuple[float, float]:
        """Times of cursors A and B."""
        return float(self.cursors[0].value()), float(self.cursors[1].value())

    def set_cursor_times(self, t_a: float, t_b: float) -> None:
        """Place cursors A and B."""
        self.cursors[0].setValue(t_a)
        self.cursors[1].setValue(t_b)

    def render_image(self) -> QImage:
        """The legend strip and plot as an image (PNG export)."""
        return self.grab().toImage()

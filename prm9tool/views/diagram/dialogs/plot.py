"""A small QPainter plot for the block dialogs: axes, grid, labelled curves, reference lines.

Colours are given as on paper (white background, dark ink) and drawn moved onto the widget's
palette (:func:`~prm9tool.views.diagram.colours.on_palette`): on a dark palette the plot is
dark with light axes and the curves keep their hues.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from PySide6.QtCore import QEvent, QPointF, QRectF, Qt
from PySide6.QtGui import QColor, QFont, QPainter, QPainterPath, QPaintEvent, QPen
from PySide6.QtWidgets import QSizePolicy, QWidget

from prm9tool.i18n import format_significant
from prm9tool.views.diagram.colours import on_palette, readable

AXIS = QColor("#44505c")
GRID = QColor("#e3e7eb")
BLUE = QColor("#1f6fb2")
ORANGE = QColor("#e07b12")
GREEN = QColor("#2c9a4b")
PURPLE = QColor("#7b4bb2")
RED = QColor("#c8201a")
GREY = QColor("#8a939c")
PAPER = QColor("white")
LEGEND_PLATE = QColor(255, 255, 255, 225)


@dataclass
class Curve:
    """A polyline in data coordinates."""

    points: list[tuple[float, float]]
    colour: QColor
    label: str = ""
    dashed: bool = False
    width: float = 2.0


@dataclass
class Axes:
    """Ranges and titles of the two axes."""

    x_range: tuple[float, float] = (-100.0, 100.0)
    y_range: tuple[float, float] = (-100.0, 100.0)
    x_title: str = ""
    y_title: str = ""
    hlines: list[tuple[float, QColor, str]] = field(default_factory=list)


def nice_ticks(low: float, high: float, count: int = 5) -> list[float]:
    """Round tick values (1, 2, 5 × 10ⁿ steps) covering ``low``…``high``."""
    span = high - low
    if span <= 0:
        return [low]
    raw_step = span / count
    magnitude = 10 ** math.floor(math.log10(raw_step))
    step = next(m * magnitude for m in (1, 2, 2.5, 5, 10) if m * magnitude >= raw_step)
    first = math.ceil(low / step - 1e-9) * step
    ticks = []
    value = first
    while value <= high + step * 1e-6:
        ticks.append(0.0 if abs(value) < step * 1e-9 else value)
        value += step
    return ticks


def tick_text(value: float) -> str:
    """Shortest readable text of a tick value."""
    if abs(value - round(value)) < 1e-9:
        return str(round(value))
    return format_significant(value, 3)


class PlotWidget(QWidget):
    """Draws :class:`Curve` objects on :class:`Axes`; subclasses add interaction."""

    MARGINS = (58.0, 14.0, 16.0, 42.0)  # left, right, top, bottom

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.axes = Axes()
        self.curves: list[Curve] = []
        self.legend_bottom_right = False  # True: where a step response leaves room
        self.setMinimumSize(380, 260)
        self.setSizePolicy(QSizePolicy.Policy.Expanding, QSizePolicy.Policy.Expanding)

    def set_axes(self, axes: Axes) -> None:
        """Replace the axes and redraw."""
        self.axes = axes
        self.update()

    def set_curves(self, curves: list[Curve]) -> None:
        """Replace the curves and redraw."""
        self.curves = curves
        self.update()

    # --- coordinates -------------------------------------------------------------------
    def plot_rect(self) -> QRectF:
        """The data area in widget pixels."""
        left, right, top, bottom = self.MARGINS
        return QRectF(left, top, self.width() - left - right, self.height() - top - bottom)

    def to_pixel(self, x: float, y: float) -> QPointF:
        """Data → widget coordinates."""
        rect = self.plot_rect()
        (x0, x1), (y0, y1) = self.axes.x_range, self.axes.y_range
        px = rect.left() + (x - x0) / (x1 - x0) * rect.width()
        py = rect.bottom() - (y - y0) / (y1 - y0) * rect.height()
        return QPointF(px, py)

    def to_value(self, point: QPointF) -> tuple[float, float]:
        """Widget → data coordinates."""
        rect = self.plot_rect()
        (x0, x1), (y0, y1) = self.axes.x_range, self.axes.y_range
        x = x0 + (point.x() - rect.left()) / rect.width() * (x1 - x0)
        y = y0 + (rect.bottom() - point.y()) / rect.height() * (y1 - y0)
        return x, y

    # --- painting ----------------------------------------------------------------------------
    def tone(self, colour: QColor) -> QColor:
        """``colour`` (as on paper) as drawn on the widget's palette."""
        return on_palette(colour, self.palette())

    def paintEvent(self, event: QPaintEvent) -> None:
        painter = QPainter(self)
        painter.setRenderHint(QPainter.RenderHint.Antialiasing)
        painter.fillRect(self.rect(), self.tone(PAPER))
        self._paint_grid(painter)
        painter.save()
        painter.setClipRect(self.plot_rect().adjusted(-1, -1, 1, 1))
        for value, colour, _label in self.axes.hlines:
            pen = QPen(self.tone(colour), 1.2, Qt.PenStyle.DashLine)
            painter.setPen(pen)
            painter.drawLine(
                self.to_pixel(self.axes.x_range[0], value),
                self.to_pixel(self.axes.x_range[1], value),
            )
        for curve in self.curves:
            self._paint_curve(painter, curve)
        painter.restore()
        self._paint_hline_labels(painter)
        self._paint_legend(painter)
        self.paint_overlay(painter)
        painter.end()

    def paint_overlay(self, painter: QPainter) -> None:
        """Hook for subclasses: draw handles on top of the curves."""

    def changeEvent(self, event: QEvent) -> None:
        if event.type() in (QEvent.Type.PaletteChange, QEvent.Type.ApplicationPaletteChange):
            self.update()
        super().changeEvent(event)

    def _paint_grid(self, painter: QPainter) -> None:
        rect = self.plot_rect()
        font = QFont(self.font())
        font.setPointSizeF(max(7.5, font.pointSizeF() - 1))
        painter.setFont(font)
        for x in nice_ticks(*self.axes.x_range):
            p = self.to_pixel(x, self.axes.y_range[0])
            self._grid_line(painter, x, QPointF(p.x(), rect.top()), QPointF(p.x(), rect.bottom()))
            label = QRectF(p.x() - 30, rect.bottom() + 3, 60, 14)
            painter.drawText(label, Qt.AlignmentFlag.AlignHCenter, tick_text(x))
        for y in nice_ticks(*self.axes.y_range):
            p = self.to_pixel(self.axes.x_range[0], y)
            self._grid_line(painter, y, QPointF(rect.left(), p.y()), QPointF(rect.right(), p.y()))
            label = QRectF(0, p.y() - 7, rect.left() - 5, 14)
            align = Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter
            painter.drawText(label, align, tick_text(y))
        painter.setPen(QPen(self.tone(AXIS), 1.2))
        painter.setBrush(Qt.BrushStyle.NoBrush)
        painter.drawRect(rect)
        self._paint_titles(painter, rect)

    def _grid_line(self, painter: QPainter, value: float, start: QPointF, end: QPointF) -> None:
        """A grid line (the zero line darker); leaves the pen ready for the tick label."""
        painter.setPen(QPen(self.tone(AXIS if value == 0 else GRID), 1))
        painter.drawLine(start, end)
        painter.setPen(self.tone(AXIS))

    def _paint_titles(self, painter: QPainter, rect: QRectF) -> None:
        centre = Qt.AlignmentFlag.AlignHCenter
        painter.drawText(
            QRectF(rect.left(), rect.bottom() + 20, rect.width(), 16), centre, self.axes.x_title
        )
        painter.save()
        painter.translate(12, rect.center().y())
        painter.rotate(-90)
        painter.drawText(
            QRectF(-rect.height() / 2, -8, rect.height(), 16), centre, self.axes.y_title
        )
        painter.restore()

    def _paint_curve(self, painter: QPainter, curve: Curve) -> None:
        if len(curve.points) < 2:
            return
        pen = QPen(self.tone(curve.colour), curve.width)
        if curve.dashed:
            pen.setStyle(Qt.PenStyle.DashLine)
        painter.setPen(pen)
        painter.setBrush(Qt.BrushStyle.NoBrush)
        path = QPainterPath(self.to_pixel(*curve.points[0]))
        for x, y in curve.points[1:]:
            path.lineTo(self.to_pixel(x, y))
        painter.drawPath(path)

    def _paint_hline_labels(self, painter: QPainter) -> None:
        rect = self.plot_rect()
        middle = (self.axes.y_range[0] + self.axes.y_range[1]) / 2
        for value, colour, label in self.axes.hlines:
            if label:
                p = self.to_pixel(self.axes.x_range[0], value)
                top = p.y() - 16 if value >= middle else p.y() + 2
                painter.setPen(readable(self.tone(colour), self.tone(PAPER)))
                painter.drawText(
                    QRectF(rect.left() + 4, top, rect.width() - 8, 14),
                    Qt.AlignmentFlag.AlignRight,
                    label,
                )

    def _paint_legend(self, painter: QPainter) -> None:
        labelled = [c for c in self.curves if c.label]
        if not labelled:
            return
        rect = self.plot_rect()
        metrics = painter.fontMetrics()
        width = max(metrics.horizontalAdvance(c.label) for c in labelled) + 34
        height = 6 + 16 * len(labelled)
        if self.legend_bottom_right:
            box = QRectF(rect.right() - 6 - width, rect.bottom() - 6 - height, width, height)
        else:
            box = QRectF(rect.left() + 6, rect.top() + 6, width, height)
        painter.setPen(QPen(self.tone(GRID), 1))
        painter.setBrush(self.tone(LEGEND_PLATE))
        painter.drawRect(box)
        for n, curve in enumerate(labelled):
            y = box.top() + 11 + 16 * n
            pen = QPen(self.tone(curve.colour), curve.width)
            if curve.dashed:
                pen.setStyle(Qt.PenStyle.DashLine)
            painter.setPen(pen)
            painter.drawLine(QPointF(box.left() + 5, y), QPointF(box.left() + 25, y))
            painter.setPen(self.tone(AXIS))
            painter.drawText(QPointF(box.left() + 30, y + 4), curve.label)

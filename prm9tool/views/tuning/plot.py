"""Small line plots drawn with QPainter: the tuning report's and the Tuning window's figures.

No pyqtgraph here: the same picture goes into a PDF page and onto the screen, at any size.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np
from PySide6.QtCore import QPointF, QRectF, Qt
from PySide6.QtGui import QColor, QFont, QFontMetrics, QImage, QPainter, QPainterPath, QPen

from prm9tool.i18n import current_language
from prm9tool.messages import localized_number

COLOURS = ("#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e")


@dataclass
class Series:
    """One line: x, y, its legend text ("": not in the legend) and colour (index into
    COLOURS or a name)."""

    x: np.ndarray
    y: np.ndarray
    label: str
    colour: str = COLOURS[0]
    dashed: bool = False


@dataclass
class Plot:
    """A plot: lines, axis titles, a log x axis, and marker lines (x or y, text)."""

    title: str
    xlabel: str
    ylabel: str
    series: list[Series] = field(default_factory=list)
    logx: bool = False
    vlines: list[tuple[float, str]] = field(default_factory=list)
    hlines: list[tuple[float, str]] = field(default_factory=list)


def _number(value: float) -> str:
    """A tick label with the program language's decimal separator (``0,5`` in German)."""
    return localized_number(f"{value:g}".replace("-", "−"), current_language())


def _range(values: Sequence[np.ndarray], log: bool) -> tuple[float, float]:
    data = np.concatenate([v[np.isfinite(v)] for v in values]) if values else np.zeros(1)
    if log:
        data = np.log10(data[data > 0]) if np.any(data > 0) else np.zeros(1)
    lo, hi = (float(data.min()), float(data.max())) if len(data) else (0.0, 1.0)
    if hi - lo < 1e-9:
        lo, hi = lo - 1.0, hi + 1.0
    pad = 0.05 * (hi - lo) if not log else 0.0
    return lo - pad, hi + pad


def _ticks(lo: float, hi: float, log: bool) -> list[float]:
    if log:
        return [float(d) for d in range(math.floor(lo), math.ceil(hi) + 1) if lo <= d <= hi]
    step = 10 ** math.floor(math.log10((hi - lo) / 4))
    for mult in (1, 2, 5, 10):
        if (hi - lo) / (step * mult) <= 6:
            step *= mult
            break
    first = math.ceil(lo / step) * step
    return [first + k * step for k in range(int((hi - first) / step) + 1)]


@dataclass(frozen=True)
class Painted:
    """Where :func:`paint_plot` drew: the data's rectangle, its x and y ranges (x as log10 on
    a log axis) and the legend's box (None without one)."""

    area: QRectF
    x_range: tuple[float, float]
    y_range: tuple[float, float]
    legend: QRectF | None

    def pixels(self, series: Series, logx: bool = False) -> np.ndarray:
        """The finite points of ``series`` in pixels, shape (n, 2)."""
        (x0, x1), (y0, y1), a = self.x_range, self.y_range, self.area
        ok = np.isfinite(series.x) & np.isfinite(series.y) & ((series.x > 0) if logx else True)
        x = np.log10(series.x[ok]) if logx else series.x[ok]
        px = a.left() + (x - x0) / (x1 - x0) * a.width()
        py = a.bottom() - (series.y[ok] - y0) / (y1 - y0) * a.height()
        return np.column_stack([px, py])


def paint_plot(painter: QPainter, rect: QRectF, plot: Plot, ink: QColor | None = None) -> Painted:
    """Draw ``plot`` into ``rect`` (axes, grid, lines, legend, markers); where it went."""
    ink = ink or QColor("black")
    font = QFont(painter.font())
    font.setPixelSize(min(max(9, int(rect.height() / 22)), max(9, int(rect.width() / 60))))
    painter.setFont(font)
    metrics = painter.fontMetrics()
    line = metrics.height()
    area = rect.adjusted(
        metrics.horizontalAdvance("-0000.0") + line, line * 1.6, -line, -line * 2.4
    )
    xs = [s.x for s in plot.series]
    ys = [s.y for s in plot.series] + [np.array([v for v, _ in plot.hlines])]
    x0, x1 = _range(xs, plot.logx)
    y0, y1 = _range(ys, False)

    def px(x: float) -> float:
        v = math.log10(x) if plot.logx else x
        return area.left() + (v - x0) / (x1 - x0) * area.width()

    def py(y: float) -> float:
        return area.bottom() - (y - y0) / (y1 - y0) * area.height()

    named = [s for s in plot.series if s.label]  # a line without a label is not in the legend
    legend = _legend_size(named, metrics, line)
    inner = area.adjusted(line * 0.5, line * 0.5, -line * 0.5, -line * 0.5)
    points = _pixels(plot.series, px, py, plot.logx)
    if named and _covered(legend_box(inner, legend, points), points):
        # every corner would hide data (steps both ways fill the top and the bottom): room
        # above the data for the legend, which no choice of corner can give
        free = area.height() - legend[1] - line
        if free > area.height() / 3:
            y1 = y0 + (y1 - y0) * area.height() / free
    painter.setPen(QPen(ink, 0))
    painter.drawText(QRectF(rect.left(), rect.top(), rect.width(), line * 1.4),
                     Qt.AlignmentFlag.AlignCenter, plot.title)  # fmt: skip
    grid = QColor(ink)
    grid.setAlpha(50)
    for tick in _ticks(x0, x1, plot.logx):
        x = area.left() + (tick - x0) / (x1 - x0) * area.width()
        painter.setPen(QPen(grid, 0))
        painter.drawLine(QPointF(x, area.top()), QPointF(x, area.bottom()))
        painter.setPen(QPen(ink, 0))
        label = _number(10**tick if plot.logx else tick)
        painter.drawText(
            QRectF(x - 40, area.bottom() + 2, 80, line), Qt.AlignmentFlag.AlignHCenter, label
        )
    for tick in _ticks(y0, y1, False):
        y = py(tick)
        painter.setPen(QPen(grid, 0))
        painter.drawLine(QPointF(area.left(), y), QPointF(area.right(), y))
        painter.setPen(QPen(ink, 0))
        painter.drawText(QRectF(rect.left(), y - line / 2, area.left() - rect.left() - 4, line),
                         Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter, _number(tick))  # fmt: skip
    painter.drawRect(area)
    painter.drawText(QRectF(area.left(), area.bottom() + line, area.width(), line * 1.3),
                     Qt.AlignmentFlag.AlignCenter, plot.xlabel)  # fmt: skip
    painter.save()
    painter.translate(rect.left() + line * 0.1, area.center().y())
    painter.rotate(-90)
    painter.drawText(
        QRectF(-area.height() / 2, 0, area.height(), line),
        Qt.AlignmentFlag.AlignCenter,
        plot.ylabel,
    )
    painter.restore()
    painter.save()
    painter.setClipRect(area)
    for value, text in plot.hlines:
        _marker(
            painter,
            QPointF(area.left(), py(value)),
            QPointF(area.right(), py(value)),
            text,
            ink,
            area,
        )
    for value, text in plot.vlines:
        if math.isfinite(value) and value > 0:
            _marker(
                painter,
                QPointF(px(value), area.top()),
                QPointF(px(value), area.bottom()),
                text,
                ink,
                area,
            )
    for s in plot.series:
        _line(painter, s, px, py)
    painter.restore()
    if not named:
        return Painted(area, (x0, x1), (y0, y1), None)
    width = legend[0]
    box = legend_box(inner, legend, _pixels(plot.series, px, py, plot.logx))
    backdrop = QColor("black" if ink.lightness() > 128 else "white")  # under the text
    backdrop.setAlpha(220)
    painter.fillRect(box, backdrop)
    for k, s in enumerate(named):
        y = box.top() + line * (k + 0.2)
        painter.setPen(QPen(QColor(s.colour), 2))
        painter.drawLine(
            QPointF(box.left() + line * 0.3, y + line / 2),
            QPointF(box.left() + line * 1.8, y + line / 2),
        )
        painter.setPen(QPen(ink, 0))
        painter.drawText(
            QRectF(box.left() + line * 2.1, y, width, line), Qt.AlignmentFlag.AlignLeft, s.label
        )
    return Painted(area, (x0, x1), (y0, y1), box)


def _pixels(series: Sequence[Series], px: object, py: object, logx: bool) -> np.ndarray:
    """The finite data points of ``series`` (at most ~500 each) in pixels, shape (n, 2)."""
    rows: list[tuple[float, float]] = []
    for s in series:
        ok = np.isfinite(s.x) & np.isfinite(s.y) & ((s.x > 0) if logx else True)
        x, y = s.x[ok], s.y[ok]
        step = max(1, len(x) // 500)
        rows += [(px(float(a)), py(float(b))) for a, b in zip(x[::step], y[::step], strict=True)]  # type: ignore[operator]
    return np.array(rows, dtype=float).reshape(-1, 2)


def _legend_size(
    series: Sequence[Series], metrics: QFontMetrics, line: float
) -> tuple[float, float]:
    """The legend's (w, h) in pixels; (0, 0) without lines."""
    if not series:
        return (0.0, 0.0)
    width = max(metrics.horizontalAdvance(s.label) for s in series) + line * 2.3
    return (width, line * (len(series) + 0.4))


def _covered(box: QRectF, points: np.ndarray) -> int:
    """How many of the data ``points`` (pixels, shape (n, 2)) ``box`` covers."""
    x, y = points[:, 0], points[:, 1]
    inside = (x >= box.left()) & (x <= box.right()) & (y >= box.top()) & (y <= box.bottom())
    return int(inside.sum())


def legend_box(area: QRectF, size: tuple[float, float], points: np.ndarray) -> QRectF:
    """The corner of ``area`` for a legend of ``size`` (w, h) that covers the fewest of the
    data ``points`` (pixels, shape (n, 2)); top right on a tie, then top left, bottom right,
    bottom left."""
    w, h = size
    corners = [
        QRectF(area.right() - w, area.top(), w, h),
        QRectF(area.left(), area.top(), w, h),
        QRectF(area.right() - w, area.bottom() - h, w, h),
        QRectF(area.left(), area.bottom() - h, w, h),
    ]

    return min(corners, key=lambda box: _covered(box, points))


def _marker(
    painter: QPainter, a: QPointF, b: QPointF, text: str, ink: QColor, area: QRectF
) -> None:
    """A dashed marker line from ``a`` to ``b`` and its text just below ``a``, whole inside
    ``area`` (the "−3 dB" label lost its top to the clip, and ran off near the right edge)."""
    pen = QPen(QColor("#888888"), 1, Qt.PenStyle.DashLine)
    painter.setPen(pen)
    painter.drawLine(a, b)
    painter.setPen(QPen(ink, 0))
    metrics = painter.fontMetrics()
    width = metrics.horizontalAdvance(text)
    x = a.x() + 3 if a.x() + 3 + width <= area.right() else a.x() - 3 - width
    painter.drawText(QPointF(x, a.y() + metrics.ascent() + 2), text)


def _line(painter: QPainter, s: Series, px: object, py: object) -> None:
    ok = np.isfinite(s.x) & np.isfinite(s.y)
    if ok.sum() < 2:
        return
    x, y = s.x[ok], s.y[ok]
    step = max(1, len(x) // 2000)
    path = QPainterPath(QPointF(px(float(x[0])), py(float(y[0]))))  # type: ignore[operator]
    for xv, yv in zip(x[::step], y[::step], strict=True):
        path.lineTo(px(float(xv)), py(float(yv)))  # type: ignore[operator]
    pen = QPen(QColor(s.colour), 1.6, Qt.PenStyle.DashLine if s.dashed else Qt.PenStyle.SolidLine)
    painter.setPen(pen)
    painter.drawPath(path)


def plot_image(plot: Plot, width: int = 1200, height: int = 560) -> QImage:
    """``plot`` on a white image (for the PDF report)."""
    image = QImage(width, height, QImage.Format.Format_RGB32)
    image.fill(QColor("white"))
    painter = QPainter(image)
    painter.setRenderHint(QPainter.RenderHint.Antialiasing)
    paint_plot(painter, QRectF(0, 0, width, height), plot)
    painter.end()
    return image

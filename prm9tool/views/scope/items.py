"""Two graphics items of the oscilloscope's plot: the opaque grid and the A/B cursor lines."""

from __future__ import annotations

import pyqtgraph as pg
from PySide6.QtCore import QLineF, QRectF, Qt
from PySide6.QtGui import QColor, QPainter, QPen
from PySide6.QtWidgets import QGraphicsItem

GRAB_PX = 6  # the mouse grabs a cursor line this many pixels either side of it
GRID_COLOUR = "#3a3d42"  # opaque: a translucent grid line costs 2-4 ms per rolling frame


class PlotGrid(QGraphicsItem):
    """The grid at channel 1's major ticks, under every channel's curves.

    pyqtgraph's own grid is drawn by the axes, above the main view, so it has to be translucent
    not to cut the curves; blending it across the plot on every frame of a running recording
    costs more than the curves. This one lies under all views and is drawn opaque.
    """

    def __init__(self, view: pg.ViewBox, x_axis: pg.AxisItem, y_axis: pg.AxisItem) -> None:
        super().__init__()
        self._view, self._x_axis, self._y_axis = view, x_axis, y_axis
        self._rect = QRectF()
        self._pen = QPen(QColor(GRID_COLOUR), 0)  # cosmetic, 1 pixel
        self.setZValue(-20)  # under the views of channels 2 and 3 (-10) and the plot item (0)
        self.setAcceptedMouseButtons(Qt.MouseButton.NoButton)
        view.sigResized.connect(self.follow_view)
        view.sigRangeChanged.connect(lambda *_: self.update())

    def follow_view(self) -> None:
        """Take the main view's place in the scene."""
        self.prepareGeometryChange()
        self._rect = self._view.sceneBoundingRect()
        self.update()

    def boundingRect(self) -> QRectF:
        """The main view's rectangle in scene coordinates."""
        return self._rect

    def lines(self) -> tuple[list[float], list[float]]:
        """The x and y values (channel 1's view units) a grid line is drawn at."""
        (x0, x1), (y0, y1) = self._view.viewRange()
        r = self._rect
        return (
            self._major(self._x_axis, x0, x1, r.width()),
            self._major(self._y_axis, y0, y1, r.height()),
        )

    @staticmethod
    def _major(axis: pg.AxisItem, low: float, high: float, pixels: float) -> list[float]:
        if not high > low or pixels <= 0:
            return []
        levels = axis.tickValues(low, high, pixels)
        return [v for v in levels[0][1] if low <= v <= high] if levels else []

    def paint(self, painter: QPainter, _option: object, _widget: object = None) -> None:
        """Vertical lines at the time ticks, horizontal ones at channel 1's ticks."""
        r = self._rect
        (x0, x1), (y0, y1) = self._view.viewRange()
        if r.isEmpty() or not (x1 > x0 and y1 > y0):
            return
        xs, ys = self.lines()
        sx, sy = r.width() / (x1 - x0), r.height() / (y1 - y0)
        painter.setPen(self._pen)
        segments = [
            QLineF(r.left() + (x - x0) * sx, r.top(), r.left() + (x - x0) * sx, r.bottom())
            for x in xs
        ]
        segments += [
            QLineF(r.left(), r.bottom() - (y - y0) * sy, r.right(), r.bottom() - (y - y0) * sy)
            for y in ys
        ]
        painter.drawLines(segments)


class CursorLine(pg.InfiniteLine):
    """A cursor line the mouse grabs up to GRAB_PX pixels either side of it.

    pyqtgraph's line reacts only within its pen width plus a pixel (±1.5 pixels for a
    cosmetic 1-pixel pen), so a press next to it panned the plot instead of moving it.
    """

    def _computeBoundingRect(self) -> QRectF:
        rect = QRectF(super()._computeBoundingRect())  # the drawing area, along the line
        _, ortho = self.pixelVectors(direction=pg.Point(1, 0))
        if ortho is not None:
            grab = GRAB_PX * abs(ortho.y())
            rect.setTop(min(rect.top(), -grab))
            rect.setBottom(max(rect.bottom(), grab))
        return rect

"""Graphics items of the signal-flow diagram: blocks, summing junctions, arrows, red dots."""

from __future__ import annotations

import math

from PySide6.QtCore import QPointF, QRectF, Qt, Signal
from PySide6.QtGui import (
    QBrush,
    QColor,
    QFont,
    QFontMetricsF,
    QPainter,
    QPainterPath,
    QPen,
    QPolygonF,
)
from PySide6.QtWidgets import (
    QGraphicsItem,
    QGraphicsObject,
    QGraphicsPathItem,
    QGraphicsSceneHoverEvent,
    QGraphicsSceneMouseEvent,
    QGraphicsSimpleTextItem,
    QStyleOptionGraphicsItem,
    QWidget,
)

INK = QColor("#1f2d3a")
EDIT_FILL = QColor("#eaf2fb")
EDIT_EDGE = QColor("#2f6592")
HOVER_FILL = QColor("#d3e5f7")
LOCKED_FILL = QColor("#e4e4e4")
LOCKED_EDGE = QColor("#a0a0a0")
LOCKED_INK = QColor("#808080")
INFO_FILL = QColor("#f7f7f2")
DOT_ON = QColor("#d91e18")
DOT_OFF = QColor("#eaa3a0")
VALUE_INK = QColor("#a3140f")


def _font(pixels: int, bold: bool = False) -> QFont:
    font = QFont()
    font.setPixelSize(pixels)
    font.setBold(bold)
    return font


def _fitting_font(text: str, width: float) -> QFont:
    """The bold title font, shrunk (down to 10 px) until ``text`` fits ``width``."""
    for pixels in range(14, 9, -1):
        font = _font(pixels, bold=True)
        if QFontMetricsF(font).horizontalAdvance(text) <= width:
            return font
    return _font(10, bold=True)


class BlockItem(QGraphicsObject):
    """One block: a title and up to three value lines; grey and inert when locked."""

    activated = Signal(str)  # block id; emitted on a click when the block has a dialog

    LINE_FONT = _font(13)

    def __init__(self, block_id: str, rect: QRectF, info: bool = False) -> None:
        super().__init__()
        self.block_id = block_id
        self._rect = QRectF(0, 0, rect.width(), rect.height())
        self.setPos(rect.topLeft())
        self.info = info
        self.title = ""
        self._title_font = _font(14, bold=True)
        self.lines: list[str] = []
        self.locked = False
        self._hovered = False
        self.setAcceptHoverEvents(True)
        if not info:
            self.setCursor(Qt.CursorShape.PointingHandCursor)

    def set_content(self, title: str, lines: list[str]) -> None:
        """Show ``title`` and the value ``lines``."""
        if (title, lines) != (self.title, self.lines):
            if title != self.title:
                self._title_font = _fitting_font(title, self._rect.width() - 8)
            self.title, self.lines = title, list(lines)
            self.update()

    def set_locked(self, locked: bool, tooltip: str) -> None:
        """Grey the block out (``locked``) and explain on hover."""
        self.locked = locked
        self.setToolTip(tooltip)
        self.update()

    def scene_rect(self) -> QRectF:
        """The block's rectangle in scene coordinates."""
        return self.mapRectToScene(self._rect)

    def boundingRect(self) -> QRectF:
        return self._rect.adjusted(-2, -2, 2, 2)

    def paint(
        self, painter: QPainter, option: QStyleOptionGraphicsItem, widget: QWidget | None = None
    ) -> None:
        fill, edge, ink = self._colours()
        painter.setRenderHint(QPainter.RenderHint.Antialiasing)
        pen = QPen(edge, 1.6)
        if self.info:
            pen.setStyle(Qt.PenStyle.DashLine)
        painter.setPen(pen)
        painter.setBrush(fill)
        painter.drawRoundedRect(self._rect, 7, 7)
        painter.setPen(ink)
        title_rect = QRectF(4, 4, self._rect.width() - 8, 20)
        painter.setFont(self._title_font)
        painter.drawText(
            title_rect, Qt.AlignmentFlag.AlignHCenter | Qt.AlignmentFlag.AlignVCenter, self.title
        )
        painter.setPen(QPen(edge.lighter(130), 1))
        painter.drawLine(QPointF(8, 25), QPointF(self._rect.width() - 8, 25))
        painter.setPen(ink)
        painter.setFont(self.LINE_FONT)
        for n, line in enumerate(self.lines):
            rect = QRectF(5, 28 + n * 18, self._rect.width() - 10, 18)
            painter.drawText(
                rect, Qt.AlignmentFlag.AlignHCenter | Qt.AlignmentFlag.AlignVCenter, line
            )

    def _colours(self) -> tuple[QColor, QColor, QColor]:
        if self.info:
            return INFO_FILL, LOCKED_EDGE, INK
        if self.locked:
            return LOCKED_FILL, LOCKED_EDGE, LOCKED_INK
        return (HOVER_FILL if self._hovered else EDIT_FILL), EDIT_EDGE, INK

    def hoverEnterEvent(self, event: QGraphicsSceneHoverEvent) -> None:
        self._hovered = True
        self.update()
        super().hoverEnterEvent(event)

    def hoverLeaveEvent(self, event: QGraphicsSceneHoverEvent) -> None:
        self._hovered = False
        self.update()
        super().hoverLeaveEvent(event)

    def mousePressEvent(self, event: QGraphicsSceneMouseEvent) -> None:
        event.setAccepted(not self.info and event.button() == Qt.MouseButton.LeftButton)

    def mouseReleaseEvent(self, event: QGraphicsSceneMouseEvent) -> None:
        if self.boundingRect().contains(event.pos()):
            self.activated.emit(self.block_id)


class SumItem(QGraphicsItem):
    """A summing junction (circle with a cross); the feedback input carries a minus sign."""

    RADIUS = 9.0

    def __init__(self, centre: QPointF, minus_at: str = "bottom") -> None:
        super().__init__()
        self.setPos(centre)
        self._minus_at = minus_at

    def boundingRect(self) -> QRectF:
        r = self.RADIUS + 12
        return QRectF(-r, -r, 2 * r, 2 * r)

    def paint(
        self, painter: QPainter, option: QStyleOptionGraphicsItem, widget: QWidget | None = None
    ) -> None:
        r = self.RADIUS
        painter.setRenderHint(QPainter.RenderHint.Antialiasing)
        painter.setPen(QPen(INK, 1.4))
        painter.setBrush(QColor("white"))
        painter.drawEllipse(QPointF(0, 0), r, r)
        d = r * math.sqrt(0.5)
        painter.drawLine(QPointF(-d, -d), QPointF(d, d))
        painter.drawLine(QPointF(-d, d), QPointF(d, -d))
        painter.setFont(_font(14, bold=True))
        if self._minus_at == "bottom":
            painter.drawText(QPointF(-r - 9, r + 10), "−")
        else:
            painter.drawText(QPointF(r + 2, -r - 1), "−")


class ArrowItem(QGraphicsPathItem):
    """A polyline with an arrow head at its last point; dashed for optional paths."""

    def __init__(self, points: list[QPointF], dashed: bool = False) -> None:
        path = QPainterPath(points[0])
        for point in points[1:]:
            path.lineTo(point)
        super().__init__(path)
        pen = QPen(INK, 1.5)
        if dashed:
            pen.setStyle(Qt.PenStyle.DashLine)
        self.setPen(pen)
        self._head = self._arrow_head(points[-2], points[-1])

    @staticmethod
    def _arrow_head(start: QPointF, end: QPointF) -> QPolygonF:
        angle = math.atan2(end.y() - start.y(), end.x() - start.x())
        size, spread = 9.0, 0.42
        left = QPointF(
            end.x() - size * math.cos(angle - spread), end.y() - size * math.sin(angle - spread)
        )
        right = QPointF(
            end.x() - size * math.cos(angle + spread), end.y() - size * math.sin(angle + spread)
        )
        return QPolygonF([end, left, right])

    def boundingRect(self) -> QRectF:
        return super().boundingRect().united(self._head.boundingRect()).adjusted(-2, -2, 2, 2)

    def paint(
        self, painter: QPainter, option: QStyleOptionGraphicsItem, widget: QWidget | None = None
    ) -> None:
        painter.setRenderHint(QPainter.RenderHint.Antialiasing)
        super().paint(painter, option, widget)
        painter.setPen(QPen(INK, 1))
        painter.setBrush(QBrush(INK))
        painter.drawPolygon(self._head)


class _ValueLabel(QGraphicsSimpleTextItem):
    """A live value in small bold red on a white plate (readable where it crosses a line)."""

    def paint(
        self, painter: QPainter, option: QStyleOptionGraphicsItem, widget: QWidget | None = None
    ) -> None:
        if self.text():
            painter.setPen(Qt.PenStyle.NoPen)
            painter.setBrush(QColor(255, 255, 255, 230))
            painter.drawRoundedRect(self.boundingRect().adjusted(-2, 0, 2, 0), 3, 3)
        # Qt passes no widget when the scene is rendered into an image; the stub wants one
        super().paint(painter, option, widget)  # type: ignore[arg-type]


class DotItem(QGraphicsObject):
    """A red measuring point; online it shows the live value and a click asks for the scope."""

    clicked = Signal(str)  # measuring-point key

    RADIUS = 5.5

    def __init__(self, key: str, centre: QPointF, label_side: str) -> None:
        super().__init__()
        self.key = key
        self.setPos(centre)
        self.active = False
        self._label = _ValueLabel(self)
        self._label.setFont(_font(11, bold=True))
        self._label.setBrush(VALUE_INK)
        self._label_side = label_side
        self.setAcceptHoverEvents(True)
        self.setZValue(2)

    @property
    def value_text(self) -> str:
        """The live value shown next to the dot ('' offline)."""
        return self._label.text()

    def set_active(self, active: bool, tooltip: str) -> None:
        """Online dots are bright and clickable; offline ones are pale and inert."""
        self.active = active
        self.setToolTip(tooltip)
        self.setCursor(Qt.CursorShape.PointingHandCursor if active else Qt.CursorShape.ArrowCursor)
        if not active:
            self.set_value_text("")
        self.update()

    def set_value_text(self, text: str) -> None:
        """Show ``text`` beside the dot."""
        if text == self._label.text():
            return
        self._label.setText(text)
        height = self._label.boundingRect().height()
        offsets = {
            "right": QPointF(self.RADIUS + 4, -height / 2),
            "below": QPointF(-self.RADIUS, self.RADIUS + 1),
            "below_centre": QPointF(-self._label.boundingRect().width() / 2, self.RADIUS + 1),
        }
        self._label.setPos(
            offsets.get(self._label_side, QPointF(-self.RADIUS, -height - self.RADIUS + 1))
        )

    def boundingRect(self) -> QRectF:
        r = self.RADIUS + 2
        return QRectF(-r, -r, 2 * r, 2 * r)

    def shape(self) -> QPainterPath:
        path = QPainterPath()
        r = self.RADIUS + 4  # a slightly larger target than the drawn dot
        path.addEllipse(QPointF(0, 0), r, r)
        return path

    def paint(
        self, painter: QPainter, option: QStyleOptionGraphicsItem, widget: QWidget | None = None
    ) -> None:
        painter.setRenderHint(QPainter.RenderHint.Antialiasing)
        colour = DOT_ON if self.active else DOT_OFF
        painter.setPen(QPen(colour.darker(140), 1))
        painter.setBrush(colour)
        painter.drawEllipse(QPointF(0, 0), self.RADIUS, self.RADIUS)

    def mousePressEvent(self, event: QGraphicsSceneMouseEvent) -> None:
        event.setAccepted(self.active and event.button() == Qt.MouseButton.LeftButton)

    def mouseReleaseEvent(self, event: QGraphicsSceneMouseEvent) -> None:
        if self.active:
            self.clicked.emit(self.key)

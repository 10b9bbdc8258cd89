"""Graphics items of the signal-flow diagram: blocks, summing junctions, arrows, red dots."""

from __future__ import annotations

import math
from typing import NamedTuple

from PySide6.QtCore import QPointF, QRectF, Qt, Signal
from PySide6.QtGui import (
    QBrush,
    QColor,
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

from prm9tool.views.diagram.colours import PAPER, DiagramColours
from prm9tool.views.diagram.text_fit import (
    LINE_H,
    LINE_PIXELS,
    PAD,
    TITLE_LINE_H,
    TITLE_PIXELS,
    TITLE_TOP,
    fit_lines,
    fit_title,
    pixel_font,
)


class BlockLook(NamedTuple):
    """The colours a block is painted in now."""

    fill: QColor
    edge: QColor
    rule: QColor  # the line under the title
    ink: QColor


class BlockItem(QGraphicsObject):
    """One block: a title (one or two lines) and up to three value lines; grey when locked.

    Texts too long for the block are elided; the tooltip then carries them in full.
    """

    activated = Signal(str)  # block id; emitted on a click when the block has a dialog

    def __init__(
        self, block_id: str, rect: QRectF, info: bool = False, title_lines: int = 2
    ) -> None:
        super().__init__()
        self.block_id = block_id
        self._rect = QRectF(0, 0, rect.width(), rect.height())
        self.setPos(rect.topLeft())
        self.info = info
        self.title_lines = title_lines  # the title area's height in lines
        self.title = ""
        self.lines: list[str] = []
        self.title_font = pixel_font(TITLE_PIXELS[0], bold=True)
        self.shown_title: list[str] = []
        self.line_font = pixel_font(LINE_PIXELS[0])
        self.shown_lines: list[str] = []
        self.fits = True  # False when a text had to be elided
        self._tip = ""
        self.locked = False
        self._hovered = False
        self._colours = PAPER
        self.setAcceptHoverEvents(True)
        if not info:
            self.setCursor(Qt.CursorShape.PointingHandCursor)

    @property
    def text_width(self) -> float:
        """Width available to the block's texts."""
        return self._rect.width() - 2 * PAD

    @property
    def separator_y(self) -> float:
        """Height of the rule under the title."""
        return TITLE_TOP + self.title_lines * TITLE_LINE_H + 3

    def set_content(self, title: str, lines: list[str]) -> None:
        """Show ``title`` and the value ``lines``."""
        if (title, lines) == (self.title, self.lines):
            return
        self.title, self.lines = title, list(lines)
        self.title_font, self.shown_title, title_fits = fit_title(
            title, self.text_width, self.title_lines
        )
        self.line_font, self.shown_lines, lines_fit = fit_lines(self.lines, self.text_width)
        self.fits = title_fits and lines_fit
        self._show_tooltip()
        self.update()

    def set_locked(self, locked: bool, tooltip: str) -> None:
        """Grey the block out (``locked``) and explain on hover."""
        self.locked = locked
        self._tip = tooltip
        self._show_tooltip()
        self.update()

    def set_colours(self, colours: DiagramColours) -> None:
        """Paint in ``colours`` from now on."""
        self._colours = colours
        self.update()

    def _show_tooltip(self) -> None:
        full = "" if self.fits else "\n".join([self.title, *self.lines])
        self.setToolTip("\n\n".join(part for part in (full, self._tip) if part))

    def scene_rect(self) -> QRectF:
        """The block's rectangle in scene coordinates."""
        return self.mapRectToScene(self._rect)

    def boundingRect(self) -> QRectF:
        return self._rect.adjusted(-2, -2, 2, 2)

    def paint(
        self, painter: QPainter, option: QStyleOptionGraphicsItem, widget: QWidget | None = None
    ) -> None:
        fill, edge, rule_colour, ink = self.look()
        painter.setRenderHint(QPainter.RenderHint.Antialiasing)
        pen = QPen(edge, 1.6)
        if self.info:
            pen.setStyle(Qt.PenStyle.DashLine)
        painter.setPen(pen)
        painter.setBrush(fill)
        painter.drawRoundedRect(self._rect, 7, 7)
        painter.setPen(ink)
        painter.setFont(self.title_font)
        centre = Qt.AlignmentFlag.AlignHCenter | Qt.AlignmentFlag.AlignVCenter
        width = self.text_width
        title_h = self.title_lines * TITLE_LINE_H
        top = TITLE_TOP + (title_h - len(self.shown_title) * TITLE_LINE_H) / 2
        for n, line in enumerate(self.shown_title):
            painter.drawText(QRectF(PAD, top + n * TITLE_LINE_H, width, TITLE_LINE_H), centre, line)
        rule = self.separator_y
        painter.setPen(QPen(rule_colour, 1))
        painter.drawLine(QPointF(8, rule), QPointF(self._rect.width() - 8, rule))
        painter.setPen(ink)
        painter.setFont(self.line_font)
        free = self._rect.height() - rule - 6 - len(self.shown_lines) * LINE_H
        top = rule + 2 + max(0.0, free / 2)  # the value lines centred under the rule
        for n, line in enumerate(self.shown_lines):
            painter.drawText(QRectF(PAD, top + n * LINE_H, width, LINE_H), centre, line)

    def look(self) -> BlockLook:
        """Fill, border, rule and text colour for the block's state (info, locked, hovered)."""
        c = self._colours
        if self.info:
            return BlockLook(c.info_fill, c.locked_edge, c.locked_rule, c.ink)
        if self.locked:
            return BlockLook(c.locked_fill, c.locked_edge, c.locked_rule, c.locked_ink)
        fill = c.hover_fill if self._hovered else c.edit_fill
        return BlockLook(fill, c.edit_edge, c.edit_rule, c.ink)

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
        self._colours = PAPER

    def set_colours(self, colours: DiagramColours) -> None:
        """Paint in ``colours`` from now on."""
        self._colours = colours
        self.update()

    def boundingRect(self) -> QRectF:
        r = self.RADIUS + 12
        return QRectF(-r, -r, 2 * r, 2 * r)

    def paint(
        self, painter: QPainter, option: QStyleOptionGraphicsItem, widget: QWidget | None = None
    ) -> None:
        r = self.RADIUS
        painter.setRenderHint(QPainter.RenderHint.Antialiasing)
        painter.setPen(QPen(self._colours.ink, 1.4))
        painter.setBrush(self._colours.sheet)
        painter.drawEllipse(QPointF(0, 0), r, r)
        d = r * math.sqrt(0.5)
        painter.drawLine(QPointF(-d, -d), QPointF(d, d))
        painter.drawLine(QPointF(-d, d), QPointF(d, -d))
        painter.setFont(pixel_font(14, bold=True))
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
        self.points = list(points)
        self._dashed = dashed
        self._ink = PAPER.ink
        self.set_colours(PAPER)
        self._head = self._arrow_head(points[-2], points[-1])

    def set_colours(self, colours: DiagramColours) -> None:
        """Draw in ``colours``' ink from now on."""
        self._ink = colours.ink
        pen = QPen(self._ink, 1.5)
        if self._dashed:
            pen.setStyle(Qt.PenStyle.DashLine)
        self.setPen(pen)

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
        painter.setPen(QPen(self._ink, 1))
        painter.setBrush(QBrush(self._ink))
        painter.drawPolygon(self._head)


class _ValueLabel(QGraphicsSimpleTextItem):
    """A live value in small bold red on a plate of the sheet's colour (readable where it
    crosses a line)."""

    plate = PAPER.value_plate

    def paint(
        self, painter: QPainter, option: QStyleOptionGraphicsItem, widget: QWidget | None = None
    ) -> None:
        if self.text():
            painter.setPen(Qt.PenStyle.NoPen)
            painter.setBrush(self.plate)
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
        self._label.setFont(pixel_font(11, bold=True))
        self._label_side = label_side
        self._colours = PAPER
        self.set_colours(PAPER)
        self.setAcceptHoverEvents(True)
        self.setZValue(2)

    def set_colours(self, colours: DiagramColours) -> None:
        """Paint the dot and its value in ``colours`` from now on."""
        self._colours = colours
        self._label.setBrush(colours.value_ink)
        self._label.plate = colours.value_plate
        self._label.update()
        self.update()

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
            "above_right": QPointF(self.RADIUS - 1, -height - self.RADIUS + 1),
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
        c = self._colours
        painter.setPen(QPen(c.dot_edge_on if self.active else c.dot_edge_off, 1))
        painter.setBrush(c.dot_on if self.active else c.dot_off)
        painter.drawEllipse(QPointF(0, 0), self.RADIUS, self.RADIUS)

    def mousePressEvent(self, event: QGraphicsSceneMouseEvent) -> None:
        event.setAccepted(self.active and event.button() == Qt.MouseButton.LeftButton)

    def mouseReleaseEvent(self, event: QGraphicsSceneMouseEvent) -> None:
        if self.active:
            self.clicked.emit(self.key)

"""Builds the QGraphicsScene of one variant's diagram from :mod:`.layout`."""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication, QPointF, QRectF
from PySide6.QtGui import QFont
from PySide6.QtWidgets import QGraphicsScene, QGraphicsSimpleTextItem

from prm9tool.views.diagram.colours import PAPER, DiagramColours
from prm9tool.views.diagram.items import ArrowItem, BlockItem, DotItem, SumItem
from prm9tool.views.diagram.layout import (
    COL_PITCH,
    DOT_STEP,
    ROW_PITCH,
    SUM_R,
    BlockSpec,
    Layout,
    Link,
    block_rect,
)

GAP = COL_PITCH - block_rect(BlockSpec("", "", (), 0, 1))[2]
JOG = 24.0  # horizontal run of an arrow before it turns
FEEDBACK_DROP = 34.0
# Distance of a dot from its block: clear of the arrow heads into a summing junction.
OUT_DOT = 10.0
IN_DOT = 17.0


class DiagramScene(QGraphicsScene):
    """The items of one layout, with lookups by block id and measuring-point key.

    Drawn on paper (dark ink on white) until :meth:`set_colours` says otherwise.
    """

    def __init__(self, layout: Layout, colours: DiagramColours = PAPER) -> None:
        super().__init__()
        self.layout = layout
        self.colours = colours
        # ~80 items that never move except the live value labels: no BSP index to maintain
        self.setItemIndexMethod(QGraphicsScene.ItemIndexMethod.NoIndex)
        self.blocks: dict[str, BlockItem] = {}
        self.sums: dict[str, SumItem] = {}
        self.dots: dict[str, DotItem] = {}
        self._rects: dict[str, QRectF] = {}
        for spec in layout.blocks:
            self._add_block(spec)
        for sum_id, block_id in layout.sums.items():
            self._add_sum(sum_id, block_id)
        self.arrows: list[ArrowItem] = []
        for link in layout.links:
            arrow = ArrowItem(self._route(link), dashed=link.route == "down")
            self.addItem(arrow)
            self.arrows.append(arrow)
        self._add_feedback_label()
        for key, (block_id, side, index) in layout.dots.items():
            self._add_dot(key, block_id, side, index)
        # room on the right and below for the live values that appear online
        self.setSceneRect(self.itemsBoundingRect().adjusted(-18, -18, 70, 24))
        self.set_colours(colours)

    def set_colours(self, colours: DiagramColours) -> None:
        """Repaint the background and every item in ``colours``."""
        self.colours = colours
        self.setBackgroundBrush(colours.sheet)
        items: list[BlockItem | SumItem | ArrowItem | DotItem] = [
            *self.blocks.values(),
            *self.sums.values(),
            *self.arrows,
            *self.dots.values(),
        ]
        for item in items:
            item.set_colours(colours)
        self.feedback_label.setBrush(colours.ink)

    # --- items -------------------------------------------------------------------------
    def _add_block(self, spec: BlockSpec) -> None:
        rect = QRectF(*block_rect(spec, self.layout.compact_header))
        item = BlockItem(spec.id, rect, info=spec.info, title_lines=1 if spec.compact else 2)
        self.addItem(item)
        self.blocks[spec.id] = item
        self._rects[spec.id] = rect

    def _add_sum(self, sum_id: str, block_id: str) -> None:
        rect = self._rects[block_id]
        centre = QPointF(rect.left() - GAP / 2, rect.center().y())
        minus_at = "top" if sum_id == "sum_process" else "bottom"
        item = SumItem(centre, minus_at)
        self.addItem(item)
        self.sums[sum_id] = item
        self._rects[sum_id] = QRectF(centre.x() - SUM_R, centre.y() - SUM_R, 2 * SUM_R, 2 * SUM_R)

    def _add_dot(self, key: str, block_id: str, side: str, index: int) -> None:
        """A dot on the line it measures: the arrow leaving its block, the arrow into it after
        the junction, or the feedback line. Several outputs of one block (the two coils, PWM,
        supply and temperature) stand in a column on the block's right edge, the first where
        the arrow leaves."""
        if side == "feedback":
            valve = self._rects["valve"]
            centre = QPointF(valve.center().x() - COL_PITCH / 2, valve.bottom() + FEEDBACK_DROP)
            label_side = "below_centre"
        elif side == "in":
            rect = self._rects[block_id]
            centre = QPointF(rect.left() - IN_DOT, rect.center().y())
            label_side = "below"
        else:
            rect = self._rects[block_id]
            count = sum(1 for b, s, _i in self.layout.dots.values() if (b, s) == (block_id, side))
            if self.blocks[block_id].info:  # no arrow leaves: the column is centred
                step = index - (count - 1) / 2
                centre = QPointF(rect.right(), rect.center().y() + step * DOT_STEP)
                label_side = "right"
            elif count > 1:
                centre = QPointF(rect.right(), rect.center().y() + index * DOT_STEP)
                label_side = "right" if index else "above_right"
            else:
                centre = QPointF(rect.right() + OUT_DOT, rect.center().y())
                # before the process junction the sensor arrives from above: label below
                into_sum = any(
                    link.source == block_id and link.target == "sum_process"
                    for link in self.layout.links
                )
                label_side = "below" if into_sum else "above"
        item = DotItem(key, centre, label_side)
        self.addItem(item)
        self.dots[key] = item

    def _add_feedback_label(self) -> None:
        valve = self._rects["valve"]
        label = QGraphicsSimpleTextItem()
        font = QFont()
        font.setPixelSize(12)
        font.setItalic(True)
        label.setFont(font)
        label.setPos(self._rects["sum_position"].right() + 14, valve.bottom() + FEEDBACK_DROP + 2)
        self.addItem(label)
        self.feedback_label = label
        self.retranslate()

    def retranslate(self) -> None:
        """Texts drawn by the scene itself, in the current language."""
        self.feedback_label.setText(
            QCoreApplication.translate("DiagramBlock", "spool position (LVDT)")
        )

    # --- arrow routes ------------------------------------------------------------------------
    def _out(self, item_id: str) -> QPointF:
        rect = self._rects[item_id]
        return QPointF(rect.right(), rect.center().y())

    def _in(self, item_id: str) -> QPointF:
        rect = self._rects[item_id]
        return QPointF(rect.left(), rect.center().y())

    def _route(self, link: Link) -> list[QPointF]:
        src, dst = self._rects[link.source], self._rects[link.target]
        if link.route == "right":
            return [self._out(link.source), self._in(link.target)]
        if link.route == "wrap":
            start, end = self._out(link.source), self._in(link.target)
            mid_y = src.bottom() + (ROW_PITCH - src.height()) / 2
            return [
                start,
                QPointF(start.x() + JOG, start.y()),
                QPointF(start.x() + JOG, mid_y),
                QPointF(end.x() - JOG, mid_y),
                QPointF(end.x() - JOG, end.y()),
                end,
            ]
        if link.route == "feedback":
            start = QPointF(src.center().x(), src.bottom())
            low = src.bottom() + FEEDBACK_DROP
            return [
                start,
                QPointF(start.x(), low),
                QPointF(dst.center().x(), low),
                QPointF(dst.center().x(), dst.bottom()),
            ]
        if link.route == "sensor":
            start = self._out(link.source)
            return [
                start,
                QPointF(dst.center().x(), start.y()),
                QPointF(dst.center().x(), dst.top()),
            ]
        # "down": a dashed optional path straight down into the block below
        return [QPointF(src.center().x(), src.bottom()), QPointF(dst.center().x(), dst.top())]

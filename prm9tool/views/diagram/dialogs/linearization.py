"""9-point linearization of the setpoint or (E04) of the external sensor (figs. 8-10, 8-16).

The curve is drawn with its nine points; a point can be dragged with the mouse (kept strictly
increasing in X and monotonic in Y while dragging) or typed in the table. Releasing a drag is
one undo step. A drag moves the point by the mouse's movement since the press (pressing beside
the handle's centre does not move it), and along the axis the user moves: a sideways (or
vertical) component smaller than a third of the other, as a hand's jitter, is left out, so a
vertical drag keeps X exactly (it moved 50 → 49.384 %, issue 34 item 16).
"""

from __future__ import annotations

from PySide6.QtCore import QPointF, QSignalBlocker, Qt, Signal
from PySide6.QtGui import QColor, QMouseEvent, QPainter, QPen
from PySide6.QtWidgets import (
    QAbstractItemView,
    QHeaderView,
    QPushButton,
    QTableWidget,
    QTableWidgetItem,
    QWidget,
)

from prm9tool.catalogue import CATALOGUE
from prm9tool.errors import ValueRangeError
from prm9tool.i18n import format_value, parse_value
from prm9tool.translate import error_text
from prm9tool.views.diagram.curves import FULL, clamp_point
from prm9tool.views.diagram.dialogs.base import BlockContext, BlockDialog
from prm9tool.views.diagram.dialogs.plot import BLUE, GREY, PAPER, Axes, Curve, PlotWidget

LETTERS = "ABCDEFGHI"
PCT = 100.0 / FULL
HANDLE_INK = QColor("#0d3d66")
HANDLE_ACTIVE = QColor("#f6a21a")  # the point being dragged
HANDLE_LOCKED = QColor("#dddddd")


class CurveEditor(PlotWidget):
    """The 9-point curve with draggable handles."""

    point_dragged = Signal(int, int, int)  # index, raw x, raw y — while the mouse moves
    point_released = Signal(int, int, int)  # index, raw x, raw y — drag finished

    GRAB_PX = 11.0
    JITTER_RATIO = 3.0  # the smaller movement is left out below a third of the larger one

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.xs: list[int] = []
        self.ys: list[int] = []
        self.editable = True
        self.dragging: int | None = None
        self._grab = QPointF()  # where the drag was pressed (widget position)
        self._origin = (0, 0)  # the point's raw (x, y) then
        self.setMouseTracking(True)
        self.set_axes(Axes((-105.0, 105.0), (-105.0, 105.0)))

    def set_points(self, xs: list[int], ys: list[int]) -> None:
        """Show the raw points (ignored while the user is dragging one)."""
        if self.dragging is None:
            self.xs, self.ys = list(xs), list(ys)
            self._update_curves()

    def handle_position(self, index: int) -> QPointF:
        """Widget position of point ``index`` (used by tests to drag it)."""
        return self.to_pixel(self.xs[index] * PCT, self.ys[index] * PCT)

    def _update_curves(self) -> None:
        points = [(x * PCT, y * PCT) for x, y in zip(self.xs, self.ys, strict=True)]
        self.set_curves(
            [
                Curve(
                    [(-100.0, -100.0), (100.0, 100.0)], GREY, self.tr("1:1"), dashed=True, width=1.2
                ),
                Curve(points, BLUE, self.tr("characteristic")),
            ]
        )

    def paint_overlay(self, painter: QPainter) -> None:
        painter.setFont(self.font())
        for n in range(len(self.xs)):
            centre = self.handle_position(n)
            active = n == self.dragging
            painter.setPen(QPen(self.tone(HANDLE_INK), 1.5))
            fill = HANDLE_ACTIVE if active else (PAPER if self.editable else HANDLE_LOCKED)
            painter.setBrush(self.tone(fill))
            painter.drawEllipse(centre, 6.0, 6.0)
            painter.setPen(self.tone(HANDLE_INK))
            # the label goes up-right of its point, below-left where that would leave the plot
            inside = self.plot_rect().contains(centre + QPointF(16, -18))
            painter.drawText(centre + (QPointF(7, -7) if inside else QPointF(-16, 19)), LETTERS[n])

    def _nearest(self, pos: QPointF) -> int | None:
        best, best_dist = None, self.GRAB_PX
        for n in range(len(self.xs)):
            delta = self.handle_position(n) - pos
            dist = (delta.x() ** 2 + delta.y() ** 2) ** 0.5
            if dist <= best_dist:
                best, best_dist = n, dist
        return best

    def _raw_at(self, pos: QPointF) -> tuple[int, int]:
        x, y = self.to_value(pos)
        return round(x / PCT), round(y / PCT)

    def _dragged_to(self, pos: QPointF) -> tuple[int, int]:
        """The raw point the drag has reached at mouse position ``pos``: the point as pressed,
        moved by the mouse's movement along the axis the user moves (the module docstring)."""
        dx, dy = pos.x() - self._grab.x(), pos.y() - self._grab.y()
        if abs(dx) * self.JITTER_RATIO < abs(dy):
            dx = 0.0
        elif abs(dy) * self.JITTER_RATIO < abs(dx):
            dy = 0.0
        x0, y0 = self._origin
        x, y = self._raw_at(self.to_pixel(x0 * PCT, y0 * PCT) + QPointF(dx, dy))
        return (x0 if dx == 0.0 else x), (y0 if dy == 0.0 else y)

    def mousePressEvent(self, event: QMouseEvent) -> None:
        if self.editable and event.button() == Qt.MouseButton.LeftButton:
            self.dragging = self._nearest(event.position())
            if self.dragging is not None:
                self._grab = event.position()
                self._origin = (self.xs[self.dragging], self.ys[self.dragging])
            self.update()

    def mouseMoveEvent(self, event: QMouseEvent) -> None:
        if self.dragging is None:
            near = self.editable and self._nearest(event.position()) is not None
            self.setCursor(Qt.CursorShape.OpenHandCursor if near else Qt.CursorShape.ArrowCursor)
            return
        index = self.dragging
        x, y = clamp_point(self.xs, self.ys, index, *self._dragged_to(event.position()))
        self.xs[index], self.ys[index] = x, y
        self._update_curves()
        self.point_dragged.emit(index, x, y)

    def mouseReleaseEvent(self, event: QMouseEvent) -> None:
        if self.dragging is None:
            return
        index, self.dragging = self.dragging, None
        self.update()
        self.point_released.emit(index, self.xs[index], self.ys[index])


class LinearizationDialog(BlockDialog):
    """Curve editor, point table and on/off switch of one 9-point linearization."""

    def __init__(
        self,
        ctx: BlockContext,
        block_id: str,
        title: str,
        prefix: str,
        switch: str,
        parent: QWidget | None = None,
    ) -> None:
        super().__init__(ctx, block_id, title, parent)
        self.prefix = prefix
        self.x_names = [f"{prefix}X{p}" for p in LETTERS]
        self.y_names = [f"{prefix}Y{p}" for p in LETTERS]
        self.watch(*self.x_names, *self.y_names)
        self.switch_field = self.choice_field(switch)
        self.table = self._make_table()
        self.form.addRow(self.table)
        self.reset_button = QPushButton()
        self.reset_button.clicked.connect(self._on_reset_clicked)
        self.form.addRow(self.reset_button)
        self.editor = CurveEditor()
        self.editor.point_dragged.connect(self._on_point_dragged)
        self.editor.point_released.connect(self._on_point_released)
        self.side.addWidget(self.editor)
        self.finish()

    def _make_table(self) -> QTableWidget:
        table = QTableWidget(len(LETTERS), 2)
        table.setVerticalHeaderLabels(list(LETTERS))
        table.horizontalHeader().setSectionResizeMode(QHeaderView.ResizeMode.Stretch)
        table.setEditTriggers(QAbstractItemView.EditTrigger.AllEditTriggers)
        table.setMinimumHeight(300)
        table.setMaximumWidth(260)
        table.itemChanged.connect(self._on_table_item_changed)
        return table

    def retranslate(self) -> None:
        super().retranslate()
        headers = [self.tr("Input X (%)"), self.tr("Output Y (%)")]
        self.table.setHorizontalHeaderLabels(headers)
        self._fit_table_width(headers)
        self.reset_button.setText(self.tr("Reset to a straight line"))
        self.editor.set_axes(
            Axes((-105.0, 105.0), (-105.0, 105.0), self.tr("Input (%)"), self.tr("Output (%)"))
        )

    def _fit_table_width(self, headers: list[str]) -> None:
        """Wide enough for both column titles in the current language."""
        metrics = self.table.horizontalHeader().fontMetrics()
        columns = sum(metrics.horizontalAdvance(h) + 28 for h in headers)
        width = columns + self.table.verticalHeader().sizeHint().width() + 4
        self.table.setMinimumWidth(width)
        self.table.setMaximumWidth(max(width, 260))

    def points(self) -> tuple[list[int], list[int]]:
        """The raw X and Y values of the document."""
        xs = [int(self.doc.value(n)) for n in self.x_names]
        ys = [int(self.doc.value(n)) for n in self.y_names]
        return xs, ys

    def refresh_extra(self) -> None:
        xs, ys = self.points()
        self.editor.set_points(xs, ys)
        self._fill_table(xs, ys)

    def _fill_table(self, xs: list[int], ys: list[int]) -> None:
        with QSignalBlocker(self.table):
            for row, (x, y) in enumerate(zip(xs, ys, strict=True)):
                for col, (name, raw) in enumerate(((self.x_names[row], x), (self.y_names[row], y))):
                    item = QTableWidgetItem(format_value(CATALOGUE[name], raw))
                    item.setData(Qt.ItemDataRole.UserRole, name)
                    item.setTextAlignment(
                        Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter
                    )
                    self.table.setItem(row, col, item)

    def update_access_extra(self, read_only: bool) -> None:
        editable = not read_only and self.access.may_edit(CATALOGUE[self.x_names[0]])
        self.editor.editable = editable
        self.editor.update()
        self.reset_button.setEnabled(editable)
        triggers = (
            QAbstractItemView.EditTrigger.AllEditTriggers
            if editable
            else QAbstractItemView.EditTrigger.NoEditTriggers
        )
        self.table.setEditTriggers(triggers)

    # --- user actions -------------------------------------------------------------------------------
    def _on_point_dragged(self, index: int, x: int, y: int) -> None:
        xs, ys = list(self.editor.xs), list(self.editor.ys)
        self._fill_table(xs, ys)

    def _on_point_released(self, index: int, x: int, y: int) -> None:
        values = {self.x_names[index]: x, self.y_names[index]: y}
        label = self.tr("Linearization point %1").replace("%1", LETTERS[index])
        if not self.apply_values(values, label):
            self.refresh_extra()

    def _on_table_item_changed(self, item: QTableWidgetItem) -> None:
        name = item.data(Qt.ItemDataRole.UserRole)
        try:
            raw = parse_value(CATALOGUE[name], item.text())
        except ValueRangeError as exc:
            self.show_error(error_text(exc))
            self.refresh_extra()
            return
        if not self.apply_value(name, raw):
            self.refresh_extra()

    def _on_reset_clicked(self) -> None:
        values = {}
        for name in (*self.x_names, *self.y_names):
            values[name] = CATALOGUE[name].default_for(self.doc.variant)
        self.apply_values(values, self.tr("Linearization reset to a straight line"))

"""The two switch tables of the CANopen window (manual §8.7, figure 8-17, marks "a", "c", "d").

Left the interface/bit-rate switch, right the node-ID switch, each with the position the valve
read at its last power-up marked; a part of the interface switch's position that the node-ID
switch overrides (:func:`prm9tool.catalogue.canopen_switches.overridden`) is struck through and says why.
Texts use the translation context of the window ("CanopenWindow").
"""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication, QEvent, Qt
from PySide6.QtGui import QBrush, QColor, QFont
from PySide6.QtWidgets import (
    QAbstractItemView,
    QGroupBox,
    QHBoxLayout,
    QHeaderView,
    QTableWidget,
    QTableWidgetItem,
    QVBoxLayout,
    QWidget,
)

from prm9tool.catalogue.canopen_switches import (
    POSITIONS,
    Overridden,
    baud_position,
    format_bitrate,
    node_position,
    overridden,
)
from prm9tool.views.diagram.colours import on_palette, readable

translate = QCoreApplication.translate  # the name pyside6-lupdate looks for
CURRENT_PAPER = QColor("#ffe9a8")  # colours as on paper, moved onto the palette when shown
OVERRIDDEN_PAPER = QColor("#8a8a8a")
ROW_H = 20


class SwitchTables(QWidget):
    """Both switch tables side by side; :meth:`show_switches` marks the positions read."""

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.switches: tuple[int, int] | None = None
        self.baud_table = _table(3)
        self.node_table = _table(2)
        self.baud_box, self.node_box = QGroupBox(), QGroupBox()
        QVBoxLayout(self.baud_box).addWidget(self.baud_table)
        QVBoxLayout(self.node_box).addWidget(self.node_table)
        tables = QHBoxLayout(self)
        tables.setContentsMargins(0, 0, 0, 0)
        tables.addWidget(self.baud_box, 3)
        tables.addWidget(self.node_box, 2)

    def retranslate(self) -> None:
        """Titles and headers in the current language (then call :meth:`show_switches`)."""
        self.baud_box.setTitle(translate("CanopenWindow", "Interface / bit-rate switch"))
        self.node_box.setTitle(translate("CanopenWindow", "Node-ID switch"))
        self.baud_table.setHorizontalHeaderLabels(
            [
                translate("CanopenWindow", "Position"),
                translate("CanopenWindow", "Interface / bit rate"),
                translate("CanopenWindow", "Terminator"),
            ]
        )
        self.node_table.setHorizontalHeaderLabels(
            [translate("CanopenWindow", "Position"), translate("CanopenWindow", "Node ID")]
        )

    def changeEvent(self, event: QEvent) -> None:
        """Re-colour the marked row when the palette changes (light / dark)."""
        if event.type() == QEvent.Type.PaletteChange:
            self.show_switches(self.switches)
        super().changeEvent(event)

    def show_switches(self, switches: tuple[int, int] | None) -> None:
        """Fill both tables; mark ``(interface, node)`` if known."""
        self.switches = switches
        baud, node = switches if switches is not None else (None, None)
        override = overridden(*switches) if switches is not None else Overridden(False, False)
        for position in POSITIONS:
            cells: tuple[str, ...] = (f"{position:X}", *_baud_texts(position))
            current = position == baud
            struck = {1: override.bitrate, 2: override.terminator} if current else {}
            self._fill_row(self.baud_table, position, cells, current, struck)
            cells = (f"{position:X}", _node_text(position))
            self._fill_row(self.node_table, position, cells, position == node, {})

    def _fill_row(
        self,
        table: QTableWidget,
        row: int,
        cells: tuple[str, ...],
        current: bool,
        struck: dict[int, bool],
    ) -> None:
        for column, text in enumerate(cells):
            shown = f"▶ {text}" if current and column == 0 else text
            item = QTableWidgetItem(shown)
            if current:
                font = QFont(item.font())
                font.setBold(True)
                item.setFont(font)
                item.setBackground(QBrush(on_palette(CURRENT_PAPER, self.palette())))
                item.setToolTip(
                    translate("CanopenWindow", "Position read by the valve at its last power-up")
                )
            if struck.get(column):
                self._strike(item, column)
            table.setItem(row, column, item)

    def _strike(self, item: QTableWidgetItem, column: int) -> None:
        """Mark a cell of the switch position that the node-ID switch overrides."""
        font = QFont(item.font())
        font.setStrikeOut(True)
        item.setFont(font)
        palette = self.palette()
        base = on_palette(CURRENT_PAPER, palette)  # a struck cell is in the marked row
        item.setForeground(QBrush(readable(on_palette(OVERRIDDEN_PAPER, palette), base, 3.0)))
        node = self.switches[1] if self.switches is not None else 0
        if column == 2:
            why = translate(
                "CanopenWindow",
                "Overridden: with the node-ID switch at 1 the interface switch has no function; "
                "the terminator follows the software setting below.",
            )
        elif node == 1:
            why = translate(
                "CanopenWindow",
                "Overridden: with the node-ID switch at 1 (LSS) the valve detects the bit rate "
                "of the bus.",
            )
        else:
            why = translate(
                "CanopenWindow",
                "Overridden: with the node-ID switch at 0 the bit rate set by software below "
                "applies.",
            )
        item.setToolTip(why)


def _baud_texts(position: int) -> tuple[str, str]:
    decoded = baud_position(position)
    if position == 0:
        return translate("CanopenWindow", "CANopen off, analog setpoint only"), "—"
    if position == 1:
        return translate("CanopenWindow", "reserved (as position 0)"), "—"
    rate = format_bitrate(decoded.bitrate_kbit)
    if decoded.terminator:
        terminator = translate("CanopenWindow", "on")
    else:
        terminator = translate("CanopenWindow", "off (on by software)")
    return translate("CanopenWindow", "CANopen, %1").replace("%1", rate), terminator


def _node_text(position: int) -> str:
    decoded = node_position(position)
    if decoded.software:
        return translate("CanopenWindow", "set by software: 1 … 127 (below)")
    if decoded.lss:
        return translate("CanopenWindow", "LSS, automatic bit rate")
    return str(decoded.node_id)


def _table(columns: int) -> QTableWidget:
    table = QTableWidget(len(POSITIONS), columns)
    table.verticalHeader().hide()
    table.setEditTriggers(QAbstractItemView.EditTrigger.NoEditTriggers)
    table.setSelectionMode(QAbstractItemView.SelectionMode.NoSelection)
    table.setFocusPolicy(Qt.FocusPolicy.NoFocus)
    table.verticalHeader().setDefaultSectionSize(ROW_H)
    table.setMinimumHeight(ROW_H * len(POSITIONS) + 28)
    table.setVerticalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
    header = table.horizontalHeader()
    header.setSectionResizeMode(QHeaderView.ResizeMode.ResizeToContents)
    header.setStretchLastSection(True)
    return table

"""The CAN bus dialog's table of nodes: what the search listed (PRM9 valves with type key,
serial and firmware, other nodes as "not a PRM9", not selectable), kept live by the bus
monitor's news — NMT state, heartbeat age, last EMCY, a boot-up pointed out, a node that
appears added ("new on the bus"), one whose heartbeat stopped shown silent. Its texts are the
dialog's (translation context ``CanBusDialog``).
"""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication, Qt
from PySide6.QtGui import QBrush, QPalette
from PySide6.QtWidgets import QTableWidget, QTableWidgetItem

from prm9tool.online.bus_monitor import HeardNode
from prm9tool.online.connection_protocol import ValveIdentity, ValveListing
from prm9tool.views.canbus.node_text import node_description
from prm9tool.views.row_table import row_table

BOOT_SHOWN_S = 10.0  # a boot-up is pointed out this long
NMT_COLUMN, HEARTBEAT_COLUMN, EMCY_COLUMN = 4, 5, 6


class NodeTable:
    """The nodes of one bus by row: :attr:`entries` the search listed, then the nodes heard
    since (not identified). ``watched``: the valve online on this bus (the dialog watching the
    session's bus), whose row says so."""

    def __init__(self) -> None:
        self.widget: QTableWidget = row_table(
            [
                QCoreApplication.translate("CanBusDialog", "Node"),
                QCoreApplication.translate("CanBusDialog", "Type key"),
                QCoreApplication.translate("CanBusDialog", "Serial"),
                QCoreApplication.translate("CanBusDialog", "Firmware"),
                QCoreApplication.translate("CanBusDialog", "NMT state"),
                QCoreApplication.translate("CanBusDialog", "Heartbeat"),
                QCoreApplication.translate("CanBusDialog", "Last EMCY"),
                QCoreApplication.translate("CanBusDialog", "Description"),
            ]
        )
        self.entries: list[ValveListing] = []
        self._extra: list[int] = []  # nodes heard after the search, not identified (rows after)
        self.watched: ValveIdentity | None = None

    def fill(self, entries: list[ValveListing]) -> None:
        """Show what a search listed (the nodes heard before it are forgotten)."""
        self.entries, self._extra = entries, []
        table = self.widget
        table.setRowCount(len(entries))
        for row, entry in enumerate(entries):
            valve = entry.kind == "can"
            age = entry.heartbeat_age_s
            cells = [
                entry.device_id,
                entry.type_key if valve else _verdict(entry),
                str(entry.serial) if valve else "",
                entry.firmware,
                entry.nmt_state or "",
                _age(age),
                entry.last_emcy,
                node_description(entry),
            ]
            for column, text in enumerate(cells):
                item = QTableWidgetItem(text)
                if not valve:
                    item.setFlags(item.flags() & ~Qt.ItemFlag.ItemIsSelectable)
                table.setItem(row, column, item)

    def show_heard(self, nodes: list[HeardNode]) -> None:
        """The monitor's news: NMT state, heartbeat age, last EMCY; new and silent nodes."""
        rows = {e.device_id: row for row, e in enumerate(self.entries)}
        rows |= {f"can:{n}": len(self.entries) + i for i, n in enumerate(self._extra)}
        for node in nodes:
            row = rows.get(node.device_id)
            if row is None:
                row = self._add_new_node(node.node_id)
            self._show(row, node)

    def taken(self) -> set[int]:
        """Node IDs that answered the search or were heard since."""
        ids = {int(e.device_id.removeprefix("can:")) for e in self.entries}
        return ids | set(self._extra)

    def _add_new_node(self, node_id: int) -> int:
        self._extra.append(node_id)
        table = self.widget
        row = table.rowCount()
        table.insertRow(row)
        valve = self.watched
        if valve is None:
            told = QCoreApplication.translate(
                "CanBusDialog", "new on the bus: search again to identify it"
            )
        elif valve.device_id == f"can:{node_id}":
            told = QCoreApplication.translate("CanBusDialog", "the valve prm9tool is online with")
        else:
            told = QCoreApplication.translate("CanBusDialog", "heard on the bus")
        cells = [f"can:{node_id}", told]
        if valve is not None and valve.device_id == f"can:{node_id}":
            cells = [valve.device_id, valve.type_key, str(valve.serial), valve.firmware]
            cells += ["", "", "", told]
        for column in range(table.columnCount()):
            item = QTableWidgetItem(cells[column] if column < len(cells) else "")
            item.setFlags(item.flags() & ~Qt.ItemFlag.ItemIsSelectable)
            table.setItem(row, column, item)
        return row

    def _show(self, row: int, node: HeardNode) -> None:
        state, age = node.nmt_state or "", node.heartbeat_age_s
        booted = node.boot_up_age_s
        if booted is not None and booted < BOOT_SHOWN_S:
            state = QCoreApplication.translate(
                "CanBusDialog", "{0} (boot-up {1:.1f} s ago)"
            ).format(state, booted)
        if node.silent:
            beat = QCoreApplication.translate("CanBusDialog", "silent for {0:.1f} s").format(age)
        else:
            beat = _age(age)
        role = QPalette.ColorRole.PlaceholderText if node.silent else QPalette.ColorRole.Text
        table = self.widget
        for column, text in (
            (NMT_COLUMN, state),
            (HEARTBEAT_COLUMN, beat),
            (EMCY_COLUMN, node.last_emcy),
        ):
            item = table.item(row, column)
            if item is not None:
                item.setText(text)
        for column in range(table.columnCount()):
            item = table.item(row, column)
            if item is not None:
                item.setForeground(QBrush(table.palette().color(role)))


def _age(age: float | None) -> str:
    return (
        QCoreApplication.translate("CanBusDialog", "{0:.1f} s ago").format(age)
        if age is not None
        else QCoreApplication.translate("CanBusDialog", "none")
    )


def _verdict(entry: ValveListing) -> str:
    """``not a PRM9`` for another kind of device, ``not identified`` for a node that did not
    answer, answered what no PRM9 holds or shares its node ID (as --list-devices)."""
    node = entry.can
    if node is not None and (node.device_type is None or node.detail):
        return QCoreApplication.translate("CanBusDialog", "not identified")
    return QCoreApplication.translate("CanBusDialog", "not a PRM9")

"""View → Object dictionary: every object of the connected valve's dictionary, from the
catalogue (index, sub-index, name, type, access, raw value); read all, and at Expert level write
any writable object (double-click). Over any link; over CANopen the objects a valve lacks show
"not available over CANopen on this valve". A search line filters the rows (index, name, type,
value: any column) through a QSortFilterProxyModel over the objects' model."""

from __future__ import annotations

from PySide6.QtCore import QModelIndex, QSortFilterProxyModel, Qt
from PySide6.QtGui import QStandardItem, QStandardItemModel
from PySide6.QtWidgets import (
    QAbstractItemView,
    QDialog,
    QHBoxLayout,
    QHeaderView,
    QInputDialog,
    QLabel,
    QLineEdit,
    QPushButton,
    QTableView,
    QVBoxLayout,
    QWidget,
)

from prm9tool.catalogue import CATALOGUE, Access, DataType, Parameter
from prm9tool.catalogue.variant import Variant
from prm9tool.errors import AbortCode, Prm9Error, SdoAbortError
from prm9tool.i18n import text
from prm9tool.model.access import AccessModel
from prm9tool.online.connection import ValveConnection
from prm9tool.translate import error_text
from prm9tool.views.help_dialog import add_context_help

READ_ALL = "od_read_all"
COLUMNS = 6


class ObjectDictionaryDialog(QDialog):
    """The object-dictionary browser of the connected valve."""

    def __init__(
        self,
        connection: ValveConnection,
        access: AccessModel,
        variant: Variant,
        parent: QWidget | None = None,
    ) -> None:
        super().__init__(parent)
        self.setWindowTitle(self.tr("Object dictionary"))
        add_context_help(self, "can")  # F1
        self._connection, self._access = connection, access
        self._params: list[Parameter] = sorted(CATALOGUE.for_variant(variant), key=lambda p: p.key)
        self.model = QStandardItemModel(len(self._params), COLUMNS, self)
        self.model.setHorizontalHeaderLabels(
            [self.tr("Index"), self.tr("Sub"), self.tr("Name"), self.tr("Type"),
             self.tr("Access"), self.tr("Value")]
        )  # fmt: skip
        self.proxy = QSortFilterProxyModel(self)
        self.proxy.setSourceModel(self.model)
        self.proxy.setFilterKeyColumn(-1)  # a match in any column keeps the row
        self.proxy.setFilterCaseSensitivity(Qt.CaseSensitivity.CaseInsensitive)
        self.search = QLineEdit()
        self.search.setClearButtonEnabled(True)
        self.search.setPlaceholderText(self.tr("Search: index, name, type or value"))
        self.search.textChanged.connect(self.proxy.setFilterFixedString)
        self.table = QTableView()
        self.table.setModel(self.proxy)
        self.table.verticalHeader().hide()
        self.table.setEditTriggers(QAbstractItemView.EditTrigger.NoEditTriggers)
        self.table.setSelectionBehavior(QAbstractItemView.SelectionBehavior.SelectRows)
        header = self.table.horizontalHeader()
        header.setSectionResizeMode(QHeaderView.ResizeMode.ResizeToContents)
        header.setSectionResizeMode(5, QHeaderView.ResizeMode.Stretch)
        self.table.setWordWrap(False)
        for row, param in enumerate(self._params):
            cells = [f"0x{param.index:04X}", str(param.subindex), text(param.text),
                     param.dtype.name, param.obj_access.value, ""]  # fmt: skip
            for column, cell in enumerate(cells):
                item = QStandardItem(cell)
                item.setEditable(False)
                self.model.setItem(row, column, item)
        self.table.doubleClicked.connect(self._on_table_double_clicked_at)
        self.read = QPushButton(self.tr("Read all"))
        self.read.clicked.connect(self.read_all)
        self.note = QLabel()
        self.note.setWordWrap(True)
        buttons = QHBoxLayout()
        buttons.addWidget(self.read)
        buttons.addWidget(self.search, 1)
        buttons.addWidget(self.note, 1)
        layout = QVBoxLayout(self)
        layout.addLayout(buttons)
        layout.addWidget(self.table)
        self.resize(980, 560)
        connection.operation_finished.connect(self._on_connection_operation_finished)
        self._show_level()

    def read_all(self) -> None:
        """Read every object (in the connection's worker)."""
        self.read.setEnabled(False)
        self._connection.read_each([p.mnemonic for p in self._params], READ_ALL)

    def _show_level(self) -> None:
        expert = self._access.level is Access.EXPERT
        self.note.setText(
            self.tr("Double-click a writable object to write it.")
            if expert
            else self.tr("Reading only: writing needs the Expert level.")
        )

    def _on_connection_operation_finished(self, name: str, result: object) -> None:
        if name != READ_ALL or not isinstance(result, dict):
            return
        self.read.setEnabled(True)
        for row, param in enumerate(self._params):
            if param.mnemonic in result:
                shown = self._shown(param, result[param.mnemonic])
                self._value_cell(row).setText(shown)
                self._value_cell(row).setToolTip(shown)

    def _value_cell(self, row: int) -> QStandardItem:
        item = self.model.item(row, 5)
        assert item is not None  # every cell is filled in __init__
        return item

    def _on_table_double_clicked_at(self, index: QModelIndex) -> None:
        source = self.proxy.mapToSource(index)
        self._on_table_double_clicked(source.row(), source.column())

    def _shown(self, param: Parameter, value: object) -> str:
        if isinstance(value, SdoAbortError) and value.code == AbortCode.NO_DATA:
            return self.tr("— (no entry)")  # e.g. 0x1003/n beyond the number of errors
        if isinstance(value, Exception):
            return error_text(value)
        if isinstance(value, int) and param.dtype is DataType.UNSIGNED32:
            return f"0x{value:X}"
        return str(value)

    def _on_table_double_clicked(self, row: int, _column: int) -> None:
        param = self._params[row]
        if self._access.level is not Access.EXPERT or not param.writable:
            return
        entry, ok = QInputDialog.getText(
            self,
            self.tr("Write {0}").format(f"0x{param.index:04X}/{param.subindex}"),
            self.tr("{0} ({1}), raw value:").format(text(param.text), param.dtype.name),
            text=self._value_cell(row).text(),
        )
        if not ok:
            return
        try:
            raw: int | str = entry if param.is_string else _raw(entry)
            param.check_raw(raw)
        except (Prm9Error, ValueError) as exc:
            self.note.setText(error_text(exc) if isinstance(exc, Prm9Error) else str(exc))
            return
        self._connection.write(param.mnemonic, raw)
        self.read_all()


def _raw(entry: str) -> int:
    """A raw number as typed: decimal or 0x hexadecimal."""
    return int(entry.strip(), 0)

"""The parameter list view (manual figure 8-18): search, "modified only", table, edit dialog."""

from __future__ import annotations

from PySide6.QtCore import QEvent, QModelIndex, QSortFilterProxyModel, Qt, Signal
from PySide6.QtWidgets import (
    QAbstractItemView,
    QCheckBox,
    QHBoxLayout,
    QHeaderView,
    QLineEdit,
    QTableView,
    QVBoxLayout,
    QWidget,
)

from prm9tool.model.access import AccessModel
from prm9tool.model.document import ParameterDocument
from prm9tool.views.parameters.dialog import ParameterEditDialog
from prm9tool.views.parameters.model import (
    MNEMONIC_ROLE,
    Column,
    ParameterFilterProxy,
    ParameterTableModel,
)


class _ListTable(QTableView):
    """The list's table: a column sized to its contents keeps the width it had with every
    row shown, so a search that leaves few rows or none no longer collapses the columns to
    their headers (issue 34 item 20)."""

    def __init__(self) -> None:
        super().__init__()
        self._all_rows: dict[int, int] = {}  # column -> its width the last time all rows showed

    def sizeHintForColumn(self, column: int) -> int:
        """The widest shown row's width, at least the width with every row."""
        hint = super().sizeHintForColumn(column)
        proxy = self.model()
        source = proxy.sourceModel() if isinstance(proxy, QSortFilterProxyModel) else None
        if source is None or proxy.rowCount() >= source.rowCount():
            self._all_rows[column] = hint
            return hint
        return max(hint, self._all_rows.get(column, 0))


class ParameterListView(QWidget):
    """Table of every parameter of the variant at the current access level."""

    edit_requested = Signal(str)  # mnemonic whose edit dialog is about to open
    message_posted = Signal(str)  # for the status bar: a typed value was rounded

    def __init__(
        self, doc: ParameterDocument, access: AccessModel, parent: QWidget | None = None
    ) -> None:
        super().__init__(parent)
        self._doc = doc
        self._access = access
        self._dialog: ParameterEditDialog | None = None  # the edit dialog open, if any
        self.model = ParameterTableModel(doc, access, self)
        self.proxy = ParameterFilterProxy(self)
        self.proxy.setSourceModel(self.model)
        self.search = QLineEdit()
        self.search.setClearButtonEnabled(True)
        self.search.textChanged.connect(self.proxy.set_search)
        self.modified_only = QCheckBox()
        self.modified_only.toggled.connect(self.proxy.set_non_default_only)
        self.table = self._make_table()
        self._build_layout()
        self.retranslate()

    def _make_table(self) -> QTableView:
        table = _ListTable()
        table.setModel(self.proxy)
        table.setSelectionBehavior(QAbstractItemView.SelectionBehavior.SelectRows)
        table.setSelectionMode(QAbstractItemView.SelectionMode.SingleSelection)
        table.setEditTriggers(QAbstractItemView.EditTrigger.NoEditTriggers)
        table.setAlternatingRowColors(True)
        table.setWordWrap(False)
        header = table.horizontalHeader()
        header.setSectionResizeMode(Column.MNEMONIC, QHeaderView.ResizeMode.ResizeToContents)
        header.setSectionResizeMode(Column.DESCRIPTION, QHeaderView.ResizeMode.Stretch)
        header.setSectionResizeMode(Column.VALUE, QHeaderView.ResizeMode.ResizeToContents)
        header.setSectionResizeMode(Column.UNIT, QHeaderView.ResizeMode.ResizeToContents)
        table.verticalHeader().setDefaultSectionSize(table.fontMetrics().height() + 8)
        # activated alone: Qt emits it after doubleClicked on a double-click (or on one click
        # where the platform activates items so) and on Enter; both meant two dialogs.
        table.activated.connect(self._on_table_activated)
        return table

    def _build_layout(self) -> None:
        bar = QHBoxLayout()
        bar.addWidget(self.search, 1)
        bar.addWidget(self.modified_only)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(4, 4, 4, 4)
        layout.addLayout(bar)
        layout.addWidget(self.table)

    def retranslate(self) -> None:
        """Set every text in the current language (parameter texts come from the catalogue)."""
        self.search.setPlaceholderText(self.tr("Search mnemonic or description…"))
        self.modified_only.setText(self.tr("Modified only"))
        self.modified_only.setToolTip(
            self.tr("Show only the values that differ from the factory defaults")
        )
        self.model.refresh()

    def changeEvent(self, event: QEvent) -> None:
        """Retranslate when the program language changes."""
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate()
        super().changeEvent(event)

    def _on_table_activated(self, index: QModelIndex) -> None:
        mnemonic = self.proxy.data(index, MNEMONIC_ROLE)
        if mnemonic:
            self.edit_parameter(str(mnemonic))

    def make_edit_dialog(self, mnemonic: str) -> ParameterEditDialog:
        """The edit dialog for ``mnemonic`` (not yet shown)."""
        dialog = ParameterEditDialog(self._doc, self._access, mnemonic, self)
        dialog.value_rounded.connect(self.message_posted)
        return dialog

    def edit_parameter(self, mnemonic: str) -> None:
        """Open the edit dialog for ``mnemonic`` (window-modal; one at a time)."""
        if self._dialog is not None and self._dialog.isVisible():
            self._dialog.raise_()  # a second dialog would show a value that may be stale
            return
        self.edit_requested.emit(mnemonic)
        dialog = self.make_edit_dialog(mnemonic)
        dialog.setAttribute(Qt.WidgetAttribute.WA_DeleteOnClose)
        dialog.destroyed.connect(self._on_dialog_destroyed)
        self._dialog = dialog
        dialog.open()

    def _on_dialog_destroyed(self) -> None:
        self._dialog = None

    def select(self, mnemonic: str) -> None:
        """Scroll to and select the row of ``mnemonic`` if it is shown."""
        row = self.model.row_of(mnemonic)
        if row < 0:
            return
        index = self.proxy.mapFromSource(self.model.index(row, 0))
        if index.isValid():
            self.table.selectRow(index.row())
            self.table.scrollTo(index)

"""The parameter list as a Qt item model over the document, plus the search/filter proxy.

No state lives in the model: every cell is computed from the document, the access model and
the catalogue. Rows are the parameters visible for the document's variant at the current
access level (``CATALOGUE.visible``); columns are mnemonic, description, value and unit.
"""

from __future__ import annotations

from collections.abc import Mapping
from enum import IntEnum

from PySide6.QtCore import (
    QAbstractTableModel,
    QModelIndex,
    QObject,
    QPersistentModelIndex,
    QSortFilterProxyModel,
    Qt,
)
from PySide6.QtGui import QColor, QFont, QGuiApplication, QPalette

from prm9tool import i18n
from prm9tool.catalogue import CATALOGUE, Access, Parameter
from prm9tool.catalogue.signals import MEASURED_DECIMALS
from prm9tool.i18n import current_language, text
from prm9tool.model.access import AccessModel
from prm9tool.model.document import ParameterDocument

MNEMONIC_ROLE = Qt.ItemDataRole.UserRole + 1
NON_DEFAULT_ROLE = Qt.ItemDataRole.UserRole + 2
AnyIndex = QModelIndex | QPersistentModelIndex


class Column(IntEnum):
    """Columns of the parameter list."""

    MNEMONIC = 0
    DESCRIPTION = 1
    VALUE = 2
    UNIT = 3


def format_value(doc: ParameterDocument, param: Parameter, live: bool) -> str:
    """A parameter's value as the list shows it ('—' for a live value never read)."""
    mnemonic = param.mnemonic
    if mnemonic == "PCODE" and not live:
        return str(doc.type_key)
    if mnemonic == "SNV" and not live:
        return str(doc.source_serial) if doc.source_serial else "—"
    if mnemonic == "FWVER" and not live:
        return doc.source_firmware or "—"
    if not param.in_file and not live:
        return "—"
    raw = doc.value(mnemonic)
    if mnemonic == "ERROR" and isinstance(raw, int):
        return f"0x{raw:04X}"
    if param.choices and isinstance(raw, int):
        return f"{raw}: {param.choice_text(raw, current_language())}"
    if live and not param.in_file and param.unit in MEASURED_DECIMALS and isinstance(raw, int):
        return i18n.format_measured(raw * param.scale, param.unit)  # as the diagram shows it
    return i18n.format_value(param, raw)


def is_non_default(doc: ParameterDocument, param: Parameter) -> bool:
    """True for file parameters whose value differs from the variant's factory default."""
    return param.in_file and not doc.is_default(param.mnemonic)


class ParameterTableModel(QAbstractTableModel):
    """Rows = parameters visible for the document's variant and the access level."""

    def __init__(
        self, doc: ParameterDocument, access: AccessModel, parent: QObject | None = None
    ) -> None:
        super().__init__(parent)
        self._doc = doc
        self._access = access
        self._params: list[Parameter] = []
        self._rows: dict[str, int] = {}
        self._live_seen: set[str] = set()
        doc.value_changed.connect(self._on_document_value_changed)
        doc.values_reset.connect(self._on_document_values_reset)
        doc.type_key_changed.connect(self.refresh)
        doc.source_changed.connect(self._on_document_source_changed)
        access.level_changed.connect(self.refresh)
        self.refresh()

    # --- structure ----------------------------------------------------------------------
    def refresh(self, *_args: object) -> None:
        """Rebuild the rows (variant, access level or language changed)."""
        self.beginResetModel()
        self._params = CATALOGUE.visible(self._doc.variant, self._access.level)
        self._rows = {p.mnemonic: row for row, p in enumerate(self._params)}
        self.endResetModel()

    def forget_live_values(self) -> None:
        """Show live values as unknown again (offline they would be stale)."""
        self._live_seen.clear()
        self._emit_all_values()

    def show_live(self, values: Mapping[str, object]) -> None:
        """Show the live values just read (connected to the connection's live values): the
        document signals only values that changed, so a valve read again after going offline
        and online, with the same supply voltage as before, would stay '—' without this."""
        for mnemonic in values:
            if mnemonic not in self._live_seen:
                self._live_seen.add(mnemonic)
                row = self._rows.get(mnemonic)
                if row is not None:
                    self.dataChanged.emit(self.index(row, 0), self.index(row, len(Column) - 1))

    def parameter(self, row: int) -> Parameter:
        """The parameter shown in ``row``."""
        return self._params[row]

    def row_of(self, mnemonic: str) -> int:
        """Row of ``mnemonic``, or -1 if it is not shown."""
        return self._rows.get(mnemonic, -1)

    def rowCount(self, parent: AnyIndex = QModelIndex()) -> int:  # noqa: B008
        """Number of visible parameters."""
        return 0 if parent.isValid() else len(self._params)

    def columnCount(self, parent: AnyIndex = QModelIndex()) -> int:  # noqa: B008
        """Mnemonic, description, value, unit."""
        return 0 if parent.isValid() else len(Column)

    def headerData(
        self, section: int, orientation: Qt.Orientation, role: int = Qt.ItemDataRole.DisplayRole
    ) -> object:
        """Translated column titles; row numbers as in the manual's figure 8-18."""
        if role != Qt.ItemDataRole.DisplayRole:
            return None
        if orientation == Qt.Orientation.Vertical:
            return str(section + 1)
        titles = {
            Column.MNEMONIC: self.tr("Mnemonic"),
            Column.DESCRIPTION: self.tr("Description"),
            Column.VALUE: self.tr("Value"),
            Column.UNIT: self.tr("Unit"),
        }
        return titles.get(Column(section))

    # --- cells ----------------------------------------------------------------------------
    def data(self, index: AnyIndex, role: int = Qt.ItemDataRole.DisplayRole) -> object:
        """Cell contents, tooltips and highlighting."""
        if not index.isValid():
            return None
        param = self._params[index.row()]
        column = Column(index.column())
        if role == Qt.ItemDataRole.DisplayRole:
            return self._display(param, column)
        if role == MNEMONIC_ROLE:
            return param.mnemonic
        if role == NON_DEFAULT_ROLE:
            return is_non_default(self._doc, param)
        if role == Qt.ItemDataRole.ToolTipRole:
            return self._tooltip(param)
        if role == Qt.ItemDataRole.FontRole and is_non_default(self._doc, param):
            font = QFont()
            font.setBold(True)
            return font
        if role == Qt.ItemDataRole.BackgroundRole and is_non_default(self._doc, param):
            return _highlight_colour()
        if role == Qt.ItemDataRole.ForegroundRole and not self._access.may_edit(param):
            return QGuiApplication.palette().color(
                QPalette.ColorGroup.Disabled, QPalette.ColorRole.Text
            )
        if role == Qt.ItemDataRole.TextAlignmentRole and column is Column.VALUE:
            return int(Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter)
        return None

    def _display(self, param: Parameter, column: Column) -> str:
        if column is Column.MNEMONIC:
            return param.mnemonic
        if column is Column.DESCRIPTION:
            return text(param.text)
        if column is Column.VALUE:
            return format_value(self._doc, param, param.mnemonic in self._live_seen)
        return param.unit

    def _tooltip(self, param: Parameter) -> str:
        lines = [f"{param.mnemonic} ({param.address}): {text(param.text)}"]
        if param.help is not None:
            lines.append(text(param.help))
        if param.in_file and not param.is_string:
            lo, hi = (
                i18n.format_value(param, param.raw_min),
                i18n.format_value(param, param.raw_max),
            )
            default = i18n.format_value(param, param.default_for(self._doc.variant))
            lines.append(self.tr("Range: {0} … {1} {2}").format(lo, hi, param.unit).rstrip())
            lines.append(self.tr("Factory default: {0} {1}").format(default, param.unit).rstrip())
        locked = self._lock_reason(param)
        if locked:
            lines.append(locked)
        return "\n".join(lines)

    def _lock_reason(self, param: Parameter) -> str:
        if param.access is Access.READ_ONLY or not param.writable:
            return self.tr("Read-only value of the valve.")
        if not self._access.may_edit(param):
            return self.tr("Can only be changed at Expert access level.")
        return ""

    def lock_reason(self, param: Parameter) -> str:
        """Translated reason why ``param`` cannot be edited ('' if it can)."""
        return self._lock_reason(param)

    # --- document signals -----------------------------------------------------------------
    def _on_document_value_changed(self, mnemonic: str) -> None:
        param = CATALOGUE.get(mnemonic)
        if param is not None and not param.in_file:
            self._live_seen.add(mnemonic)
        row = self._rows.get(mnemonic)
        if row is not None:
            self.dataChanged.emit(self.index(row, 0), self.index(row, len(Column) - 1))

    def _on_document_source_changed(self) -> None:
        for mnemonic in ("SNV", "FWVER"):
            row = self._rows.get(mnemonic)
            if row is not None:
                self.dataChanged.emit(self.index(row, 0), self.index(row, len(Column) - 1))

    def _on_document_values_reset(self) -> None:
        self._emit_all_values()

    def _emit_all_values(self) -> None:
        if self._params:
            last = self.index(len(self._params) - 1, len(Column) - 1)
            self.dataChanged.emit(self.index(0, 0), last)


def _highlight_colour() -> QColor:
    """A soft tint of the palette's highlight colour (readable on light and dark palettes)."""
    colour = QColor(QGuiApplication.palette().color(QPalette.ColorRole.Highlight))
    colour.setAlpha(70)
    return colour


class ParameterFilterProxy(QSortFilterProxyModel):
    """Search in mnemonic and description; optionally only values changed from the default."""

    def __init__(self, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self._search = ""
        self._non_default_only = False

    def set_search(self, search: str) -> None:
        """Show rows whose mnemonic or description contains ``search`` (case-insensitive)."""
        self.beginFilterChange()
        self._search = search.strip().casefold()
        self.endFilterChange(QSortFilterProxyModel.Direction.Rows)

    def set_non_default_only(self, enabled: bool) -> None:
        """Show only values that differ from the factory defaults."""
        self.beginFilterChange()
        self._non_default_only = enabled
        self.endFilterChange(QSortFilterProxyModel.Direction.Rows)

    def filterAcceptsRow(self, source_row: int, source_parent: AnyIndex) -> bool:
        """Apply the search text and the "modified only" switch."""
        model = self.sourceModel()
        if self._non_default_only:
            index = model.index(source_row, Column.MNEMONIC, source_parent)
            if not model.data(index, NON_DEFAULT_ROLE):
                return False
        if not self._search:
            return True
        for column in (Column.MNEMONIC, Column.DESCRIPTION):
            cell = model.data(model.index(source_row, column, source_parent))
            if self._search in str(cell).casefold():
                return True
        return False

"""The compare view: two parameter sets side by side (and the factory defaults), a choice per
parameter, filters, and apply to the document or to the valve.

The table is a :class:`CompareTableModel` over a :class:`~prm9tool.compare.model.Comparison`;
a value cell is checkable: checking it chooses that side's value for the row. The dialog
does not apply anything itself: it reports the target and the values (``applied``), and the
caller writes them (one undo step in the document, a transactional upload to the valve).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

from PySide6.QtCore import (
    QAbstractTableModel,
    QCoreApplication,
    QModelIndex,
    QPersistentModelIndex,
    QSize,
    Qt,
)
from PySide6.QtGui import QFont
from PySide6.QtWidgets import (
    QCheckBox,
    QComboBox,
    QDialog,
    QHBoxLayout,
    QHeaderView,
    QLabel,
    QPushButton,
    QTableView,
    QVBoxLayout,
    QWidget,
)

from prm9tool.catalogue import Access
from prm9tool.compare.model import Comparison, Row
from prm9tool.i18n import format_shown, text
from prm9tool.translate import translated
from prm9tool.views.diagram.layout import layout_for
from prm9tool.views.help_dialog import add_context_help
from prm9tool.views.icons import icon

Index = QModelIndex | QPersistentModelIndex
FIRST_VALUE = 2  # columns: mnemonic, description, side 0, side 1[, reference]
BOTH = -1  # target: each side takes the values chosen from the other (going online)
DOCUMENT, VALVE = "document", "valve"  # what a side is; or a target outside the comparison
Target = int | str  # a side, BOTH, or DOCUMENT / VALVE outside the comparison


class CompareTableModel(QAbstractTableModel):
    """The rows the filters keep; value cells show display units and carry the choice."""

    def __init__(self, comparison: Comparison, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.comparison = comparison
        self.rows: list[Row] = list(comparison.rows)

    def set_rows(self, rows: Sequence[Row]) -> None:
        """Show these rows (the filtered ones)."""
        self.beginResetModel()
        self.rows = list(rows)
        self.endResetModel()

    def rowCount(self, parent: Index = QModelIndex()) -> int:  # noqa: B008
        return 0 if parent.isValid() else len(self.rows)

    def columnCount(self, parent: Index = QModelIndex()) -> int:  # noqa: B008
        return 0 if parent.isValid() else FIRST_VALUE + 2 + (self.comparison.reference is not None)

    def headerData(self, section: int, orientation: Qt.Orientation, role: int = 0) -> Any:
        if orientation != Qt.Orientation.Horizontal or role != Qt.ItemDataRole.DisplayRole:
            return None
        if section < FIRST_VALUE:
            return [self.tr("Mnemonic"), self.tr("Description")][section]
        side = section - FIRST_VALUE
        entry = [*self.comparison.sides, self.comparison.reference][side]
        return entry.label if entry is not None else ""

    def _side(self, column: int) -> int:
        side = column - FIRST_VALUE
        return -1 if side == 2 else side

    def data(self, index: Index, role: int = 0) -> Any:
        row, column = self.rows[index.row()], index.column()
        if role == Qt.ItemDataRole.DisplayRole:
            if column == 0:
                return row.mnemonic
            if column == 1:
                return text(row.parameter.text)
            side = self._side(column)
            raw = row.reference if side < 0 else row.values[side]
            if raw is None and side >= 0 and row.absent[side]:
                return translated(self.comparison.sides[side].absent)
            if raw is None:
                return "—"
            return format_shown(row.parameter, raw)  # a choice with its meaning, as the list
        chosen = self.comparison.choices.get(row.mnemonic)
        side = self._side(column)
        if role == Qt.ItemDataRole.CheckStateRole and column >= FIRST_VALUE and side >= 0:
            if not row.comparable:  # missing on a side, or not on the valve: nothing to choose
                return None
            return Qt.CheckState.Checked if chosen == side else Qt.CheckState.Unchecked
        if role == Qt.ItemDataRole.FontRole and row.differs and column >= FIRST_VALUE:
            font = QFont()
            font.setBold(side >= 0)
            return font
        if role == Qt.ItemDataRole.ToolTipRole and row.missing:
            return self.tr("One side's valve type has no such parameter; it cannot be chosen.")
        if role == Qt.ItemDataRole.ToolTipRole and row.not_on_valve:
            return self.tr(
                "The valve type has this parameter, but the valve does not (a valve over CANopen"
                " without this object): not compared, not a difference; it cannot be chosen."
            )
        return None

    def flags(self, index: Index) -> Qt.ItemFlag:
        flags = Qt.ItemFlag.ItemIsEnabled | Qt.ItemFlag.ItemIsSelectable
        row = self.rows[index.row()]
        if index.column() >= FIRST_VALUE and self._side(index.column()) >= 0 and row.changed:
            flags |= Qt.ItemFlag.ItemIsUserCheckable
        return flags

    def setData(self, index: Index, value: Any, role: int = 0) -> bool:
        if (
            role != Qt.ItemDataRole.CheckStateRole
            or not self.flags(index) & Qt.ItemFlag.ItemIsUserCheckable
        ):
            return False
        row = self.rows[index.row()]
        checked = Qt.CheckState(value) == Qt.CheckState.Checked
        self.comparison.choose(row.mnemonic, self._side(index.column()) if checked else None)
        self.dataChanged.emit(
            self.index(index.row(), FIRST_VALUE), self.index(index.row(), FIRST_VALUE + 1)
        )
        return True

    def choose_all(self, side: int) -> None:
        """Choose ``side`` for every changed row shown."""
        self.comparison.choose_all(side, self.rows)
        if self.rows:
            self.dataChanged.emit(
                self.index(0, 0), self.index(len(self.rows) - 1, self.columnCount() - 1)
            )


class CompareDialog(QDialog):
    """Compare two sides, choose per parameter, apply to one of the ``targets`` sides.

    ``roles`` names what a side is (:data:`DOCUMENT`, :data:`VALVE`), so that its apply
    button says what it does ("Write 2 ticked values into Valve 4711"). ``destinations`` are
    targets outside the comparison (two history records: the document, the valve), which take
    every ticked value. After ``exec()``, ``applied`` is ``(target, {mnemonic: raw})`` or None.
    """

    def __init__(
        self,
        comparison: Comparison,
        targets: Sequence[int] = (0, 1),
        access: Access = Access.EXPERT,
        parent: QWidget | None = None,
        roles: Mapping[int, str] | None = None,
        destinations: Sequence[str] = (),
    ) -> None:
        super().__init__(parent)
        self.comparison = comparison
        self.roles = dict(roles or {})
        self.applied: tuple[Target, dict[str, int | str]] | None = None
        self.setWindowTitle(self.tr("Compare parameters"))
        add_context_help(self, "compare")  # F1
        self.summary = QLabel()
        self.summary.setWordWrap(True)
        self.model = CompareTableModel(comparison, self)
        self.table = QTableView(self)
        self.table.setModel(self.model)
        self.table.verticalHeader().hide()
        header = self.table.horizontalHeader()
        header.setSectionResizeMode(QHeaderView.ResizeMode.ResizeToContents)
        header.setSectionResizeMode(1, QHeaderView.ResizeMode.Stretch)
        self.hint = QLabel(self._hint(targets, destinations))
        self.hint.setObjectName("compare_hint")
        self.hint.setWordWrap(True)
        layout = QVBoxLayout(self)
        layout.addWidget(self.summary)
        layout.addLayout(self._filters(access))
        layout.addWidget(self.hint)
        layout.addWidget(self.table)
        layout.addLayout(self._choice_buttons())
        layout.addLayout(self._apply_bar([*targets, *destinations]))
        self.model.dataChanged.connect(lambda *_args: self._update_summary())
        self._refilter()
        self.resize(900, 560)

    # --- building -------------------------------------------------------------------------
    def _filters(self, access: Access) -> QHBoxLayout:
        row = QHBoxLayout()
        self.differences_only = QCheckBox(self.tr("Differences only"))
        self.differences_only.setChecked(True)
        self.block = QComboBox()
        self.block.addItem(self.tr("All blocks"), None)
        variant = self.comparison.sides[1].type_key.variant
        for spec in layout_for(variant).blocks:
            if spec.mnemonics:
                title = QCoreApplication.translate("DiagramBlock", spec.title)
                self.block.addItem(title.replace("\n", " "), list(spec.mnemonics))
        self.level = QComboBox()
        self.level.addItem(self.tr("Basic level"), Access.BASIC)
        self.level.addItem(self.tr("Expert level"), Access.EXPERT)
        self.level.setCurrentIndex(0 if access is Access.BASIC else 1)
        for label, widget in ((None, self.differences_only), (self.tr("Block:"), self.block),
                              (self.tr("Access level:"), self.level)):  # fmt: skip
            if label:
                row.addWidget(QLabel(label))
            row.addWidget(widget)
        row.addStretch(1)
        self.differences_only.toggled.connect(self._refilter)
        self.block.currentIndexChanged.connect(self._refilter)
        self.level.currentIndexChanged.connect(self._refilter)
        return row

    def _choice_buttons(self) -> QHBoxLayout:
        row = QHBoxLayout()
        for side, source in enumerate(self.comparison.sides):
            button = QPushButton(self.tr("Tick every shown value of {0}").format(source.label))
            button.clicked.connect(lambda _c=False, s=side: self._choose_all(s))
            row.addWidget(button)
        row.addStretch(1)
        return row

    def _apply_bar(self, targets: Sequence[Target]) -> QHBoxLayout:
        """The apply buttons, large, with the icon of where the values go; then Close."""
        row = QHBoxLayout()
        self.apply_buttons: dict[Target, QPushButton] = {}
        for target in targets:
            button = QPushButton(icon(self._icon_name(target)), "")
            button.setObjectName(f"apply_{target}")
            button.setIconSize(QSize(24, 24))
            button.setMinimumHeight(36)
            button.clicked.connect(lambda _c=False, t=target: self._apply(t))
            row.addWidget(button)
            self.apply_buttons[target] = button
        row.addStretch(1)
        close = QPushButton(self.tr("Close"))
        close.clicked.connect(self.reject)
        row.addWidget(close)
        return row

    def _role(self, target: Target) -> str | None:
        return target if isinstance(target, str) else self.roles.get(target)

    def _icon_name(self, target: Target) -> str:
        return {VALVE: "upload", DOCUMENT: "parameters"}.get(self._role(target) or "", "")

    def _hint(self, targets: Sequence[int], destinations: Sequence[str]) -> str:
        """How to put values back, in one or two sentences above the table."""
        labels = [side.label for side in self.comparison.sides]
        if BOTH in targets:
            return self.tr(
                "Every row starts with the valve's value ticked. Tick the document's value "
                "where the document is right, then press Apply: the document takes the ticked "
                "valve values and the valve the ticked document values."
            )
        lines = []
        for target in targets:
            source, role = labels[1 - target], self._role(target)
            if role == VALVE:
                line = self.tr("To write values into the valve: tick them in the column “{0}”, "
                               "then press the button below.").format(source)  # fmt: skip
            elif role == DOCUMENT:
                line = self.tr("To take values into the document: tick them in the column "
                               "“{0}”, then press the button below.").format(source)  # fmt: skip
            else:
                line = self.tr("To copy values into “{0}”: tick them in the column “{1}”, "
                               "then press the button below.").format(labels[target], source)  # fmt: skip
            lines.append(line)
        if destinations:
            lines.append(
                self.tr(
                    "Tick the values to take, in either column; then take them into the "
                    "document, or write them into the valve (online with this valve)."
                )
            )
        return "\n".join(lines) or self.tr("Shown for comparison only.")

    # --- behaviour ------------------------------------------------------------------------
    def _refilter(self) -> None:
        rows = self.comparison.filtered(
            self.differences_only.isChecked(), self.block.currentData(), self.level.currentData()
        )
        self.model.set_rows(rows)
        self._update_summary()

    def _choose_all(self, side: int) -> None:
        self.model.choose_all(side)
        self._update_summary()

    def _update_summary(self) -> None:
        c = self.comparison
        parts = [
            self.tr("%n parameter(s) differ", "", len(c.changed)),
            self.tr("%n parameter(s) only on one side", "", len(c.missing)),
        ]
        if c.not_on_valve:  # two files have no valve: "0 … not on the valve" said nothing
            parts.append(
                self.tr("%n parameter(s) not on the valve, not compared", "", len(c.not_on_valve))
            )
        parts.append(self.tr("%n shown", "", self.model.rowCount()))
        lines = [", ".join(parts)]
        lines += [translated(warning) for warning in c.warnings()]
        self.summary.setText("\n".join(lines))
        for target, button in getattr(self, "apply_buttons", {}).items():
            self._update_apply_button(target, button)

    def _update_apply_button(self, target: Target, button: QPushButton) -> None:
        c = self.comparison
        if target == BOTH:  # every difference needs a choice, then both sides agree
            button.setText(self.tr("Apply: each side takes the ticked values"))
            button.setEnabled(all(row.mnemonic in c.choices for row in c.changed))
            return
        count = len(self._values_for(target))
        role = self._role(target)
        label = "" if isinstance(target, str) else c.sides[target].label
        if role == VALVE:
            text = self.tr("Write %n ticked value(s) into the valve", "", count)
        elif role == DOCUMENT:
            text = self.tr("Take %n ticked value(s) into the document", "", count)
        else:
            text = self.tr("Copy %n ticked value(s) into “{0}”", "", count)
        button.setText(text.format(label))
        button.setEnabled(count > 0)
        source = "" if isinstance(target, str) else c.sides[1 - target].label
        button.setToolTip(
            ""
            if count or not source
            else self.tr("Tick values in the column “{0}” first").format(source)
        )

    def _values_for(self, target: Target) -> dict[str, int | str]:
        if isinstance(target, str):
            return self.comparison.chosen()
        return {} if target == BOTH else self.comparison.to_apply(target)

    def _apply(self, target: Target) -> None:
        self.applied = (target, self._values_for(target))
        self.accept()

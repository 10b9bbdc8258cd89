"""Dialogs of the online workflow: document/valve differences, and the restart confirmation."""

from __future__ import annotations

from collections.abc import Mapping
from enum import Enum

from PySide6.QtWidgets import (
    QAbstractItemView,
    QCheckBox,
    QDialog,
    QDialogButtonBox,
    QHeaderView,
    QLabel,
    QPushButton,
    QTableWidget,
    QTableWidgetItem,
    QVBoxLayout,
    QWidget,
)

from prm9tool.catalogue import CATALOGUE
from prm9tool.i18n import format_shown, text

Raw = int | str


class DiffChoice(Enum):
    """What to do when document and valve differ on going online."""

    TAKE_VALVE = "take_valve"
    SEND_DOCUMENT = "send_document"
    CHOOSE = "choose"  # per parameter, in the compare view
    CANCEL = "cancel"


def _cell(mnemonic: str, raw: Raw | None) -> str:
    if raw is None:
        return "—"
    return format_shown(CATALOGUE[mnemonic], raw)  # a choice with its meaning, as the list


class OnlineDiffDialog(QDialog):
    """Shows where document and valve differ; the user takes one side or cancels."""

    def __init__(
        self,
        document_values: Mapping[str, Raw],
        valve_values: Mapping[str, Raw],
        document_key: str,
        valve_key: str,
        parent: QWidget | None = None,
    ) -> None:
        super().__init__(parent)
        self.choice = DiffChoice.CANCEL
        self.setWindowTitle(self.tr("Document and valve differ"))
        same_variant = set(document_values) == set(valve_values)
        names = [
            mn
            for mn in [*document_values, *(m for m in valve_values if m not in document_values)]
            if document_values.get(mn) != valve_values.get(mn)
        ]
        self.intro = QLabel(self._intro(document_key, valve_key, len(names), same_variant))
        self.intro.setWordWrap(True)
        self.table = self._table(names, document_values, valve_values)
        buttons = QDialogButtonBox()
        self.take_button = QPushButton(self.tr("Take the valve's values"))
        self.send_button = QPushButton(self.tr("Send the document's values"))
        self.send_button.setEnabled(same_variant)
        if not same_variant:
            self.send_button.setToolTip(
                self.tr("The document is for another valve variant; it cannot be sent.")
            )
        self.choose_button = QPushButton(self.tr("Choose per parameter…"))
        self.choose_button.setEnabled(same_variant)
        buttons.addButton(self.take_button, QDialogButtonBox.ButtonRole.AcceptRole)
        buttons.addButton(self.send_button, QDialogButtonBox.ButtonRole.AcceptRole)
        buttons.addButton(self.choose_button, QDialogButtonBox.ButtonRole.AcceptRole)
        self.choose_button.clicked.connect(lambda: self._choose(DiffChoice.CHOOSE))
        buttons.addButton(QDialogButtonBox.StandardButton.Cancel)
        self.take_button.clicked.connect(lambda: self._choose(DiffChoice.TAKE_VALVE))
        self.send_button.clicked.connect(lambda: self._choose(DiffChoice.SEND_DOCUMENT))
        buttons.rejected.connect(self.reject)
        layout = QVBoxLayout(self)
        layout.addWidget(self.intro)
        layout.addWidget(self.table)
        layout.addWidget(buttons)
        self.resize(720, 420)

    def _intro(self, document_key: str, valve_key: str, count: int, same_variant: bool) -> str:
        lines = [self.tr("%n value(s) in the document differ from the valve.", "", count)]
        if document_key != valve_key:
            lines.append(
                self.tr("Document type key: {0} — valve type key: {1}").format(
                    document_key, valve_key
                )
            )
        if not same_variant:
            lines.append(self.tr("The valve is of another variant: only its values can be taken."))
        lines.append(
            self.tr("Cancel stays offline; the document is not changed and nothing is written.")
        )
        return "\n".join(lines)

    def _table(
        self, names: list[str], doc: Mapping[str, Raw], valve: Mapping[str, Raw]
    ) -> QTableWidget:
        table = QTableWidget(len(names), 4)
        table.setHorizontalHeaderLabels(
            [self.tr("Mnemonic"), self.tr("Description"), self.tr("Document"), self.tr("Valve")]
        )
        table.setEditTriggers(QAbstractItemView.EditTrigger.NoEditTriggers)
        table.verticalHeader().hide()
        for row, mn in enumerate(names):
            cells = [mn, text(CATALOGUE[mn].text), _cell(mn, doc.get(mn)), _cell(mn, valve.get(mn))]
            for column, cell in enumerate(cells):
                table.setItem(row, column, QTableWidgetItem(cell))
        header = table.horizontalHeader()
        header.setSectionResizeMode(QHeaderView.ResizeMode.ResizeToContents)
        header.setSectionResizeMode(1, QHeaderView.ResizeMode.Stretch)
        return table

    def _choose(self, choice: DiffChoice) -> None:
        self.choice = choice
        self.accept()


class RestartDialog(QDialog):
    """Restart only after the user confirms that the hydraulics are disconnected.

    With ``factory`` the restart is the one that makes the factory values effective: the
    dialog says so, and that a backup of the valve's parameters is saved first. With
    ``verify`` (what will be verified, rich text) it is Valve → Verify by restart….
    """

    def __init__(
        self, parent: QWidget | None = None, factory: bool = False, verify: str = ""
    ) -> None:
        super().__init__(parent)
        self.factory = factory
        title = self.tr("Restore factory values") if factory else self.tr("Restart valve")
        self.setWindowTitle(self.tr("Verify by restart") if verify else title)
        text = self._warning(factory)
        warning = QLabel(f"{verify}<br><br>{text}" if verify else text)
        warning.setWordWrap(True)
        self.confirm = QCheckBox(self.tr("The hydraulics are disconnected"))
        self.buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Cancel)
        button = self.tr("Restore and restart") if factory else self.tr("Restart")
        button = self.tr("Restart and verify") if verify else button
        self.restart_button = self.buttons.addButton(button, QDialogButtonBox.ButtonRole.AcceptRole)
        self.restart_button.setEnabled(False)
        self.confirm.toggled.connect(self.restart_button.setEnabled)
        self.buttons.accepted.connect(self.accept)
        self.buttons.rejected.connect(self.reject)
        layout = QVBoxLayout(self)
        layout.addWidget(warning)
        layout.addWidget(self.confirm)
        layout.addWidget(self.buttons)
        self.setMinimumWidth(440)

    def _warning(self, factory: bool) -> str:
        restart = self.tr(
            "<b>Restarting the valve electronics is only allowed with the hydraulic circuit "
            "disconnected.</b><br>During the restart the spool returns to its spring-centred "
            "position and the setpoint is ignored for a few seconds."
        )
        if not factory:
            return restart
        reset = self.tr(
            "The valve's stored parameters are reset to the factory values, which take effect "
            "after a restart of the valve. Before that, the valve's parameters are saved to a "
            "backup file (if this valve has no backup yet)."
        )
        return f"{reset}<br><br>{restart}"

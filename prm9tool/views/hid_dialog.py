"""HID configuration (manual §8.5, Communication): choose the valve to communicate with.

Lists the valves connected over USB and the emulated valves the user added (type key and
serial number). The emulated valves and the choice are remembered in QSettings.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from PySide6.QtCore import QEvent, QSettings, Qt
from PySide6.QtWidgets import (
    QAbstractItemView,
    QComboBox,
    QDialog,
    QDialogButtonBox,
    QFileDialog,
    QFormLayout,
    QHBoxLayout,
    QHeaderView,
    QLabel,
    QLineEdit,
    QPushButton,
    QSpinBox,
    QTableWidget,
    QTableWidgetItem,
    QVBoxLayout,
    QWidget,
)
from shiboken6 import isValid

from prm9tool.catalogue.typekey import DEFAULT_EMULATOR_TYPE_KEY, TypeKey
from prm9tool.online.connection_protocol import ListedValves, ValveListing
from prm9tool.online.twins import TwinChoice, spec_serial, twins_of
from prm9tool.translate import error_text
from prm9tool.views.valve.selection import ValveSelectionDialog

EMULATORS_KEY = "hid/emulators"
SELECTED_KEY = "hid/selected"
UNUSABLE = "emulator-unusable"  # the kind of a remembered emulated valve that cannot be made
DEFAULT_EMULATOR_SERIAL = 1001
DEFAULT_EMULATOR = f"{DEFAULT_EMULATOR_TYPE_KEY}:{DEFAULT_EMULATOR_SERIAL}"
# (emulator specs, deliver): lists the valves off the GUI thread — identifying a USB valve that
# does not answer takes up to 0.6 s — and calls deliver(entries or the exception) on the GUI
# thread (ValveConnection.list_devices_async)
Lister = Callable[[Sequence[str], Callable[[ListedValves], None]], None]


def saved_emulators(settings: QSettings) -> list[str]:
    """The emulated valves the user added ("TYPEKEY:SERIAL"); one default at first.

    One serial is one valve: of two entries with the same serial the later one counts (two
    used to make every listing fail, "two emulated valves with serial 1001", with no row left
    to remove)."""
    value = settings.value(EMULATORS_KEY, None)
    if value is None:
        return [DEFAULT_EMULATOR]
    if isinstance(value, str):
        specs = [value] if value else []
    elif isinstance(value, list | tuple):
        specs = [str(v) for v in value]
    else:  # e.g. a number in a hand-edited settings file
        return []
    return one_per_serial(specs)


def one_per_serial(specs: Sequence[str]) -> list[str]:
    """``specs`` ("TYPEKEY:SERIAL") without the earlier entries of a serial given again."""
    last = {spec.rpartition(":")[2]: i for i, spec in enumerate(specs)}
    return [spec for i, spec in enumerate(specs) if last[spec.rpartition(":")[2]] == i]


def describe(entry: ValveListing) -> list[str]:
    """Table cells for a device entry: kind, type key, serial, firmware, description."""
    return [entry.kind, entry.type_key, str(entry.serial), entry.firmware, entry.description]


class EmulatorDialog(QDialog):
    """Add an emulated valve: type key (the valve-selection builder) and serial number, or the
    twin of a measured valve (issue 31): one of the serial's twins in the history, or a twin
    file (docs/twin.md)."""

    def __init__(
        self,
        parent: QWidget | None = None,
        twins: Callable[[int], Sequence[TwinChoice]] | None = None,
    ) -> None:
        super().__init__(parent)
        self._twins = twins or twins_of
        self.setWindowTitle(self.tr("Add emulated valve"))
        self.selection = ValveSelectionDialog(TypeKey.parse(DEFAULT_EMULATOR_TYPE_KEY), self)
        self.selection.setWindowFlags(Qt.WindowType.Widget)
        self.selection.buttons.hide()
        self.serial = QSpinBox()
        self.serial.setRange(1, 99_999_999)
        self.serial.setValue(1002)
        self.twin = QComboBox()  # "" (no twin) or a twin file of the serial's history
        self.twin_file = QLineEdit()
        self.twin_file.setPlaceholderText(self.tr("none: the emulator's plant"))
        self.twin_file.setToolTip(
            self.tr("A twin brings its own type key, serial number and parameter set.")
        )
        self.browse = QPushButton(self.tr("Browse…"))
        self.browse.clicked.connect(self._on_browse_clicked)
        self.twin.currentIndexChanged.connect(self._on_twin_chosen)
        self.serial.valueChanged.connect(self._list_twins)
        file_row = QHBoxLayout()
        file_row.addWidget(self.twin_file, 1)
        file_row.addWidget(self.browse)
        form = QFormLayout()
        form.addRow(self.tr("Serial number:"), self.serial)
        form.addRow(self.tr("Twin from the history:"), self.twin)
        form.addRow(self.tr("Twin file:"), file_row)
        buttons = QDialogButtonBox(
            QDialogButtonBox.StandardButton.Ok | QDialogButtonBox.StandardButton.Cancel
        )
        buttons.accepted.connect(self.accept)
        buttons.rejected.connect(self.reject)
        layout = QVBoxLayout(self)
        layout.addWidget(self.selection)
        layout.addLayout(form)
        layout.addWidget(buttons)
        self._list_twins()

    def _list_twins(self) -> None:
        """The twins the history has for the serial entered (newest first)."""
        self.twin.blockSignals(True)
        self.twin.clear()
        self.twin.addItem(self.tr("none"), "")
        for choice in self._twins(self.serial.value()):
            text = self.tr("fitted {0}: {1}").format(choice.date[:10], choice.path)
            if choice.problem:
                text = self.tr("{0} (cannot be used: {1})").format(text, choice.problem)
            self.twin.addItem(text, "" if choice.problem else choice.path)
        self.twin.blockSignals(False)

    def _on_twin_chosen(self, _index: int) -> None:
        path = self.twin.currentData()
        if path:
            self.twin_file.setText(str(path))

    def _on_browse_clicked(self) -> None:
        path, _filter = QFileDialog.getOpenFileName(
            self, self.tr("Twin file"), self.twin_file.text(), self.tr("Twin files (*.toml)")
        )
        if path:
            self.twin_file.setText(path)

    def spec(self) -> str:
        """``TYPEKEY:SERIAL`` of the emulated valve, or ``twin:FILE`` for a twin (its file
        brings its type key and serial)."""
        twin = self.twin_file.text().strip()
        if twin:
            return f"twin:{twin}"
        return f"{self.selection.selected_type_key()}:{self.serial.value()}"


class HidConfigurationDialog(QDialog):
    """Lists connected and emulated valves; ``selected_entry()`` after ``accept``."""

    def __init__(self, lister: Lister, settings: QSettings, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._lister = lister
        self._settings = settings
        self._entries: list[ValveListing] = []
        self._listing = 0  # number of the newest listing asked for (older answers are stale)
        self._select_last = False  # an emulated valve was just added: select it when listed
        self.table = QTableWidget(0, 5)
        self.table.setSelectionBehavior(QAbstractItemView.SelectionBehavior.SelectRows)
        self.table.setSelectionMode(QAbstractItemView.SelectionMode.SingleSelection)
        self.table.setEditTriggers(QAbstractItemView.EditTrigger.NoEditTriggers)
        self.table.verticalHeader().hide()
        self.table.setWordWrap(False)
        header = self.table.horizontalHeader()
        header.setSectionResizeMode(QHeaderView.ResizeMode.ResizeToContents)
        header.setSectionResizeMode(4, QHeaderView.ResizeMode.Stretch)
        self.table.itemSelectionChanged.connect(self._on_selection_changed)
        self.table.doubleClicked.connect(lambda _index: self.accept())
        self.info = QLabel()
        self.info.setWordWrap(True)
        self.add_button = QPushButton()
        self.remove_button = QPushButton()
        self.refresh_button = QPushButton()
        self.add_button.clicked.connect(self._on_add_clicked)
        self.remove_button.clicked.connect(self._on_remove_clicked)
        self.refresh_button.clicked.connect(self.refresh)
        self.buttons = QDialogButtonBox(
            QDialogButtonBox.StandardButton.Ok | QDialogButtonBox.StandardButton.Cancel
        )
        self.buttons.accepted.connect(self.accept)
        self.buttons.rejected.connect(self.reject)
        row = QHBoxLayout()
        for button in (self.add_button, self.remove_button, self.refresh_button):
            row.addWidget(button)
        row.addStretch(1)
        layout = QVBoxLayout(self)
        layout.addWidget(self.info)
        layout.addWidget(self.table)
        layout.addLayout(row)
        layout.addWidget(self.buttons)
        self.resize(760, 320)
        self.retranslate()
        self.refresh()

    def retranslate(self) -> None:
        """Set every text in the current language."""
        self.setWindowTitle(self.tr("HID configuration"))
        if not self.listing:
            self._set_info()
        self.table.setHorizontalHeaderLabels(
            [
                self.tr("Connection"),
                self.tr("Type key"),
                self.tr("Serial number"),
                self.tr("Firmware"),
                self.tr("Description"),
            ]
        )
        self.add_button.setText(self.tr("Add emulated valve…"))
        self.remove_button.setText(self.tr("Remove emulated valve"))
        self.refresh_button.setText(self.tr("Refresh"))

    def _set_info(self) -> None:
        self.info.setText(
            self.tr(
                "Valves connected to this computer and emulated valves. Choose the one to "
                "communicate with."
            )
        )

    def changeEvent(self, event: QEvent) -> None:
        """Retranslate when the program language changes."""
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate()
        super().changeEvent(event)

    @property
    def listing(self) -> bool:
        """True while the valves are being listed (the table shows the previous list)."""
        return self._listing > 0

    def refresh(self) -> None:
        """List the valves again (off the GUI thread; the table fills when they answered)."""
        self._listing += 1
        number = self._listing
        self.refresh_button.setEnabled(False)
        self._on_selection_changed()  # OK and Remove only for a listed, selected valve
        self.info.setText(self.tr("Looking for valves…"))
        self._lister(saved_emulators(self._settings), lambda found: self._listed(number, found))

    def _listed(self, number: int, found: ListedValves) -> None:
        if not isValid(self) or number != self._listing:
            return  # the dialog is gone, or a newer listing was asked for
        self._listing = 0
        self.refresh_button.setEnabled(True)
        if isinstance(found, Exception):  # a broken USB stack must not prevent an emulator
            self._entries = []
            self.info.setText(self.tr("Listing the valves failed: {0}").format(error_text(found)))
        else:
            self._entries = list(found)
            self._set_info()
        self.table.setRowCount(len(self._entries))
        selected = str(self._settings.value(SELECTED_KEY, ""))
        for row, entry in enumerate(self._entries):
            cells = describe(entry)
            if cells[0] == "emulator":  # the device layer describes it in English
                cells[4] = self.tr("emulated {0}, serial {1}").format(cells[1], cells[2])
            elif cells[0] == UNUSABLE:
                why = getattr(entry, "error", None)  # the device layer's reason, translatable
                reason = error_text(why) if isinstance(why, Exception) else cells[4]
                cells[4] = self.tr("cannot be used (remove it): {0}").format(reason)
            cells[0] = self._kind_text(cells[0])
            for column, cell in enumerate(cells):
                self.table.setItem(row, column, QTableWidgetItem(cell))
            if entry.device_id == selected:
                self.table.selectRow(row)
        if self._select_last and self._entries:
            self.table.selectRow(len(self._entries) - 1)
        self._select_last = False
        if self._entries and not self.table.selectedItems():
            self.table.selectRow(0)
        self._on_selection_changed()

    def _kind_text(self, kind: str) -> str:
        return self.tr("Emulated valve") if kind in ("emulator", UNUSABLE) else self.tr("USB")

    def selected_entry(self) -> ValveListing | None:
        """The chosen device entry (None if the list is empty)."""
        rows = self.table.selectionModel().selectedRows()
        return self._entries[rows[0].row()] if rows else None

    def _on_selection_changed(self) -> None:
        entry = self.selected_entry()
        usable = entry is not None and entry.kind != UNUSABLE
        self.buttons.button(QDialogButtonBox.StandardButton.Ok).setEnabled(usable)
        self.remove_button.setEnabled(entry is not None and entry.kind in ("emulator", UNUSABLE))

    def accept(self) -> None:
        """Remember the choice."""
        entry = self.selected_entry()
        if entry is None or entry.kind == UNUSABLE:
            return
        self._settings.setValue(SELECTED_KEY, entry.device_id)
        super().accept()

    def _on_add_clicked(self) -> None:
        dialog = EmulatorDialog(self)
        if dialog.exec() == QDialog.DialogCode.Accepted:
            self.add_emulator(dialog.spec())

    def add_emulator(self, spec: str) -> None:
        """Add an emulated valve ``TYPEKEY:SERIAL`` (or a twin, ``twin:FILE``) to the list and
        select it; it replaces an entry of the same serial (one serial is one valve)."""
        serial = spec_serial(spec)
        kept = [
            e for e in saved_emulators(self._settings) if serial is None or spec_serial(e) != serial
        ]
        emulators = one_per_serial([*kept, spec])
        self._settings.setValue(EMULATORS_KEY, emulators)
        self._select_last = True
        self.refresh()

    def _on_remove_clicked(self) -> None:
        entry = self.selected_entry()
        if entry is None:
            return
        spec = f"{entry.type_key}:{entry.serial}"
        emulators = [
            e
            for e in saved_emulators(self._settings)
            if e != spec and not (e.startswith("twin:") and spec_serial(e) == entry.serial)
        ]
        self._settings.setValue(EMULATORS_KEY, emulators)
        self.refresh()

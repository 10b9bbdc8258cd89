"""Valve → History: the records of a valve, the difference of two, restore and export.

The records are read in a thread of its own (a PostgreSQL server may be slow or away; the
window never waits for it) and delivered by a signal. The table is a model over the record
summaries (table.py); a record's parameter set is read when it is needed.
"""

from __future__ import annotations

import json
import threading
from collections.abc import Callable
from pathlib import Path

from PySide6.QtCore import QEvent, QModelIndex, Signal
from PySide6.QtWidgets import (
    QAbstractItemView,
    QDialog,
    QHBoxLayout,
    QHeaderView,
    QLabel,
    QLineEdit,
    QPushButton,
    QTableView,
    QVBoxLayout,
    QWidget,
)

from prm9tool.catalogue.typekey import TypeKey
from prm9tool.compare.model import Comparison, Side
from prm9tool.errors import Prm9Error
from prm9tool.history.recorder import Recorder
from prm9tool.translate import error_text
from prm9tool.views import prompts
from prm9tool.views.files import dialogs as file_dialogs
from prm9tool.views.help_dialog import add_context_help
from prm9tool.views.history.details import RecordDetailsDialog
from prm9tool.views.history.table import HistoryTableModel, Record


class HistoryWindow(QDialog):
    """The records of the connected valve or of a typed serial number."""

    loaded = Signal(object, object)  # (records or None, error or None), from the reader thread
    database_changed = Signal(object)  # the new Recorder after the setting changed

    def __init__(
        self,
        recorder: Recorder,
        serial: int | None,
        restore_document: Callable[[TypeKey | None, dict[str, int | str]], None],
        restore_valve: Callable[[int, dict[str, int | str]], bool],
        parent: QWidget | None = None,
        type_key: str | None = None,
    ) -> None:
        """``type_key``: the type key of the valve ``serial`` is of (the connected one):
        records of another are marked."""
        super().__init__(parent)
        self._recorder = recorder
        self._valve_key = (serial, type_key) if serial and type_key else None
        self._restore_document, self._restore_valve = restore_document, restore_valve
        add_context_help(self, "history")  # F1
        self.serial = QLineEdit(str(serial) if serial else "")
        show = self._show = QPushButton()
        self._serial_label = QLabel()
        self.state = QLabel()
        self._shown: tuple[int, str, bool] | None = None  # records, where, error: the state line
        self.state.setWordWrap(True)
        self.model = HistoryTableModel(self)
        self.table = QTableView(self)
        self.table.setModel(self.model)
        self.table.setSelectionBehavior(QAbstractItemView.SelectionBehavior.SelectRows)
        self.table.verticalHeader().hide()
        self.table.horizontalHeader().setSectionResizeMode(QHeaderView.ResizeMode.ResizeToContents)
        # not stretched: the last column got only the room left ("tzer, Station, Verbin")
        self.table.horizontalHeader().setStretchLastSection(False)
        top = QHBoxLayout()
        top.addWidget(self._serial_label)
        top.addWidget(self.serial)
        top.addWidget(show)
        top.addStretch(1)
        self.buttons = {
            key: QPushButton() for key in ("compare", "document", "valve", "export", "settings")
        }
        self._retranslate()
        actions = QHBoxLayout()
        for button in self.buttons.values():
            actions.addWidget(button)
        actions.addStretch(1)
        layout = QVBoxLayout(self)
        for part in (top, self.state, self.table, actions):
            layout.addLayout(part) if isinstance(part, QHBoxLayout) else layout.addWidget(part)
        show.clicked.connect(self.reload)
        self.serial.returnPressed.connect(self.reload)
        self.loaded.connect(self._on_loaded)
        self.table.selectionModel().selectionChanged.connect(self._update_buttons)
        self.table.doubleClicked.connect(self.open_record)
        self.buttons["compare"].clicked.connect(self.compare_selected)
        self.buttons["document"].clicked.connect(
            lambda: self._restore(self._restore_document_record)
        )
        self.buttons["valve"].clicked.connect(lambda: self._restore(self._restore_valve_record))
        self.buttons["export"].clicked.connect(self.export_selected)
        self.buttons["settings"].clicked.connect(self.edit_settings)
        self._update_buttons()
        self.resize(980, 520)
        if serial:
            self.reload()

    def changeEvent(self, event: QEvent) -> None:
        """The window follows the program language: its own words, and the table's (its model
        builds them again)."""
        if event.type() == QEvent.Type.LanguageChange:
            self.model.retranslate()
            self._retranslate()
        super().changeEvent(event)

    def _retranslate(self) -> None:
        self.setWindowTitle(self.tr("History"))
        self.serial.setPlaceholderText(self.tr("serial number"))
        self._show.setText(self.tr("Show"))
        self._serial_label.setText(self.tr("Valve serial number:"))
        texts = {
            "compare": self.tr("Compare the two selected records"),
            "document": self.tr("Restore into the document"),
            "valve": self.tr("Restore to the valve"),
            "export": self.tr("Export…"),
            "settings": self.tr("Database…"),
        }
        for key, text in texts.items():
            self.buttons[key].setText(text)
        if self._shown is not None and not self._shown[2]:  # an error keeps its own words
            self.state.setText(self._state_text())

    def _state_text(self) -> str:
        assert self._shown is not None
        count, where, _error = self._shown
        state = self.tr("%n record(s) in {0}", "", count).format(where)
        if self.model.other_type:
            state += "\n" + self.model.other_type_text()
        return state

    # --- loading (off the GUI thread) -------------------------------------------------------
    def reload(self) -> None:
        """Read the records of the serial number typed in."""
        text = self.serial.text().strip()
        if not text.isdigit():  # the last valve's records must not stand under another text
            self.model.set_records([])
            self._shown = None
            self.state.setText(self.tr("Type a valve's serial number."))
            self._update_buttons()
            return
        self.state.setText(self.tr("Reading the history…"))
        threading.Thread(target=self._read, args=(int(text),), daemon=True, name="history").start()

    def _read(self, serial: int) -> None:
        try:
            store = self._recorder.store()
            records = store.records(serial)
        except Prm9Error as exc:
            self.loaded.emit(None, exc)
            return
        self.loaded.emit((records, store.shown_url), None)

    def _on_loaded(self, records: object, error: object) -> None:
        if isinstance(error, Exception):
            self.model.set_records([])
            self._shown = (0, "", True)
            self.state.setText(error_text(error))
        else:
            assert isinstance(records, tuple)
            rows, where = records
            serial = int(rows[0]["serial"]) if rows else None
            known = self._valve_key
            self.model.set_records(rows, known[1] if known and known[0] == serial else None)
            self._shown = (len(rows), where, False)
            self.state.setText(self._state_text())
            self.table.scrollToBottom()
        self._update_buttons()

    # --- selection and actions --------------------------------------------------------------
    def selected(self) -> list[Record]:
        """The selected records, oldest first."""
        rows = sorted({index.row() for index in self.table.selectionModel().selectedRows()})
        return [self.model.records[row] for row in rows]

    def _update_buttons(self, *_args: object) -> None:
        count = len(self.selected())
        self.buttons["compare"].setEnabled(count == 2)
        for name in ("document", "valve", "export"):
            self.buttons[name].setEnabled(count == 1)

    def open_record(self, index: QModelIndex | None = None) -> QDialog | None:
        """Double-click: two selected records open their comparison, one record its details
        (with its PDF and the comparison with the record before)."""
        selected = self.selected()
        if len(selected) == 2:
            return self.compare_selected()
        row = index.row() if index is not None and index.isValid() else None
        if row is None:
            if len(selected) != 1:
                return None
            row = self.model.records.index(selected[0])
        record = self.model.records[row]
        before = self._record_with_parameters_before(row)
        dialog = RecordDetailsDialog(record, self.model.meaning(record), before is not None, self)
        if before is not None:
            dialog.compare_requested.connect(lambda: self._compare_records([before, record]))
        dialog.open()
        return dialog

    def _record_with_parameters_before(self, row: int) -> Record | None:
        """The nearest earlier record of the same valve type (the ones with a parameter set
        are known only when read: the comparison says so when one has none)."""
        key = self.model.records[row]["type_key"]
        earlier = [r for r in self.model.records[:row] if r["type_key"] == key]
        return earlier[-1] if earlier else None

    def _full(self, record: Record) -> tuple[TypeKey, dict[str, int | str]] | None:
        whole = self._recorder.store().record(record["id"])
        if whole is None or whole["parameters"] is None:
            prompts.inform(self, prompts.Icon.Information, self.tr("History"),
                           self.tr("This record holds no parameter set (the operation did not "
                                   "change the valve's stored parameters)."))  # fmt: skip
            return None
        return TypeKey.parse(whole["type_key"]), dict(json.loads(whole["parameters"]))

    def compare_selected(self) -> CompareDialogLike | None:
        """Show the difference of the two selected records in the compare view, from which
        the ticked values go into the document or into the valve they were recorded from."""
        return self._compare_records(self.selected())

    def _compare_records(self, records: list[Record]) -> CompareDialogLike | None:
        from prm9tool.views.compare.view import DOCUMENT, VALVE, CompareDialog

        sides = []
        for record in records:
            full = self._full(record)
            if full is None:
                return None
            label = self.tr("No. {0}, {1}").format(record["seq"], record["recorded_at"][:19])
            sides.append(Side(label, full[0], full[1]))
        comparison = Comparison((sides[0], sides[1]))
        dialog = CompareDialog(comparison, (), parent=self, destinations=(DOCUMENT, VALVE))
        serial = int(records[0]["serial"])
        dialog.accepted.connect(lambda: self._on_compare_applied(dialog.applied, serial))
        dialog.open()
        return dialog

    def _on_compare_applied(self, applied: object, serial: int) -> None:
        """Ticked values of two records: into the document (one undo step, its type key kept)
        or into the valve they came from (a transactional upload)."""
        from prm9tool.views.compare.view import DOCUMENT

        if not isinstance(applied, tuple) or not applied[1]:
            return
        target, values = applied
        if target == DOCUMENT:
            self._restore_document(None, dict(values))
        elif not self._restore_valve(serial, dict(values)):
            self._not_online(serial)

    def _restore(self, how: Callable[[Record, TypeKey, dict[str, int | str]], None]) -> None:
        (record,) = self.selected()
        full = self._full(record)
        if full is not None:
            how(record, *full)

    def _restore_document_record(
        self, _record: Record, key: TypeKey, values: dict[str, int | str]
    ) -> None:
        self._restore_document(key, values)

    def _restore_valve_record(
        self, record: Record, _key: TypeKey, values: dict[str, int | str]
    ) -> None:
        if not self._restore_valve(int(record["serial"]), values):
            self._not_online(int(record["serial"]))

    def _not_online(self, serial: int) -> None:
        prompts.inform(self, prompts.Icon.Warning, self.tr("Restore to the valve"),
                       self.tr("Go online with valve {0} first: a record is restored only "
                               "into the valve it was recorded from.").format(serial))  # fmt: skip

    def edit_settings(self) -> None:
        """Choose the database and the policy; the new database is used from now on."""
        from prm9tool.views.history.settings import HistorySettingsDialog

        dialog = HistorySettingsDialog(self)
        if dialog.exec() == QDialog.DialogCode.Accepted:
            self._recorder = Recorder()
            self.database_changed.emit(self._recorder)
            self.reload()

    def export_selected(self, path: str | None = None) -> None:
        """Write the selected record to a *.prm or CSV file."""
        from prm9tool.history.export import export_record

        (record,) = self.selected()
        if path is None:
            path, _filter = file_dialogs.save_file_name(
                self, self.tr("Export record"), f"{record['serial']}_{record['seq']}.prm",
                self.tr("Parameter files (*.prm);;CSV tables (*.csv)"),
            )  # fmt: skip
            if not path:
                return
        try:
            whole = self._recorder.store().record(record["id"])
            export_record(whole or record, Path(path))
        except (Prm9Error, ValueError) as exc:
            prompts.inform(self, prompts.Icon.Warning, self.tr("Export record"),
                           self.tr("The record was not exported."), str(exc))  # fmt: skip


CompareDialogLike = QDialog

"""Valve → History: the records of a valve, the difference of two, restore and export.

The records are read in a thread of its own (a PostgreSQL server may be slow or away; the
window never waits for it) and delivered by a signal. The table is a model over the record
summaries; a record's parameter set is read when it is needed.
"""

from __future__ import annotations

import json
import threading
from collections.abc import Callable
from pathlib import Path
from typing import Any

from PySide6.QtCore import QAbstractTableModel, QModelIndex, QPersistentModelIndex, Qt, Signal
from PySide6.QtGui import QColor
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

from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.manual_od import KEPT_AS_WRITTEN, STORED_WITH_1010, VERIFIED_RESTART
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.compare.model import Comparison, Side
from prm9tool.errors import Prm9Error
from prm9tool.history.chain import other_type
from prm9tool.history.recorder import Recorder
from prm9tool.i18n import format_number, format_value
from prm9tool.translate import error_text
from prm9tool.views import prompts
from prm9tool.views.files import dialogs as file_dialogs
from prm9tool.views.help_dialog import add_context_help
from prm9tool.views.history.details import (
    MAX_FIGURES,
    RecordDetailsDialog,
    failing_figures,
    pdf_of,
    record_details,
)

Index = QModelIndex | QPersistentModelIndex
Record = dict[str, Any]
MEANING = 3  # the column saying what was done
TYPE_KEY = 5  # the column of the type key (marked on a record of another valve type)
OTHER_TYPE_MARK = "⚠ "
MAX_CHANGES = 4  # changed values listed in that column (all of them in the record)


def _details(record: Record) -> dict[str, Any]:
    return record_details(record)


def _change(mnemonic: str, pair: object) -> str:
    """``POSKP 0.4 → 0.6`` in display units (raw when the catalogue has no such parameter)."""
    param = CATALOGUE.get(mnemonic)
    old, new = pair if isinstance(pair, list) and len(pair) == 2 else ("?", "?")
    if param is None or not isinstance(old, int | str) or not isinstance(new, int | str):
        return f"{mnemonic} {old} → {new}"
    return (
        f"{mnemonic} {format_value(param, old)} → {format_value(param, new)} {param.unit}".strip()
    )


class HistoryTableModel(QAbstractTableModel):
    """One row per record, oldest first."""

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.records: list[Record] = []
        self.other_type: set[int] = set()  # rows of another type key than the chain's
        self.chain_type_key = ""

    def set_records(self, records: list[Record], type_key: str | None = None) -> None:
        """Show these records; those whose type key is not the chain's (``type_key``, the
        valve's now, else the newest record's) are marked: another valve under this serial."""
        self.beginResetModel()
        self.records = records
        self.other_type = set(other_type(records, type_key))
        self.chain_type_key = type_key or (str(records[-1]["type_key"]) if records else "")
        self.endResetModel()

    def rowCount(self, parent: Index = QModelIndex()) -> int:  # noqa: B008
        return 0 if parent.isValid() else len(self.records)

    def columnCount(self, parent: Index = QModelIndex()) -> int:  # noqa: B008
        return 0 if parent.isValid() else 8

    def headerData(self, section: int, orientation: Qt.Orientation, role: int = 0) -> Any:
        if orientation != Qt.Orientation.Horizontal or role != Qt.ItemDataRole.DisplayRole:
            return None
        return [self.tr("No."), self.tr("Time (UTC)"), self.tr("Operation"),
                self.tr("What was done"), self.tr("Outcome"), self.tr("Type key"),
                self.tr("Firmware"), self.tr("User, station, link")][section]  # fmt: skip

    def data(self, index: Index, role: int = 0) -> Any:
        r = self.records[index.row()]
        if role == Qt.ItemDataRole.ToolTipRole and index.column() == MEANING:
            return self.meaning(r)
        other = index.row() in self.other_type
        if other and role == Qt.ItemDataRole.ToolTipRole:
            return self.other_type_text()
        if other and role == Qt.ItemDataRole.ForegroundRole:
            return QColor(170, 0, 0)
        if role != Qt.ItemDataRole.DisplayRole:
            return None
        failed = f" ({r['failed_step']})" if r["failed_step"] else ""
        cells = [
            str(r["seq"]), r["recorded_at"][:19].replace("T", " "), r["operation"],
            self.meaning(r), r["outcome"] + failed, r["type_key"], r["firmware"],
            f"{r['os_user']}@{r['host']}, {r['device_id']}",
        ]  # fmt: skip
        if other:
            cells[TYPE_KEY] = OTHER_TYPE_MARK + cells[TYPE_KEY]
        return cells[index.column()]

    def other_type_text(self) -> str:
        """Why a row is marked (also the window's warning line)."""
        return self.tr(
            "Marked {0}: records of another valve type than {1} under this serial number — "
            "another valve (emulated valves of two runs of the program may share a serial "
            "number); compare or restore them only knowingly."
        ).format(OTHER_TYPE_MARK.strip(), self.chain_type_key)

    def meaning(self, record: Record) -> str:
        """What the user did, in the program language: the operation, why, and the values
        it changed in display units ("Tuning accepted online: Autotune; POSKP 0.4 → 0.6")."""
        details = _details(record)
        operation = record["operation"]
        text = self._operations().get(operation) or str(operation)
        why = [self._purposes().get(str(details["purpose"]), str(details["purpose"]))
               if "purpose" in details else "",
               str(details.get("source", "")), str(details.get("what", "")),
               self._stores().get(str(details.get("store")), "")]  # fmt: skip
        shown = ", ".join(part for part in why if part)
        if operation in ("characterization", "report-saved"):
            shown = ", ".join(part for part in (shown, self._report_text(details)) if part)
        elif operation in ("autotune", "frequency-response"):
            shown = ", ".join(part for part in (shown, self._run_text(details)) if part)
        changed = details.get("changes")
        if isinstance(changed, dict) and changed:
            listed = [_change(mn, pair) for mn, pair in list(changed.items())[:MAX_CHANGES]]
            more = len(changed) - MAX_CHANGES
            if more > 0:
                listed.append(self.tr("%n more", "", more))
            shown = "; ".join(part for part in (shown, ", ".join(listed)) if part)
        return f"{text}: {shown}" if shown else text

    def _report_text(self, details: dict[str, Any]) -> str:
        """A test report's loop, profile, failing figures and PDF."""
        parts = []
        loops = {"position": self.tr("position loop"), "process": self.tr("process loop")}
        if details.get("loop"):
            parts.append(loops.get(str(details["loop"]), str(details["loop"])))
        if details.get("profile"):
            parts.append(self.tr("profile {0}").format(details["profile"]))
        failing = failing_figures(details)
        if failing:
            listed = failing[:MAX_FIGURES]
            if len(failing) > MAX_FIGURES:
                listed.append(self.tr("%n more", "", len(failing) - MAX_FIGURES))
            parts.append(self.tr("failed: {0}").format("; ".join(listed)))
        pdf = pdf_of(details)
        if pdf is not None:
            parts.append(self.tr("PDF {0}").format(str(pdf)))
        return ", ".join(parts)

    def _run_text(self, details: dict[str, Any]) -> str:
        """An autotune run's loop and proposed gains, a frequency response's figures."""
        parts = []
        loops = {"position": self.tr("position loop"), "process": self.tr("process loop")}
        if details.get("loop"):
            parts.append(loops.get(str(details["loop"]), str(details["loop"])))
        proposed = details.get("proposed")
        if isinstance(proposed, dict) and proposed:
            listed = [_change(mn, pair) for mn, pair in list(proposed.items())[:MAX_CHANGES]]
            parts.append(self.tr("proposed {0}").format(", ".join(listed)))
        if "meets_targets" in details and not details["meets_targets"]:
            parts.append(self.tr("misses the targets"))
        for key, name in (("bandwidth_hz", "−3 dB"), ("phase_90_hz", "−90°")):
            if key in details:
                value = details[key]
                found = isinstance(value, int | float) and not isinstance(value, bool)
                shown = f"{format_number(value, 1)} Hz" if found else self.tr("not found")
                parts.append(f"{name}: {shown}")
        return ", ".join(parts)

    def _operations(self) -> dict[str, str]:
        return {
            "download": self.tr("Read from the valve"),
            "upload": self.tr("Written, verified and stored"),
            "batch-upload": self.tr("Written by --batch"),
            "store": self.tr("Stored (Valve → Store in valve)"),
            "online-edits": self.tr("Values changed online, stored"),
            "backup": self.tr("Backup of the valve's values"),
            "restore-factory": self.tr("Factory values restored"),
            "characterization": self.tr("Test report"),
            "compare-apply": self.tr("Values from a compared file, written online"),
            "history-restore": self.tr("Values from the history, written online"),
            "tuning-accepted": self.tr("Tuning accepted, written online"),
            "restart-verify": self.tr("Restarted and read back (Valve → Verify by restart…)"),
            "restart": self.tr("Restarted (Valve → Restart valve)"),
            "autotune": self.tr("Autotune run"),
            "frequency-response": self.tr("Frequency response measured"),
            "report-saved": self.tr("Test report saved"),
            "twin": self.tr("Twin fitted (--fit-twin)"),
            "signature": self.tr("Compared with the birth certificate (--signature)"),
        }

    def _stores(self) -> dict[str, str]:
        """How the valve kept an upload (prm9tool.device.canlink.storing; ``store`` in the
        details of upload, batch-upload and restart-verify records)."""
        return {
            STORED_WITH_1010: self.tr("stored with 0x1010"),
            KEPT_AS_WRITTEN: self.tr("kept by the valve as written (it has no store command)"),
            VERIFIED_RESTART: self.tr("verified after a restart"),
        }

    def _purposes(self) -> dict[str, str]:
        return {
            "compare": self.tr("going online"),
            "download": self.tr("Valve → Download"),
            "compare_view": self.tr("Compare with valve"),
            "upload": self.tr("Valve → Upload"),
            "compare: values chosen from the document": self.tr("chosen in the compare view"),
            "going online: values chosen per parameter": self.tr(
                "chosen per parameter going online"
            ),
            "history: a record's values restored": self.tr("a history record restored"),
        }


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
        self.setWindowTitle(self.tr("History"))
        add_context_help(self, "history")  # F1
        self.serial = QLineEdit(str(serial) if serial else "")
        self.serial.setPlaceholderText(self.tr("serial number"))
        show = QPushButton(self.tr("Show"))
        self.state = QLabel()
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
        top.addWidget(QLabel(self.tr("Valve serial number:")))
        top.addWidget(self.serial)
        top.addWidget(show)
        top.addStretch(1)
        self.buttons = {
            "compare": QPushButton(self.tr("Compare the two selected records")),
            "document": QPushButton(self.tr("Restore into the document")),
            "valve": QPushButton(self.tr("Restore to the valve")),
            "export": QPushButton(self.tr("Export…")),
            "settings": QPushButton(self.tr("Database…")),
        }
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

    # --- loading (off the GUI thread) -------------------------------------------------------
    def reload(self) -> None:
        """Read the records of the serial number typed in."""
        text = self.serial.text().strip()
        if not text.isdigit():
            self.state.setText(self.tr("Type a valve's serial number."))
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
            self.state.setText(error_text(error))
        else:
            assert isinstance(records, tuple)
            rows, where = records
            serial = int(rows[0]["serial"]) if rows else None
            known = self._valve_key
            self.model.set_records(rows, known[1] if known and known[0] == serial else None)
            state = self.tr("%n record(s) in {0}", "", len(rows)).format(where)
            if self.model.other_type:
                state += "\n" + self.model.other_type_text()
            self.state.setText(state)
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

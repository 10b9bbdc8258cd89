"""The history window's table: one row per record of a valve, what was done in words, the
values it changed, and the records of another valve type under the same serial marked.
A model over the record summaries (``HistoryTableModel``); the window is
:mod:`prm9tool.views.history.window`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from PySide6.QtCore import QAbstractTableModel, QModelIndex, QPersistentModelIndex, Qt
from PySide6.QtGui import QColor
from PySide6.QtWidgets import QWidget

from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.manual_od import KEPT_AS_WRITTEN, STORED_WITH_1010, VERIFIED_RESTART
from prm9tool.history.chain import other_type
from prm9tool.i18n import format_number, format_value
from prm9tool.views.history.details import MAX_FIGURES, failing_figures, pdf_of, record_details

Index = QModelIndex | QPersistentModelIndex
Record = dict[str, Any]
OPERATION = 2  # the column of the operation
MEANING = 3  # the column saying what was done
OUTCOME = 4  # the column of the outcome (and the step that failed)
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


@dataclass(frozen=True)
class _Texts:
    """The model's fixed words in one program language: built once per language (not in each
    call of ``data()``), by :meth:`HistoryTableModel.retranslate`."""

    headers: list[str]
    operation_names: dict[str, str]  # the Operation column
    outcomes: dict[str, str]
    steps: dict[str, str]
    operations: dict[str, str]  # the What was done column
    stores: dict[str, str]
    purposes: dict[str, str]
    loops: dict[str, str]


class HistoryTableModel(QAbstractTableModel):
    """One row per record, oldest first; its words follow the program language through
    :meth:`retranslate` (the window calls it at a LanguageChange)."""

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.records: list[Record] = []
        self.other_type: set[int] = set()  # rows of another type key than the chain's
        self.chain_type_key = ""
        self._texts = self._build_texts()

    def retranslate(self) -> None:
        """Build the words again in the program language, and have the views read them."""
        self._texts = self._build_texts()
        columns = self.columnCount()
        self.headerDataChanged.emit(Qt.Orientation.Horizontal, 0, columns - 1)
        if self.records:
            self.dataChanged.emit(self.index(0, 0), self.index(len(self.records) - 1, columns - 1))

    def _build_texts(self) -> _Texts:
        loops = {"position": self.tr("position loop"), "process": self.tr("process loop")}
        return _Texts(
            headers=self._headers(),
            operation_names=self._operation_names(),
            outcomes=self._outcomes(),
            steps=self._steps(),
            operations=self._operations(),
            stores=self._stores(),
            purposes=self._purposes(),
            loops=loops,
        )

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
        return self._texts.headers[section]

    def _headers(self) -> list[str]:
        return [self.tr("No."), self.tr("Time (UTC)"), self.tr("Operation"),
                self.tr("What was done"), self.tr("Outcome"), self.tr("Type key"),
                self.tr("Firmware"), self.tr("User, station, link")]  # fmt: skip

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
        cells = [
            str(r["seq"]), r["recorded_at"][:19].replace("T", " "), self.operation(r),
            self.meaning(r), self.outcome(r), r["type_key"], r["firmware"],
            f"{r['os_user']}@{r['host']}, {r['device_id']}",
        ]  # fmt: skip
        if other:
            cells[TYPE_KEY] = OTHER_TYPE_MARK + cells[TYPE_KEY]
        return cells[index.column()]

    def operation(self, record: Record) -> str:
        """The operation in a word of the program language (German read "download",
        "characterization"); English shows the recorded word, as ``--history`` does."""
        operation = str(record["operation"])
        return self._texts.operation_names.get(operation, operation)

    def _operation_names(self) -> dict[str, str]:
        """The operations docs/history.md names (their English is the recorded word)."""
        return {
            "download": self.tr("download"),
            "upload": self.tr("upload"),
            "batch-upload": self.tr("batch-upload"),
            "store": self.tr("store"),
            "online-edits": self.tr("online-edits"),
            "backup": self.tr("backup"),
            "restore-factory": self.tr("restore-factory"),
            "characterization": self.tr("characterization"),
            "compare-apply": self.tr("compare-apply"),
            "history-restore": self.tr("history-restore"),
            "tuning-accepted": self.tr("tuning-accepted"),
            "restart-verify": self.tr("restart-verify"),
            "restart": self.tr("restart"),
            "autotune": self.tr("autotune"),
            "frequency-response": self.tr("frequency-response"),
            "report-saved": self.tr("report-saved"),
            "twin": self.tr("twin"),
            "signature": self.tr("signature"),
        }

    def outcome(self, record: Record) -> str:
        """The outcome and the step that failed, in the program language (German read
        "passed", "no-drift"); a word this program does not know stays as recorded. English
        shows the recorded words, as ``--history`` does."""
        outcome = str(record["outcome"])
        text = self._texts.outcomes.get(outcome, outcome)
        step = record["failed_step"]
        if not step:
            return text
        return f"{text} ({self._texts.steps.get(str(step), str(step))})"

    def _outcomes(self) -> dict[str, str]:
        """The outcomes docs/history.md names (their English is the recorded word)."""
        return {
            "ok": self.tr("ok"),
            "passed": self.tr("passed"),
            "failed": self.tr("failed"),
            "verification-failed": self.tr("verification-failed"),
            "store-failed": self.tr("store-failed"),
            "communication-error": self.tr("communication-error"),
            "type-mismatch": self.tr("type-mismatch"),
            "error": self.tr("error"),
            "dry-run": self.tr("dry-run"),
            "downloaded": self.tr("downloaded"),
            "proposed": self.tr("proposed"),
            "targets-missed": self.tr("targets-missed"),
            "explained": self.tr("explained"),
            "not-explained": self.tr("not-explained"),
            "no-drift": self.tr("no-drift"),
            "drifted": self.tr("drifted"),
        }

    def _steps(self) -> dict[str, str]:
        return {
            "backup": self.tr("backup"),
            "write": self.tr("write"),
            "verify": self.tr("verify"),
            "store": self.tr("store"),
        }

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
        text = self._texts.operations.get(operation) or str(operation)
        why = [self._texts.purposes.get(str(details["purpose"]), str(details["purpose"]))
               if "purpose" in details else "",
               str(details.get("source", "")), str(details.get("what", "")),
               self._texts.stores.get(str(details.get("store")), "")]  # fmt: skip
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
        if details.get("loop"):
            parts.append(self._texts.loops.get(str(details["loop"]), str(details["loop"])))
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
        if details.get("loop"):
            parts.append(self._texts.loops.get(str(details["loop"]), str(details["loop"])))
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

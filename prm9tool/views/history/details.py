"""One history record in words: the figures a test report failed, its PDF, and the details
window a double-click in Valve → History opens (every field, the details, the PDF, the
comparison with the record before)."""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

from PySide6.QtCore import QUrl, Signal
from PySide6.QtGui import QDesktopServices
from PySide6.QtWidgets import (
    QDialog,
    QDialogButtonBox,
    QFormLayout,
    QLabel,
    QPlainTextEdit,
    QPushButton,
    QVBoxLayout,
    QWidget,
)

Record = dict[str, Any]
MAX_FIGURES = 3  # failing figures named in the list's column (all of them in the details)


def record_details(record: Record) -> dict[str, Any]:
    """A record's details as a dict (empty when they are missing or not an object)."""
    try:
        details = json.loads(record.get("details") or "{}")
    except (TypeError, ValueError):
        return {}
    return details if isinstance(details, dict) else {}


def failing_figures(details: dict[str, Any]) -> list[str]:
    """The figures of a test report that failed their limit, in the program language
    (``step 0 → 90 %: rise time (10–90 %) not reached``)."""
    from prm9tool.characterize.run import Figure
    from prm9tool.views.tuning.report import figure_label, value_text

    figures = details.get("figures")
    shown: list[str] = []
    for entry in figures if isinstance(figures, list) else []:
        if not isinstance(entry, dict) or entry.get("passed") is not False:
            continue
        value = entry.get("value")
        if isinstance(value, bool):
            value = None
        figure = Figure(
            str(entry.get("name", "?")),
            "",
            float(value) if isinstance(value, int | float) else math.nan,
            str(entry.get("unit", "")),
            None,
            above=bool(entry.get("above")),
        )
        try:
            label = figure_label(figure)
        except (IndexError, KeyError):  # a name of another program version: as it is
            label = figure.name
        shown.append(f"{label} {value_text(figure)}")
    return shown


def pdf_of(details: dict[str, Any]) -> Path | None:
    """The PDF a record names (a saved test report), None without one."""
    pdf = details.get("pdf")
    return Path(pdf) if isinstance(pdf, str) and pdf else None


def open_pdf(path: Path) -> bool:
    """Open ``path`` in the desktop's PDF viewer; False when it is gone or cannot open."""
    return path.is_file() and QDesktopServices.openUrl(QUrl.fromLocalFile(str(path)))


class RecordDetailsDialog(QDialog):
    """Every field of one record and its details; buttons for its PDF and for the
    comparison with the valve's record before it (``compare_requested``)."""

    compare_requested = Signal()

    def __init__(
        self, record: Record, meaning: str, can_compare: bool, parent: QWidget | None = None
    ) -> None:
        super().__init__(parent)
        self.record = record
        self.setWindowTitle(self.tr("History record {0} of valve {1}").format(
            record.get("seq", "?"), record.get("serial", "?")))  # fmt: skip
        form = QFormLayout()
        failed = f" ({record['failed_step']})" if record.get("failed_step") else ""
        rows = [
            (self.tr("What was done"), meaning),
            (self.tr("Outcome"), f"{record.get('outcome', '')}{failed}"),
            (self.tr("Time (UTC)"), str(record.get("recorded_at", ""))),
            (self.tr("Type key"), str(record.get("type_key", ""))),
            (self.tr("Firmware"), str(record.get("firmware", ""))),
            (self.tr("User, station, link"),
             f"{record.get('os_user', '')}@{record.get('host', '')}, "
             f"{record.get('device_id', '')}"),
        ]  # fmt: skip
        self.labels: dict[str, QLabel] = {}
        for title, text in rows:
            label = QLabel(text)
            label.setWordWrap(True)
            self.labels[title] = label
            form.addRow(title + ":", label)
        details = record_details(record)
        self.failing = failing_figures(details)
        if self.failing:
            label = QLabel("\n".join(self.failing))
            self.labels["failed"] = label
            form.addRow(self.tr("Failed figures:"), label)
        shown = dict(details)
        if isinstance(shown.get("curves"), dict):  # a characterization's curves for a later
            shown["curves"] = "…"  # signature: some thousand numbers, not for reading here
        self.text = QPlainTextEdit(json.dumps(shown, indent=1, ensure_ascii=False))
        self.text.setReadOnly(True)
        self.pdf = pdf_of(details)
        self.pdf_button = QPushButton(self.tr("Open the PDF"))
        self.pdf_button.setToolTip(str(self.pdf or ""))
        self.pdf_button.clicked.connect(self.open_pdf)
        self.compare_button = QPushButton(self.tr("Compare with the record before"))
        self.compare_button.setEnabled(can_compare)
        self.compare_button.clicked.connect(self.compare_requested)
        buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Close)
        buttons.addButton(self.pdf_button, QDialogButtonBox.ButtonRole.ActionRole)
        buttons.addButton(self.compare_button, QDialogButtonBox.ButtonRole.ActionRole)
        # after addButton, which shows every button it lays out (a record without a PDF
        # offered "Open the PDF" and then said "cannot be opened: None")
        self.pdf_button.setVisible(self.pdf is not None)
        buttons.rejected.connect(self.reject)
        layout = QVBoxLayout(self)
        layout.addLayout(form)
        layout.addWidget(QLabel(self.tr("Details:")))
        layout.addWidget(self.text, 1)
        self.status = QLabel()
        self.status.setWordWrap(True)
        layout.addWidget(self.status)
        layout.addWidget(buttons)
        self.resize(640, 480)

    def open_pdf(self) -> bool:
        """Open the record's PDF; says so when it cannot (moved or deleted since)."""
        if self.pdf is not None and open_pdf(self.pdf):
            return True
        self.status.setText(self.tr("The PDF cannot be opened: {0}").format(str(self.pdf)))
        return False

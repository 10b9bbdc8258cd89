"""The Tuning window's "Birth certificate" page: Compare with birth certificate (issue 31 item 5).

The field signature runs on the connected valve like the other tests (off the GUI thread, the
hydraulics confirmed first, Stop at any time) and is compared with the valve's end-of-line
test in the history; the table, the sentence and the plots of the drift report are shown, and
the PDF can be saved. Offline there is no valve to compare: the page says so.
"""

from __future__ import annotations

from PySide6.QtGui import QBrush, QColor
from PySide6.QtWidgets import QLabel, QPushButton, QTableWidgetItem

from prm9tool.analysis.profile import ProfileError
from prm9tool.characterize.drift import DriftReport
from prm9tool.characterize.signature import MOTION_LIMIT_S
from prm9tool.service.history import birth_certificate_problem, signature_with_history
from prm9tool.translate import error_text
from prm9tool.views.tuning.host import TuningHost, figure_table
from prm9tool.views.tuning.pages import Page
from prm9tool.views.tuning.signature_report import (
    headers,
    no_curves_note,
    plots,
    summary_text,
    table_rows,
    write_signature_pdf,
)


class SignaturePage(Page):
    """Compare with birth certificate: the signature, its drift table, plots and PDF."""

    def __init__(self, window: TuningHost) -> None:
        super().__init__(window)
        self.table = figure_table(6)
        self.layout().insertWidget(3, self.table, 1)  # type: ignore[union-attr]
        self.about = QLabel()
        self.about.setWordWrap(True)
        self.layout().insertWidget(0, self.about)  # type: ignore[union-attr]
        self.save_button = QPushButton()
        self.save_button.setEnabled(False)
        self.save_button.clicked.connect(self.save)
        self.buttons.insertWidget(1, self.save_button)
        self.last: DriftReport | None = None

    def run(self) -> None:
        """The signature on the valve, compared with its birth certificate."""
        connection = self.window_.connection
        if connection is None or not getattr(connection, "is_online", False):
            self.result.setText(
                self.tr(
                    "The birth certificate is compared with the valve itself: go online with "
                    "the valve first."
                )
            )
            return
        problem = birth_certificate_problem(connection)  # before the questions: none asked
        if problem is not None:
            self.show_failure(error_text(problem))
            return
        try:
            profile = self.window_.profile()  # the drift limits: the Test report page's profile
        except ProfileError as exc:
            self.result.setText(error_text(exc))
            return
        what = self.tr(
            "a small and a large step each way, a short sine sweep and a hysteresis loop, at "
            "most %1 s"
        ).replace("%1", f"{MOTION_LIMIT_S:.0f}")
        run = lambda rig: signature_with_history(connection, rig, profile)  # noqa: E731
        if self.window_.start("signature", what, run, 15.0):
            self.result.clear()  # an earlier refusal is not the answer to this run

    def show_result(self, result: object) -> None:
        """The drift table, the sentence and today's curves over the birth certificate's."""
        assert isinstance(result, DriftReport)
        self.last = result
        rows = table_rows(result)
        self.table.setRowCount(len(rows))
        red = QBrush(QColor("#c0392b"))
        for row, (*texts, drifted) in enumerate(rows):
            for col, text in enumerate(texts):
                item = QTableWidgetItem(str(text))
                if drifted and col == 5:
                    item.setForeground(red)
                self.table.setItem(row, col, item)
        self.table.resizeRowsToContents()
        note = no_curves_note(result)
        self.result.setText(summary_text(result) + (f" {note}" if note else ""))
        self.plot.show_plots(plots(result))
        self.save_button.setEnabled(True)

    def show_failure(self, message: str) -> None:
        """Why the comparison did not run or stopped (the status line's "Ready." may follow)."""
        self.result.setText(self.tr("Not compared: %1").replace("%1", message))

    def save(self) -> None:
        """The drift report as PDF."""
        if self.last is None:
            return
        name = f"{self.last.today.info.serial}-drift.pdf"
        path = self.window_.save_file(self.tr("Save the drift report"), "PDF (*.pdf)", name)
        if path is None:
            return
        try:
            write_signature_pdf(self.last, path)
        except OSError as exc:
            self.result.setText(self.tr("Cannot write the report: %1").replace("%1", str(exc)))

    def retranslate(self) -> None:
        """Texts."""
        self.about.setText(
            self.tr(
                "A short field signature of the valve, compared with its birth certificate: "
                "the end-of-line test kept in the history for its serial. Each figure is judged "
                "against the drift limits of the acceptance profile chosen on the Test report "
                "page ([drift]; empty: the defaults)."
            )
        )
        self.run_button.setText(self.tr("Compare with birth certificate"))
        self.save_button.setText(self.tr("Save PDF…"))
        self.table.setHorizontalHeaderLabels(headers())
        if self.last is not None:
            self.show_result(self.last)

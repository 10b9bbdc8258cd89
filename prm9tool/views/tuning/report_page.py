"""The Tuning window's "Test report" page: the end-of-line test with an acceptance profile."""

from __future__ import annotations

from PySide6.QtWidgets import (
    QHBoxLayout,
    QLabel,
    QLineEdit,
    QPushButton,
    QTableWidgetItem,
)

from prm9tool.analysis.profile import DEFAULT, ProfileError, load_profile
from prm9tool.catalogue.variant import Config
from prm9tool.characterize.run import (
    Characterization,
    characterize,
    planned_s,
    write_csv_files,
)
from prm9tool.i18n import format_significant
from prm9tool.service.history import run_with_history
from prm9tool.translate import error_text, translated
from prm9tool.views.files import dialogs as file_dialogs
from prm9tool.views.history.notes import record_report_saved
from prm9tool.views.tuning.host import TuningHost, figure_table
from prm9tool.views.tuning.pages import Page
from prm9tool.views.tuning.report import figure_label, limit_text, value_short, verdict, write_pdf


class ReportPage(Page):
    """The end-of-line test with an acceptance profile; PDF and CSV."""

    def __init__(self, window: TuningHost) -> None:
        super().__init__(window)
        self.profile_path = QLineEdit()
        self.profile_path.textChanged.connect(self._on_profile_changed)
        self._profile_error = False  # the result line shows why the profile was refused
        self.browse_button = QPushButton()
        self.browse_button.clicked.connect(self.browse)
        row = QHBoxLayout()
        row.addWidget(self.profile_path, 1)
        row.addWidget(self.browse_button)
        self.labels["profile"] = QLabel()
        self.form.addRow(self.labels["profile"], row)
        self.table = figure_table(4)
        self.layout().insertWidget(3, self.table, 1)  # type: ignore[union-attr]
        self.plot.hide()
        self.save_button = QPushButton()
        self.save_button.setEnabled(False)
        self.save_button.clicked.connect(self.save)
        self.buttons.insertWidget(1, self.save_button)
        self.last: Characterization | None = None
        self._from_valve = False  # the last result was measured on the valve (online)

    def browse(self) -> None:
        """Choose the acceptance profile file."""
        path, _ = file_dialogs.open_file_name(
            self, self.tr("Acceptance profile"), self.profile_path.text(), "TOML (*.toml)"
        )
        if path:
            self.profile_path.setText(path)

    def _on_profile_changed(self) -> None:
        """A refusal of the profile named before no longer applies once the field changes
        (cleared, typed over or another file chosen): it would blame the new one."""
        if self._profile_error:
            self._profile_error = False
            self.result.clear()

    def run(self) -> None:
        """All tests of the profile."""
        path = self.profile_path.text().strip()
        try:
            profile = load_profile(path) if path else DEFAULT
        except ProfileError as exc:
            self.result.setText(error_text(exc))
            self._profile_error = True
            return
        connection = self.window_.connection  # online, the result goes into the history too
        flow = (
            self.window_.doc.variant.config is Config.E04
            and self.window_.doc.value("CTRLMODE") == 4
        )
        part = profile.for_loop("process" if flow else "position")  # what the test runs
        what = self.tr("steps of %1 %, a sine sweep of ±%2 % and a triangle over the whole range, about %3 s").replace(
            "%1", ", ".join(format_significant(a, 6) for a in part.step_amplitudes_pct)).replace(
            "%2", format_significant(part.bode_amplitude_pct, 6)).replace(
            "%3", f"{planned_s(profile, flow):.0f}")  # fmt: skip
        self.window_.start("report", what, lambda rig: run_with_history(
            connection, lambda: characterize(rig, profile)), planned_s(profile, flow))  # fmt: skip

    def show_result(self, result: object) -> None:
        """Every figure with its verdict."""
        assert isinstance(result, Characterization)
        self.last = result
        self._from_valve = bool(getattr(self.window_.connection, "is_online", False))
        self.table.setRowCount(len(result.figures))
        for row, f in enumerate(result.figures):
            value, tip = value_short(f)
            cells = (figure_label(f), value, limit_text(f), verdict(f.passed))
            for col, text in enumerate(cells):
                item = QTableWidgetItem(text)
                item.setToolTip(tip if col == 1 else "")
                self.table.setItem(row, col, item)
        self.table.resizeRowsToContents()
        text = self.tr("Result: %1").replace("%1", verdict(result.passed))
        for note in result.notes:  # what the link or a busy PC limited, as the PDF says it
            text += "\n" + self.tr("Limited by the link: %1").replace("%1", translated(note))
        self.result.setText(text)
        self.save_button.setEnabled(True)

    def save(self) -> None:
        """The PDF report and the raw data as CSV beside it."""
        if self.last is None:
            return
        name = f"{self.last.info.serial}-report.pdf"
        path = self.window_.save_file(self.tr("Save the test report"), "PDF (*.pdf)", name)
        if path is None:
            return
        try:
            write_pdf(self.last, path)
            write_csv_files(self.last, path.with_suffix(""))
        except OSError as exc:
            self.result.setText(self.tr("Cannot write the report: %1").replace("%1", str(exc)))
            return
        if self._from_valve:  # not a run on the simulated valve
            connection, loop = self.window_.connection, self.window_.current_loop()
            record_report_saved(connection, self.last, str(path), loop)

    def retranslate(self) -> None:
        """Texts."""
        self.tr_label("profile", self.tr("Acceptance profile (TOML, empty: default):"))
        self.run_button.setText(self.tr("Run the end-of-line test"))
        self.save_button.setText(self.tr("Save PDF and CSV…"))
        self.browse_button.setText(self.tr("Browse…"))
        self.table.setHorizontalHeaderLabels(
            [self.tr("Figure"), self.tr("Value"), self.tr("Limit"), self.tr("Result")]
        )

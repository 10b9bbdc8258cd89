"""The Tuning window's "Twin" page (issue 31 item 2): fit a twin of the valve.

**Fit twin of the valve** (online) characterizes the connected valve with the profile of the
Test report page (the spool moves: the hydraulics are confirmed first, Stop at any time), fits
the twin, writes the twin file and records the run and the twin in the history — what
``prm9tool --fit-twin OUT.toml --device ID`` does, through the same implementation
(:mod:`prm9tool.online.twin_fit`). **Fit from a report…** does what ``--fit-twin OUT.toml
--from RUN.json`` does, with or without a valve. The page shows the fit report: the residuals,
each constant and whether the data determine it, and the twin characterized as the valve was
(a figure in % by twin − valve in percentage points, the others by twin/valve).
"""

from __future__ import annotations

import json
import math
import tomllib
from pathlib import Path
from typing import TYPE_CHECKING, cast

from PySide6.QtWidgets import QHBoxLayout, QLabel, QLineEdit, QPushButton, QTableWidgetItem

from prm9tool.analysis.profile import ProfileError
from prm9tool.characterize.run import planned_s
from prm9tool.i18n import format_significant
from prm9tool.online.twin_fit import ReportFit, history_of, valve_procedure
from prm9tool.service.twin import ProvenTwin
from prm9tool.translate import error_text
from prm9tool.twin import proof
from prm9tool.views.files import dialogs as file_dialogs
from prm9tool.views.tuning.host import TuningHost, figure_table
from prm9tool.views.tuning.pages import Page
from prm9tool.views.tuning.report import figure_label

if TYPE_CHECKING:
    from prm9tool.characterize.run import Figure


def _g(value: float | None, digits: int = 4) -> str:
    if value is None or not math.isfinite(value):
        return "—"
    return format_significant(value, digits).replace("-", "−")


def _with_unit(value: float | None, unit: str) -> str:
    """``0.0158 s``; a figure not measured is "—" alone (not "— s")."""
    shown = _g(value)
    return shown if shown == "—" else f"{shown} {unit}".strip()


def _twin_serial(path: Path) -> int | None:
    """The serial an existing twin file is of (None: no such file, or not a twin file)."""
    try:
        serial = tomllib.loads(path.read_text(encoding="utf-8")).get("serial")
    except (OSError, UnicodeDecodeError, tomllib.TOMLDecodeError):
        return None
    return serial if isinstance(serial, int) else None


def _report_serial(path: Path) -> int | None:
    """The valve's serial in a characterization's JSON report (None: not readable here; the
    fit itself says why)."""
    try:
        serial = json.loads(path.read_text(encoding="utf-8")).get("valve", {}).get("serial")
    except (OSError, UnicodeDecodeError, ValueError, AttributeError):
        return None
    return serial if isinstance(serial, int) else None


class TwinPage(Page):
    """Fit twin: the valve characterized and fitted, or a report fitted; the fit report."""

    def __init__(self, window: TuningHost) -> None:
        super().__init__(window)
        self.about = QLabel()
        self.about.setWordWrap(True)
        self.layout().insertWidget(0, self.about)  # type: ignore[union-attr]
        self.out = QLineEdit()
        self.browse = QPushButton()
        self.browse.clicked.connect(self._browse)
        row = QHBoxLayout()
        row.addWidget(self.out, 1)
        row.addWidget(self.browse)
        self.labels["out"] = QLabel()
        self.form.addRow(self.labels["out"], row)
        self.from_report = QPushButton()
        self.from_report.clicked.connect(self.fit_report_file)
        self.buttons.insertWidget(1, self.from_report)
        self.constants = figure_table(4)
        self.sides = figure_table(4)
        self.layout().insertWidget(4, self.constants, 1)  # type: ignore[union-attr]
        self.layout().insertWidget(5, self.sides, 1)  # type: ignore[union-attr]
        self.plot.hide()  # the page shows tables, no curves
        self.reports = ReportFit(self)
        self.reports.finished.connect(self.show_result)
        self.reports.failed.connect(self.show_failure)
        self.reports.busy_changed.connect(self._on_report_busy)
        self.last: ProvenTwin | None = None
        self._busy = {"test": False, "report": False}  # a test on the valve, a report's fit

    def _suggested(self, serial: int | None = None) -> str:
        serial = serial or getattr(getattr(self.window_.connection, "device", None), "serial", None)
        serial = serial or self.window_.doc.source_serial
        return f"{serial}-twin.toml" if serial else "twin.toml"

    def _browse(self, serial: int | None = None) -> None:
        path = self.window_.save_file(
            self.tr("Save the twin file"), self.tr("Twin file (*.toml)"), self._suggested(serial)
        )
        if path is not None:
            self.out.setText(str(path))

    def _target(self, serial: int | None = None) -> Path | None:
        """The twin file to write for the valve ``serial`` (asked for when the field is empty
        or names the twin of another serial: never overwritten unasked); None: cancelled or a
        folder that does not exist (the result line says so)."""
        text = self.out.text().strip()
        if not text or (serial and _twin_serial(Path(text)) not in (None, serial)):
            chosen = self.window_.save_file(
                self.tr("Save the twin file"),
                self.tr("Twin file (*.toml)"),
                self._suggested(serial),
            )
            if chosen is None:  # cancelled: the field keeps what it named
                return None
            text = str(chosen)
            self.out.setText(text)
        path = Path(text)
        if not path.parent.is_dir():
            self.result.setText(
                self.tr("There is no folder %1 for the twin file.").replace("%1", str(path.parent))
            )
            return None
        return path

    def run(self) -> None:
        """Characterize the connected valve and fit its twin (``--fit-twin --device``)."""
        connection = self.window_.connection
        if connection is None or not getattr(connection, "is_online", False):
            self.result.setText(
                self.tr(
                    "A twin is fitted to a valve's own measurement: go online with the valve, "
                    "or fit it from a characterization report (Fit from a report…)."
                )
            )
            return
        try:
            profile = self.window_.profile()
        except ProfileError as exc:
            self.result.setText(error_text(exc))
            return
        path = self._target(getattr(getattr(connection, "device", None), "serial", None))
        if path is None:
            return
        seconds = planned_s(profile)
        what = self.tr(
            "the end-of-line test (steps, a sine sweep and a triangle, about %1 s), then the "
            "twin fitted to it"
        ).replace("%1", f"{seconds:.0f}")
        self.window_.start("twin", what, valve_procedure(connection, path, profile), seconds)

    def fit_report_file(self) -> None:
        """Fit the twin of a characterization's JSON report (``--fit-twin --from``)."""
        name, _ = file_dialogs.open_file_name(
            self, self.tr("Characterization report"), "", self.tr("JSON report (*.json)")
        )
        if not name:
            return
        path = self._target(_report_serial(Path(name)))
        if path is None:
            return
        self.result.setText(self.tr("Fitting the twin of %1…").replace("%1", name))
        self.reports.start(name, path, history_of(self.window_.connection))

    def set_busy(self, busy: bool) -> None:
        """A test runs on the valve (or no longer): no fit meanwhile."""
        self._busy["test"] = busy
        self._enable()

    def _on_report_busy(self, busy: bool) -> None:
        self._busy["report"] = busy
        self._enable()

    def _enable(self) -> None:
        idle = not any(self._busy.values())
        self.run_button.setEnabled(idle)
        self.from_report.setEnabled(idle)

    def show_failure(self, message: str) -> None:
        """Why the fit did not run or stopped."""
        self.result.setText(self.tr("Not fitted: %1").replace("%1", message))

    def show_result(self, result: object) -> None:
        """The fit report: residuals, constants, the twin characterized as the valve was."""
        assert isinstance(result, ProvenTwin)
        self.last = result
        fit = result.twin.fit
        verdict = (
            self.tr("explained by the plant structure")
            if fit.explained
            else self.tr(
                "NOT explained by the plant structure: its constants are the best it allows"
            )
        )
        text = self.tr(
            "Twin written to %1 and recorded in the history. Residual %2 % → %3 % rms (%4)."
        )
        text = text.replace("%1", str(result.twin.path)).replace("%2", _g(fit.start_rms_pct, 3))
        text = text.replace("%3", _g(fit.rms_pct, 3)).replace("%4", verdict)
        parts = ", ".join(
            f"{self._part(kind)} {_g(value, 3)} %" for kind, value in fit.parts_rms_pct.items()
        )
        if parts:
            text += " " + self.tr("Fitted: %1.").replace("%1", parts)
        if result.proof_problem:
            text += " " + self.tr("The twin could not be characterized: %1").replace(
                "%1", result.proof_problem
            )
        elif result.proof_link:  # over the valve's kind of link (its run's, in English)
            text += " " + self.tr("The twin was characterized over: %1.").replace(
                "%1", result.proof_link
            )
        self.result.setText(text)
        self.constants.setRowCount(len(fit.constants))
        for row, c in enumerate(fit.constants):
            state = self.tr("determined") if c.determined else self.tr("not determined, kept")
            if c.correlated_with:
                state += " " + self.tr("(seen only with %1)").replace("%1", c.correlated_with)
            for col, value in enumerate((c.name, _g(c.start), _g(c.value), state)):
                self.constants.setItem(row, col, QTableWidgetItem(value))
        kinds = {"difference": self.tr("%1 pp (twin − valve)"),
                 "ratio": self.tr("×%1 (twin/valve)")}  # fmt: skip
        self.sides.setRowCount(len(result.sides))
        for row, s in enumerate(result.sides):
            compared = proof.compared(s, lambda v: _g(v, 3), kinds)  # the command line's
            label = figure_label(cast("Figure", s))  # by its name, as the test report's
            cells = (label, _with_unit(s.valve, s.unit), _with_unit(s.twin, s.unit), compared)
            for col, value in enumerate(cells):
                self.sides.setItem(row, col, QTableWidgetItem(value.strip()))
        self.constants.resizeRowsToContents()
        self.sides.resizeRowsToContents()

    def _part(self, kind: str) -> str:
        names = {"step": self.tr("steps"), "sweep": self.tr("sweep"),
                 "static": self.tr("static characteristic")}  # fmt: skip
        return names.get(kind, kind)

    def retranslate(self) -> None:
        """Texts."""
        self.about.setText(
            self.tr(
                "A twin is the emulator's plant with the constants of this valve, fitted to its "
                "characterization (steps, sweep and static characteristic) and kept in a twin "
                "file with its serial and parameter set (docs/twin.md). Fit twin of the valve "
                "runs the end-of-line test of the profile chosen on the Test report page on the "
                "connected valve; Fit from a report… takes a characterization's JSON report "
                "(prm9tool --characterize --json) and its CSV files. Both record the twin in the "
                "history for the serial; offline tuning then runs on it."
            )
        )
        self.tr_label("out", self.tr("Twin file:"))
        self.browse.setText(self.tr("Browse…"))
        self.run_button.setText(self.tr("Fit twin of the valve"))
        self.from_report.setText(self.tr("Fit from a report…"))
        self.constants.setHorizontalHeaderLabels(
            [self.tr("Constant"), self.tr("Start"), self.tr("Fitted"), self.tr("Data")]
        )
        self.sides.setHorizontalHeaderLabels(
            [
                self.tr("Figure"),
                self.tr("Valve"),
                self.tr("Twin"),
                self.tr("Twin compared with valve"),
            ]
        )
        if self.last is not None:
            self.show_result(self.last)

"""The Tuning window's "Autotune" page: a proposal checked against the acceptance profile.

The procedure (:func:`prm9tool.characterize.acceptance.propose`) tunes, checks the proposal with
the profile's steps in both directions and its static test, and retries with a stricter
overshoot target while it fails. The page shows the gains, the autotune's step before/after
(measured) and simulated as the controller dialog simulates it, the profile's figures before
and after with their verdicts, and overlays of the profile's steps. Gains that fail the profile,
or rest on an identification that is not trustworthy, are accepted only after "Accept anyway".
"""

from __future__ import annotations

from typing import Any

from PySide6.QtWidgets import (
    QCheckBox,
    QComboBox,
    QHBoxLayout,
    QPushButton,
    QTableWidgetItem,
)

from prm9tool.analysis.model import Targets
from prm9tool.analysis.profile import ProfileError
from prm9tool.characterize.acceptance import TRIES, Proposal, step_start
from prm9tool.characterize.autotune import AutotuneResult
from prm9tool.characterize.frame import LOOPS, step_window
from prm9tool.characterize.procedures import StepResult
from prm9tool.i18n import format_number, format_significant
from prm9tool.service import autotune
from prm9tool.service.autotune import LOOP_DEFAULTS, AutotuneSettings
from prm9tool.translate import error_text, translated
from prm9tool.views.tuning.host import TuningHost, figure_table, gain_text, spin
from prm9tool.views.tuning.pages import Page
from prm9tool.views.tuning.plot import COLOURS, Plot, Series
from prm9tool.views.tuning.report import (
    figure_label,
    limit_text,
    profile_name,
    value_short,
    value_text,
    verdict,
)

GREY = "#808080"
RED, GREEN = "#c00000", "#207020"


class AutotunePage(Page):
    """Model-based (no oscillation) or critical-gain autotune, checked, before/after, accept."""

    def __init__(self, window: TuningHost) -> None:
        super().__init__(window)
        self.method = self.field("method", QComboBox())
        self.method.addItems(["", ""])
        self.amplitude = self.field("amplitude", spin(50.0, 1.0, 90.0, "%"))
        self.overshoot = self.field("overshoot", spin(10.0, 0.0, 50.0, "%"))
        self.settling = self.field("settling", spin(40.0, 2.0, 2000.0, "ms", 0))
        self.limit = self.field("limit", spin(60.0, 5.0, 100.0, "%"))
        self.accept_button = QPushButton()
        self.accept_button.setEnabled(False)
        self.accept_button.clicked.connect(self.accept)
        self.buttons.insertWidget(1, self.accept_button)
        self.override = QCheckBox()  # shown when the proposal fails the profile or is untrusted
        self.override.setVisible(False)
        self.override.toggled.connect(self._override_toggled)
        self.buttons.insertWidget(2, self.override)
        self.table = figure_table(5)  # figure, before, proposed, limit, result
        layout = self.layout()
        layout.removeWidget(self.plot)  # type: ignore[union-attr]
        row = QHBoxLayout()
        row.addWidget(self.plot, 1)
        row.addWidget(self.table, 1)
        layout.addLayout(row, 1)  # type: ignore[union-attr]
        self.proposal: dict[str, int] = {}
        self.last: Proposal | None = None
        self.loop_shown = "position"  # the loop whose default targets the fields show

    def set_loop(self, loop: str) -> None:
        """The step amplitude and settling target follow the loop chosen (the process loop's
        integrating actuator settles in about 0.5 s, not the spool's 40 ms), unless the user
        changed them from the previous loop's defaults."""
        before, after = LOOP_DEFAULTS[self.loop_shown], LOOP_DEFAULTS[loop]
        self.loop_shown = loop
        for box, old, new in zip((self.amplitude, self.settling), before, after, strict=True):
            if box.value() == old:
                box.setValue(new)

    def run(self) -> None:
        """Tune with the chosen method and check the proposal against the profile."""
        try:
            profile = self.window_.profile()
        except ProfileError as exc:
            self.result.setText(error_text(exc))
            return
        loop = self.window_.current_loop()
        amplitude, limit = self.amplitude.value(), self.limit.value()
        targets = Targets(self.overshoot.value(), self.settling.value() / 1000.0)
        settings = AutotuneSettings(loop, "model" if self.method.currentIndex() == 0 else
                                    "critical", targets.overshoot_pct, self.settling.value(),
                                    amplitude, limit, profile)  # fmt: skip
        steps = ", ".join(
            f"±{format_significant(a, 6)}" for a in profile.for_loop(loop).step_amplitudes_pct
        )
        method = "model" if self.method.currentIndex() == 0 else "critical"
        if method == "model":
            what = self.tr("steps of %1 % from 0 %, a few times").replace(
                "%1", format_significant(amplitude, 6)
            )
        else:
            what = self.tr("P only with rising gain until the loop oscillates (steps of 5 %, "
                           "oscillation stopped at ±%1 %)").replace("%1", format_significant(limit, 6))  # fmt: skip
        seconds = planned_s(profile.for_loop(loop), loop, targets.settling_s, method)
        what += self.tr(
            "; then the acceptance profile's steps of %1 % and its static test (a triangle of "
            "%2 s) with the present and the proposed gains; about %3 s in all"
        ).replace("%1", steps).replace("%2", format_significant(profile.for_loop(loop).static_period_s, 6)).replace(
            "%3", f"{seconds:.0f}"
        )  # fmt: skip
        self.window_.start(
            "autotune",
            what,
            lambda rig: autotune.run(rig, settings),  # --autotune's, Valve.autotune()'s
            seconds,
        )

    def show_result(self, result: object) -> None:
        """Proposed gains, before/after (measured, simulated), the profile's verdict."""
        assert isinstance(result, Proposal)
        self.last = result
        self.proposal = dict(result.values)
        found = result.method
        if isinstance(found, AutotuneResult):
            m = found.model
            doubts = [translated(d) for d in found.doubts]
            head = self.tr("Model: gain %1, lags %2 ms, dead time %3 ms (fit error %4 %).").replace(
                "%1", format_significant(m.gain, 3)).replace(
                "%2", ", ".join(format_number(t * 1000, 2) for t in (m.tau1, m.tau2, m.tau3))).replace(
                "%3", format_number(m.delay * 0.2, 1)).replace("%4", format_number(m.fit_error, 1))  # fmt: skip
        else:
            doubts = []
            head = self.tr("Critical gain Kkr = %1, period Tkr = %2 ms: K = 0.5·Kkr, Ti = 0.8·Tkr, Td = 0.12·Tkr.").replace(
                "%1", format_number(found.kkr, 2)).replace("%2", format_number(found.tkr * 1000, 1))  # fmt: skip
        rows = [
            f"{k}: {gain_text(k, result.present[k])} → <b>{gain_text(k, v)}</b>"
            for k, v in self.proposal.items()
        ]
        figures = (
            self.tr("%1 — before: %2; proposed: %3.")
            .replace("%1", translated(result.before.caption()))
            .replace("%2", self._step_text(result.before))
            .replace("%3", self._step_text(result.after))
        )
        figures += " " + self.tr(
            "Proposed, simulated on the emulator's firmware (as the controller dialog): %1."
        ).replace("%1", self._step_text(result.simulated))
        lines = [head, " · ".join(rows), figures]
        for earlier in result.tried:
            gains = ", ".join(f"{k} {gain_text(k, v)}" for k, v in earlier.values.items())
            failed = ", ".join(figure_label(f) for f in earlier.failed[:3])
            lines.append(
                self.tr("Tried before and failed the profile: %1 (%2).")
                .replace("%1", gains)
                .replace("%2", failed)
            )
        colour = GREEN if result.passes else RED
        label = lambda f: f"{figure_label(f)} {value_text(f)}"  # noqa: E731
        said = translated(result.verdict(label, profile_name(result.profile.name)))
        lines.append(f'<b><font color="{colour}">{said}</font></b>')
        if doubts:
            warning = self.tr("Do not accept these gains: the identification is not trustworthy.")
            lines.append(f'<b><font color="{RED}">' + " ".join([warning, *doubts]) + "</font></b>")
        self.result.setText("<br>".join(lines))
        self._fill_table(result)
        self.plot.show_plots(self._plots(result))
        self.override.blockSignals(True)
        self.override.setChecked(False)
        self.override.blockSignals(False)
        refused = not autotune.may_apply(result)  # the rule of --autotune --apply
        self.override.setVisible(refused)
        self.accept_button.setEnabled(not refused)

    def _fill_table(self, result: Proposal) -> None:
        pairs = list(zip(result.before_check.figures, result.after_check.figures, strict=True))
        self.table.setRowCount(len(pairs))
        for row, (before, after) in enumerate(pairs):
            cells = (
                (figure_label(after), ""),
                value_short(before),
                value_short(after),
                (limit_text(after), ""),
                (verdict(after.passed), ""),
            )
            for col, (text, tip) in enumerate(cells):
                item = QTableWidgetItem(text)
                item.setToolTip(tip)
                self.table.setItem(row, col, item)
        self.table.resizeRowsToContents()

    def _plots(self, result: Proposal) -> list[Plot]:
        actual = LOOPS[result.before.loop].actual
        ms, pct = self.tr("time [ms]"), "%"

        def line(step: StepResult, label: str, colour: str, dashed: bool = False) -> Series:
            return Series(step.record.t * 1000, step.record.channels[actual], label, colour, dashed)

        plots = [
            Plot(
                translated(result.before.caption()),
                ms,
                pct,
                [
                    line(result.before, self.tr("before (measured)"), COLOURS[0]),
                    line(result.after, self.tr("proposed (measured)"), COLOURS[1]),
                    line(result.simulated, self.tr("proposed (simulated)"), COLOURS[2], True),
                ],
            )
        ]
        pairs = zip(result.before_check.steps, result.after_check.steps, strict=True)
        by_size: dict[tuple[float, float], list[Series]] = {}
        for before, after in pairs:
            series = by_size.setdefault((abs(after.amplitude_pct), step_start(after)), [])
            # the steps both ways share their colours: one legend entry each, not four
            first = not series
            series.append(line(before, self.tr("before") if first else "", GREY, True))
            series.append(line(after, self.tr("proposed") if first else "", COLOURS[1]))
        for (size, start), series in by_size.items():
            title = self.tr("Acceptance steps of %1 %").replace("%1", format_significant(size, 6))
            if start:  # steps around an operating point (the E04 process loop's)
                title = (
                    self.tr("Acceptance steps of %1 % from %2 %")
                    .replace("%1", format_significant(size, 6))
                    .replace("%2", format_significant(start, 6).replace("-", "−"))
                )
            plots.append(Plot(title, ms, pct, series))
        return plots

    def _override_toggled(self, checked: bool) -> None:
        """A proposal that fails the profile or rests on an untrusted fit needs this choice."""
        self.accept_button.setEnabled(checked and bool(self.proposal))

    def _step_text(self, step: Any) -> str:
        f = step.figures
        if f is None:
            return self.tr("no response")
        why = f.not_settled("%")
        settle = (
            f"{format_number(f.settling_time * 1000, 1)} ms" if why is None else translated(why)
        )
        return (
            self.tr("overshoot %1 %, settling %2")
            .replace("%1", format_number(f.overshoot, 1))
            .replace("%2", settle)
        )

    def accept(self) -> None:
        """The proposal into the document, one undo step."""
        if self.proposal and self.window_.accept_values(self.proposal, self.tr("Autotune")):
            self.accept_button.setEnabled(False)  # refused (access level): kept to accept later
            self.override.setVisible(False)

    def retranslate(self) -> None:
        """Texts."""
        self.method.setItemText(0, self.tr("Model-based (never oscillates)"))
        self.method.setItemText(1, self.tr("Critical gain (APOSYS 10 rule)"))
        self.tr_label("method", self.tr("Method:"))
        self.tr_label("amplitude", self.tr("Step amplitude:"))
        self.tr_label("overshoot", self.tr("Target overshoot at most:"))
        self.tr_label("settling", self.tr("Target settling time (±2 %) at most:"))
        self.tr_label("limit", self.tr("Stop when the response leaves 0 ± (band):"))
        self.run_button.setText(self.tr("Run autotune"))
        self.accept_button.setText(self.tr("Accept the proposed gains"))
        self.override.setText(self.tr("Accept anyway (I checked the measurement)"))
        self.table.setHorizontalHeaderLabels(
            [
                self.tr("Figure"),
                self.tr("Before"),
                self.tr("Proposed"),
                self.tr("Limit"),
                self.tr("Result"),
            ]
        )


def planned_s(profile: Any, loop: str, settling_s: float, method: str) -> float:
    """Valve seconds the autotune with its acceptance check takes about (for the progress)."""
    window = step_window(loop, settling_s)
    tune = (6 if method == "model" else 40) * (max(0.1, window) + window)
    one = profile.step_duration_s * 2 + max(0.1, profile.step_duration_s) * 2
    checks = len(profile.step_amplitudes_pct) * one * (TRIES + 2) + 2 * profile.static_period_s
    return tune * (TRIES if method == "model" else 1) + checks

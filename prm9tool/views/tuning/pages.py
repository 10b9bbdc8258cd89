"""The pages of the Tuning window: autotune, Bode, static characteristic, test report."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from PySide6.QtCore import QRectF
from PySide6.QtGui import QPainter, QPaintEvent
from PySide6.QtWidgets import (
    QCheckBox,
    QComboBox,
    QFormLayout,
    QHBoxLayout,
    QLabel,
    QPushButton,
    QVBoxLayout,
    QWidget,
)

from prm9tool.analysis.model import Targets
from prm9tool.analysis.pid import to_parameters
from prm9tool.analysis.profile import DEFAULT
from prm9tool.characterize.autotune import (
    AutotuneResult,
    compare_steps,
    model_tune,
    simulate_steps,
)
from prm9tool.characterize.procedures import (
    LOOPS,
    BodeResult,
    CriticalGainResult,
    StepResult,
    bode_test,
    critical_gain_tune,
)
from prm9tool.characterize.run import Characterization
from prm9tool.translate import translated
from prm9tool.views.tuning.host import TuningHost, gain_text, spin
from prm9tool.views.tuning.plot import COLOURS, Plot, Series, paint_plot
from prm9tool.views.tuning.report import (
    bode_plots,
)


class PlotView(QWidget):
    """Shows one or more :class:`Plot` stacked vertically, in the palette's colours."""

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.plots: list[Plot] = []
        self.setMinimumHeight(200)

    def show_plots(self, plots: list[Plot]) -> None:
        """Replace what is shown."""
        self.plots = plots
        self.update()

    def paintEvent(self, _event: QPaintEvent) -> None:
        painter = QPainter(self)
        painter.setRenderHint(QPainter.RenderHint.Antialiasing)
        painter.fillRect(self.rect(), self.palette().base())
        ink = self.palette().text().color()
        height = self.height() / max(1, len(self.plots))
        for k, plot in enumerate(self.plots):
            paint_plot(painter, QRectF(0, k * height, self.width(), height), plot, ink)
        painter.end()


class Page(QWidget):
    """Common parts: a form of settings, a Run button, a result text and a plot."""

    def __init__(self, window: TuningHost) -> None:
        super().__init__()  # the window's tabs become its parent
        self.window_ = window
        self.form = QFormLayout()
        self.labels: dict[str, QLabel] = {}
        self.run_button = QPushButton()
        self.run_button.clicked.connect(self.run)
        self.result = QLabel()
        self.result.setWordWrap(True)
        self.result.setMinimumHeight(self.result.fontMetrics().height() * 3)
        self.plot = PlotView()
        self.buttons = QHBoxLayout()
        self.buttons.addWidget(self.run_button)
        self.buttons.addStretch(1)
        layout = QVBoxLayout(self)
        layout.addLayout(self.form)
        layout.addLayout(self.buttons)
        layout.addWidget(self.result)
        layout.addWidget(self.plot, 1)

    def field(self, key: str, widget: QWidget) -> Any:
        """Add a labelled settings field."""
        self.labels[key] = QLabel()
        self.form.addRow(self.labels[key], widget)
        return widget

    def set_busy(self, busy: bool) -> None:
        """Disable the Run button while a test runs."""
        self.run_button.setEnabled(not busy)

    def run(self) -> None:
        """Start this page's test."""

    def show_result(self, result: object) -> None:
        """Show a finished test's result."""

    def retranslate(self) -> None:
        """Texts in the program language."""

    def tr_label(self, key: str, text: str) -> None:
        """Set a field's label."""
        self.labels[key].setText(text)


class AutotunePage(Page):
    """Model-based (no oscillation) or critical-gain autotune, before/after, accept."""

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
        self.override = QCheckBox()  # shown when the identification is not trustworthy
        self.override.setVisible(False)
        self.override.toggled.connect(self._override_toggled)
        self.buttons.insertWidget(2, self.override)
        self.proposal: dict[str, int] = {}

    def run(self) -> None:
        """Run the chosen method."""
        loop = self.window_.current_loop()
        amplitude = self.amplitude.value()
        targets = Targets(self.overshoot.value(), self.settling.value() / 1000.0)
        duration = max(3 * targets.settling_s, 0.06)
        limit = self.limit.value()
        if self.method.currentIndex() == 0:
            what = self.tr("steps of %1 % from 0 %, a few times, about %2 s in all")
            what = what.replace("%1", f"{amplitude:g}").replace("%2", f"{4 * duration:.1f}")
            self.window_.start(
                "autotune", what, lambda rig: model_tune(rig, targets, loop, amplitude, 3, limit)
            )
            return
        what = self.tr("P only with rising gain until the loop oscillates (steps of 5 %, "
                       "oscillation stopped at ±%1 %), about 5 s").replace("%1", f"{limit:g}")  # fmt: skip

        def critical(rig: Any) -> tuple[CriticalGainResult, Any, Any]:
            found = critical_gain_tune(rig, loop, limit_pct=limit)
            proposed = to_parameters(LOOPS[loop].prefix, found.gains)
            simulated = simulate_steps(rig, loop, proposed, amplitude, duration)
            return found, compare_steps(rig, loop, proposed, amplitude, duration), simulated

        self.window_.start("autotune", what, critical)

    def show_result(self, result: object) -> None:
        """Proposed gains, before/after (simulated, measured)."""
        loop = self.window_.current_loop()
        prefix = LOOPS[loop].prefix
        present = {
            k: int(self.window_.doc.value(k))
            for k in (prefix + s for s in ("KP", "KI", "KD", "T1"))
        }
        doubts: list[str] = []
        if isinstance(result, AutotuneResult):
            doubts = [translated(d) for d in result.doubts]
            self.proposal = result.proposed_values
            before, after, simulated = result.before, result.after, result.simulated
            head = self.tr("Model: gain %1, lags %2 ms, dead time %3 ms (fit error %4 %).").replace(
                "%1", f"{result.model.gain:.3g}").replace(
                "%2", ", ".join(f"{t * 1000:.2f}" for t in (result.model.tau1, result.model.tau2, result.model.tau3))).replace(
                "%3", f"{result.model.delay * 0.2:.1f}").replace("%4", f"{result.model.fit_error:.1f}")  # fmt: skip
        else:
            found: CriticalGainResult = result[0]  # type: ignore[index]
            before, after = result[1]  # type: ignore[index]
            self.proposal = to_parameters(prefix, found.gains)
            simulated = result[2][1]  # type: ignore[index]  # a StepResult on the emulator
            head = self.tr("Critical gain Kkr = %1, period Tkr = %2 ms: K = 0.5·Kkr, Ti = 0.8·Tkr, Td = 0.12·Tkr.").replace(
                "%1", f"{found.kkr:.2f}").replace("%2", f"{found.tkr * 1000:.1f}")  # fmt: skip

        rows = [
            f"{k}: {gain_text(k, present[k])} → <b>{gain_text(k, v)}</b>"
            for k, v in self.proposal.items()
        ]
        figures = self._figures(before, after)
        if isinstance(simulated, StepResult):
            figures += " " + self.tr("Proposed, simulated on the emulator's firmware: %1.").replace(
                "%1", self._step_text(simulated)
            )
        text = head + "<br>" + " · ".join(rows) + "<br>" + figures
        if doubts:
            warning = self.tr("Do not accept these gains: the identification is not trustworthy.")
            text += '<br><b><font color="#c00000">' + " ".join([warning, *doubts]) + "</font></b>"
        self.result.setText(text)
        series = [
            Series(before.record.t * 1000, before.record.channels[LOOPS[loop].actual], self.tr("before (measured)"), COLOURS[0]),
            Series(after.record.t * 1000, after.record.channels[LOOPS[loop].actual], self.tr("proposed (measured)"), COLOURS[1]),
        ]  # fmt: skip
        if isinstance(simulated, StepResult):
            t, y = simulated.record.t * 1000, simulated.record.channels[LOOPS[loop].actual]
            series.append(Series(t, y, self.tr("proposed (simulated)"), COLOURS[2], True))
        elif simulated is not None:
            t = np.arange(len(simulated)) * 0.2
            series.append(Series(t, simulated, self.tr("proposed (simulated)"), COLOURS[2], True))
        self.plot.show_plots([Plot(self.tr("Step response"), self.tr("time [ms]"), "%", series)])
        self.override.blockSignals(True)
        self.override.setChecked(False)
        self.override.blockSignals(False)
        self.override.setVisible(bool(doubts))
        self.accept_button.setEnabled(not doubts)

    def _override_toggled(self, checked: bool) -> None:
        """An untrustworthy proposal can be accepted only after this explicit choice."""
        self.accept_button.setEnabled(checked and bool(self.proposal))

    def _step_text(self, step: Any) -> str:
        f = step.figures
        if f is None:
            return self.tr("no response")
        settle = "—" if math.isnan(f.settling_time) else f"{f.settling_time * 1000:.1f} ms"
        return (
            self.tr("overshoot %1 %, settling %2")
            .replace("%1", f"{f.overshoot:.1f}")
            .replace("%2", settle)
        )

    def _figures(self, before: Any, after: Any) -> str:
        return (
            self.tr("Before: %1. Proposed: %2.")
            .replace("%1", self._step_text(before))
            .replace("%2", self._step_text(after))
        )

    def accept(self) -> None:
        """The proposal into the document, one undo step."""
        if self.proposal:
            self.window_.accept_values(self.proposal, self.tr("Autotune"))
            self.accept_button.setEnabled(False)
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


class BodePage(Page):
    """A logarithmic sine sweep around an operating point."""

    def __init__(self, window: TuningHost) -> None:
        super().__init__(window)

        self.amplitude = self.field("amplitude", spin(10.0, 1.0, 90.0, "%"))
        self.centre = self.field("centre", spin(0.0, -50.0, 50.0, "%"))
        self.f_min = self.field("f_min", spin(1.0, 0.1, 100.0, "Hz"))
        self.f_max = self.field("f_max", spin(200.0, 10.0, 1000.0, "Hz"))
        self.duration = self.field("duration", spin(10.0, 1.0, 60.0, "s"))

    def run(self) -> None:
        """Sweep."""
        a, c, lo, hi, d = (
            w.value() for w in (self.amplitude, self.centre, self.f_min, self.f_max, self.duration)
        )
        loop = self.window_.current_loop()
        what = self.tr("a sine sweep %1 … %2 Hz of ±%3 % around %4 %, %5 s").replace("%1", f"{lo:g}").replace(
            "%2", f"{hi:g}").replace("%3", f"{a:g}").replace("%4", f"{c:g}").replace("%5", f"{d:g}")  # fmt: skip
        self.window_.start("bode", what, lambda rig: bode_test(rig, a, c, lo, hi, d, loop))

    def _frequency(self, value: float, above: float) -> str:
        """``29.3 Hz``, ``above 100 Hz`` (not reached by the sweep's end) or ``not reached``."""
        if not math.isnan(value):
            return f"{value:.1f} Hz"
        if not math.isnan(above):
            return self.tr("above %1 Hz").replace("%1", f"{above:g}")
        return self.tr("not reached")

    def show_result(self, result: object) -> None:
        """Magnitude, phase, −3 dB and −90°."""
        assert isinstance(result, BodeResult)
        fake = Characterization(None, DEFAULT, "", {}, bode=result)  # type: ignore[arg-type]
        self.plot.show_plots(list(bode_plots(fake)))
        r = result.response
        text = self.tr("−3 dB: %1, −90°: %2.").replace(
            "%1", self._frequency(r.bandwidth_hz(), r.bandwidth_above_hz())).replace(
            "%2", self._frequency(r.phase_90_hz(), r.phase_90_above_hz()))  # fmt: skip
        if result.lost_samples:
            text += " " + self.tr(
                "%1 of %2 samples were lost on the link and left out of the estimate."
            ).replace("%1", str(result.lost_samples)).replace("%2", str(len(result.record.t)))
        if result.limited_to_hz is not None:
            text += " " + self.tr(
                "The link's sample rate limited the sweep to %1 Hz (nothing interpolated)."
            ).replace("%1", f"{result.limited_to_hz:g}")
        self.result.setText(text)

    def retranslate(self) -> None:
        """Texts."""
        for key, text in (
            ("amplitude", self.tr("Amplitude:")),
            ("centre", self.tr("Operating point:")),
            ("f_min", self.tr("From:")),
            ("f_max", self.tr("To:")),
            ("duration", self.tr("Duration:")),
        ):
            self.tr_label(key, text)  # fmt: skip
        self.run_button.setText(self.tr("Measure the frequency response"))

"""The Tuning window's static pages: the static characteristic with its proposals (dead-band
offsets and 9-point linearization, previewed together and applied as one undo step) and, on
E04, the flow characteristic (actuator velocity over spool opening) with its offsets."""

from __future__ import annotations

import numpy as np
from PySide6.QtWidgets import QPushButton

from prm9tool.analysis.deadband import (
    FULL,
    dead_band,
    gain_offset,
    gain_offset_inverse,
    offsets_for,
)
from prm9tool.analysis.profile import DEFAULT
from prm9tool.analysis.static import linearization_values, propose_linearization
from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.variant import Config
from prm9tool.characterize.flow import FlowResult, flow_test
from prm9tool.characterize.procedures import StaticResult, static_test
from prm9tool.characterize.run import Characterization
from prm9tool.i18n import format_number, format_significant
from prm9tool.views.tuning.host import TuningHost, spin
from prm9tool.views.tuning.pages import Page
from prm9tool.views.tuning.plot import COLOURS, Plot, Series
from prm9tool.views.tuning.report import static_plot

STAGE = ("GAINSETPOS", "OFFSETPOS", "GAINSETNEG", "OFFSETNEG")
PREVIEW_POINTS = 400


def _pct(raw: float) -> str:
    return format_number(raw / FULL * 100.0, 1)


class ProposalPage(Page):
    """A page whose result is a set of parameter values to apply as one undo step."""

    def __init__(self, window: TuningHost) -> None:
        super().__init__(window)
        self.apply_button = QPushButton()
        self.apply_button.setEnabled(False)
        self.apply_button.clicked.connect(self.apply)
        self.buttons.insertWidget(1, self.apply_button)
        self.proposal: dict[str, int] = {}

    def stage_values(self) -> dict[str, int]:
        """The document's gain/offset stage (the parameters this valve has)."""
        variant = self.window_.doc.variant
        return {k: int(self.window_.doc.value(k)) for k in STAGE if CATALOGUE[k].applies(variant)}

    def undo_text(self) -> str:
        """The undo step's name."""
        return ""

    def apply(self) -> None:
        """The proposal into the document, one undo step."""
        if self.proposal and self.window_.accept_values(self.proposal, self.undo_text()):
            self.apply_button.setEnabled(False)  # refused (access level): kept to apply later


class StaticPage(ProposalPage):
    """A slow triangle; hysteresis, linearity, dead band, gain; offsets and linearization."""

    def __init__(self, window: TuningHost) -> None:
        super().__init__(window)

        self.period = self.field("period", spin(20.0, 2.0, 600.0, "s"))

    def run(self) -> None:
        """Triangle over the whole range."""
        period = self.period.value()
        what = self.tr("a triangle over the whole range −100 … 100 %, %1 s").replace(
            "%1", format_significant(period, 6)
        )
        self.window_.start("static", what, lambda rig: static_test(rig, period))

    def show_result(self, result: object) -> None:
        """Figures, the curve, and the offsets and linearization previewed on it."""
        assert isinstance(result, StaticResult)
        c = result.characteristic
        fake = Characterization(None, DEFAULT, "", {}, static=result)  # type: ignore[arg-type]
        plot = static_plot(fake)
        text = self.tr("Gain %1, hysteresis %2 %, linearity error %3 %, dead band %4 %.").replace(
            "%1", format_number(c.gain, 3)).replace("%2", format_number(c.hysteresis_pct, 2)).replace(
            "%3", format_number(c.linearity_pct, 2)).replace("%4", format_number(c.dead_band_pct, 1))  # fmt: skip
        ch = result.record.channels
        self.proposal = {}
        if not np.isfinite(ch["setpoint_gain"]).all():  # a link without these measuring points
            text += " " + self.tr(
                "No proposal: this link does not sample the setpoint chain (USB and the "
                "emulator do)."
            )
        else:
            text += " " + self._propose(result, plot)
        self.plot.show_plots([plot])
        self.result.setText(text)
        self.apply_button.setEnabled(bool(self.proposal))

    def _propose(self, result: StaticResult, plot: Plot) -> str:
        ch = result.record.channels
        stage_out = ch["setpoint_gain"] * FULL / 100.0
        lin_out = ch["setpoint_linearized"] * FULL / 100.0
        response = ch["position_actual"]
        present = self.stage_values()
        doc = self.window_.doc
        offsets: dict[str, int] = {}
        note = ""
        # E04 in control mode 4: the stage acts on the control deviation (flow page)
        if doc.variant.config is not Config.E04 or int(doc.value("CTRLMODE")) != 4:
            band = dead_band(stage_out, response)
            offsets = {k: v for k, v in offsets_for(band, present).items() if k in present}
            note = self.tr(
                "Dead band behind the gain/offset stage %1 … %2 %: offsets %3."
            ).replace("%1", _pct(band.negative)).replace("%2", _pct(band.positive)).replace(
                "%3", ", ".join(f"{k} {_pct(v)} %" for k, v in offsets.items()))  # fmt: skip
        new_stage = {**present, **offsets}
        new_out = gain_offset(gain_offset_inverse(stage_out, present), new_stage)
        lin = propose_linearization(new_out, lin_out, response, result.demand)
        self.proposal = {
            **{k: v for k, v in offsets.items() if present[k] != v},
            **linearization_values(lin),
        }
        order = np.argsort(lin_out)
        predicted = np.interp(np.interp(new_out, lin.xs, lin.ys), lin_out[order], response[order])
        step = max(1, len(predicted) // PREVIEW_POINTS)
        label = self.tr("with the proposed offsets and linearization (preview)")
        plot.series.append(
            Series(result.demand[::step], predicted[::step], label, COLOURS[3], True)
        )
        return note

    def undo_text(self) -> str:
        """The undo step's name."""
        return self.tr("Offsets and linearization from the static characteristic")

    def retranslate(self) -> None:
        """Texts."""
        self.tr_label("period", self.tr("Triangle period:"))
        self.run_button.setText(self.tr("Measure the static characteristic"))
        self.apply_button.setText(self.tr("Apply the proposed offsets and linearization"))


class FlowPage(ProposalPage):
    """E04: the actuator's velocity over the spool's opening; dead-band offsets from it."""

    def __init__(self, window: TuningHost) -> None:
        super().__init__(window)

        self.amplitude = self.field("amplitude", spin(40.0, 5.0, 90.0, "%"))
        self.centre = self.field("centre", spin(0.0, -50.0, 50.0, "%"))
        self.duration = self.field("duration", spin(1.0, 0.2, 30.0, "s"))

    def run(self) -> None:
        """Two process setpoint steps with the process loop made proportional."""
        a, c, d = self.amplitude.value(), self.centre.value(), self.duration.value()
        what = (
            self.tr(
                "process setpoint steps %1 → %2 → %1 % with the process controller proportional "
                "only, %3 s each"
            )
            .replace("%1", format_significant(c - a, 6).replace("-", "−"))
            .replace("%2", format_significant(c + a, 6).replace("-", "−"))
            .replace("%3", format_significant(d, 6))
        )
        self.window_.start("flow", what, lambda rig: flow_test(rig, a, c, d))

    def show_result(self, result: object) -> None:
        """The curve, its gain and dead band, the offsets previewed on it."""
        assert isinstance(result, FlowResult)
        flow = result.characteristic
        present = self.stage_values()
        self.proposal = {
            k: v for k, v in result.offsets.items() if k in present and present[k] != v
        }
        lo, hi = flow.band.negative / FULL * 100.0, flow.band.positive / FULL * 100.0
        x = np.linspace(-100.0, 100.0, 201)
        shift_pos = result.offsets["OFFSETPOS"] / FULL
        shift_neg = result.offsets.get("OFFSETNEG", result.offsets["OFFSETPOS"]) / FULL
        # the jump Kp·offset opens the spool to the edge; the rest of the range is squeezed
        shifted = np.where(
            x > 0, hi + x * (1 - shift_pos), np.where(x < 0, lo + x * (1 - shift_neg), 0.0)
        )
        ok = np.isfinite(flow.velocity)
        preview = np.interp(shifted, flow.x[ok], flow.velocity[ok])
        plot = Plot(
            self.tr("Flow characteristic"),
            self.tr("spool opening [%]"),
            self.tr("actuator velocity [%/s]"),
            [
                Series(flow.x, flow.velocity, self.tr("measured"), COLOURS[0]),
                Series(x, preview, self.tr("with the proposed offsets (preview)"), COLOURS[3], True),
            ],
        )  # fmt: skip
        self.plot.show_plots([plot])
        self.result.setText(
            self.tr("Flow gain %1 %/s per % of opening, dead band %2 … %3 % (width %4 %). "
                    "Proposed offsets on the control deviation (process Kp %5): %6.")
            .replace("%1", format_number(flow.gain, 2)).replace("%2", format_number(lo, 1))
            .replace("%3", format_number(hi, 1)).replace("%4", format_number(flow.dead_band_pct, 1))
            .replace("%5", format_significant(result.kp, 6))
            .replace("%6", ", ".join(f"{k} {_pct(v)} %" for k, v in result.offsets.items()))
        )  # fmt: skip
        self.apply_button.setEnabled(bool(self.proposal))

    def undo_text(self) -> str:
        """The undo step's name."""
        return self.tr("Offsets from the flow characteristic")

    def retranslate(self) -> None:
        """Texts."""
        self.tr_label("amplitude", self.tr("Step around the operating point:"))
        self.tr_label("centre", self.tr("Operating point:"))
        self.tr_label("duration", self.tr("Duration of each step:"))
        self.run_button.setText(self.tr("Measure the flow characteristic"))
        self.apply_button.setText(self.tr("Apply the proposed offsets"))

"""Threshold, gain and zero offset with the resulting transfer curve (manual figure 8-9).

On E02 valves threshold, gain and offset act on the setpoint one after the other. On E04
the threshold acts on the setpoint while gain and offset act on the control deviation of the
process loop (manual §8.7.2, figure 8-18 items 12–15), so the E04 diagram has two blocks.
"""

from __future__ import annotations

from PySide6.QtWidgets import QWidget

from prm9tool.catalogue import CATALOGUE
from prm9tool.views.diagram.curves import transfer_curve
from prm9tool.views.diagram.dialogs.base import BlockContext, BlockDialog
from prm9tool.views.diagram.dialogs.plot import BLUE, GREY, Axes, Curve, PlotWidget

THRESHOLD = ("THRESETP",)
GAIN_OFFSET = ("GAINSETPOS", "GAINSETNEG", "OFFSETPOS", "OFFSETNEG")


class ThresholdGainDialog(BlockDialog):
    """Edits any of threshold / gain / offset and draws input → output."""

    def __init__(
        self,
        ctx: BlockContext,
        block_id: str,
        title: str,
        with_threshold: bool,
        with_gain: bool,
        parent: QWidget | None = None,
    ) -> None:
        super().__init__(ctx, block_id, title, parent)
        self.with_threshold, self.with_gain = with_threshold, with_gain
        names = (THRESHOLD if with_threshold else ()) + (GAIN_OFFSET if with_gain else ())
        for mnemonic in names:
            if CATALOGUE[mnemonic].applies(self.doc.variant):
                self.value_field(mnemonic)
        self.plot = PlotWidget()
        self.side.addWidget(self.plot)
        self.finish()

    def _display(self, mnemonic: str, absent: float) -> float:
        param = CATALOGUE[mnemonic]
        if not param.applies(self.doc.variant):
            return absent
        value = param.to_display(self.doc.value(mnemonic))
        return float(value) if isinstance(value, (int, float)) else absent

    def curve_parameters(self) -> tuple[float, tuple[float, float], tuple[float, float]]:
        """Threshold (%), gains (+, −) and offsets (+, −) as the curve uses them."""
        limit = self._display("THRESETP", 0.0) if self.with_threshold else 0.0
        if not self.with_gain:
            return limit, (1.0, 1.0), (0.0, 0.0)
        gain_pos = self._display("GAINSETPOS", 1.0)
        off_pos = self._display("OFFSETPOS", 0.0)
        gains = (gain_pos, self._display("GAINSETNEG", gain_pos))
        offsets = (off_pos, self._display("OFFSETNEG", off_pos))
        return limit, gains, offsets

    def refresh_extra(self) -> None:
        limit, gains, offsets = self.curve_parameters()
        one_sided = not CATALOGUE["GAINSETNEG"].applies(self.doc.variant)
        deviation = self.with_gain and not self.with_threshold
        x_title = self.tr("Control deviation in (%)") if deviation else self.tr("Setpoint in (%)")
        y_title = self.tr("Control deviation out (%)") if deviation else self.tr("Setpoint out (%)")
        x_low = 0.0 if one_sided and not deviation else -100.0
        self.plot.set_axes(Axes((x_low, 100.0), (x_low * 1.1, 110.0), x_title, y_title))
        curve = [(x, y) for x, y in transfer_curve(limit, gains, offsets) if x >= x_low]
        self.plot.set_curves(
            [
                Curve(
                    [(x_low, x_low), (100.0, 100.0)], GREY, self.tr("1:1"), dashed=True, width=1.2
                ),
                Curve(curve, BLUE, self.tr("output")),
            ]
        )

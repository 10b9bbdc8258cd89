"""Current limiter per coil and dither amplitude/frequency (manual figure 8-13).

The sketch shows each coil's current at 60 % of its limit with the dither superimposed,
clipped at the limit (coil B drawn downwards on two-coil valves). The dither is drawn by the
rule the valve applies (:mod:`prm9tool.catalogue.dither`: DTAMP 100 % = a peak of 10 % of the
nominal coil current CURNORM, a decision; the manual gives only "%").
"""

from __future__ import annotations

from PySide6.QtWidgets import QLabel, QWidget

from prm9tool.catalogue import CATALOGUE, dither
from prm9tool.i18n import format_significant, unbroken_units
from prm9tool.views.diagram.curves import dither_wave
from prm9tool.views.diagram.dialogs.base import BlockContext, BlockDialog
from prm9tool.views.diagram.dialogs.plot import BLUE, GREEN, RED, Axes, Curve, PlotWidget

LOAD = 0.6  # the sketched operating point, as a fraction of the coil's limit


class CurrentDitherDialog(BlockDialog):
    """LIMTA/LIMTB, DTAMP, DYNFREQ and the dithered coil current."""

    def __init__(
        self, ctx: BlockContext, block_id: str, title: str, parent: QWidget | None = None
    ) -> None:
        super().__init__(ctx, block_id, title, parent)
        self.coils = [c for c in "AB" if CATALOGUE[f"LIMT{c}"].applies(self.doc.variant)]
        for coil in self.coils:
            self.value_field(f"LIMT{coil}")
        self.curnorm_label = QLabel()
        self.curnorm_label.setWordWrap(True)
        self.form.addRow(self.curnorm_label)
        self.value_field("DTAMP")
        self.value_field("DYNFREQ")
        self.watch("CURNORM")
        self.plot = PlotWidget()
        self.side.addWidget(self.plot)
        self.finish()

    def curnorm(self) -> int:
        """Nominal coil current in mA (read from the valve, or the catalogue default)."""
        return int(self.doc.value("CURNORM"))

    def refresh_extra(self) -> None:
        curnorm = self.curnorm()
        amplitude = dither.amplitude_ma(float(self.doc.value("DTAMP")), curnorm)
        self.curnorm_label.setText(  # wrapped, but never between "2600" and "mA"
            unbroken_units(
                self.tr("Nominal coil current CURNORM: %1 mA — no limit may exceed it.").replace(
                    "%1", str(curnorm)
                )
                + "\n"
                + self.tr("Dither: ±%1 mA peak (DTAMP 100 % = %2 % of CURNORM).")
                .replace("%1", f"{amplitude:.0f}")
                .replace("%2", format_significant(dither.FULL_SCALE * 100, 6))
            )
        )
        freq = dither.frequency_hz(float(self.doc.value("DYNFREQ")))
        curves, lines = [], []
        for coil, colour, sign in (("A", BLUE, 1.0), ("B", GREEN, -1.0)):
            if coil not in self.coils:
                continue
            limit = float(self.doc.value(f"LIMT{coil}"))
            wave = [(t, sign * i) for t, i in dither_wave(LOAD * limit, amplitude, freq, limit)]
            curves.append(Curve(wave, colour, self.tr("coil %1").replace("%1", coil)))
            lines.append((sign * limit, RED, self.tr("limit %1").replace("%1", coil)))
        end = curves[0].points[-1][0] if curves else 1.0
        top = max(curnorm, *(abs(value) for value, _c, _l in lines)) * 1.12
        bottom = -top if "B" in self.coils else 0.0
        title = self.tr("Coil current (mA)")
        if self.coils == ["A", "B"]:
            title = self.tr("Coil current (mA), coil B downwards")
        self.plot.set_axes(Axes((0.0, end), (bottom, top), self.tr("Time (ms)"), title, lines))
        self.plot.set_curves(curves)

"""Signal type and polarity of the setpoint input and (E04) of the external sensor input.

Manual §8.7.2 figures 8-8 and 8-14; the recommended setpoint types per coil layout are those
of table 8-4 (catalogue ``RECOMMENDED_SETPOINT_TYPES``).
"""

from __future__ import annotations

from PySide6.QtWidgets import QLabel, QWidget

from prm9tool.catalogue import CATALOGUE, RECOMMENDED_SETPOINT_TYPES, variant_label
from prm9tool.translate import translated
from prm9tool.views.diagram.curves import INPUT_RANGES, input_curve
from prm9tool.views.diagram.dialogs.base import BlockContext, BlockDialog
from prm9tool.views.diagram.dialogs.plot import BLUE, Axes, Curve, PlotWidget

CANOPEN_CODE = 14


class SignalInputDialog(BlockDialog):
    """Type and polarity of an analog input, with the input → internal value line drawn."""

    def __init__(
        self,
        ctx: BlockContext,
        block_id: str,
        title: str,
        type_mn: str,
        polarity_mn: str,
        parent: QWidget | None = None,
    ) -> None:
        super().__init__(ctx, block_id, title, parent)
        self._type_mn, self._polarity_mn = type_mn, polarity_mn
        self._setpoint = type_mn == "AINSETP"
        codes = [
            c
            for c, _ in CATALOGUE[type_mn].choices
            if c != CANOPEN_CODE or self.doc.variant.canopen
        ]
        self.type_field = self.choice_field(type_mn, codes, self._decorate)
        self.polarity_field = self.choice_field(polarity_mn)
        self.note = QLabel()
        self.note.setWordWrap(True)
        self.form.addRow(self.note)
        self.warning = QLabel()
        self.warning.setWordWrap(True)
        self.set_paper_style(self.warning, "color: #a15c00;")
        self.form.addRow(self.warning)
        self.plot = PlotWidget()
        self.side.addWidget(self.plot)
        self.finish()

    def _recommended(self) -> frozenset[int]:
        if not self._setpoint:
            return frozenset()
        return RECOMMENDED_SETPOINT_TYPES[self.doc.variant.coils]

    def _decorate(self, code: int, label: str) -> str:
        if code in self._recommended():
            return self.tr("%1 — recommended").replace("%1", label)
        return label

    def retranslate(self) -> None:
        super().retranslate()
        if self._setpoint:
            self.note.setText(
                self.tr(
                    "Recommended for this coil layout (manual table 8-4) are the types marked "
                    "'recommended'. With positive polarity a positive setpoint drives coil A."
                )
            )
        else:
            self.note.setText(
                self.tr(
                    "With inverted polarity the sensor signal enters the process loop with a negative sign."
                )
            )

    def refresh_extra(self) -> None:
        code = self.doc.value(self._type_mn)
        inverted = self.doc.value(self._polarity_mn) == 1
        if not isinstance(code, int) or code not in INPUT_RANGES:
            return
        rng = INPUT_RANGES[code]
        margin = 0.05 * (rng.high - rng.low)
        self.plot.set_axes(
            Axes(
                (min(0.0, rng.low) - margin, rng.high + margin),
                (-110.0, 110.0),
                self.tr("Input signal (%1)").replace("%1", rng.unit),
                self.tr("Internal value (%)"),
            )
        )
        self.plot.set_curves([Curve(input_curve(code, inverted), BLUE, self.tr("internal value"))])
        warn = self._setpoint and code != CANOPEN_CODE and code not in self._recommended()
        self.warning.setText(
            self.tr("This type is not recommended for a valve with %1 (manual table 8-4).").replace(
                "%1", translated(variant_label(self.doc.variant))
            )
            if warn
            else ""
        )

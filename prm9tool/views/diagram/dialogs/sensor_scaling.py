"""Zero offset and gain of the external sensor signal (E04, manual figure 8-15)."""

from __future__ import annotations

from PySide6.QtWidgets import QWidget

from prm9tool.catalogue import CATALOGUE
from prm9tool.views.diagram.curves import sensor_curve
from prm9tool.views.diagram.dialogs.base import BlockContext, BlockDialog
from prm9tool.views.diagram.dialogs.plot import BLUE, GREY, Axes, Curve, PlotWidget


class SensorScalingDialog(BlockDialog):
    """SENSOFFS and SENSGAIN with the sensor's input → output line."""

    def __init__(
        self, ctx: BlockContext, block_id: str, title: str, parent: QWidget | None = None
    ) -> None:
        super().__init__(ctx, block_id, title, parent)
        self.value_field("SENSOFFS")
        self.value_field("SENSGAIN")
        self.plot = PlotWidget()
        self.side.addWidget(self.plot)
        self.finish()

    def refresh_extra(self) -> None:
        offset = float(CATALOGUE["SENSOFFS"].to_display(self.doc.value("SENSOFFS")))
        gain = float(CATALOGUE["SENSGAIN"].to_display(self.doc.value("SENSGAIN")))
        self.plot.set_axes(
            Axes(
                (-100.0, 100.0),
                (-110.0, 110.0),
                self.tr("Sensor signal in (%)"),
                self.tr("Process actual value (%)"),
            )
        )
        self.plot.set_curves(
            [
                Curve(
                    [(-100.0, -100.0), (100.0, 100.0)], GREY, self.tr("1:1"), dashed=True, width=1.2
                ),
                Curve(sensor_curve(offset, gain), BLUE, self.tr("after offset and gain")),
            ]
        )

"""The four setpoint ramps with a preview of a 100 % and a 50 % step (manual figure 8-11).

Each time is for a 100 % step; smaller steps take proportionally less. At Basic access level
all four ramps are set together with one value (one undo step, :mod:`prm9tool.model.editing`).
"""

from __future__ import annotations

from PySide6.QtWidgets import QHBoxLayout, QLabel, QWidget

from prm9tool.catalogue import CATALOGUE, Access
from prm9tool.views.diagram.curves import ramp_preview
from prm9tool.views.diagram.dialogs.base import BlockContext, BlockDialog
from prm9tool.views.diagram.dialogs.fields import ValueField
from prm9tool.views.diagram.dialogs.plot import BLUE, ORANGE, Axes, Curve, PlotWidget

RAMPS = ("RAMPSETPOSUP", "RAMPSETPOSDOWN", "RAMPSETNEGUP", "RAMPSETNEGDOWN")


class RampsDialog(BlockDialog):
    """Four ramp times (Expert) or one time for all (Basic), and the step preview."""

    def __init__(
        self, ctx: BlockContext, block_id: str, title: str, parent: QWidget | None = None
    ) -> None:
        super().__init__(ctx, block_id, title, parent)
        self.present = [mn for mn in RAMPS if CATALOGUE[mn].applies(self.doc.variant)]
        for mnemonic in self.present:
            self.value_field(mnemonic)
        # At Basic level one field sets all ramps; it writes RAMPSETPOSUP, which
        # prm9tool.model.editing links to every ramp of the valve.
        self.all_field = ValueField("RAMPSETPOSUP", self.apply_value, self.show_error)
        self.all_caption = QLabel()
        row = QWidget()  # with its unit, as every other field of the dialogs
        layout = QHBoxLayout(row)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addWidget(self.all_field)
        self.all_unit = QLabel(CATALOGUE["RAMPSETPOSUP"].unit)
        layout.addWidget(self.all_unit)
        layout.addStretch(1)
        self.form.addRow(self.all_caption, row)
        self.note = QLabel()
        self.note.setWordWrap(True)
        self.form.addRow(self.note)
        self.plot = PlotWidget()
        self.side.addWidget(self.plot)
        self.finish()

    @property
    def basic(self) -> bool:
        """True when the four ramps are edited together."""
        return self.access.level is Access.BASIC

    def retranslate(self) -> None:
        super().retranslate()
        self.all_caption.setText(self.tr("All ramps (for a 100 % step)"))

    def refresh(self) -> None:
        super().refresh()
        basic = self.basic
        for mnemonic in self.present:
            self._set_row_visible(self.fields[mnemonic], not basic)
        self._set_row_visible(self.all_field, basic)
        times = {self.doc.value(mn) for mn in self.present}
        if len(times) == 1:
            self.all_field.show_value(self.doc)
        else:
            self.all_field.show_blank(self.tr("the ramps differ"))
        self.all_field.update_access(self.access, False)
        self.note.setText(
            self.tr(
                "Basic access level: one time sets all ramps. Expert level sets each ramp on its own."
            )
            if basic
            else self.tr("Each time is for a 100 % step; a 50 % step takes half as long.")
        )

    def _set_row_visible(self, field: QWidget, visible: bool) -> None:
        row_widget = field.parentWidget() if field.parentWidget() is not self else field
        if row_widget is None:
            return
        label = self.form.labelForField(row_widget)
        row_widget.setVisible(visible)
        if label is not None:
            label.setVisible(visible)

    def _ms(self, mnemonic: str) -> float:
        if mnemonic not in self.present:
            return 0.0
        return float(self.doc.value(mnemonic))

    def refresh_extra(self) -> None:
        up, down = self._ms("RAMPSETPOSUP"), self._ms("RAMPSETPOSDOWN")
        neg_up, neg_down = self._ms("RAMPSETNEGUP"), self._ms("RAMPSETNEGDOWN")
        longest = max(up, down, neg_up, neg_down, 1.0)
        hold = max(longest * 1.2, 20.0)
        two_sided = "RAMPSETNEGUP" in self.present
        curves = [
            Curve(ramp_preview(100.0, up, down, hold), BLUE, self.tr("100 % step")),
            Curve(ramp_preview(50.0, up, down, hold), ORANGE, self.tr("50 % step")),
        ]
        if two_sided:
            curves += [
                Curve(ramp_preview(-100.0, neg_up, neg_down, hold), BLUE, dashed=True),
                Curve(ramp_preview(-50.0, neg_up, neg_down, hold), ORANGE, dashed=True),
            ]
        end = curves[0].points[-1][0]
        y_low = -110.0 if two_sided else -5.0
        self.plot.set_axes(
            Axes(
                (-0.1 * hold, max(end, hold * 1.3)),
                (y_low, 110.0),
                self.tr("Time (ms)"),
                self.tr("Demand value (%)"),
            )
        )
        self.plot.set_curves(curves)

"""Cursor read-out and step-response figures shown next to the oscilloscope plot."""

from __future__ import annotations

import math
from collections.abc import Sequence

from PySide6.QtCore import Qt, Signal
from PySide6.QtWidgets import (
    QCheckBox,
    QComboBox,
    QFormLayout,
    QGridLayout,
    QLabel,
    QVBoxLayout,
    QWidget,
)

from prm9tool.catalogue.signals import MAX_CHANNELS
from prm9tool.catalogue.signals import Signal as MeasuringPoint
from prm9tool.i18n import format_number, format_significant, text
from prm9tool.scope import CursorReadout, StepMeasurement, Verdict
from prm9tool.translate import translated
from prm9tool.views.scope.legend import COLOURS


def _value(value: float, unit: str, digits: int = 4) -> str:
    return "—" if math.isnan(value) else f"{format_significant(value, digits)} {unit}".rstrip()


def _fixed(value: float, unit: str, size: float) -> str:
    """``value`` with three significant digits of ``size`` (the step), so noise reads as 0."""
    if math.isnan(value):
        return "—"
    decimals = max(0, 2 - math.floor(math.log10(abs(size)))) if size else 2
    return f"{format_number(value, decimals)} {unit}".rstrip()


def _time(seconds: float) -> str:
    if math.isnan(seconds):
        return "—"
    if abs(seconds) < 1.0:
        return f"{format_significant(seconds * 1000, 4)} ms"
    return f"{format_significant(seconds, 4)} s"


class CursorPanel(QWidget):
    """Δt, 1/Δt and per channel the values at A and B and their difference (a tab; its
    window title is the tab's name)."""

    cursors_toggled = Signal(bool)

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        grid = QGridLayout(self)
        self.show_cursors = QCheckBox()
        self.show_cursors.toggled.connect(self.cursors_toggled)
        grid.addWidget(self.show_cursors, 0, 0, 1, 4)
        self.headers = [QLabel() for _ in range(4)]
        for col, header in enumerate(self.headers):
            grid.addWidget(header, 1, col)
        self.cells = [[QLabel() for _ in range(4)] for _ in range(MAX_CHANNELS)]
        for row, cells in enumerate(self.cells, start=2):
            for col, cell in enumerate(cells):
                grid.addWidget(cell, row, col)
        self.dt = QLabel()
        grid.addWidget(self.dt, MAX_CHANNELS + 2, 0, 1, 4)
        grid.setRowStretch(MAX_CHANNELS + 3, 1)
        self._units: list[str] = []
        self.retranslate()
        self.show_readout(None)

    def retranslate(self) -> None:
        """Re-read user-visible texts (after a language change)."""
        self.setWindowTitle(self.tr("Cursors"))
        self.show_cursors.setText(self.tr("Cursors A/B"))
        for header, label in zip(self.headers, ("", "A", "B", "B − A"), strict=True):
            header.setText(f"<b>{label}</b>")

    def set_channels(self, signals: Sequence[MeasuringPoint]) -> None:
        """One row per active channel."""
        self._units = [s.unit for s in signals]
        for slot, cells in enumerate(self.cells):
            for cell in cells:
                cell.setVisible(slot < len(signals))
            if slot < len(signals):
                cells[0].setText(f'<span style="color:{COLOURS[slot]}">■</span> {slot + 1}')
                cells[0].setToolTip(text(signals[slot].text))
        self.show_readout(None)

    def show_readout(self, readout: CursorReadout | None) -> None:
        """Show the values of ``readout`` (None: cursors off)."""
        for slot, unit in enumerate(self._units):
            values = (
                (readout.a[slot], readout.b[slot], readout.delta[slot])
                if readout is not None
                else (math.nan,) * 3
            )
            for cell, value in zip(self.cells[slot][1:], values, strict=True):
                cell.setText(_value(float(value), unit))
        if readout is None:
            self.dt.setText(self.tr("Switch the cursors on to measure."))
        else:
            self.dt.setText(
                self.tr("Δt = {0}    1/Δt = {1}").format(
                    _time(readout.dt), _value(readout.frequency, "Hz")
                )
            )


class StepPanel(QWidget):
    """Rise time, overshoot, settling time and steady-state error of the response channel
    (a tab; its window title is the tab's name)."""

    channels_changed = Signal()  # reference, response or region changed

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.reference, self.response = QComboBox(), QComboBox()
        for combo in (self.reference, self.response):
            combo.setSizeAdjustPolicy(
                QComboBox.SizeAdjustPolicy.AdjustToMinimumContentsLengthWithIcon
            )
            combo.setMinimumContentsLength(10)  # as wide as the panel; full name: tooltip
        self.region = QLabel()
        self.region.setWordWrap(True)
        self.between_cursors = QCheckBox()
        self.between_cursors.toggled.connect(lambda _: self.channels_changed.emit())
        self.figures = {
            name: QLabel() for name in ("step", "rise", "overshoot", "settling", "error")
        }
        settling = self.figures["settling"]  # "did not settle …: oscillation of …"
        settling.setWordWrap(True)
        settling.setMinimumHeight(settling.fontMetrics().lineSpacing() * 3)  # room kept for it
        settling.setAlignment(Qt.AlignmentFlag.AlignLeft | Qt.AlignmentFlag.AlignTop)  # by its name
        channels, self.form = QFormLayout(), QFormLayout()  # short labels: wide combos
        channels.setFieldGrowthPolicy(QFormLayout.FieldGrowthPolicy.AllNonFixedFieldsGrow)
        fields = [self.reference, self.response, *self.figures.values()]
        self.labels = [QLabel() for _ in fields]
        for n, (label, field) in enumerate(zip(self.labels, fields, strict=True)):
            (channels if n < 2 else self.form).addRow(label, field)
        self.labels[fields.index(settling)].setAlignment(settling.alignment())  # one line
        layout = QVBoxLayout(self)
        layout.addLayout(channels)
        layout.addLayout(self.form)
        layout.addWidget(self.between_cursors)
        layout.addWidget(self.region)
        self.reference.currentIndexChanged.connect(lambda _: self.channels_changed.emit())
        self.response.currentIndexChanged.connect(lambda _: self.channels_changed.emit())
        self._units: list[str] = []
        self.retranslate()
        self.show_figures(None, "")

    def retranslate(self) -> None:
        """Re-read user-visible texts (after a language change)."""
        self.setWindowTitle(self.tr("Step response"))
        self.between_cursors.setText(self.tr("Only between cursors A and B"))
        labels = (
            self.tr("Reference"),
            self.tr("Response"),
            self.tr("Step"),
            self.tr("Rise time 10–90 %"),
            self.tr("Overshoot"),
            self.tr("Settling time ±2 %"),
            self.tr("Steady-state error"),
        )
        for label, label_text in zip(self.labels, labels, strict=True):
            label.setText(label_text)
        if self.reference.count():
            self.reference.setItemText(0, self.tr("(none: step on the response)"))

    def set_channels(self, signals: Sequence[MeasuringPoint]) -> None:
        """Offer the active channels; default: channel 1 is the reference, channel 2 responds."""
        self._units = [s.unit for s in signals]
        for combo in (self.reference, self.response):
            combo.blockSignals(True)
            combo.clear()
        self.reference.addItem(self.tr("(none: step on the response)"), -1)
        for slot, signal in enumerate(signals):
            label = f"{slot + 1}: {text(signal.text)}"
            for combo in (self.reference, self.response):
                combo.addItem(label, slot)
                combo.setItemData(combo.count() - 1, label, Qt.ItemDataRole.ToolTipRole)
        two = len(signals) >= 2
        self.reference.setCurrentIndex(1 if two else 0)
        self.response.setCurrentIndex(1 if two else 0)
        for combo in (self.reference, self.response):
            combo.blockSignals(False)
            combo.updateGeometry()  # its size hint follows the longest name
        self.channels_changed.emit()

    def reference_slot(self) -> int | None:
        """Channel whose step is the reference (None: detect the step on the response)."""
        slot = self.reference.currentData()
        return None if slot is None or slot < 0 else int(slot)

    def response_slot(self) -> int | None:
        """Channel whose response is measured."""
        slot = self.response.currentData()
        return None if slot is None else int(slot)

    def units_match(self) -> bool:
        """True when the reference and the response have the same unit (or no reference)."""
        ref, resp = self.reference_slot(), self.response_slot()
        if ref is None or resp is None or max(ref, resp) >= len(self._units):
            return True
        return self._units[ref] == self._units[resp]

    def show_figures(self, measurement: StepMeasurement | None, region: str) -> None:
        """Show the figures of ``measurement`` made on ``region`` (a description like 'the
        visible window'), or why there are none; None: nothing recorded."""
        slot = self.response_slot()
        unit = self._units[slot] if slot is not None and slot < len(self._units) else ""
        figures = measurement.figures if measurement is not None else None
        if figures is None:
            for label in self.figures.values():
                label.setText("—")
            self.region.setText(self._why_not(measurement, region))
            return
        assert measurement is not None
        size = figures.final - figures.initial
        self.figures["step"].setText(
            f"{_fixed(figures.initial, unit, size)} → {_fixed(figures.final, unit, size)}"
            f"  @ {_time(figures.t_step)}"
        )
        self.figures["rise"].setText(_time(figures.rise_time))
        self.figures["overshoot"].setText(f"{format_number(figures.overshoot, 1)} %")
        why = figures.not_settled(unit)  # what it did instead, e.g. oscillate at 24 Hz
        self.figures["settling"].setText(
            _time(figures.settling_time) if why is None else translated(why)
        )
        self.figures["error"].setText(_fixed(figures.steady_state_error, unit, size))
        if measurement.steps > 1:
            self.region.setText(
                self.tr("Measured on step {0} of {1} in {2}.").format(
                    measurement.measured + 1, measurement.steps, region
                )
            )
        else:
            self.region.setText(self.tr("Measured on {0}.").format(region))

    def _why_not(self, measurement: StepMeasurement | None, region: str) -> str:
        """Why ``measurement`` has no figures, in words."""
        if measurement is None or not region:
            return ""
        if measurement.verdict is Verdict.TOO_SHORT:
            return self.tr(
                "Window too short: in {0} the response has not come to rest yet. "
                "Widen the time window or move the cursors apart."
            ).format(region)
        if measurement.verdict is Verdict.NO_REFERENCE:
            return self.tr(
                "No step found: the reference channel has no data in {0}. Over CANopen the "
                "valve does not report its demand value; the channel shows the setpoint "
                "prm9tool sends while its setpoint generator runs. Start the generator, or "
                "choose “(none: step on the response)”."
            ).format(region)
        if measurement.verdict is Verdict.NO_DATA:
            return self.tr(
                "No step found: the response channel has no data in {0} (the link does not "
                "deliver this measuring point, or lost every sample)."
            ).format(region)
        if measurement.verdict is Verdict.NO_RESPONSE:
            return self.tr(
                "No response to the step in {0}: the response stays flat or within its noise."
            ).format(region)
        return self.tr("No step found in {0}.").format(region)

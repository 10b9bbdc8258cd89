"""Analog inputs: the electrical signal types of manual table 7-15 and their A/D conversion.

Reading of the code table (inference, documented in docs/emulator.md): "unipolar" maps the
electrical range onto 0…+100 %, "bipolar" onto −100…+100 % (e.g. 7 = 0…10 V with 5 V as 0 %,
3 = 4…20 mA bipolar = the "12 ± 8 mA" of table 8-4). Ratiometric types refer to
Uref = supply voltage / 2 (table 7-15: "U napájení/2").
"""

from __future__ import annotations

from dataclasses import dataclass

from prm9tool.device.emulator.constants import FULL, FirmwareConstants

CANOPEN_TYPE = 14  # "value received over CANopen" (0x2100/2 or RPDO2; for AINSETP: 0x6300)


@dataclass(frozen=True)
class InputType:
    """One electrical signal type: unit, nominal range and output polarity."""

    code: int
    unit: str  # "V" or "mA"
    lo: float
    hi: float
    bipolar: bool
    ratiometric: bool = False

    @property
    def loop_powered(self) -> bool:
        """True for 4…20 mA, where a current below 3.6 mA means a broken wire."""
        return self.unit == "mA" and self.lo == 4.0

    def span(self, supply_v: float) -> tuple[float, float]:
        """Electrical range ``(lo, hi)``; ratiometric types scale with Uref = supply / 2."""
        if self.ratiometric:
            return 0.0, supply_v / 2.0
        return self.lo, self.hi

    def to_normalized(self, value: float, supply_v: float, fw: FirmwareConstants) -> float:
        """A/D-convert an electrical value (12 bit over the input's clamp range) to ±16384."""
        clamp = fw.current_input_range_ma if self.unit == "mA" else fw.voltage_input_range_v
        value = min(max(value, -clamp), clamp)
        step = 2.0 * clamp / 2**fw.adc_bits
        value = round(value / step) * step
        lo, hi = self.span(supply_v)
        fraction = (value - lo) / (hi - lo)
        out = (2.0 * fraction - 1.0) * FULL if self.bipolar else fraction * FULL
        return min(max(out, -FULL if self.bipolar else 0.0), FULL)

    def from_fraction(self, fraction: float, supply_v: float) -> float:
        """The electrical value a sensor sends for ``fraction`` (0…1) of its measuring range."""
        lo, hi = self.span(supply_v)
        return lo + fraction * (hi - lo)

    def signal_error(self, value: float, supply_v: float, fw: FirmwareConstants) -> bool:
        """True if the value means a broken wire or a signal beyond its range."""
        if self.loop_powered and value < fw.loop_break_ma:
            return True
        lo, hi = self.span(supply_v)
        margin = (fw.over_range - 1.0) * (hi - lo)
        return value < lo - margin or value > hi + margin


INPUT_TYPES: dict[int, InputType] = {
    0: InputType(0, "mA", 0.0, 20.0, False),
    1: InputType(1, "mA", 0.0, 20.0, True),
    2: InputType(2, "mA", 4.0, 20.0, False),
    3: InputType(3, "mA", 4.0, 20.0, True),
    4: InputType(4, "mA", -10.0, 10.0, False),
    5: InputType(5, "mA", -10.0, 10.0, True),
    6: InputType(6, "V", 0.0, 10.0, False),
    7: InputType(7, "V", 0.0, 10.0, True),
    8: InputType(8, "V", -10.0, 10.0, False),
    9: InputType(9, "V", -10.0, 10.0, True),
    10: InputType(10, "V", 0.0, 12.0, False, ratiometric=True),
    11: InputType(11, "V", 0.0, 12.0, True, ratiometric=True),
}

"""The mailbox between the control loop and the firmware, and the 9-point characteristics.

:class:`LoopState` carries *coefficients* (rebuilt by :mod:`.config`, re-read by the loop only
when ``version`` changes), *per-batch inputs* (mode, static setpoint, supply, plant faults) and
*outputs* (every measuring point, written back by the loop once per batch).
"""

from __future__ import annotations

from bisect import bisect_right
from typing import Any

MODE_OFF = 0  # output stage off, controllers reset, spool spring-centred
MODE_HOLD = 1  # position loop holds the preset hold setpoint (0 %)
MODE_ACTIVE = 2  # the signal chain drives the valve

SIGNAL_ORDER = (
    "setpoint_raw",
    "setpoint_threshold",
    "setpoint_gain",
    "setpoint_linearized",
    "demand",
    "process_setpoint",
    "process_actual",
    "process_deviation",
    "position_setpoint",
    "position_actual",
    "position_deviation",
    "controller_output",
    "current_setpoint_a",
    "current_setpoint_b",
    "current_a",
    "current_b",
    "pwm_a",
    "pwm_b",
    "supply_voltage",
    "temperature",
    "sensor_raw",
)
"""Order of the values the loop hands to the capture (one slot per measuring point)."""


class LoopState:
    """Mailbox between the control loop and the firmware (see module docstring)."""

    def __init__(self) -> None:
        self.version = 0  # coefficients changed
        self.inputs_version = 0  # per-batch inputs changed
        self.coefficients: dict[str, Any] = {}
        # per-batch inputs
        self.mode = MODE_OFF
        self.target = 0.0  # static part of the setpoint chain (after linearization)
        self.static_signals = (0.0, 0.0, 0.0, 0.0)  # raw, threshold, gain, linearized
        self.supply_v = 24.0
        self.temperature_c = 25.0
        self.coil_r = (4.0, 4.0)  # actual resistance A, B (temperature dependent)
        self.coil_open = (False, False)
        self.coil_short = (False, False)
        self.stage_on = (True, True)  # the firmware's safety switch per output stage
        self.lvdt_break = False
        self.sensor_static = 0.0  # sensor value when it does not come from the plant
        self.sensor_from_plant = True
        self.sensor_break_value: float | None = None  # reading of a broken sensor, or None
        self.capture: Any = None  # (extend, itemgetter, decimation, buffer, index) or None
        # outputs (measuring points and plant state), written back every batch
        self.signals: tuple[float, ...] = (0.0,) * len(SIGNAL_ORDER)
        self.ctrl_dev = 0.0  # 0x6350: deviation of the active control mode
        self.spool_m = 0.0
        self.spool_v = 0.0
        self.actuator = 0.5
        self.current_ma = (0.0, 0.0)
        self.duty = (0.0, 0.0)  # PWM duty A, B (0…1) at the end of the last batch
        self.lvdt_ma = 12.0  # LVDT 4…20 mA loop current (0 with a cut wire)
        self.sensor_chain = (0.0, 0.0, 0.0, 0.0, 0.0)  # 0x2100/1, /3, /4, /5, /6


Curve = tuple[list[float], list[float], list[float]]


def prepare_curve(xs: list[int], ys: list[int]) -> Curve:
    """Prepare a 9-point characteristic: breakpoints, per-segment slope and intercept.

    ``bisect_right(breakpoints, v)`` selects the segment: 0 is "below X_A" (constant Y_A),
    1…8 interpolate between neighbouring points, 9 is "at or above X_I" (constant Y_I). X points
    that do not increase are raised to the previous one (a curve being edited point by point
    is never an error for the firmware).
    """
    fixed = [float(xs[0])]
    for x in xs[1:]:
        fixed.append(max(float(x), fixed[-1]))
    slopes, icepts = [0.0], [float(ys[0])]
    for i in range(len(fixed) - 1):
        dx = fixed[i + 1] - fixed[i]
        k = (ys[i + 1] - ys[i]) / dx if dx > 0 else 0.0
        slopes.append(k)
        icepts.append(ys[i] - k * fixed[i])
    slopes.append(0.0)
    icepts.append(float(ys[-1]))
    return fixed, slopes, icepts


def evaluate_curve(curve: Curve, v: float) -> float:
    """The characteristic's output at ``v`` (the loop inlines the same two lines)."""
    i = bisect_right(curve[0], v)
    return curve[2][i] + curve[1][i] * v

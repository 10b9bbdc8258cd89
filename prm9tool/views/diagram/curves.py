"""The small curves the block dialogs draw, as plain arithmetic on display units (%, ms, mA).

These are previews of what the valve does with a parameter set (manual §8.7.2, tables 8-1 and 8-2);
the valve (and the emulator) does the real thing every 200 µs.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

from prm9tool.catalogue.scale import FULL_SCALE

FULL = FULL_SCALE  # raw value of 100 % on the normalized internal scale


@dataclass(frozen=True)
class InputRange:
    """How an analog signal type maps its electrical range onto −100…100 %."""

    low: float  # electrical value at the low end (V, mA or % of Uref)
    high: float
    unit: str
    bipolar: bool  # True: low…high → −100…100 %; False: low…high → 0…100 %


# Signal-type codes of manual table 7-15, read as the emulator reads them (docs/emulator.md):
# "unipolar" maps the whole electrical range onto 0…100 %, "bipolar" onto −100…+100 % (e.g.
# 3 = 12±8 mA: 4 mA = −100 %, 12 mA = 0, 20 mA = +100 %). Ratiometric types refer to
# Uref = supply voltage / 2, drawn here in % of Uref.
INPUT_RANGES: dict[int, InputRange] = {
    0: InputRange(0, 20, "mA", False),
    1: InputRange(0, 20, "mA", True),
    2: InputRange(4, 20, "mA", False),
    3: InputRange(4, 20, "mA", True),
    4: InputRange(-10, 10, "mA", False),
    5: InputRange(-10, 10, "mA", True),
    6: InputRange(0, 10, "V", False),
    7: InputRange(0, 10, "V", True),
    8: InputRange(-10, 10, "V", False),
    9: InputRange(-10, 10, "V", True),
    10: InputRange(0, 100, "% of Uref", False),
    11: InputRange(0, 100, "% of Uref", True),
    14: InputRange(-100, 100, "% over CANopen", True),
}


def input_curve(code: int, inverted: bool) -> list[tuple[float, float]]:
    """Electrical input → internal setpoint (%) of signal type ``code`` as a polyline."""
    rng = INPUT_RANGES[code]
    low_pct = -100.0 if rng.bipolar else 0.0
    sign = -1.0 if inverted else 1.0
    return [(rng.low, sign * low_pct), (rng.high, sign * 100.0)]


def threshold(x: float, limit: float) -> float:
    """Dead band around zero: below ``limit`` (%) the signal is 0, above it passes 1:1."""
    return 0.0 if abs(x) < limit else x


def gain_offset(
    x: float, gain_pos: float, gain_neg: float, off_pos: float, off_neg: float
) -> float:
    """Dead-band compensation jump and gain per sign: ``y = off + x·g·(1 − off/100 %)``.

    With gain 1 a 100 % input still gives 100 % (the emulator's firmware does the same);
    the result is clipped to ±100 %.
    """
    if x > 0:
        return min(100.0, off_pos + gain_pos * x * (1.0 - off_pos / 100.0))
    if x < 0:
        return max(-100.0, -off_neg + gain_neg * x * (1.0 - off_neg / 100.0))
    return 0.0


def transfer_curve(
    limit: float, gains: tuple[float, float], offsets: tuple[float, float], steps: int = 400
) -> list[tuple[float, float]]:
    """Input (%) → output (%) through threshold then gain/offset, sampled over ±100 %.

    The jumps at the threshold and at zero (dead-band compensation) are drawn vertical.
    """

    def f(x: float) -> float:
        return gain_offset(threshold(x, limit), *gains, *offsets)

    breaks = sorted({-limit, 0.0, limit} - {-100.0, 100.0})
    xs = sorted({-100.0 + 200.0 * n / steps for n in range(steps + 1)} | set(breaks))
    points = []
    for x in xs:
        if x in breaks:
            points += [(x, f(x - 1e-9)), (x, f(x)), (x, f(x + 1e-9))]
        else:
            points.append((x, f(x)))
    return points


def interpolate(xs: Sequence[float], ys: Sequence[float], x: float) -> float:
    """Piecewise-linear curve through ``xs``/``ys``, held constant outside."""
    if x <= xs[0]:
        return ys[0]
    for x0, x1, y0, y1 in zip(xs, xs[1:], ys, ys[1:], strict=False):
        if x <= x1:
            return y0 if x1 == x0 else y0 + (y1 - y0) * (x - x0) / (x1 - x0)
    return ys[-1]


def clamp_point(
    xs: Sequence[int], ys: Sequence[int], index: int, x: int, y: int
) -> tuple[int, int]:
    """Move point ``index`` of a raw 9-point curve to the nearest spot that keeps it valid.

    X values stay strictly increasing, Y values monotonic (non-decreasing), both within
    ±16384 — the rules of the valve (manual §8.7.2 "Linearizace").
    """
    x_low = xs[index - 1] + 1 if index > 0 else -FULL
    x_high = xs[index + 1] - 1 if index < len(xs) - 1 else FULL
    y_low = ys[index - 1] if index > 0 else -FULL
    y_high = ys[index + 1] if index < len(ys) - 1 else FULL
    return (min(max(x, x_low), x_high), min(max(y, y_low), y_high))


def ramp_response(step: float, ramp_ms: float, t_ms: float) -> float:
    """The demand value (%) ``t_ms`` after a 0 → ``step`` % step with a ramp time for 100 %."""
    if ramp_ms <= 0:
        return step if t_ms >= 0 else 0.0
    slope = 100.0 / ramp_ms
    return math.copysign(min(abs(step), max(0.0, t_ms) * slope), step)


def ramp_preview(
    step: float, up_ms: float, down_ms: float, hold_ms: float
) -> list[tuple[float, float]]:
    """Demand over time (ms, %) for a step to ``step`` % at t = 0 and back to 0 at ``hold_ms``."""
    up_time = abs(step) / 100.0 * up_ms
    down_time = abs(step) / 100.0 * down_ms
    return [
        (-0.1 * hold_ms, 0.0),
        (0.0, 0.0),
        (up_time, step),
        (max(hold_ms, up_time), step),
        (max(hold_ms, up_time) + down_time, 0.0),
        (max(hold_ms, up_time) + down_time + 0.25 * hold_ms, 0.0),
    ]


def dither_wave(
    mean_ma: float,
    amplitude_ma: float,
    freq_hz: float,
    limit_ma: float,
    periods: float = 3.0,
    steps: int = 240,
) -> list[tuple[float, float]]:
    """A coil current (ms, mA) with dither superimposed, clipped at 0 and ``limit_ma``."""
    if freq_hz <= 0:
        return [(0.0, min(mean_ma, limit_ma)), (periods * 10.0, min(mean_ma, limit_ma))]
    duration_ms = periods * 1000.0 / freq_hz
    points = []
    for n in range(steps + 1):
        t = duration_ms * n / steps
        value = mean_ma + amplitude_ma * math.sin(2 * math.pi * freq_hz * t / 1000.0)
        points.append((t, min(max(value, 0.0), limit_ma)))
    return points


def sensor_curve(offset: float, gain: float) -> list[tuple[float, float]]:
    """Sensor (%) after zero offset then gain, clipped to ±100 %, over ±100 % input."""
    points = []
    for n in range(201):
        x = -100.0 + n
        points.append((x, max(-100.0, min(100.0, gain * (x + offset)))))
    return points

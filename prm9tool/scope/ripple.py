"""What a response does when it does not settle: the oscillation left after a step.

A spool that hunts (a limit cycle of friction and dither around a position) never comes into
the settling band, yet it is at rest in the sense that matters for a window: its mean no longer
moves. :func:`ripple` measures such an oscillation on the last part of a step's samples — its
amplitude, its frequency from the crossings of its mean, and how far the mean moved between the
first and the last whole period — so a step-figure verdict can say what it saw ("did not settle
within ±2 %: oscillation of ±1.5 % at 24 Hz") instead of "window too short".
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from prm9tool.messages import QT_TRANSLATE_NOOP, Message, Number

HYSTERESIS = 0.25  # a crossing of the mean must pass it by a quarter of the half peak-to-peak
MIN_PERIODS = 2  # whole periods needed for a frequency and a drift
END_SHARE = 0.5  # a step's oscillation is measured on the last half of its samples


@dataclass(frozen=True)
class Ripple:
    """An oscillation on a stretch of samples; values in the signal's units."""

    amplitude: float  # half the peak-to-peak
    frequency_hz: float  # NaN: fewer than MIN_PERIODS whole periods (no periodic oscillation)
    drift: float  # mean over the last whole period minus that over the first (NaN: no periods)

    @property
    def periodic(self) -> bool:
        """True when the stretch holds at least MIN_PERIODS whole periods."""
        return math.isfinite(self.frequency_hz)


def upward_crossings(y: np.ndarray, level: float, hysteresis: float) -> np.ndarray:
    """Indices where ``y`` passes from below ``level − hysteresis`` to above ``level +
    hysteresis`` (the first sample above); noise smaller than the hysteresis is no crossing."""
    state = np.where(y > level + hysteresis, 1, np.where(y < level - hysteresis, -1, 0))
    marked = np.flatnonzero(state)
    if len(marked) < 2:
        return np.empty(0, int)
    sides = state[marked]
    rising = np.flatnonzero((sides[:-1] < 0) & (sides[1:] > 0)) + 1
    return marked[rising]


def ripple(t: np.ndarray, y: np.ndarray) -> Ripple:
    """The oscillation of ``y`` (see the module docstring); needs no knowledge of its period."""
    if len(y) < 4:
        return Ripple(0.0, math.nan, math.nan)
    amplitude = float(np.ptp(y)) / 2.0
    up = upward_crossings(y, float(np.mean(y)), HYSTERESIS * amplitude)
    if len(up) < MIN_PERIODS + 1 or amplitude == 0.0:
        return Ripple(amplitude, math.nan, math.nan)
    frequency = (len(up) - 1) / float(t[up[-1]] - t[up[0]])
    first = float(np.mean(y[up[0] : up[1]]))
    last = float(np.mean(y[up[-2] : up[-1]]))
    return Ripple(amplitude, frequency, last - first)


def ripple_at_end(t: np.ndarray, y: np.ndarray) -> Ripple:
    """The oscillation over the last END_SHARE of a step's samples (at least six)."""
    start = max(0, len(y) - max(6, int(len(y) * END_SHARE)))
    return ripple(t[start:], y[start:])


def not_settled(band: float, amplitude: float, frequency_hz: float, unit: str) -> Message:
    """Why a step has no settling time, in words: the oscillation seen (``band`` a share of
    the step, ``amplitude`` half the peak-to-peak in ``unit``; NaN frequency: not periodic)."""
    band_text = Number(f"{band * 100.0:.3g}")
    size = Number(f"±{amplitude:.2g} {unit}".rstrip())
    if math.isfinite(frequency_hz):
        return QT_TRANSLATE_NOOP(
            "StepFigures", "did not settle within ±{0} % of the step: oscillation of {1} at {2} Hz"
        )(band_text, size, Number(f"{frequency_hz:.0f}"))
    return QT_TRANSLATE_NOOP(
        "StepFigures", "did not settle within ±{0} % of the step: still moving by {1} at the end"
    )(band_text, size)

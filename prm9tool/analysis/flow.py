"""The flow characteristic of an E04 valve: the actuator's velocity over the spool's opening.

Inputs are recorded in the same firmware cycle: the spool position (% of opening) and the
process actual value (% of the sensor's range, the actuator's position). The velocity is the
process value's derivative from a Savitzky-Golay filter (``scipy.signal.savgol_filter``,
quadratic over 10 ms), so the sensor's quantization does not enter as noise. The curve is the
mean velocity on 101 bins of the opening; its dead band comes from
:func:`prm9tool.analysis.deadband.dead_band` (straight lines through each side's working range)
and the gain is the mean of both sides' slopes.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from prm9tool.analysis.deadband import FULL, DeadBand, dead_band

SMOOTHING_S = 0.01


@dataclass(frozen=True)
class FlowCharacteristic:
    """Velocity over opening: the binned curve, its dead band and gains."""

    x: np.ndarray  # opening grid, %
    velocity: np.ndarray  # mean velocity per bin, %/s (NaN where no sample)
    band: DeadBand  # in counts of the opening
    gain_positive: float  # (%/s) per % of opening beyond the dead band
    gain_negative: float

    @property
    def gain(self) -> float:
        """The mean of both sides' gains."""
        return (self.gain_positive + self.gain_negative) / 2.0

    @property
    def dead_band_pct(self) -> float:
        """The dead band's width in % of opening."""
        return self.band.width_pct


def velocity(position: np.ndarray, fs: float) -> np.ndarray:
    """d position / dt in units per second (Savitzky-Golay, quadratic over 10 ms)."""
    window = max(5, int(SMOOTHING_S * fs) | 1)
    from scipy.signal import savgol_filter  # imported when used: see prm9tool.analysis.model

    return np.asarray(savgol_filter(position, window, 2, deriv=1, delta=1.0 / fs))


def flow_characteristic(
    opening: np.ndarray, speed: np.ndarray, bins: int = 101
) -> FlowCharacteristic:
    """Analyse ``speed`` (%/s) over ``opening`` (%) recorded together."""
    opening = np.asarray(opening, dtype=float)
    speed = np.asarray(speed, dtype=float)
    if opening.shape != speed.shape or len(opening) < 3 * bins:
        raise ValueError(f"opening and velocity must be equally long, at least {3 * bins} samples")
    band = dead_band(opening / 100.0 * FULL, speed, rest=0.0)  # inside it nothing moves
    edges = np.linspace(-100.0, 100.0, bins + 1)
    index = np.clip(np.digitize(opening, edges) - 1, 0, bins - 1)
    sums = np.bincount(index, weights=speed, minlength=bins)
    counts = np.bincount(index, minlength=bins)
    with np.errstate(invalid="ignore", divide="ignore"):
        curve = np.where(counts > 0, sums / np.maximum(counts, 1), np.nan)
    centres = (edges[:-1] + edges[1:]) / 2.0
    lo, hi = band.negative / FULL * 100.0, band.positive / FULL * 100.0
    return FlowCharacteristic(
        centres,
        curve,
        band,
        _slope(opening, speed, opening > hi),
        _slope(opening, speed, opening < lo),
    )


def _slope(x: np.ndarray, y: np.ndarray, side: np.ndarray) -> float:
    """Slope of the straight line through the side's working range (10 … 90 % of its span)."""
    if side.sum() < 3:
        return float("nan")
    xs, ys = x[side], y[side]
    span = float(np.max(np.abs(ys)))
    working = (np.abs(ys) >= 0.1 * span) & (np.abs(ys) <= 0.9 * span)
    if working.sum() < 3:
        return float("nan")
    return float(np.polyfit(xs[working], ys[working], 1)[0])

"""Static characteristic from a slow triangle: hysteresis, linearity, dead band, gain.

Inputs are the demand ``x`` and the response ``y`` in % (100 % = full opening); the up and the
down branch are told apart by the direction the demand moves. Figures are in % of the
response's span (ISO 10770-1 style), the gain is the slope of the best straight line.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from prm9tool.catalogue.scale import FULL_SCALE

DEAD_BAND_LEVEL = 1.0  # % of span: the response counts as "not moving" below this
LIN_POINTS = 9  # the firmware's characteristics have nine points (A…I)


@dataclass(frozen=True)
class StaticCharacteristic:
    """Branch means on a grid of demand values and the figures derived from them."""

    x: np.ndarray  # demand grid, %
    up: np.ndarray  # mean response on the rising branch (NaN where none)
    down: np.ndarray  # mean response on the falling branch (NaN where none)
    gain: float  # slope of the best straight line (response % per demand %)
    intercept: float
    hysteresis_pct: float  # largest up/down difference, % of span
    linearity_pct: float  # largest deviation of the mean curve from the line, % of span
    dead_band_pct: float  # width of the demand range with no response, % of demand span
    # (where the response stays within DEAD_BAND_LEVEL of its level at 0, less what a
    # straight line of the measured gain needs to leave that band: 0 for a linear valve)

    @property
    def mean(self) -> np.ndarray:
        """The mean of both branches (one branch where only one was measured, NaN where
        neither has a sample)."""
        return branch_mean(self.up, self.down)


def branch_mean(up: np.ndarray, down: np.ndarray) -> np.ndarray:
    """Per bin: the mean of both branches, the one measured, or NaN where neither was (a bin
    no sample fell in: samples lost on a busy link, a demand the sweep jumped over)."""
    return np.where(np.isnan(up), down, np.where(np.isnan(down), up, (up + down) / 2.0))


def static_characteristic(
    x: np.ndarray, y: np.ndarray, bins: int = 101, exclude_dead_band: bool = True
) -> StaticCharacteristic:
    """Analyse a slow sweep ``y(x)`` (see the module docstring)."""
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    if x.shape != y.shape or len(x) < 3 * bins:
        raise ValueError(f"x and y must be equally long records of at least {3 * bins} samples")
    edges = np.linspace(float(x.min()), float(x.max()), bins + 1)
    centres = (edges[:-1] + edges[1:]) / 2.0
    rising = np.gradient(x) >= 0.0
    up = _branch(x[rising], y[rising], edges)
    down = _branch(x[~rising], y[~rising], edges)
    mean = branch_mean(up, down)
    fit = np.isfinite(mean)  # bins no sample fell in are left out of every figure
    if np.count_nonzero(fit) < 2:
        raise ValueError("the sweep's samples fall in fewer than two bins of its demand range")
    span = float(np.max(mean[fit]) - np.min(mean[fit])) or 1.0
    still = _still(centres[fit], mean[fit], span)
    if exclude_dead_band and still[1] > still[0]:
        fit &= (centres <= still[0]) | (centres >= still[1])
    gain, intercept = np.polyfit(centres[fit], mean[fit], 1)
    dead = _dead_band(still, span, float(gain))
    deviation = np.abs(mean[fit] - (gain * centres[fit] + intercept))
    both = np.isfinite(up) & np.isfinite(down)
    hysteresis = float(np.max(np.abs(up[both] - down[both]))) if both.any() else math.nan
    x_span = float(edges[-1] - edges[0]) or 1.0
    return StaticCharacteristic(
        centres,
        up,
        down,
        float(gain),
        float(intercept),
        hysteresis / span * 100.0,
        float(np.max(deviation)) / span * 100.0,
        (dead[1] - dead[0]) / x_span * 100.0,
    )


def _branch(x: np.ndarray, y: np.ndarray, edges: np.ndarray) -> np.ndarray:
    index = np.clip(np.digitize(x, edges) - 1, 0, len(edges) - 2)
    sums = np.bincount(index, weights=y, minlength=len(edges) - 1)
    counts = np.bincount(index, minlength=len(edges) - 1)
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(counts > 0, sums / np.maximum(counts, 1), np.nan)


def _still(x: np.ndarray, mean: np.ndarray, span: float) -> tuple[float, float]:
    """The demand interval around 0 in which the mean response stays within DEAD_BAND_LEVEL
    of its level at 0: on each side where it first leaves that band, interpolated between
    the bins (the ends of the range where it never does)."""
    level = DEAD_BAND_LEVEL / 100.0 * span
    away = np.abs(mean - np.interp(0.0, x, mean))
    centre = int(np.argmin(np.abs(x)))
    return _leaves(x, away, level, centre, -1), _leaves(x, away, level, centre, 1)


def _leaves(x: np.ndarray, away: np.ndarray, level: float, centre: int, side: int) -> float:
    k = centre
    while 0 <= k + side < len(x) and away[k + side] <= level:
        k += side
    if not 0 <= k + side < len(x):
        return float(x[k])
    a, b = away[k], away[k + side]  # a ≤ level < b: the crossing between them
    share = (level - a) / (b - a) if b > a else 0.0
    return float(x[k] + (x[k + side] - x[k]) * min(max(share, 0.0), 1.0))


def _dead_band(still: tuple[float, float], span: float, gain: float) -> tuple[float, float]:
    """The dead band's edges: the band the response stays in, less the demand a response of
    ``gain`` needs to move DEAD_BAND_LEVEL on each side (which is no dead band: a linear valve
    leaves the band after that much demand too). Without that, a linear valve showed one to
    three bins of "dead band", whichever way its spool's hunting at 0 and the number of
    samples per bin (the link's sample rate) fell: 0.99 % in-process, 3.96 % over CANopen."""
    needs = DEAD_BAND_LEVEL / 100.0 * span / abs(gain) if gain else 0.0
    return min(0.0, still[0] + needs), max(0.0, still[1] - needs)


@dataclass(frozen=True)
class Linearization:
    """A proposed 9-point characteristic (raw counts, ±16384 = ±100 %) and its target line."""

    xs: tuple[int, ...]
    ys: tuple[int, ...]
    gain: float


def propose_linearization(
    lin_in: np.ndarray,
    lin_out: np.ndarray,
    response: np.ndarray,
    demand: np.ndarray,
    bipolar: bool = True,
) -> Linearization:
    """The 9 points that make ``response`` a straight line through 0 over ``demand``.

    Recorded together on a slow sweep: ``demand`` (what the valve is told, %), ``lin_in`` and
    ``lin_out`` (the linearization's input and output, counts) and ``response`` (%). The
    present linearization is part of what was measured, so the new points are found by
    inverting the measured path from the linearization's output to the response: for each
    new input point X the output Y is the one that produced the response the straight line
    asks for. The line has the measured gain between the sweep's ends.
    """
    order = np.argsort(lin_in)
    d_at = _monotonic(lin_in[order], demand[order])
    out_sorted = np.argsort(lin_out)
    y_of_out = _monotonic(lin_out[out_sorted], response[out_sorted])
    ends = np.array([d_at[0].min(), d_at[0].max()])
    lo_d, hi_d = float(np.interp(ends[0], *d_at)), float(np.interp(ends[1], *d_at))
    y_lo = float(np.interp(lo_d, demand[order], response[order]))
    y_hi = float(np.interp(hi_d, demand[order], response[order]))
    gain = (y_hi - y_lo) / (hi_d - lo_d) if hi_d != lo_d else 1.0
    first = -FULL_SCALE if bipolar else 0
    xs = np.linspace(first, FULL_SCALE, LIN_POINTS)
    wanted = gain * np.interp(xs, *d_at)
    inverse = _monotonic(y_of_out[1], y_of_out[0])
    ys = np.interp(wanted, *inverse)
    return Linearization(
        tuple(round(v) for v in xs),
        tuple(round(float(np.clip(v, -FULL_SCALE, FULL_SCALE))) for v in ys),
        float(gain),
    )


def _monotonic(x: np.ndarray, y: np.ndarray, bins: int = 200) -> tuple[np.ndarray, np.ndarray]:
    """``y(x)`` averaged on a grid and made non-decreasing (for interpolation and inversion)."""
    edges = np.linspace(float(x.min()), float(x.max()), bins + 1)
    means = _branch(x, y, edges)
    centres = (edges[:-1] + edges[1:]) / 2.0
    ok = np.isfinite(means)
    return centres[ok], np.maximum.accumulate(means[ok])


def linearization_values(lin: Linearization, prefix: str = "SETPLIN") -> dict[str, int]:
    """The parameters that install ``lin``: ``<prefix>X?``/``Y?`` for A…I and the switch on."""
    values = {"SETPLINON": -1} if prefix == "SETPLIN" else {"SENSLINON": 1}
    for letter, x, y in zip("ABCDEFGHI", lin.xs, lin.ys, strict=True):
        values[f"{prefix}X{letter}"] = x
        values[f"{prefix}Y{letter}"] = y
    return values

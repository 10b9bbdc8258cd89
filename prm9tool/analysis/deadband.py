"""Dead-band compensation: the offsets OFFSETPOS/OFFSETNEG from a measured characteristic.

The firmware's gain/offset stage (manual fig. 8-18, "Zesílení / posunutí nuly") maps a value
``x`` that has passed the threshold to ``off + x·g·(1 − off/100 %)`` for ``x > 0`` (and
mirrored with the negative pair for ``x < 0``): as soon as the setpoint leaves the threshold
the output jumps to ``off`` and the rest of the range is squeezed so that 100 % stays 100 %.
That jump compensates a dead band *behind* the stage — the spool's overlap, a flat part of a
characteristic —, so the offset that compensates it is the dead band's edge measured on the
stage's output: where a straight line through the response's working range crosses the level
the response has at rest. On E04 in control mode 4 the stage acts on the control deviation in
front of the process PIDT1, whose proportional part multiplies the jump by Kp: there the
offset is the edge divided by Kp (:func:`deviation_offset`).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from prm9tool.catalogue.scale import FULL_SCALE

FULL = float(FULL_SCALE)  # 100 % in counts
WORKING = (0.1, 0.9)  # share of each side's response span used for the straight line


@dataclass(frozen=True)
class DeadBand:
    """Where the response starts on each side, in counts of the axis it was measured on."""

    negative: float  # ≤ 0
    positive: float  # ≥ 0

    @property
    def width_pct(self) -> float:
        """The dead band's width in % of 100 %."""
        return (self.positive - self.negative) / FULL * 100.0


def dead_band(x: np.ndarray, y: np.ndarray, bins: int = 201, rest: float | None = None) -> DeadBand:
    """The edges of the dead band of ``y(x)`` (``x`` in counts, ±16384 = ±100 %).

    ``y`` is averaged on a grid of ``x``; each side's straight line is fitted where the
    response is between 10 and 90 % of that side's span from its level at rest (the level
    at x = 0, or ``rest`` when given: a velocity rests at 0), and its crossing of that level is
    the edge (0 where the line crosses it on the other side: no dead band there).
    """
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    ok = np.isfinite(x) & np.isfinite(y)
    x, y = x[ok], y[ok]
    edges = np.linspace(float(x.min()), float(x.max()), bins + 1)
    index = np.clip(np.digitize(x, edges) - 1, 0, bins - 1)
    sums = np.bincount(index, weights=y, minlength=bins)
    counts = np.bincount(index, minlength=bins)
    have = counts > 0
    centres = ((edges[:-1] + edges[1:]) / 2.0)[have]
    means = sums[have] / counts[have]
    if rest is None:
        rest = float(np.interp(0.0, centres, means))
    return DeadBand(
        min(0.0, _edge(centres, means, rest, -1.0)), max(0.0, _edge(centres, means, rest, 1.0))
    )


def _edge(x: np.ndarray, y: np.ndarray, rest: float, side: float) -> float:
    on_side = x * side > 0
    if on_side.sum() < 4:
        return 0.0
    xs, rise = x[on_side], (y[on_side] - rest) * side
    span = float(rise.max())
    if span <= 0:
        return 0.0
    working = (rise >= WORKING[0] * span) & (rise <= WORKING[1] * span)
    if working.sum() < 3:
        return 0.0
    slope, intercept = np.polyfit(xs[working], rise[working], 1)
    return float(-intercept / slope) if slope else 0.0


def gain_offset(x: np.ndarray, values: Mapping[str, int]) -> np.ndarray:
    """The firmware's gain/offset stage (counts in and out; ``values``: GAINSETPOS/NEG,
    OFFSETPOS/NEG raw; a missing negative pair, one-coil valves, acts as the positive one)."""
    x = np.asarray(x, dtype=float)
    gp, op = _pair(values, "POS")
    gn, on = _pair(values, "NEG", gp, op)
    out = np.where(x > 0, op + x * gp, np.where(x < 0, -on + x * gn, 0.0))
    return np.clip(out, -FULL, FULL)


def gain_offset_inverse(out: np.ndarray, values: Mapping[str, int]) -> np.ndarray:
    """The stage's input for its output ``out`` (0 for outputs inside the jump)."""
    out = np.asarray(out, dtype=float)
    gp, op = _pair(values, "POS")
    gn, on = _pair(values, "NEG", gp, op)
    pos = np.where(out > op, (out - op) / (gp or 1.0), 0.0)
    neg = np.where(out < -on, (out + on) / (gn or 1.0), 0.0)
    return np.where(out > 0, pos, neg)


def _pair(
    values: Mapping[str, int], side: str, gain: float | None = None, offset: float | None = None
) -> tuple[float, float]:
    """(g, off) as the firmware computes them: g = gain/100 % × (100 % − off)/100 %."""
    raw_gain, raw_off = values.get(f"GAINSET{side}"), values.get(f"OFFSET{side}")
    if raw_gain is None or raw_off is None:
        assert gain is not None and offset is not None
        return gain, offset
    off = float(raw_off)
    return float(raw_gain) / FULL * (FULL - off) / FULL, off


def offsets_for(band: DeadBand, present: Mapping[str, int]) -> dict[str, int]:
    """OFFSETPOS/OFFSETNEG (raw counts) that jump over ``band`` (measured on the stage's
    output with the ``present`` offsets): the jump is the edge itself."""
    del present  # the edge is on the stage's output axis: independent of the present offsets
    return {
        "OFFSETPOS": round(min(max(band.positive, 0.0), FULL)),
        "OFFSETNEG": round(min(max(-band.negative, 0.0), FULL)),
    }


def deviation_offset(band: DeadBand, kp: float) -> dict[str, int]:
    """E04, control mode 4: the offsets on the control deviation whose jump, through the
    process controller's proportional gain ``kp``, opens the spool to the dead band's edges."""
    if kp <= 0:
        raise ValueError("the process controller's Kp must be positive")
    return {
        "OFFSETPOS": round(min(max(band.positive / kp, 0.0), FULL)),
        "OFFSETNEG": round(min(max(-band.negative / kp, 0.0), FULL)),
    }

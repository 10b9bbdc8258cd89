"""Measuring on captured samples: cursors, step-response figures and CSV export."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TextIO

import numpy as np

from prm9tool.catalogue.signals import Signal


@dataclass(frozen=True)
class CursorReadout:
    """Values of every channel at cursors A and B (NaN outside the data) and their differences."""

    t_a: float
    t_b: float
    a: np.ndarray
    b: np.ndarray

    @property
    def dt(self) -> float:
        """B − A in seconds."""
        return self.t_b - self.t_a

    @property
    def frequency(self) -> float:
        """1 / |Δt| in Hz (NaN when the cursors coincide)."""
        return 1.0 / abs(self.dt) if self.dt else math.nan

    @property
    def delta(self) -> np.ndarray:
        """B − A per channel."""
        return self.b - self.a


def cursor_readout(t: np.ndarray, values: np.ndarray, t_a: float, t_b: float) -> CursorReadout:
    """Linearly interpolated channel values at times ``t_a`` and ``t_b``."""

    def at(when: float) -> np.ndarray:
        if len(t) == 0 or not t[0] <= when <= t[-1]:
            return np.full(values.shape[1], math.nan)
        return np.array([np.interp(when, t, values[:, c]) for c in range(values.shape[1])])

    return CursorReadout(t_a, t_b, at(t_a), at(t_b))


# --- step response ---------------------------------------------------------------------------
NOISE_RATIO = 10.0  # a response smaller than 10 σ of its noise is no response
OVERSHOOT_NOISE = 3.0  # an overshoot within 3 σ of the noise reads as 0
SMOOTH_SAMPLES = 5  # median filter on a noisy response before peaks and crossings
SMOOTH_ABOVE = 1e-3  # noise σ (share of the step) from which the response is filtered


@dataclass(frozen=True)
class StepFigures:
    """Step-response figures; times in seconds from the step, values in the signal's units."""

    t_step: float
    initial: float
    final: float
    target: float  # level the reference stepped to (NaN without a reference)
    rise_time: float  # 10 % → 90 % of the step (NaN if not reached)
    overshoot: float  # % of the step beyond the final value
    settling_time: float  # until the response stays within ±band of the final value
    band: float = 0.02

    @property
    def steady_state_error(self) -> float:
        """Target − final value (NaN without a reference)."""
        return self.target - self.final


def find_step(t: np.ndarray, reference: np.ndarray) -> tuple[float, float, float] | None:
    """The largest jump of a reference signal: ``(time, level before, level after)``."""
    if len(reference) < 3:
        return None
    k = int(np.argmax(np.abs(np.diff(reference)))) + 1
    before, after = float(np.median(reference[:k])), float(np.median(reference[k:]))
    if before == after:
        return None
    return float(t[k]), before, after


def noise_level(y: np.ndarray) -> float:
    """Robust standard deviation of the sample noise of ``y``.

    From the median absolute deviation of the second differences: a step or a smooth curve
    moves only a few of them, white noise of σ gives them a spread of σ·√6.
    """
    if len(y) < 5:
        return 0.0
    d2 = np.diff(y, 2)
    return float(1.4826 * np.median(np.abs(d2 - np.median(d2))) / math.sqrt(6.0))


def step_figures(
    t: np.ndarray,
    y: np.ndarray,
    reference: np.ndarray | None = None,
    band: float = 0.02,
    comparable: bool = True,
) -> StepFigures | None:
    """Figures of the step response ``y`` (with the ``reference`` that stepped, if recorded).

    Without a reference the step is taken where ``y`` leaves its initial level (the samples
    before that point) by more than ``band`` of the step. The final value is the mean of the
    last 10 % of the window. A noisy response is median-filtered before its peak, crossings
    and settling are taken. Returns None when the window holds no step, and when the response
    does not follow it: a change under 10 σ of the noise or, for a ``comparable`` reference
    (the same unit), under ``band`` of the reference's step.
    """
    if len(y) < 10:
        return None
    noise = noise_level(y)
    final = float(np.mean(y[-max(1, len(y) // 10) :]))
    target, min_size = math.nan, 0.0
    if reference is not None:
        step = find_step(t, reference)
        if step is None:
            return None
        t_step, before, target = step
        initial = _level_before(t, y, t_step)
        min_size = band * abs(target - before) if comparable else 0.0
    else:
        t_step, initial = _detect_step(t, y, final, band, noise)
    noise = max(noise, _spread(y[t < t_step]))
    size = final - initial
    if math.isnan(t_step) or abs(size) <= max(NOISE_RATIO * noise, min_size):
        return None
    after = t >= t_step
    ta, ya = t[after], _smoothed(y, noise, size)[after]
    t10 = _first_crossing(ta, ya, initial, final, 0.1, t_step)
    t90 = _first_crossing(ta, ya, initial, final, 0.9, t_step)
    excess = max(0.0, float(np.max((ya - final) / size)))
    overshoot = excess * 100.0 if excess * abs(size) > OVERSHOOT_NOISE * noise else 0.0
    settling = _settling_time(ta, ya, final, band * abs(size), t_step)
    return StepFigures(t_step, initial, final, target, t90 - t10, overshoot, settling, band)


def _settling_time(
    t: np.ndarray, y: np.ndarray, final: float, tolerance: float, t_step: float
) -> float:
    """Seconds from ``t_step`` until ``y`` stays within ``final ± tolerance`` (NaN: never)."""
    outside = np.flatnonzero(np.abs(y - final) > tolerance)
    if len(outside) == 0:
        return 0.0
    if outside[-1] == len(y) - 1:
        return math.nan
    return float(t[outside[-1] + 1]) - t_step


def _detect_step(
    t: np.ndarray, y: np.ndarray, final: float, band: float, noise: float
) -> tuple[float, float]:
    """Where ``y`` leaves its initial level, and that level (the samples before the step).

    The first guess of the level comes from the first 1 % of the window only, so a short
    pre-trigger does not mix samples after the step into it; the level is then taken again
    from every sample before the step found.
    """
    initial = float(np.median(y[: max(3, len(y) // 100)]))
    smooth = _smoothed(y, noise, final - initial)
    t_step = _first_crossing(t, smooth, initial, final, band, float(t[0]))
    before = y[t < t_step]
    if len(before) >= 3:
        initial = float(np.median(before))
        again = _first_crossing(t, smooth, initial, final, band, float(t[0]))
        t_step = t_step if math.isnan(again) else again
    return t_step, initial


def _level_before(t: np.ndarray, y: np.ndarray, t_step: float) -> float:
    """Median of the samples before ``t_step`` (the first sample if there are none)."""
    before = y[t < t_step]
    return float(np.median(before)) if len(before) else float(y[0])


def _spread(y: np.ndarray) -> float:
    """Robust standard deviation of a level (0 for fewer than 5 samples)."""
    if len(y) < 5:
        return 0.0
    return float(1.4826 * np.median(np.abs(y - np.median(y))))


def _smoothed(y: np.ndarray, noise: float, size: float) -> np.ndarray:
    """``y`` through a short running median when its noise is noticeable against ``size``.

    A running median leaves a monotonic response as it is, so clean responses keep their
    exact crossings; on a noisy one it removes the noise peaks without rounding the edges.
    """
    if noise <= SMOOTH_ABOVE * abs(size) or len(y) < SMOOTH_SAMPLES:
        return y
    half = SMOOTH_SAMPLES // 2
    padded = np.pad(y, half, mode="edge")
    return np.median(np.lib.stride_tricks.sliding_window_view(padded, SMOOTH_SAMPLES), axis=1)


def _first_crossing(
    t: np.ndarray, y: np.ndarray, initial: float, final: float, share: float, t_from: float
) -> float:
    """Interpolated time at which ``y`` first reaches ``initial + share·(final − initial)``."""
    size = final - initial
    progress = (y - initial) / size if size else np.zeros_like(y)
    hits = np.flatnonzero((progress >= share) & (t >= t_from))
    if len(hits) == 0:
        return math.nan
    k = int(hits[0])
    if k == 0 or progress[k - 1] >= share:
        return float(t[k])
    p0, p1 = progress[k - 1], progress[k]
    return float(t[k - 1] + (t[k] - t[k - 1]) * (share - p0) / (p1 - p0))


# --- CSV -------------------------------------------------------------------------------------
def write_csv(out: TextIO, t: np.ndarray, values: np.ndarray, signals: Sequence[Signal]) -> int:
    """Write ``time [s]`` and one column per signal (``key [unit]``); returns the row count."""
    if values.shape != (len(t), len(signals)):
        raise ValueError("one column per signal and one row per time stamp expected")
    header = ",".join(["time [s]"] + [f"{s.key} [{s.unit}]" for s in signals])
    table = np.column_stack([t, values]) if len(t) else np.empty((0, len(signals) + 1))
    fmt = ["%.6f"] + ["%.6g"] * len(signals)
    np.savetxt(out, table, delimiter=",", fmt=fmt, header=header, comments="")
    return len(t)

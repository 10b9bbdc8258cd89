"""Measuring on captured samples: cursors, step-response figures and CSV export."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TextIO

import numpy as np

from prm9tool.signals import Signal


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


def step_figures(
    t: np.ndarray,
    y: np.ndarray,
    reference: np.ndarray | None = None,
    band: float = 0.02,
) -> StepFigures | None:
    """Figures of the step response ``y`` (with the ``reference`` that stepped, if recorded).

    Without a reference the step is taken where ``y`` leaves its initial level by more than
    ``band`` of the step. The final value is the mean of the last 10 % of the window. Returns
    None when the window holds no step.
    """
    if len(y) < 10:
        return None
    tail = max(1, len(y) // 10)
    final = float(np.mean(y[-tail:]))
    target = math.nan
    if reference is not None:
        step = find_step(t, reference)
        if step is None:
            return None
        t_step, _, target = step
        before = y[t < t_step]
        initial = float(np.median(before)) if len(before) else float(y[0])
    else:
        initial = float(np.median(y[:tail]))
        t_step = _first_crossing(t, y, initial, final, band, 0.0)
    size = final - initial
    if size == 0 or math.isnan(t_step):
        return None
    after = t >= t_step
    ta, ya = t[after], y[after]
    t10 = _first_crossing(ta, ya, initial, final, 0.1, t_step)
    t90 = _first_crossing(ta, ya, initial, final, 0.9, t_step)
    overshoot = max(0.0, float(np.max((ya - final) / size))) * 100.0
    outside = np.flatnonzero(np.abs(ya - final) > band * abs(size))
    if len(outside) == 0:
        settling = 0.0
    elif outside[-1] == len(ya) - 1:
        settling = math.nan
    else:
        settling = float(ta[outside[-1] + 1]) - t_step
    return StepFigures(t_step, initial, final, target, t90 - t10, overshoot, settling, band)


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

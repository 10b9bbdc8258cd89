"""Reading a capture: every channel's value at two cursors and their differences, and the
capture as CSV (``time [s]`` and one column per signal in its display unit). Numpy, no Qt."""

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
    """Linearly interpolated channel values at times ``t_a`` and ``t_b`` (between the samples
    that arrived; a channel without any gives NaN)."""

    def at(when: float) -> np.ndarray:
        if len(t) == 0 or not t[0] <= when <= t[-1]:
            return np.full(values.shape[1], math.nan)
        return np.array([_interp(when, t, values[:, c]) for c in range(values.shape[1])])

    return CursorReadout(t_a, t_b, at(t_a), at(t_b))


def _interp(when: float, t: np.ndarray, y: np.ndarray) -> float:
    """``y`` at ``when`` between the samples that arrived (NaN: lost, over CANopen)."""
    ok = np.isfinite(y)
    if ok.all():
        return float(np.interp(when, t, y))
    return float(np.interp(when, t[ok], y[ok])) if ok.any() else math.nan


def write_csv(out: TextIO, t: np.ndarray, values: np.ndarray, signals: Sequence[Signal]) -> int:
    """Write ``time [s]`` and one column per signal (``key [unit]``); returns the row count."""
    if values.shape != (len(t), len(signals)):
        raise ValueError("one column per signal and one row per time stamp expected")
    header = ",".join(["time [s]"] + [f"{s.key} [{s.unit}]" for s in signals])
    table = np.column_stack([t, values]) if len(t) else np.empty((0, len(signals) + 1))
    fmt = ["%.6f"] + ["%.6g"] * len(signals)
    np.savetxt(out, table, delimiter=",", fmt=fmt, header=header, comments="")
    return len(t)

"""Controller rules and the PRM9's PIDT1 parameters: critical gain, conversions, oscillation.

The firmware's PIDT1 (manual §8.7.2 "Regulátor"; scaling from the catalogue) is the parallel
form ``u = Kp·e + Ki·∫e dt + Kd·s/(1 + T1·s)·e``. The APOSYS 10 rule (critical-gain method,
K = 0.5·Kkr, Ti = 0.8·Tkr, Td = 0.12·Tkr) is written for the ideal form ``K·(1 + 1/(Ti·s) +
Td·s)``, so ``Kp = K``, ``Ki = K/Ti``, ``Kd = K·Td``; the derivative's filter is ``T1 = Td/N``.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

import numpy as np

from prm9tool.catalogue import CATALOGUE

DERIVATIVE_FILTER_N = 10.0  # T1 = Td / N (a usual choice; at least one 200 µs cycle)
CYCLE_S = 200e-6
_TO_UNIT = {"": 1.0, "1/s": 1.0, "ms": 1000.0}  # SI value × factor = value in the unit shown


@dataclass(frozen=True)
class PidGains:
    """Parallel-form gains in SI units: Kp, Ki (1/s), Kd (s) and the derivative lag T1 (s)."""

    kp: float
    ki: float
    kd: float
    t1: float

    def scaled(self, factor: float) -> PidGains:
        """Every gain times ``factor`` (T1 unchanged)."""
        return PidGains(self.kp * factor, self.ki * factor, self.kd * factor, self.t1)


def critical_gain_rule(kkr: float, tkr: float) -> PidGains:
    """K = 0.5·Kkr, Ti = 0.8·Tkr, Td = 0.12·Tkr (APOSYS 10 manual, AUTOTUNE) as parallel gains."""
    if kkr <= 0 or tkr <= 0:
        raise ValueError("the critical gain and period must be positive")
    k, ti, td = 0.5 * kkr, 0.8 * tkr, 0.12 * tkr
    return PidGains(k, k / ti, k * td, max(td / DERIVATIVE_FILTER_N, CYCLE_S))


def to_parameters(prefix: str, gains: PidGains) -> dict[str, int]:
    """Raw values of ``<prefix>KP/KI/KD/T1`` (POS or PRC), clipped to the catalogue's limits."""
    raw: dict[str, int] = {}
    for suffix, value in (("KP", gains.kp), ("KI", gains.ki), ("KD", gains.kd), ("T1", gains.t1)):
        param = CATALOGUE[prefix + suffix]
        counts = value * _TO_UNIT[param.unit] / param.scale
        raw[param.mnemonic] = int(min(max(round(counts), param.raw_min), param.raw_max))
    return raw


def from_parameters(prefix: str, values: dict[str, int]) -> PidGains:
    """The gains that raw ``<prefix>KP/KI/KD/T1`` values stand for."""

    def si(suffix: str) -> float:
        param = CATALOGUE[prefix + suffix]
        return float(values[param.mnemonic]) * param.scale / _TO_UNIT[param.unit]

    return PidGains(si("KP"), si("KI"), si("KD"), si("T1"))


@dataclass(frozen=True)
class Oscillation:
    """How a P-only loop rings after a step: amplitude of the first and last period, period."""

    first: float
    last: float
    period_s: float

    def sustained(self, floor: float) -> bool:
        """True when the ringing does not die out and is larger than ``floor``."""
        return self.last >= floor and self.last >= 0.9 * self.first


def oscillation(t: np.ndarray, y: np.ndarray) -> Oscillation:
    """Amplitudes (peak to peak) of the first and last full swing and the mean period of ``y``.

    ``y`` is the response after the step; its mean over the record is removed and the swings
    between upward zero crossings are measured.
    """
    centred = y - float(np.mean(y[len(y) // 2 :]))
    up = np.flatnonzero((centred[:-1] < 0.0) & (centred[1:] >= 0.0))
    if len(up) < 3:
        return Oscillation(float(np.ptp(y)), 0.0, math.nan)
    swings = [float(np.ptp(centred[a:b])) for a, b in itertools.pairwise(up)]
    crossings = t[up] - centred[up] * (t[up + 1] - t[up]) / (centred[up + 1] - centred[up])
    half = len(crossings) // 2
    period = float(np.mean(np.diff(crossings[half:]))) if len(crossings) - half >= 2 else math.nan
    return Oscillation(swings[0], swings[-1], period)

"""The critical-gain autotune (APOSYS 10): the loop on P only, Kp raised until a setpoint step
keeps it oscillating, the critical gain narrowed by bisection, then the rule's gains from the
critical gain and period (:func:`prm9tool.analysis.pid.critical_gain_rule`). It moves the valve
with the frame of :mod:`prm9tool.characterize.frame`: the gains and the setpoint chain
saved and put back in every case, the stimulus recorded within a limit.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from prm9tool.analysis.pid import PidGains, critical_gain_rule, from_parameters, oscillation
from prm9tool.characterize.frame import LOOPS, Loop, chain_changes, gain_names, preserved, record
from prm9tool.characterize.rig import Rig, retried
from prm9tool.errors import Prm9Error


@dataclass(frozen=True)
class CriticalGainResult:
    """Critical gain and period, the rule's gains, and every P-only trial (Kp, oscillation)."""

    kkr: float
    tkr: float
    gains: PidGains
    trials: list[tuple[float, float, float]] = field(default_factory=list)  # Kp, first, last


def critical_gain_tune(
    rig: Rig,
    loop: str = "position",
    amplitude_pct: float = 5.0,
    limit_pct: float = 40.0,
    ratio: float = 1.25,
    refine: int = 5,
    window_s: float = 0.2,
) -> CriticalGainResult:
    """APOSYS 10 critical-gain method: P only, raise Kp by ``ratio`` until the loop keeps
    oscillating after a setpoint step, then narrow Kkr by ``refine`` bisections.

    A growing oscillation that leaves ``limit_pct`` ends that trial at once (it counts as
    oscillating); the previous gains are back when this returns or raises.
    """
    lp = LOOPS[loop]
    names = gain_names(lp)
    with preserved(rig, names, chain_changes(rig, loop)) as saved:
        present = from_parameters(lp.prefix, saved)
        param = lp.prefix + "KP"
        trials: list[tuple[float, float, float]] = []

        def trial(kp_raw: int) -> tuple[bool, float]:
            # from rest, as the manual asks: the safe gains calm the loop first
            rig.write({k: saved[k] for k in names})
            rig.play(np.zeros(int(0.05 * rig.info.sample_rate_hz)), [lp.setpoint])
            rig.write({param: kp_raw, lp.prefix + "KI": 0, lp.prefix + "KD": 0})
            ringing, period = retried(lambda: _ring(rig, lp, amplitude_pct, limit_pct, window_s))
            trials.append((kp_raw * 0.01, ringing[0], ringing[1]))
            return ringing[1] >= 0.3 * amplitude_pct and ringing[1] >= 0.9 * ringing[0], period

        low = max(1, int(saved[param] / 2))
        high, period = 0, math.nan
        kp = low
        while kp <= 65535:
            rig.check()
            sustained, p = trial(kp)
            if sustained:
                high, period = kp, p
                break
            low, kp = kp, int(kp * ratio) + 1
        if not high:
            raise Prm9Error("the loop did not oscillate up to the largest Kp; no critical gain")
        for _ in range(refine):
            middle = (low + high) // 2
            if middle in (low, high):
                break
            sustained, p = trial(middle)
            if sustained:
                high, period = middle, p
            else:
                low = middle
    kkr = high * 0.01
    del present
    return CriticalGainResult(kkr, period, critical_gain_rule(kkr, period), trials)


def _growing_period(t: np.ndarray, y: np.ndarray, amplitude: float, limit: float) -> float:
    """The period of an oscillation that grew beyond the limit, from its swings after the
    step (0.02 s) while they are within half the limit: grown further, the coils' current
    limits slow it down (on the emulator from 6.9 ms to 11 ms), and the critical-gain rule
    wants the period at the stability limit. The whole record if that leaves too little."""
    beyond = np.flatnonzero((t >= 0.02) & (np.abs(y - amplitude) >= 0.5 * limit))
    early = slice(int(np.searchsorted(t, 0.02)), int(beyond[0]) if len(beyond) else len(t))
    if early.stop - early.start > 2:
        period = oscillation(t[early], y[early]).period_s
        if math.isfinite(period):
            return period
    return oscillation(t, y).period_s


def _ring(
    rig: Rig, lp: Loop, amplitude: float, limit: float, window_s: float
) -> tuple[tuple[float, float], float]:
    """Step ±amplitude and measure the ringing (first and last swing in %, period)."""
    fs = rig.info.sample_rate_hz
    rig.play(np.zeros(int(0.03 * fs)), [lp.setpoint])
    stimulus = np.full(int(window_s * fs), amplitude)
    rec = record(rig, stimulus, [lp.setpoint, lp.actual], 0.0, limit, strict=False)
    if len(rec.t) < len(stimulus):  # grew beyond the limit: oscillating
        rig.play(np.zeros(1), [lp.setpoint])
        return (0.0, 2.0 * limit), _growing_period(rec.t, rec.channels[lp.actual], amplitude, limit)
    settled = rec.t >= 0.02
    osc = oscillation(rec.t[settled], rec.channels[lp.actual][settled])
    return (osc.first, osc.last), osc.period_s

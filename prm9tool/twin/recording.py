"""Recordings to fit a twin on (issue 31 item 2): position-loop steps and windows of a
characterization run's sweep and static triangle, as :class:`Steps`.

:func:`record` runs a fixed sequence of setpoint steps (:data:`LEVELS_PCT`, each held
:data:`HOLD_S`) through the transparent setpoint chain on any rig and keeps the stimulus, the
measured response and the valve's parameter set; :func:`from_characterization` takes the same
from a characterization run (any link, or read from its JSON report). What is done with them:
:mod:`.replay` plays them on an emulated valve, :mod:`.identify` fits the plant constants.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

import numpy as np

from prm9tool.catalogue.signals import BY_KEY
from prm9tool.characterize.frame import LOOPS, chain_changes, preserved
from prm9tool.errors import Prm9Error

if TYPE_CHECKING:
    from prm9tool.characterize.rig import Rig
    from prm9tool.characterize.run import Characterization

POSITION_MODE = 2  # CTRLMODE of spool position control (an E04's position loop)
CYCLE_HZ = 5000.0  # the emulator's loop: one sample per 200 µs cycle
# 0 → ±5, ±25, ±90 % and back: small steps see the friction, large ones the force limits
LEVELS_PCT = (0.0, 25.0, 0.0, -25.0, 0.0, 5.0, 0.0, -5.0, 0.0, 90.0, 0.0, -90.0, 0.0)
HOLD_S = 0.12  # each level; the factory E02 settles within 20 ms
STATIC_AT = (0.0,)  # the triangle's windows where it passes these demands (%), going up
SWEEP_AT = (0.5, 1.0, 1.5)  # sweep windows at these multiples of the −3 dB frequency
SWEEP_LEAD_S = 0.1
STATIC_WINDOW_S = 0.2  # each static window's span
# a window's lead-in, not in the residual: on the slow triangle the integrator has to take
# up the ramp first
STATIC_LEAD_S = 0.3
MAX_LAG = 25  # cycles: the override's latency to the demand is looked for up to 5 ms


@dataclass(frozen=True)
class Steps:
    """One recording: the stimulus (override, %), the measured response (%), the parameter set
    in effect (raw values) and the valve's type key; one sample per ``rate_hz``."""

    type_key: str
    values: dict[str, int]
    stimulus: np.ndarray
    actual: np.ndarray
    rate_hz: float = CYCLE_HZ
    demand: bool = False  # the stimulus is the measured demand, not the override written
    kind: str = "step"  # "step", or "static": a window of the static characteristic's triangle
    skip: int = 0  # samples at the start left out of the residual (a window's lead-in)
    tail: int = 0  # samples at the end left out (where a demand's latency ran out of window)
    start: int = 0  # a window: its first sample in the record it was cut from


def stimulus(rate_hz: float = CYCLE_HZ) -> np.ndarray:
    """The setpoint sequence, one value per sample."""
    n = round(HOLD_S * rate_hz)
    return np.repeat(np.asarray(LEVELS_PCT, dtype=float), n)


def record(rig: Rig) -> Steps:
    """Run :func:`stimulus` on the position loop of ``rig`` through the transparent chain; the
    valve's parameter set is read first and is as it was afterwards."""
    lp = LOOPS["position"]
    values = _parameter_set(rig)
    demand = stimulus(rig.info.sample_rate_hz)
    with preserved(rig, [], chain_changes(rig, "position")):
        try:
            raw = rig.play(demand, [lp.actual])
        finally:
            rig.release()
    actual = raw[:, 0] * BY_KEY[lp.actual].scale
    return Steps(rig.info.type_key, values, demand, actual, rig.info.sample_rate_hz)


def _windows(whole: Steps, centres: Sequence[tuple[int, float]], lead_s: float) -> list[Steps]:
    """Parts of a long recording, each ``(centre sample, span s)`` with a lead-in of
    ``lead_s`` before it that the residual leaves out: a window's simulation starts
    from the spool at rest at the window's first demand, the valve's did not (the lead-in is
    where the two come together). Parts of the recording only: playing all of it at every
    evaluation (30 s of valve time with the default profile) would make the fit minutes long."""
    fs = whole.rate_hz
    lead = round(lead_s * fs)
    tail = math.ceil(MAX_LAG * fs / CYCLE_HZ) + 1  # the latency's shift fills these
    out = []
    for centre, span_s in centres:
        a = max(0, centre - round(span_s * fs / 2) - lead)
        b = min(len(whole.stimulus), centre + round(span_s * fs / 2))
        if b - a > lead + round(span_s * fs / 2):
            out.append(
                replace(
                    whole,
                    stimulus=whole.stimulus[a:b],
                    actual=whole.actual[a:b],
                    skip=lead,
                    tail=tail,
                    start=a,
                )
            )
    return out


def _with_mode(type_key: str, parameters: dict[str, int], loop: str) -> dict[str, int]:
    """A run's parameter set with the control mode it ran in where it does not keep it: a
    run that tested an E04's position loop was not in control mode 4 (the process loop, the
    E04's default), so spool position control (2)."""
    from prm9tool.catalogue.typekey import Config, TypeKey

    values = dict(parameters)
    e04 = TypeKey.parse(type_key).variant.config is Config.E04
    if e04 and loop == "position" and "CTRLMODE" not in values:
        values["CTRLMODE"] = POSITION_MODE
    return values


def from_characterization(run: Characterization, joint: bool = True) -> list[Steps]:
    """The position-loop steps of a characterization run (any link) as recordings to fit: each
    step's measured demand is its stimulus (through the transparent chain the run used, the
    demand is the override's value), from the spool at rest at the step's start. ``joint``:
    windows of the static characteristic's triangle (the override written, through the
    valve's own chain, ``kind="static"``: where it passes 0 going up and going down) follow,
    where the run has it complete. The frequency response's sweep is not among them: a window
    of it simulated from a hold does not reproduce the valve's own sweep even on the valve's
    own plant (docs/twin.md), so it would pull the constants off."""
    lp = LOOPS["position"]
    values = _with_mode(run.info.type_key, run.parameters, run.loop)
    out = []
    for step in run.steps:
        if step.loop != "position":
            continue
        channels = step.record.channels
        if lp.setpoint not in channels or lp.actual not in channels:
            continue
        demand = np.asarray(channels[lp.setpoint], dtype=float)
        actual = np.asarray(channels[lp.actual], dtype=float)
        good = np.isfinite(demand) & np.isfinite(actual)
        if not good.all():  # samples a link lost: the stimulus is not known there
            continue
        out.append(
            Steps(
                run.info.type_key,
                values,
                demand,
                actual,
                run.info.sample_rate_hz,
                demand=True,
            )
        )
    if not out:
        raise Prm9Error("the characterization has no complete position-loop step to fit")
    if not joint or run.loop != "position":
        return out
    base = out[0]
    bode, static = run.bode, run.static
    fs = run.info.sample_rate_hz
    if bode is not None and not bode.lost_samples and not bode.held_s:
        demand = np.asarray(bode.record.channels[lp.setpoint], dtype=float)
        actual = np.asarray(bode.record.channels[lp.actual], dtype=float)
        if np.isfinite(demand).all() and np.isfinite(actual).all():
            f0 = run.profile.bode_f_min_hz
            f1 = bode.limited_to_hz or run.profile.bode_f_max_hz
            near = bode.response.bandwidth_hz()
            near = near if math.isfinite(near) else bode.response.phase_90_hz()
            near = near if math.isfinite(near) else f1 / 4.0
            centres = []
            for f in (near * k for k in SWEEP_AT):
                if 1.5 * f0 <= f <= f1 / 1.1:  # the chirp's frequency at t: f0·(f1/f0)^(t/T)
                    t = len(demand) / fs * math.log(f / f0) / math.log(f1 / f0)
                    centres.append((round(t * fs), max(2.0 / f, 0.05)))
            sweep = replace(base, stimulus=demand, actual=actual, kind="sweep")
            out += _windows(sweep, centres, SWEEP_LEAD_S)
    if static is not None and static.response_key == lp.actual:
        demand = np.asarray(static.demand, dtype=float)
        actual = np.asarray(static.record.channels[lp.actual], dtype=float)[: len(demand)]
        if len(actual) == len(demand) and np.isfinite(actual).all():
            triangle = replace(base, stimulus=demand, actual=actual, demand=False, kind="static")
            half = len(demand) // 2  # up, then down: windows where it passes these demands
            centres = [
                (int(np.argmin(np.abs(demand[a:b] - level))) + a, STATIC_WINDOW_S)
                for a, b, levels in (
                    (0, half, STATIC_AT),
                    (half, len(demand), tuple(-x for x in STATIC_AT)),
                )
                for level in levels
            ]
            out += _windows(triangle, centres, STATIC_LEAD_S)
    return out


def _parameter_set(rig: Rig) -> dict[str, int]:
    """The valve's writable file parameters and its control mode, read from it."""
    from prm9tool.catalogue import CATALOGUE
    from prm9tool.catalogue.typekey import TypeKey

    variant = TypeKey.parse(rig.info.type_key).variant
    names = [p.mnemonic for p in CATALOGUE.file_parameters(variant) if p.writable]
    return {**rig.read(["CTRLMODE"]), **rig.read(names)}

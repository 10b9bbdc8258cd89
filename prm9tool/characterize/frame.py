"""The frame every procedure that moves a valve shares: the loops under test (:data:`LOOPS`),
the settled start (:func:`settle`), saving and restoring the parameters a test touches and the
transparent setpoint chain (:func:`preserved`, :func:`chain_changes`), and the recorded
stimulus (:func:`record`, which stops a test whose response leaves its band:
:class:`LimitExceededError`). The procedures built on it are
:mod:`~prm9tool.characterize.procedures` (step, sweep, static), the autotunes, the flow and
drift tests and the end-of-line run.
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from dataclasses import dataclass

import numpy as np

from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.signals import BY_KEY
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.characterize.rig import Rig
from prm9tool.characterize.transparent import TRANSPARENT
from prm9tool.errors import Prm9Error
from prm9tool.messages import QT_TRANSLATE_NOOP, Number


@dataclass(frozen=True)
class Loop:
    """A control loop under test: its parameters and measuring points."""

    prefix: str  # POS or PRC
    setpoint: str
    actual: str
    output: str
    integrating: bool
    step_pct: float  # the step the step-response simulator makes (prm9tool.online.tuning)
    simulated_s: float  # the window recorded after a step: the simulator's and the autotune's


LOOPS = {
    "position": Loop(
        "POS", "position_setpoint", "position_actual", "controller_output", False, 50.0, 0.12
    ),
    "process": Loop(
        "PRC", "process_setpoint", "process_actual", "position_setpoint", True, 20.0, 1.0
    ),
}
GAIN_SUFFIXES = ("KP", "KI", "KD", "T1")
# One step measurement for the autotune, the controller dialogs and the end-of-line steps:
# the loop rests at the start level, STEP_PRE_S of it are recorded, then the step and the
# window after it (at least STEP_WINDOW_S; the autotune takes 3× its settling target if longer).
STEP_PRE_S = 0.02
STEP_WINDOW_S = {name: lp.simulated_s for name, lp in LOOPS.items()}


class LimitExceededError(Prm9Error):
    """The valve left the allowed band around the operating point; the test was stopped."""


# Before a step or a sweep the loop is held at its start level until it is there (decision): an
# integrating loop (the E04 actuator) is still on its way back from the last step after the
# spool's 0.1 s, and a sweep that starts there leaves its band at once.
SETTLE_LIMIT_S = 5.0  # held at most this long; then the test starts as the loop is
SETTLE_BAND_PCT = 5.0  # there: the last half of a hold within this of the level (the
# spool hunting at the null, ±1.6 % at most, docs/emulator.md, is there)
REST_PCT = 0.5  # or at rest elsewhere (an offset, a dead band): moving less than this


def settle(rig: Rig, actual: str, level: float, minimum_s: float) -> None:
    """Hold the setpoint at ``level`` for ``minimum_s`` and on, in holds of that length, until
    ``actual`` is there or at rest (at most SETTLE_LIMIT_S)."""
    fs = rig.info.sample_rate_hz
    hold = max(minimum_s, 0.02)
    held = 0.0
    while True:
        raw = rig.play(np.full(max(1, round(hold * fs)), level), [actual], gaps=True)
        held += hold
        values = raw[:, 0] * BY_KEY[actual].scale
        if len(rig.last_missing) == len(values):
            values = values[~rig.last_missing]
        tail = values[len(values) // 2 :]
        if held >= SETTLE_LIMIT_S or not len(tail):
            return
        if np.max(np.abs(tail - level)) <= SETTLE_BAND_PCT or np.ptp(tail) <= REST_PCT:
            return


def step_window(loop: str, settling_s: float = 0.0) -> float:
    """Seconds recorded after a step of ``loop``: STEP_WINDOW_S, or three settling times."""
    return max(3.0 * settling_s, STEP_WINDOW_S[loop])


def gain_names(loop: Loop) -> list[str]:
    """The loop's four controller parameters."""
    return [loop.prefix + s for s in GAIN_SUFFIXES]


@contextmanager
def preserved(
    rig: Rig, mnemonics: Sequence[str], changes: dict[str, int]
) -> Iterator[dict[str, int]]:
    """Save ``mnemonics`` and ``changes``' keys, apply ``changes``; always restore and release.

    ``mnemonics`` are what the procedure changes (controller gains): a valve that lacks one on
    its link (a real valve over CANopen has no object at this project's addresses) is refused
    here, naming them, before anything is written or moved."""
    rig.ensure_active()
    names = list(dict.fromkeys([*mnemonics, *changes]))
    saved = rig.read(names)
    missing = [m for m in mnemonics if m not in saved]
    if missing:
        raise Prm9Error(
            QT_TRANSLATE_NOOP(
                "Characterize",
                "this valve has no object for {0} on this link (their addresses are this "
                "project's, not the manual's): the tuning cannot change them here; nothing "
                "was changed — tune these over USB",
            )(", ".join(missing))
        )
    try:
        rig.write(changes)
        yield saved
    finally:
        rig.release()
        rig.write(saved)


def chain_changes(rig: Rig, loop: str = "position") -> dict[str, int]:
    """The transparent-chain values that differ from the valve's present ones.

    For the process loop (E04) the deviation's gain and offset stay: they act inside it. What
    the valve lacks on its link (a real valve over CANopen has no object for them) stays as the
    valve has it: the test then runs through that part of the valve's own chain.
    """
    _check_control_mode(rig, loop)
    wanted = dict(TRANSPARENT)
    if loop == "process":
        for key in ("GAINSETPOS", "GAINSETNEG", "OFFSETPOS", "OFFSETNEG"):
            del wanted[key]
    # a single-coil valve has no negative signal range, and no object for its ramps (manual
    # §8.7.2, fig. 8-18): what its type does not have is not part of its chain
    variant = TypeKey.parse(rig.info.type_key).variant
    wanted = {k: v for k, v in wanted.items() if CATALOGUE[k].on_device(variant)}
    present = rig.read(list(wanted))
    return {k: v for k, v in wanted.items() if k in present and present[k] != v}


def _check_control_mode(rig: Rig, loop: str) -> None:
    """Refuse, before anything is written or moved, a loop the valve's control mode does not
    close: on an E04 in control mode 4 (its default) the setpoint drives the process loop, so
    a position-loop test would step the actuator, not the spool; in mode 2 there is no
    process loop. A valve without the object on its link is left to its own chain."""
    mode = rig.read(["CTRLMODE"]).get("CTRLMODE")
    wanted = 4 if loop == "process" else 2
    if mode is None or mode == wanted:
        return
    if loop == "process":
        raise Prm9Error(
            QT_TRANSLATE_NOOP(
                "Characterize",
                "the valve is in control mode {0} (spool position): it has no process loop "
                "to test; the process loop runs in control mode 4 (CTRLMODE). Nothing was "
                "changed",
            )(mode)
        )
    raise Prm9Error(
        QT_TRANSLATE_NOOP(
            "Characterize",
            "the valve is in control mode {0} (process loop): its setpoint drives the process "
            "controller, not the spool, so the position loop cannot be tested on its own. "
            "Choose the process loop, or set CTRLMODE to 2 (spool position) while the valve "
            "is not enabled. Nothing was changed",
        )(mode)
    )


@dataclass(frozen=True)
class Record:
    """Samples of one test in % (time in s from the test's start)."""

    t: np.ndarray
    channels: dict[str, np.ndarray]


def record(
    rig: Rig,
    stimulus: np.ndarray,
    keys: Sequence[str],
    centre: float,
    limit: float,
    strict: bool = True,
    gaps: bool = False,
) -> Record:
    """Play ``stimulus`` and convert the samples to %.

    ``strict``: LimitExceededError when the response leaves ``centre ± limit``; otherwise the
    record ends at the first sample outside. ``gaps``: the analysis takes lost samples
    (``rig.last_missing``) as missing.
    """
    raw = rig.play(stimulus, keys, gaps)
    channels = {k: raw[:, i] * BY_KEY[k].scale for i, k in enumerate(keys)}
    outside = np.flatnonzero(np.abs(channels[keys[1]] - centre) > limit)
    if len(outside) and not strict:
        end = int(outside[0]) + 1
        t = np.arange(end) / rig.info.sample_rate_hz
        return Record(t, {k: v[:end] for k, v in channels.items()})
    if len(outside):
        raise LimitExceededError(
            QT_TRANSLATE_NOOP(
                "Characterize",
                "{0} left the allowed band {1} ± {2} %; the test was stopped and the valve "
                "put back as it was",
            )(BY_KEY[keys[1]].text, Number(f"{centre:g}"), Number(f"{limit:g}"))
        )
    t = np.arange(len(raw)) / rig.info.sample_rate_hz
    return Record(t, channels)

"""Tests that move a valve: step, frequency sweep and static sweep, and what every procedure
that moves one shares (the loops, saving and restoring the parameters it touches, the settled
start, the recorded stimulus); the two autotune methods built on them are
:mod:`~prm9tool.characterize.autotune` (model-based) and
:mod:`~prm9tool.characterize.critical_gain`.

Each procedure saves the parameters it touches, makes the setpoint chain transparent where the
test needs it (no threshold, ramps or linearization between the override and the loop), and in
every case (done, stopped, fault, limit exceeded) puts the saved values back and switches the
override off. Amplitudes and operating points are in % of full opening.
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from dataclasses import dataclass

import numpy as np

from prm9tool.analysis.frequency import (
    UPDATES_PER_PERIOD,
    FrequencyResponse,
    frequency_response,
    frequency_response_with_gaps,
    log_chirp,
    sweep_updates,
)
from prm9tool.analysis.static import StaticCharacteristic, static_characteristic
from prm9tool.catalogue.signals import BY_KEY
from prm9tool.characterize.rig import (
    ATTEMPTS,
    LinkTooSlowError,
    Rig,
    bridgeable,
    bridged,
)
from prm9tool.characterize.transparent import TRANSPARENT
from prm9tool.errors import Prm9Error
from prm9tool.messages import QT_TRANSLATE_NOOP, Message, Number
from prm9tool.scope.measure import StepFigures, step_figures, step_figures_to_setpoint

SAMPLES_PER_PERIOD = 10  # a sweep goes no higher than the sample rate / this (decision)
SWEEP_MIN_SAMPLES = 256  # what the frequency response needs


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


# --- step ------------------------------------------------------------------------------------
@dataclass(frozen=True)
class StepResult:
    """A step from ``start`` to ``start + amplitude`` % and its figures (None: no response)."""

    amplitude_pct: float
    record: Record
    figures: StepFigures | None
    loop: str = "position"

    @property
    def to_setpoint(self) -> StepFigures | None:
        """The figures measured against the setpoint (the end-of-line test's and the
        acceptance check's): a step that never came to it is not reached
        (:func:`~prm9tool.scope.measure.step_figures_to_setpoint`)."""
        lp = LOOPS[self.loop]
        channels = self.record.channels
        if lp.actual not in channels or lp.setpoint not in channels:
            return None
        return step_figures_to_setpoint(self.record.t, channels[lp.actual], channels[lp.setpoint])

    def caption(self) -> Message:
        """The step and the window its figures were measured on, e.g. "Step 0 → 50 %, window
        −20 … 120 ms" (every view shows it next to the figures)."""
        t = self.record.t
        start = round(float(self.record.channels[LOOPS[self.loop].setpoint][0]), 1) + 0.0
        return STEP_CAPTION(
            Number(f"{start:g}"),
            Number(f"{start + self.amplitude_pct:g}"),
            Number(f"{t[0] * 1000.0:.0f}".replace("-", "−")),
            Number(f"{t[-1] * 1000.0:.0f}"),
        )


STEP_CAPTION = QT_TRANSLATE_NOOP("StepFigures", "Step {0} → {1} %, window {2} … {3} ms")


def step_test(
    rig: Rig,
    amplitude_pct: float,
    start_pct: float = 0.0,
    duration_s: float = 0.1,
    loop: str = "position",
    limit_pct: float | None = None,
) -> StepResult:
    """Settle at ``start_pct``, step by ``amplitude_pct``, record ``duration_s``."""
    lp = LOOPS[loop]
    with preserved(rig, [], chain_changes(rig, loop)):
        return _step(rig, lp, amplitude_pct, start_pct, duration_s, limit_pct, loop)


def _step(
    rig: Rig,
    lp: Loop,
    amplitude: float,
    start: float,
    duration: float,
    limit: float | None,
    loop: str,
) -> StepResult:
    """One step from rest. A link that lost samples (CANopen on a busy PC) repeats it from
    rest, at most ATTEMPTS times in all: the valve answers the same step the same way, so
    each repetition fills the samples the others lost at the same SYNC number (the record
    keeps the first that arrived at each); what none delivered is bridged when
    :func:`~prm9tool.characterize.rig.bridgeable`, else the step is refused."""
    fs = rig.info.sample_rate_hz
    pre, n = round(STEP_PRE_S * fs), round(duration * fs)
    keys = [lp.setpoint, lp.actual, lp.output]
    channels: dict[str, np.ndarray] = {}
    hole = np.zeros(0, dtype=bool)
    for attempt in range(ATTEMPTS):
        settle(rig, lp.actual, start, max(0.1, duration))  # from rest
        stimulus = np.concatenate([np.full(pre, start), np.full(n, start + amplitude)])
        band = limit if limit is not None else abs(amplitude) * 2.0 + 5.0
        try:
            rec = record(rig, stimulus, keys, start, band, gaps=True)
        except LinkTooSlowError:  # this repetition lost nearly everything: the next one
            if attempt + 1 < ATTEMPTS:
                continue
            raise
        missing = rig.last_missing if len(rig.last_missing) else np.zeros(len(rec.t), bool)
        if not channels:
            channels, hole = dict(rec.channels), missing.copy()
        else:  # the samples this repetition delivered where the record has none
            for key, values in rec.channels.items():
                channels[key] = np.where(hole & ~missing, values, channels[key])
            hole &= missing
        if bridgeable(hole, fs):
            break
    else:
        raise LinkTooSlowError(
            f"the link lost {int(hole.sum())} of {len(hole)} samples of the step even in "
            f"{ATTEMPTS} repetitions; the test was stopped, nothing was interpolated"
        )
    response = channels[lp.actual]
    if hole.any():  # the few none delivered: a straight line between their neighbours
        channels[lp.actual] = bridged(np.where(hole, np.nan, response))
    t = rec.t - pre / fs
    figures = step_figures(t, channels[lp.actual], channels[lp.setpoint])
    return StepResult(amplitude, Record(t, channels), figures, loop)


# --- frequency response -----------------------------------------------------------------------
@dataclass(frozen=True)
class BodeResult:
    """A sine sweep and the frequency response estimated from it."""

    amplitude_pct: float
    centre_pct: float
    record: Record
    response: FrequencyResponse
    note: Message | str = ""  # set when the link's sample rate limited the sweep
    limited_to_hz: float | None = None  # the sweep's highest frequency when it was limited
    lost_samples: int = 0  # responses the link lost (left out of the estimate)
    held_s: float = 0.0  # the setpoint hold that cut the sweep short (0: none did)


SWEEP_LIMITED = QT_TRANSLATE_NOOP(
    "Characterize", "sweep limited to {0} Hz (of {1} Hz asked) by the link's sample rate of {2} Hz"
)


SWEEP_UPDATED = QT_TRANSLATE_NOOP(
    "Characterize",
    "sweep usable up to {0} Hz: the PC held the valve's setpoint for {1} ms there (at least {2} "
    "updates per period are needed; the PC was busy)",
)


def bode_test(
    rig: Rig,
    amplitude_pct: float = 10.0,
    centre_pct: float = 0.0,
    f_min: float = 1.0,
    f_max: float = 200.0,
    duration_s: float = 10.0,
    loop: str = "position",
) -> BodeResult:
    """Logarithmic sweep ``f_min`` → ``f_max`` around ``centre_pct``; demand → actual.

    A link whose sample rate gives fewer than SAMPLES_PER_PERIOD samples per period at
    ``f_max`` (CANopen) limits the sweep to what it can sample, and :attr:`BodeResult.note`
    says so; nothing is interpolated. A PC too busy to update the setpoint UPDATES_PER_PERIOD
    times a period (:func:`~prm9tool.analysis.frequency.sweep_updates`) limits the estimate to
    the part of the sweep before that, or refuses it (LinkTooSlowError) when too little is left.
    """
    lp = LOOPS[loop]
    fs = rig.info.sample_rate_hz
    if duration_s * fs < SWEEP_MIN_SAMPLES:  # a slow link (CANopen): say what it needs
        raise ValueError(
            f"a sweep needs at least {SWEEP_MIN_SAMPLES} samples; at the link's {fs:g} Hz "
            f"choose a duration of at least {math.ceil(SWEEP_MIN_SAMPLES / fs * 10) / 10:g} s"
        )
    note: Message | str = ""
    highest = fs / SAMPLES_PER_PERIOD
    if f_max > highest:
        if f_min * 2.0 > highest:
            raise ValueError(
                f"the link samples at {fs:g} Hz: a sweep from {f_min:g} Hz needs at least "
                f"{f_min * 2.0 * SAMPLES_PER_PERIOD:g} Hz"
            )
        note = SWEEP_LIMITED(Number(f"{highest:g}"), Number(f"{f_max:g}"), Number(f"{fs:g}"))
        f_max = highest
    sweep = centre_pct + amplitude_pct * log_chirp(duration_s, fs, f_min, f_max)
    with preserved(rig, [], chain_changes(rig, loop)):
        settle(rig, lp.actual, centre_pct, 0.05)
        band = 2.5 * amplitude_pct + 5.0
        rec = record(rig, sweep, [lp.setpoint, lp.actual], centre_pct, band, gaps=True)
    u, y, missing = rec.channels[lp.setpoint], rec.channels[lp.actual], rig.last_missing
    updates = sweep_updates(sweep, rig.last_demand, fs, f_min, f_max, 2.0 / 163.84)
    if updates.usable < len(u):  # a busy PC wrote the setpoint too seldom from there on
        hold = Number(f"{updates.hold_s * 1000:.0f}")
        if updates.usable_hz < 2.0 * f_min or updates.usable < SWEEP_MIN_SAMPLES:
            raise LinkTooSlowError(
                f"the PC updated the valve's setpoint too seldom for the sweep: it held one "
                f"value for {hold} ms at {updates.usable_hz:.3g} Hz (at least "
                f"{UPDATES_PER_PERIOD} updates per period are needed); the test was stopped, "
                "nothing was measured from it — run it again when the PC is less busy"
            )
        note = SWEEP_UPDATED(Number(f"{updates.usable_hz:.3g}"), hold, UPDATES_PER_PERIOD)
        f_max, end = updates.usable_hz, updates.usable
        u, y, missing = u[:end], y[:end], missing[:end] if len(missing) else missing
    limited = f_max if note else None  # (the note says the sweep was limited)
    if missing.any():  # lost on the link: not filled in, the fit uses what arrived
        try:
            response = frequency_response_with_gaps(u, y, missing, fs, f_min, f_max)
        except ValueError as exc:  # too few arrived for the fit: the link's refusal
            raise LinkTooSlowError(
                f"the link lost {int(missing.sum())} of {len(missing)} samples of the sweep "
                f"({exc}); choose a longer sweep, the test was stopped, nothing was interpolated"
            ) from None
    else:
        response = frequency_response(u, y, fs, f_min, f_max)
    lost = int(missing.sum())
    held = updates.hold_s if updates.usable < len(rec.t) else 0.0
    return BodeResult(amplitude_pct, centre_pct, rec, response, note, limited, lost, held)


# --- static characteristic --------------------------------------------------------------------
@dataclass(frozen=True)
class StaticResult:
    """A slow triangle over the range: setpoint, linearization in/out, response."""

    record: Record
    characteristic: StaticCharacteristic
    demand: np.ndarray
    response_key: str


STATIC_KEYS = ("setpoint_gain", "setpoint_linearized", "position_actual")
STATIC_MIN_SAMPLES = 606  # six per bin of the characteristic's 101


def static_test(
    rig: Rig,
    period_s: float = 4.0,
    lo_pct: float = -100.0,
    hi_pct: float = 100.0,
    response: str = "position_actual",
) -> StaticResult:
    """One triangle period ``lo → hi → lo`` (through the valve's own setpoint chain).

    ``response``: the spool position, or on E04 in control mode 4 ``process_actual``.
    """
    keys = (*STATIC_KEYS[:2], response)
    fs = rig.info.sample_rate_hz
    half = int(period_s * fs / 2)
    if 2 * half < STATIC_MIN_SAMPLES:  # a slow link (CANopen): say what it needs
        raise ValueError(
            f"the static test needs at least {STATIC_MIN_SAMPLES} samples; at the link's "
            f"{fs:g} Hz choose a triangle period of at least {STATIC_MIN_SAMPLES / fs:.1f} s"
        )
    # one override value per millisecond: fine enough for a static test, fewer writes
    every = max(1, round(fs / 1000.0))
    rise = np.repeat(np.linspace(lo_pct, hi_pct, half // every + 1), every)[:half]
    rig.ensure_active()
    sweep = np.concatenate([rise, rise[::-1]])
    settle(rig, response, lo_pct, 0.2)  # not analysed
    try:  # lost samples of a slow triangle are bridged (gaps of ms in a period of seconds)
        raw = rig.play(sweep, list(keys), gaps=True)
    finally:
        rig.release()
    channels = {k: raw[:, i] * BY_KEY[k].scale for i, k in enumerate(keys)}
    demand = rig.last_demand[: len(raw)]
    rec = Record(np.arange(len(raw)) / fs, channels)
    figures = static_characteristic(demand, channels[response])
    return StaticResult(rec, figures, demand, response)

"""Tests that move a valve: step, frequency sweep and static sweep, on the frame every such
procedure shares (:mod:`~prm9tool.characterize.frame`: the loops, saving and restoring the
parameters a test touches, the settled start, the recorded stimulus); the two autotune methods
built on them are :mod:`~prm9tool.characterize.autotune` (model-based) and
:mod:`~prm9tool.characterize.critical_gain`.

Each procedure saves the parameters it touches, makes the setpoint chain transparent where the
test needs it (no threshold, ramps or linearization between the override and the loop), and in
every case (done, stopped, fault, limit exceeded) puts the saved values back and switches the
override off. Amplitudes and operating points are in % of full opening.
"""

from __future__ import annotations

import math
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
from prm9tool.characterize.frame import (
    LOOPS,
    STEP_PRE_S,
    Loop,
    Record,
    chain_changes,
    preserved,
    record,
    settle,
)
from prm9tool.characterize.rig import ATTEMPTS, LinkTooSlowError, Rig, bridgeable, bridged
from prm9tool.messages import QT_TRANSLATE_NOOP, Message, Number
from prm9tool.scope.measure import StepFigures, step_figures, step_figures_to_setpoint

SAMPLES_PER_PERIOD = 10  # a sweep goes no higher than the sample rate / this (decision)
SWEEP_MIN_SAMPLES = 256  # what the frequency response needs


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

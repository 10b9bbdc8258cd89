"""Identify the emulator's plant constants from measured position-loop steps (issue 31 item 2).

The valve under test runs a fixed sequence of setpoint steps through the transparent setpoint
chain (:data:`LEVELS_PCT`, each held :data:`HOLD_S`); :func:`record` keeps the stimulus, the
measured response and the valve's parameter set. :func:`fit` then replays the same stimulus on
an emulated valve of the same type with the same parameters and adjusts the chosen plant
constants (:data:`FITTED`) until the simulated response matches the measured one in the least
squares sense (``scipy.optimize.least_squares`` on the logarithms of the constants, so each is
adjusted relative to its size and stays positive).

Confidence: from the Jacobian at the solution, ``cov = s²·(JᵀJ)⁺`` with ``s²`` the residual
variance, the standard error of each logarithm is the constant's relative standard error. A
constant is *determined* when that is below :data:`DETERMINED_RSE` and no other fitted constant
is so correlated with it (:data:`CORRELATED`) that only a combination of the two is seen. The
samples of a step response are not independent (the residual is mostly model error, not white
noise), so the standard errors are optimistic: they say which constants the data see at all,
not a calibrated interval. A constant that is not determined keeps its value from the start
point, and the fit says so instead of inventing one.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field, fields, replace
from typing import TYPE_CHECKING, Any

import numpy as np

from prm9tool.catalogue.signals import BY_KEY
from prm9tool.characterize.frame import LOOPS, STEP_PRE_S, chain_changes, preserved
from prm9tool.characterize.transparent import TRANSPARENT
from prm9tool.errors import Prm9Error

if TYPE_CHECKING:
    from prm9tool.characterize.rig import Rig
    from prm9tool.characterize.run import Characterization
    from prm9tool.device.emulator.constants import PlantConstants

POSITION_MODE = 2  # CTRLMODE of spool position control (an E04's position loop)
CYCLE_HZ = 5000.0  # the emulator's loop: one sample per 200 µs cycle
# 0 → ±5, ±25, ±90 % and back: small steps see the friction, large ones the force limits
LEVELS_PCT = (0.0, 25.0, 0.0, -25.0, 0.0, 5.0, 0.0, -5.0, 0.0, 90.0, 0.0, -90.0, 0.0)
HOLD_S = 0.12  # each level; the factory E02 settles within 20 ms
FITTED = (  # the spool's dynamics, the solenoid and its force, friction
    "spool_mass_kg",
    "damping_n_s_per_m",
    "force_n_per_a",
    "coulomb_friction_n",
    "force_lag_s",
    "coil_l_h",
)
# with the static characteristic (:func:`from_characterization`, ``joint``): the
# break-away friction too (the spring stays: only its ratio to the force constant is seen)
JOINT = (*FITTED, "static_friction_n")
STATIC_AT = (0.0,)  # the triangle's windows where it passes these demands (%), going up
SWEEP_AT = (0.5, 1.0, 1.5)  # sweep windows at these multiples of the −3 dB frequency
SWEEP_LEAD_S = 0.1
STATIC_WINDOW_S = 0.2  # each static window's span
# a window's lead-in, not in the residual: on the slow triangle the integrator has to take
# up the ramp first
JOINT_EVALUATIONS = 12  # the joint fit's, from the steps' solution (each plays every window)
STATIC_LEAD_S = 0.3
BOUND = math.log(10.0)  # a constant moves at most tenfold from its start
DETERMINED_RSE = 0.05  # relative standard error below which a constant counts as determined
CORRELATED = 0.98  # |correlation| above which two constants are seen only together
STEP = 0.03  # the Jacobian's finite difference, in log(constant): 3 %
BETWEEN_S = 0.1  # the hold between two recordings played on one valve
MAX_LAG = 25  # cycles: the override's latency to the demand is looked for up to 5 ms
ALIGN_COARSE = 4  # cycles: the first search of a recording's dither offset
ALIGN_ROUNDS = 3  # alignments on the fitted plant, each followed by a fit from there
# the dither (80 Hz: 62.5 cycles) and the firmware's 1 ms task (5 cycles) repeat together
# every 125 cycles: a window's phase of both
PHASE_CYCLES = 125
EXPLAINED_PCT = 0.12  # rms residual of an explained recording: two LVDT steps (0.061 % each)


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


@dataclass(frozen=True)
class FittedConstant:
    """One plant constant after the fit."""

    name: str
    start: float
    value: float
    relative_se: float  # standard error of log(value): relative; inf when not seen at all
    determined: bool
    correlated_with: str | None = None  # the constant only seen together with this one
    reason: str | None = None  # why it is not determined, where the fit can say (kept)


@dataclass(frozen=True)
class Fit:
    """The fitted plant and how well it explains the recording."""

    plant: PlantConstants
    constants: tuple[FittedConstant, ...]
    rms_pct: float  # residual of the steps, % of full scale (all recordings when no step)
    max_pct: float
    start_rms_pct: float
    evaluations: int
    # rms residual per kind of measurement fitted ("step", "static": the triangle's windows)
    parts_rms_pct: dict[str, float] = field(default_factory=dict)

    @property
    def explained(self) -> bool:
        """True when the fitted plant explains the recording to :data:`EXPLAINED_PCT` rms: else
        the valve does something the plant's structure cannot represent (or the fit stopped in
        a local minimum), and its constants are the best the structure allows, not the valve's."""
        return self.rms_pct <= EXPLAINED_PCT

    def constant(self, name: str) -> FittedConstant:
        """The fitted constant ``name``."""
        return next(c for c in self.constants if c.name == name)


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


def simulate(steps: Steps, plant: PlantConstants) -> np.ndarray:
    """The response of an emulated valve with ``plant`` and the recording's parameter set to
    the recording's stimulus, at the recording's sample rate."""
    return simulate_all([steps], plant)[0]


def simulate_all(
    recordings: Sequence[Steps], plant: PlantConstants, offsets: Sequence[int] | None = None
) -> list[np.ndarray]:
    """The responses to several recordings of one valve, played one after the other on one
    emulated valve (the first recording's type and parameter set), each after a hold at its
    start level (:func:`hold_cycles`: a characterization's step after its settle hold): as a characterization run moves from one test
    to the next, so the spool comes to rest where friction holds it, not at a fresh 0.
    ``offsets``: cycles added to each recording's hold (:func:`dither_offsets`), so that the
    simulated dither is in the phase the measured spool shows at the recording's start."""
    from prm9tool.catalogue.typekey import TypeKey
    from prm9tool.characterize.rig import EmulatorRig
    from prm9tool.device.emulator import EmulatedValve

    first = recordings[0]
    key = TypeKey.parse(first.type_key)
    analog = TypeKey(key.size, key.spool, key.flow, key.supply, key.config, False)
    valve = EmulatedValve(analog, plant=plant)
    _write(valve, {**first.values, **TRANSPARENT})
    while valve.status().booting:
        valve.advance(0.05)
    rig = EmulatorRig(valve)
    lp = LOOPS["position"]
    out = []
    try:
        for i, steps in enumerate(recordings):
            ratio = CYCLE_HZ / steps.rate_hz
            per = round(ratio)
            if per < 1 or abs(ratio - per) > 1e-9:
                raise Prm9Error(
                    f"a recording at {steps.rate_hz:g} Hz: the rate must divide 5000 Hz"
                )
            played = np.repeat(steps.stimulus, per)
            if steps.kind == "static":  # the triangle runs through the valve's own chain
                own = {k: first.values[k] for k in TRANSPARENT if k in first.values}
                _write(valve, own)
            hold = hold_cycles(steps) + (offsets[i] if offsets else 0)
            samples = rig.play(
                np.concatenate([np.full(hold, played[0]), played]), [lp.setpoint, lp.actual]
            )[hold:]
            actual = measured_actual(samples, played, steps, lp)
            if steps.kind == "static":
                _write(valve, TRANSPARENT)
            out.append(actual[per - 1 :: per])
    finally:
        rig.release()
    return out


def hold_cycles(steps: Steps) -> int:
    """The cycles :func:`simulate_all` holds a recording's start level before it: for a
    characterization's step (its measured demand, ``STEP_PRE_S`` of rest before the step) the
    hold the procedure settled it with, max(0.1 s, its window) (``frame.settle``, which
    returns after one hold when the spool is there); else :data:`BETWEEN_S`. With a
    break-away friction the spool's rest, and the integrator holding it, depend on that
    history: 0.1 s instead of the 0.15 s the default profile's steps settle with left 0.5 %
    rms on the true plant of a valve with 1.2 N of static friction, 0.000 % with it."""
    if steps.kind == "step" and steps.demand:
        return settled_cycles(steps)
    return round(BETWEEN_S * CYCLE_HZ)


def settled_cycles(steps: Steps) -> int:
    """The hold the procedure settled a measured step with (``frame.settle``, which returns
    after one hold when the loop is there): max(0.1 s, the step's window), in cycles."""
    window = len(steps.stimulus) / steps.rate_hz - STEP_PRE_S
    return round(max(0.1, window) * CYCLE_HZ)


def measured_actual(samples: np.ndarray, played: np.ndarray, steps: Steps, lp: Any) -> np.ndarray:
    """The actual value of a replayed recording in %; when the stimulus is a measured demand,
    shifted by the override's latency (the lag that best lines the demand up with it)."""
    actual = samples[:, 1] * BY_KEY[lp.actual].scale
    if steps.demand:
        demand = samples[:, 0] * BY_KEY[lp.setpoint].scale
        lag = min(
            range(MAX_LAG),
            key=lambda k: float(np.abs(demand[k:] - played[: len(played) - k]).sum()),
        )
        actual = np.concatenate([actual[lag:], np.full(lag, actual[-1])])
    return actual


def dither_frequency_hz(steps: Steps) -> float:
    """The dither frequency the recording's parameter set gives (DYNFREQ, else its default)."""
    from prm9tool.catalogue import CATALOGUE
    from prm9tool.catalogue.dither import frequency_hz

    return frequency_hz(float(steps.values.get("DYNFREQ", CATALOGUE["DYNFREQ"].default)))


def _rest(steps: Steps) -> int:
    """The samples before the recording's stimulus first moves (its rest), or 0 where they are
    shorter than one dither period or the rate too low to see the dither."""
    f = dither_frequency_hz(steps)
    moved = np.flatnonzero(np.abs(steps.stimulus - steps.stimulus[0]) > 1e-9)
    n = int(moved[0]) if len(moved) else 0
    if f <= 0.0 or steps.rate_hz < 4.0 * f or n < steps.rate_hz / f:
        return 0
    return n


def dither_offsets(recordings: Sequence[Steps], plant: PlantConstants) -> list[int]:
    """Cycles to add to each recording's hold in :func:`simulate_all` so that the simulated
    spool rests as the measured one did before each recording's stimulus moved.

    The dither runs on from the valve's power-up: a valve that ran in real time before its run
    (opened with ``prm9tool.connect``) starts each test in another phase of it than a fresh
    simulated valve, and a small step's first milliseconds depend on it (the spool at the null
    moves ±0.2 % with the dither). For each step in turn (the earlier ones played with their
    offsets), the offset within one dither period whose simulated step, with ``plant``, is
    nearest the measured one: first every :data:`ALIGN_COARSE` cycles, then each cycle around
    the best (the fit aligns on its start plant, then again on the fitted one). Zero for a
    window of the triangle and where the rest does not show the dither
    (:func:`_rest`)."""
    offsets: list[int] = []
    first_of: dict[str, tuple[int, int]] = {}  # a record's first window: (its start, cycles)
    for i, steps in enumerate(recordings):
        window = steps.kind != "step"
        per = round(CYCLE_HZ / steps.rate_hz)
        if window and steps.kind in first_of:
            # a later window of the same record: the dither and the 1 ms task are where they
            # were that many samples after the first window, as in the valve's record
            start, cycles = first_of[steps.kind]
            wanted = cycles + (steps.start - start) * per
            offsets.append((wanted - _cycles_before(recordings, offsets, i)) % PHASE_CYCLES)
            continue
        if not window and not _rest(steps):
            offsets.append(0)
            continue
        # the first window of a record: the phase of the dither and of the firmware's 1 ms task
        # it meets; a step: the dither's phase at its rest
        period = PHASE_CYCLES if window else round(CYCLE_HZ / dither_frequency_hz(steps))
        scores: dict[int, float] = {}

        def score(
            extra: int,
            i: int = i,
            steps: Steps = steps,
            period: int = period,
            scores: dict[int, float] = scores,
        ) -> float:
            extra %= period
            if extra not in scores:
                played = simulate_all(recordings[: i + 1], plant, [*offsets, extra])[-1]
                end = min(len(played), len(steps.actual) - steps.tail)
                error = played[steps.skip : end] - steps.actual[steps.skip : end]
                scores[extra] = float(np.mean(error**2))
            return scores[extra]

        best = min(range(0, period, ALIGN_COARSE), key=score)
        best = min(range(best - ALIGN_COARSE + 1, best + ALIGN_COARSE), key=score) % period
        offsets.append(best)
        if window:
            first_of[steps.kind] = (steps.start, _cycles_before(recordings, offsets, i))
    return offsets


def _cycles_before(recordings: Sequence[Steps], offsets: Sequence[int], i: int) -> int:
    """Cycles :func:`simulate_all` plays before recording ``i``'s own samples (the holds, with
    ``offsets[i]`` when it is given, and the recordings before it)."""
    cycles = 0
    for j in range(i + 1):
        cycles += hold_cycles(recordings[j]) + (offsets[j] if j < len(offsets) else 0)
        if j < i:
            cycles += len(recordings[j].stimulus) * round(CYCLE_HZ / recordings[j].rate_hz)
    return cycles


def window_shifts(
    recordings: Sequence[Steps], plant: PlantConstants, offsets: Sequence[int]
) -> list[int]:
    """Per recording, the samples by which the simulated window is moved against the measured
    one (0 for a step): the shift, up to the window's tail, that explains it best. A window
    starts in the middle of a test, and the valve's own latency from the override to the
    response on that link is not in its record; the simulated window from a hold is otherwise
    the same motion."""
    played = simulate_all(recordings, plant, offsets)
    out = []
    for steps, simulated in zip(recordings, played, strict=True):
        if steps.kind == "step" or not steps.tail:
            out.append(0)
            continue
        end = min(len(simulated), len(steps.actual)) - steps.tail
        measured = steps.actual[steps.skip : end]

        errors = {
            k: float(np.mean((simulated[steps.skip - k : end - k] - measured) ** 2))
            for k in range(-steps.tail + 1, steps.tail)
        }
        out.append(min(errors, key=errors.__getitem__))
    return out


def fit(
    steps: Steps | Sequence[Steps],
    start: PlantConstants | None = None,
    free: Sequence[str] = FITTED,
    max_evaluations: int = 200,
) -> Fit:
    """Least-squares fit of the constants ``free`` (others stay as in ``start``, by default
    the emulator's plant) to the recording (or recordings: their residuals side by side)."""
    from scipy.optimize import least_squares

    from prm9tool.device.emulator.constants import PLANT

    base = start or PLANT
    names = {f.name for f in fields(base) if isinstance(getattr(base, f.name), float)}
    unknown = [n for n in free if n not in names]
    if unknown:
        raise Prm9Error(
            f"no plant constant {unknown[0]!r} to fit; constants: {', '.join(sorted(names))}"
        )
    origin = np.array([float(getattr(base, n)) for n in free])

    def plant_at(x: np.ndarray) -> PlantConstants:
        changes: dict[str, Any] = dict(zip(free, map(float, origin * np.exp(x)), strict=True))
        return replace(base, **changes)

    recordings = [steps] if isinstance(steps, Steps) else list(steps)
    if not recordings:
        raise Prm9Error("nothing to fit: no recorded steps")
    initial = origin.copy()  # where the fit starts: what the report calls each one's start
    only_steps = [r for r in recordings if r.kind == "step"]
    first_fit: Fit | None = None
    if len(only_steps) < len(recordings) and only_steps:
        # the steps first (a few seconds), the joint residual from their plant on: each of its
        # evaluations plays the triangle's windows too
        first_fit = fit(only_steps, start, [n for n in free if n in FITTED], max_evaluations)
        max_evaluations = JOINT_EVALUATIONS
        stepped: dict[str, Any] = {c.name: c.value for c in first_fit.constants}
        base = replace(base, **stepped)
        origin = np.array([float(getattr(base, n)) for n in free])
    lengths = [len(r.actual) - r.skip - r.tail for r in recordings]
    kinds = {r.kind for r in recordings}
    total = sum(lengths)
    weights = [  # each kind of measurement counts alike, whatever its number of samples
        math.sqrt(
            total
            / (
                len(kinds)
                * sum(n for n, o in zip(lengths, recordings, strict=True) if o.kind == r.kind)
            )
        )
        for r in recordings
    ]

    offsets = dither_offsets(recordings, base)
    shifts = window_shifts(recordings, base, offsets)

    def residual(x: np.ndarray) -> np.ndarray:
        parts = []
        played = simulate_all(recordings, plant_at(x), offsets)
        for i, (one, simulated) in enumerate(zip(recordings, played, strict=True)):
            end = len(one.actual) - one.tail
            part = np.zeros(end - one.skip)  # (a simulation ends where it ends)
            k = shifts[i]
            n = min(len(simulated) + k, end) - one.skip
            part[:n] = (
                simulated[one.skip - k : one.skip - k + n] - one.actual[one.skip : one.skip + n]
            )
            parts.append(weights[i] * part)
        return np.concatenate(parts)

    memo: dict[bytes, np.ndarray] = {}

    def cached(x: np.ndarray) -> np.ndarray:
        key = np.asarray(x, dtype=float).tobytes()
        if key not in memo:
            memo[key] = residual(x)
        return memo[key]

    def jacobian(x: np.ndarray) -> np.ndarray:
        """Forward differences of STEP in each logarithm: wider than the LVDT's steps and the
        friction's corners, which make the residual rough on a finer scale."""
        r0 = cached(x)
        columns = []
        for i in range(len(x)):
            moved = x.copy()
            moved[i] += STEP if moved[i] + STEP <= BOUND else -STEP
            columns.append((cached(moved) - r0) / (moved[i] - x[i]))
        return np.column_stack(columns)

    x0 = np.zeros(len(free))
    first = cached(np.clip(np.log(initial / origin), -BOUND, BOUND))
    result = least_squares(
        cached, x0, jac=jacobian, bounds=(-BOUND, BOUND), x_scale=1.0, max_nfev=max_evaluations
    )
    # the spool follows the dither with a lag the plant sets: aligned again on the fitted
    # plant, and fitted on from there while that moves an offset (at most ALIGN_ROUNDS times)
    for _round in range(ALIGN_ROUNDS):
        again = dither_offsets(recordings, plant_at(result.x))
        moved = window_shifts(recordings, plant_at(result.x), again)
        if again == offsets and moved == shifts:
            break
        offsets[:], shifts[:] = again, moved
        memo.clear()
        evaluations = int(result.nfev)
        result = least_squares(
            cached,
            result.x,
            jac=jacobian,
            bounds=(-BOUND, BOUND),
            x_scale=1.0,
            max_nfev=max_evaluations,
        )
        result.nfev += evaluations
    r = result.fun
    dof = max(1, len(r) - len(free))
    s2 = float(r @ r) / dof
    jac = np.asarray(result.jac, dtype=float)
    cov = s2 * np.linalg.pinv(jac.T @ jac)
    se = np.sqrt(np.clip(np.diag(cov), 0.0, None))
    seen = np.abs(jac).sum(axis=0) > 0.0
    with np.errstate(invalid="ignore", divide="ignore"):
        corr = cov / np.outer(se, se)
    constants = []
    for i, name in enumerate(free):
        rse = float(se[i]) if seen[i] else math.inf
        partner = None
        for j, other in enumerate(free):
            if j != i and seen[i] and seen[j] and abs(float(corr[i, j])) > CORRELATED:
                partner = other
                break
        determined = rse < DETERMINED_RSE and partner is None
        value = float(origin[i] * math.exp(result.x[i])) if determined else float(initial[i])
        constants.append(FittedConstant(name, float(initial[i]), value, rse, determined, partner))
    fitted: dict[str, Any] = {c.name: c.value for c in constants}
    plant = replace(base, **fitted)
    final = cached(
        np.array([math.log(c.value / o) for c, o in zip(constants, origin, strict=True)])
    )
    spans = np.cumsum([0, *lengths])
    parts = {  # unweighted, per kind of measurement
        kind: np.concatenate(
            [
                final[spans[i] : spans[i + 1]] / weights[i]
                for i, r in enumerate(recordings)
                if r.kind == kind
            ]
        )
        for kind in kinds
    }
    ours = parts.get("step", final)
    before = np.concatenate(
        [first[spans[i] : spans[i + 1]] / weights[i] for i, r in enumerate(recordings)
         if r.kind == "step"] or [first]
    )  # fmt: skip
    return Fit(
        plant,
        tuple(constants),
        float(np.sqrt(np.mean(ours**2))),
        float(np.max(np.abs(ours))),
        float(np.sqrt(np.mean(before**2))),
        int(result.nfev) + (first_fit.evaluations if first_fit else 0),
        {kind: float(np.sqrt(np.mean(v**2))) for kind, v in sorted(parts.items())},
    )


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


def _write(valve: Any, values: dict[str, int]) -> None:
    """Write ``values`` (raw) into the emulated ``valve``'s working memory."""
    from prm9tool.catalogue import CATALOGUE

    for mnemonic, raw in values.items():
        param = CATALOGUE[mnemonic]
        try:
            valve.write(param.index, param.subindex, raw)
        except Prm9Error:  # e.g. a CANopen setpoint type on the analog copy: keep default
            continue


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

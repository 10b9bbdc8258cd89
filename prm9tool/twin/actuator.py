"""The E04's actuator from its process-loop run (issue 31 item 2: "for E04 the actuator").

An E04 in control mode 4 (its default) is characterized on its process loop: the process
setpoint's steps (process setpoint, process value and the spool demand the process controller
gives), its sweep and triangle, and the flow characteristic — two steps of the process setpoint
with the process controller made proportional, the spool position and the process value
recorded together (:mod:`prm9tool.characterize.flow`). The actuator in the emulator's plant is
an integrator of the spool's opening beyond the hydraulic overlap: full stroke in
``actuator_full_speed_s`` at 100 % opening (``actuator_return_s``: the spring return of a
single-coil valve). :func:`from_process_run` takes the steps and the flow record as
recordings; :func:`fit_actuator` plays them on an emulated E04 in control mode 4 with the
run's parameter set and adjusts ``actuator_full_speed_s`` and ``spool_overlap`` (and
``actuator_return_s`` on a single-coil valve) by least squares on the process value, with the
same confidence rule as :func:`prm9tool.twin.identify.fit`.

What such a run does not determine is said, with why (:data:`NOT_IN_PROCESS_RUN`): the spool's
own constants (the process loop at ~1 Hz hardly sees a spool at ~95 Hz) keep the start plant's
values. A position-loop run of an E04 (control mode 2) does not record the process value at
all: its twin keeps the actuator's start values and says so (:data:`NOT_IN_POSITION_RUN`).
No Qt.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field, fields, replace
from typing import TYPE_CHECKING, Any

import numpy as np

from prm9tool.catalogue.scale import FULL_SCALE
from prm9tool.characterize.frame import LOOPS
from prm9tool.characterize.rig import write_values
from prm9tool.characterize.transparent import TRANSPARENT
from prm9tool.errors import Prm9Error
from prm9tool.twin.identify import CORRELATED, DETERMINED_RSE, FITTED, Fit, FittedConstant
from prm9tool.twin.recording import CYCLE_HZ, Steps
from prm9tool.twin.replay import measured_actual, settled_cycles

if TYPE_CHECKING:
    from prm9tool.characterize.run import Characterization
    from prm9tool.device.emulator.constants import PlantConstants

PROCESS_MODE = 4  # CTRLMODE of the process loop (an E04's default)
# the process loop's chain: the deviation's gain and offsets stay (they act inside the loop)
PROCESS_CHAIN = {
    k: v
    for k, v in TRANSPARENT.items()
    if k not in ("GAINSETPOS", "GAINSETNEG", "OFFSETPOS", "OFFSETNEG")
}
ACTUATOR = ("actuator_full_speed_s", "spool_overlap")  # fitted on every E04
SPRING_RETURN = "actuator_return_s"  # fitted on a single-coil E04 only
LINEAR = {"spool_overlap": 0.3}  # fitted on a linear scale from 0 up to this (a fraction)
LOG_BOUND = math.log(10.0)  # the others: at most tenfold from their start, on a log scale
STEP_LOG = 0.03  # the Jacobian's finite difference in a logarithm (3 %)
STEP_LINEAR = 0.004  # … and in a linear constant (0.4 % of the stroke)
LINEAR_SE = 0.005  # a linear constant is determined below this standard error (of the stroke)
STATIC_END_PCT = -100.0  # where the static characteristic's triangle ends, before the flow test
# the control monitoring as late and wide as it goes: a trial plant far from the valve's must
# not stop the simulation with a fault (the run itself had none; a diagnostic, not dynamics)
UNMONITORED = {"MONTHRES": FULL_SCALE, "MONDELAY": 5000}
NOT_IN_PROCESS_RUN = (
    "a process-loop run does not step the spool's position loop on its own (the loop at "
    "about 1 Hz hardly sees the spool): kept"
)
NOT_IN_POSITION_RUN = (
    "a position-loop run does not record the process value: the actuator is not in its "
    "data (characterize the E04 in control mode 4, its default): kept"
)


@dataclass(frozen=True)
class FlowSteps(Steps):
    """The flow test's record: played after the end of the static characteristic's triangle
    (``triangle_pct_s`` fast, through the valve's own chain ``own``), as the run played it."""

    own: dict[str, int] = field(default_factory=dict)
    triangle_pct_s: float = 10.0


def from_process_run(run: Characterization) -> list[Steps]:
    """The process-loop steps (``kind="process"``: the measured process setpoint as the
    stimulus, the process value as the response) and the flow record (``kind="flow"``: the
    process setpoint steps the flow test writes, reconstructed from the run's profile, and the
    process value) of an E04's process-loop run, each with the parameter set the procedure ran
    it with. Prm9Error when the run has neither."""
    from prm9tool.catalogue.typekey import TypeKey
    from prm9tool.catalogue.variant import Coils

    lp = LOOPS["process"]
    base = {**run.parameters, "CTRLMODE": PROCESS_MODE}
    fs = run.info.sample_rate_hz
    out = []
    for step in run.steps:
        channels = step.record.channels
        if step.loop != "process" or lp.setpoint not in channels or lp.actual not in channels:
            continue
        demand = np.asarray(channels[lp.setpoint], dtype=float)
        actual = np.asarray(channels[lp.actual], dtype=float)
        if np.isfinite(demand).all() and np.isfinite(actual).all():
            values = {**base, **PROCESS_CHAIN}
            out.append(Steps(run.info.type_key, values, demand, actual, fs, True, "process"))
    flow = run.flow
    if flow is not None and "process_actual" in flow.record.channels:
        actual = np.asarray(flow.record.channels["process_actual"], dtype=float)
        profile = run.profile.for_loop("process")
        n = len(actual) // 2
        two = TypeKey.parse(run.info.type_key).variant.coils is Coils.AB
        high = profile.flow_amplitude_pct
        low = -high if two else 0.0
        changes = {"PRCKI": 0, "PRCKD": 0, "OFFSETPOS": 0, **({"OFFSETNEG": 0} if two else {})}
        if n and np.isfinite(actual).all():
            stimulus = np.concatenate([np.full(n, high), np.full(len(actual) - n, low)])
            values = {**base, **PROCESS_CHAIN, **changes}
            rate = 200.0 / (profile.static_period_s / 2.0)  # the triangle: −100 → 100 → −100
            out.append(
                FlowSteps(
                    run.info.type_key, values, stimulus, actual, fs, False, "flow",
                    own=base, triangle_pct_s=rate,
                )
            )  # fmt: skip
    if not out:
        raise Prm9Error("the characterization has no complete process-loop step to fit")
    return out


def simulate_process(recordings: Sequence[Steps], plant: PlantConstants) -> list[np.ndarray]:
    """The process value of an emulated E04 with ``plant`` (analog, control mode 4) to each
    recording's stimulus, played one after the other on one valve, each after a hold at its
    start level as the procedure held the valve (a step: :func:`settle_cycles`; the flow test: the
    triangle's end, then as long as each of its halves at its second level). The control
    monitoring is off (:data:`UNMONITORED`)."""
    from prm9tool.catalogue.typekey import TypeKey
    from prm9tool.characterize.rig import EmulatorRig
    from prm9tool.device.emulator import EmulatedValve

    key = TypeKey.parse(recordings[0].type_key)
    analog = TypeKey(key.size, key.spool, key.flow, key.supply, key.config, False)
    valve = EmulatedValve(analog, plant=plant)
    write_values(valve, {**recordings[0].values, **UNMONITORED})
    rig = EmulatorRig(valve)
    lp = LOOPS["process"]
    out = []
    try:
        for steps in recordings:
            ratio = CYCLE_HZ / steps.rate_hz
            per = round(ratio)
            if per < 1 or abs(ratio - per) > 1e-9:
                raise Prm9Error(
                    f"a recording at {steps.rate_hz:g} Hz: the rate must divide 5000 Hz"
                )
            write_values(valve, {**steps.values, **UNMONITORED})
            played = np.repeat(steps.stimulus, per)
            if isinstance(steps, FlowSteps):
                # after the triangle's end through the valve's own chain, as in the run: the
                # flow test's first hold starts where that left the actuator
                write_values(valve, {**steps.own, **UNMONITORED})
                span = abs(STATIC_END_PCT) / max(steps.triangle_pct_s, 1.0)
                rig.play(np.linspace(0.0, STATIC_END_PCT, round(span * CYCLE_HZ)), [lp.actual])
                write_values(valve, {**steps.values, **UNMONITORED})
                hold = np.full(len(played) - len(played) // 2, played[-1])
            else:
                hold = np.full(settle_cycles(steps), played[0])
            samples = rig.play(np.concatenate([hold, played]), [lp.setpoint, lp.actual])
            samples = samples[len(hold) :]
            actual = measured_actual(samples, played, steps, lp)
            out.append(actual[per - 1 :: per])
    finally:
        rig.release()
    return out


def settle_cycles(steps: Steps) -> int:
    """The hold the procedure settled a step with (``frame.settle``, which returns after
    one hold when the loop is there): max(0.1 s, the step's window), in cycles — 1.5 s with
    the default profile's process loop."""
    return settled_cycles(steps)


def free_constants(type_key: str) -> tuple[str, ...]:
    """The actuator's constants a process-loop run of ``type_key`` determines."""
    from prm9tool.catalogue.typekey import TypeKey
    from prm9tool.catalogue.variant import Coils

    two = TypeKey.parse(type_key).variant.coils is Coils.AB
    return ACTUATOR if two else (*ACTUATOR, SPRING_RETURN)


def fit_actuator(
    recordings: Sequence[Steps],
    start: PlantConstants | None = None,
    max_evaluations: int = 40,
) -> Fit:
    """Least-squares fit of the actuator's constants (:func:`free_constants`) to the process
    value of ``recordings`` (:func:`from_process_run`); the other constants stay as in
    ``start`` (the emulator's plant) and are listed as not determined, with why. Each kind of
    recording (the steps, the flow test) counts alike in the residual."""
    from scipy.optimize import least_squares

    from prm9tool.device.emulator.constants import PLANT

    if not recordings:
        raise Prm9Error("nothing to fit: no recorded process-loop step")
    base = start or PLANT
    free = free_constants(recordings[0].type_key)
    origin = np.array([float(getattr(base, n)) for n in free])
    linear = np.array([n in LINEAR for n in free])
    lower = np.where(linear, 0.0, -LOG_BOUND)
    upper = np.array([LINEAR.get(n, LOG_BOUND) for n in free])

    def values_at(x: np.ndarray) -> np.ndarray:
        return np.where(linear, x, origin * np.exp(np.where(linear, 0.0, x)))

    def plant_at(x: np.ndarray) -> PlantConstants:
        changes: dict[str, Any] = dict(zip(free, map(float, values_at(x)), strict=True))
        return replace(base, **changes)

    kinds = {r.kind for r in recordings}
    lengths = [len(r.actual) for r in recordings]
    per_kind = {k: sum(n for n, r in zip(lengths, recordings, strict=True) if r.kind == k)
                for k in kinds}  # fmt: skip
    weights = np.array([math.sqrt(sum(lengths) / (len(kinds) * per_kind[r.kind]))
                        for r in recordings])  # fmt: skip
    memo: dict[bytes, np.ndarray] = {}

    def residual(x: np.ndarray) -> np.ndarray:
        key = np.asarray(x, dtype=float).tobytes()
        if key not in memo:
            played = simulate_process(recordings, plant_at(x))
            memo[key] = np.concatenate(
                [
                    w * (sim[: len(r.actual)] - r.actual)
                    for w, sim, r in zip(weights, played, recordings, strict=True)
                ]
            )
        return memo[key]

    steps = np.where(linear, STEP_LINEAR, STEP_LOG)

    def jacobian(x: np.ndarray) -> np.ndarray:
        r0 = residual(x)
        columns = []
        for i in range(len(x)):
            moved = x.copy()
            moved[i] += steps[i] if moved[i] + steps[i] <= upper[i] else -steps[i]
            columns.append((residual(moved) - r0) / (moved[i] - x[i]))
        return np.column_stack(columns)

    x0 = np.where(linear, np.clip(origin, 0.0, upper), 0.0)
    first = residual(x0)
    result = least_squares(
        residual,
        x0,
        jac=jacobian,
        bounds=(lower, upper),
        method="dogbox",  # a constant at its bound (no overlap) does not stall it as trf
        x_scale=1.0,
        max_nfev=max_evaluations,
    )
    rse, partners = confidence(np.asarray(result.jac, dtype=float), result.fun, free)
    found = values_at(result.x)
    constants = []
    for i, name in enumerate(free):
        # a linear constant's standard error is in its unit (of the stroke: it may be 0)
        limit = LINEAR_SE if linear[i] else DETERMINED_RSE
        determined = rse[i] < limit and partners[i] is None
        value = float(found[i]) if determined else float(origin[i])
        why = None if determined else _why_not(rse[i], partners[i], bool(linear[i]))
        constants.append(
            FittedConstant(name, float(origin[i]), value, rse[i], determined, partners[i], why)
        )
    constants += kept(base, FITTED, NOT_IN_PROCESS_RUN)
    found_values: dict[str, Any] = {c.name: c.value for c in constants}
    plant = replace(base, **found_values)
    final = residual(np.array([_x_of(c.value, o, n in LINEAR) for c, o, n in
                               zip(constants, origin, free, strict=False)]))  # fmt: skip
    spans = np.cumsum([0, *lengths])

    def part(values: np.ndarray, kind: str) -> np.ndarray:
        """The unweighted residual of the recordings of ``kind``."""
        pieces = [values[spans[i] : spans[i + 1]] / weights[i]
                  for i, r in enumerate(recordings) if r.kind == kind]  # fmt: skip
        return np.concatenate(pieces) if pieces else values

    parts = {kind: part(final, kind) for kind in sorted(kinds)}
    ours, before = part(final, "process"), part(first, "process")
    return Fit(
        plant,
        tuple(constants),
        float(np.sqrt(np.mean(ours**2))),
        float(np.max(np.abs(ours))),
        float(np.sqrt(np.mean(before**2))),
        int(result.nfev),
        {kind: float(np.sqrt(np.mean(v**2))) for kind, v in parts.items()},
    )


def _x_of(value: float, origin: float, linear: bool) -> float:
    return value if linear else math.log(value / origin)


def _why_not(rse: float, partner: str | None, linear: bool) -> str:
    if partner is not None:
        return f"seen only together with {partner}: kept"
    if not math.isfinite(rse):
        return "the run's data do not move with it at all: kept"
    if linear:
        return f"standard error {rse:.2%} of the stroke (determined below {LINEAR_SE:.1%}): kept"
    return f"relative standard error {rse:.0%} (determined below {DETERMINED_RSE:.0%}): kept"


def confidence(
    jac: np.ndarray, residual: np.ndarray, names: Sequence[str]
) -> tuple[list[float], list[str | None]]:
    """Per constant, its standard error (of the logarithm: relative; of a linear constant: in
    its unit) from the Jacobian at the solution, ``cov = s²·(JᵀJ)⁺``, inf where the residual
    does not move with it; and the constant it is correlated with beyond :data:`CORRELATED`
    (None: none)."""
    dof = max(1, len(residual) - len(names))
    s2 = float(residual @ residual) / dof
    cov = s2 * np.linalg.pinv(jac.T @ jac)
    se = np.sqrt(np.clip(np.diag(cov), 0.0, None))
    seen = np.abs(jac).sum(axis=0) > 0.0
    with np.errstate(invalid="ignore", divide="ignore"):
        corr = cov / np.outer(se, se)
    rse = [float(se[i]) if seen[i] else math.inf for i in range(len(names))]
    partners: list[str | None] = []
    for i in range(len(names)):
        partner = None
        for j, other in enumerate(names):
            if j != i and seen[i] and seen[j] and abs(float(corr[i, j])) > CORRELATED:
                partner = other
                break
        partners.append(partner)
    return rse, partners


def kept(plant: PlantConstants, names: Sequence[str], why: str) -> list[FittedConstant]:
    """``names`` as constants the data do not determine: their values as in ``plant``."""
    known = {f.name for f in fields(plant)}
    return [
        FittedConstant(n, getattr(plant, n), getattr(plant, n), math.inf, False, None, why)
        for n in names
        if n in known
    ]

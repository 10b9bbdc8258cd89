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
from dataclasses import dataclass, fields, replace
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from prm9tool.catalogue.signals import BY_KEY
from prm9tool.characterize.procedures import LOOPS, chain_changes, preserved
from prm9tool.characterize.transparent import TRANSPARENT
from prm9tool.errors import Prm9Error

if TYPE_CHECKING:
    from prm9tool.characterize.rig import Rig
    from prm9tool.characterize.run import Characterization
    from prm9tool.device.emulator.constants import PlantConstants

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
BOUND = math.log(10.0)  # a constant moves at most tenfold from its start
DETERMINED_RSE = 0.05  # relative standard error below which a constant counts as determined
CORRELATED = 0.98  # |correlation| above which two constants are seen only together
STEP = 0.03  # the Jacobian's finite difference, in log(constant): 3 %
BETWEEN_S = 0.1  # the hold between two recordings played on one valve
MAX_LAG = 25  # cycles: the override's latency to the demand is looked for up to 5 ms
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


@dataclass(frozen=True)
class FittedConstant:
    """One plant constant after the fit."""

    name: str
    start: float
    value: float
    relative_se: float  # standard error of log(value): relative; inf when not seen at all
    determined: bool
    correlated_with: str | None = None  # the constant only seen together with this one


@dataclass(frozen=True)
class Fit:
    """The fitted plant and how well it explains the recording."""

    plant: PlantConstants
    constants: tuple[FittedConstant, ...]
    rms_pct: float  # residual, % of full scale
    max_pct: float
    start_rms_pct: float
    evaluations: int

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


def simulate_all(recordings: Sequence[Steps], plant: PlantConstants) -> list[np.ndarray]:
    """The responses to several recordings of one valve, played one after the other on one
    emulated valve (the first recording's type and parameter set), each but the first after a
    hold of :data:`BETWEEN_S` at its start level: as a characterization run moves from one test
    to the next, so the spool comes to rest where friction holds it, not at a fresh 0."""
    from prm9tool.catalogue import CATALOGUE
    from prm9tool.catalogue.typekey import TypeKey
    from prm9tool.characterize.rig import EmulatorRig
    from prm9tool.device.emulator import EmulatedValve

    first = recordings[0]
    key = TypeKey.parse(first.type_key)
    analog = TypeKey(key.size, key.spool, key.flow, key.supply, key.config, False)
    valve = EmulatedValve(analog, plant=plant)
    for mnemonic, raw in {**first.values, **TRANSPARENT}.items():
        param = CATALOGUE[mnemonic]
        try:
            valve.write(param.index, param.subindex, raw)
        except Prm9Error:  # e.g. a CANopen setpoint type on the analog copy: keep default
            continue
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
            hold = round(BETWEEN_S * CYCLE_HZ) if i else 0
            samples = rig.play(
                np.concatenate([np.full(hold, played[0]), played]), [lp.setpoint, lp.actual]
            )[hold:]
            actual = samples[:, 1] * BY_KEY[lp.actual].scale
            if steps.demand:  # the stimulus is a measured demand: drop the override's latency
                demand = samples[:, 0] * BY_KEY[lp.setpoint].scale
                lag = min(
                    range(MAX_LAG),
                    key=lambda k: float(np.abs(demand[k:] - played[: len(played) - k]).sum()),
                )
                actual = np.concatenate([actual[lag:], np.full(lag, actual[-1])])
            out.append(actual[per - 1 :: per])
    finally:
        rig.release()
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

    def residual(x: np.ndarray) -> np.ndarray:
        parts = []
        for one, simulated in zip(recordings, simulate_all(recordings, plant_at(x)), strict=True):
            n = min(len(simulated), len(one.actual))
            parts.append(simulated[:n] - one.actual[:n])
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
    first = cached(x0)
    result = least_squares(
        cached, x0, jac=jacobian, bounds=(-BOUND, BOUND), x_scale=1.0, max_nfev=max_evaluations
    )
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
        value = float(origin[i] * math.exp(result.x[i])) if determined else float(origin[i])
        constants.append(FittedConstant(name, float(origin[i]), value, rse, determined, partner))
    fitted: dict[str, Any] = {c.name: c.value for c in constants}
    plant = replace(base, **fitted)
    final = cached(np.array([math.log(c.value / c.start) for c in constants]))
    return Fit(
        plant,
        tuple(constants),
        float(np.sqrt(np.mean(final**2))),
        float(np.max(np.abs(final))),
        float(np.sqrt(np.mean(first**2))),
        int(result.nfev),
    )


def from_characterization(run: Characterization) -> list[Steps]:
    """The position-loop steps of a characterization run (any link) as recordings to fit: each
    step's measured demand is its stimulus (through the transparent chain the run used, the
    demand is the override's value), from the spool at rest at the step's start."""
    lp = LOOPS["position"]
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
                dict(run.parameters),
                demand,
                actual,
                run.info.sample_rate_hz,
                demand=True,
            )
        )
    if not out:
        raise Prm9Error("the characterization has no complete position-loop step to fit")
    return out


def from_report(path: str | Path) -> list[Steps]:
    """The position-loop steps of a characterization's JSON report (``--characterize --json``
    with its CSV files, the ``-step-<a>.csv`` ones), as :func:`from_characterization` takes
    them from the run in memory. CSV paths are taken as written, else next to the report."""
    import csv
    import json

    where = Path(path)
    try:
        report = json.loads(where.read_text(encoding="utf-8"))
        valve, rate = report["valve"], float(report["sample_rate_hz"])
        type_key, parameters, files = valve["type_key"], report["parameters"], report["csv"]
    except OSError as exc:
        raise Prm9Error(f"cannot read the report {where}: {exc.strerror or exc}") from None
    except (ValueError, KeyError, TypeError) as exc:
        raise Prm9Error(f"{where}: not a characterization report ({exc})") from None
    lp = LOOPS["position"]
    out = []
    for name in files:
        if "-step-" not in Path(name).name:
            continue
        csv_path = Path(name) if Path(name).exists() else where.parent / Path(name).name
        try:
            with csv_path.open(encoding="utf-8", newline="") as stream:
                rows = list(csv.reader(stream))
        except OSError as exc:
            raise Prm9Error(f"cannot read {csv_path}: {exc.strerror or exc}") from None
        head = rows[0]
        if lp.setpoint not in head or lp.actual not in head:
            continue  # a process-loop step
        table = np.array(rows[1:], dtype=float)
        demand = table[:, head.index(lp.setpoint)]
        actual = table[:, head.index(lp.actual)]
        if not (np.isfinite(demand).all() and np.isfinite(actual).all()):
            continue
        out.append(Steps(type_key, dict(parameters), demand, actual, rate, demand=True))
    if not out:
        raise Prm9Error(f"{where}: no complete position-loop step to fit (its CSV files?)")
    return out


def _parameter_set(rig: Rig) -> dict[str, int]:
    """The valve's writable file parameters and its control mode, read from it."""
    from prm9tool.catalogue import CATALOGUE
    from prm9tool.catalogue.typekey import TypeKey

    variant = TypeKey.parse(rig.info.type_key).variant
    names = [p.mnemonic for p in CATALOGUE.file_parameters(variant) if p.writable]
    return {**rig.read(["CTRLMODE"]), **rig.read(names)}

"""Identify the emulator's plant constants from measured recordings (issue 31 item 2).

:func:`fit` replays the recordings (:mod:`.recording`: a characterization's position-loop
steps and windows of its sweep and static triangle, or :func:`~.recording.record`'s steps) on
an emulated valve of the same type with the same parameters (:mod:`.replay`) and adjusts the
chosen plant constants (:data:`FITTED`) until the simulated response matches the measured one
in the least squares sense (``scipy.optimize.least_squares`` on the logarithms of the
constants, so each is adjusted relative to its size and stays positive).

Confidence (:func:`confidence`): from the Jacobian at the solution, ``cov = s²·(JᵀJ)⁺`` with
``s²`` the residual variance, the standard error of each logarithm is the constant's relative
standard error. A constant is *determined* when that is below :data:`DETERMINED_RSE` and no
other fitted constant is so correlated with it (:data:`CORRELATED`) that only a combination of
the two is seen. The samples of a step response are not independent (the residual is mostly
model error, not white noise), so the standard errors are optimistic: they say which
constants the data see at all, not a calibrated interval. A constant that is not determined
keeps its value from the start point, and the fit says so instead of inventing one.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field, fields, replace
from typing import TYPE_CHECKING, Any

import numpy as np

from prm9tool.errors import Prm9Error
from prm9tool.twin.recording import Steps
from prm9tool.twin.replay import dither_offsets, simulate_all, window_shifts

if TYPE_CHECKING:
    from prm9tool.device.emulator.constants import PlantConstants

FITTED = (  # the spool's dynamics, the solenoid and its force, friction
    "spool_mass_kg",
    "damping_n_s_per_m",
    "force_n_per_a",
    "coulomb_friction_n",
    "force_lag_s",
    "coil_l_h",
)
# with the static characteristic (:func:`~.recording.from_characterization`): the
# break-away friction too (the spring stays: only its ratio to the force constant is seen)
JOINT = (*FITTED, "static_friction_n")
JOINT_EVALUATIONS = 12  # the joint fit's, from the steps' solution (each plays every window)
BOUND = math.log(10.0)  # a constant moves at most tenfold from its start
DETERMINED_RSE = 0.05  # relative standard error below which a constant counts as determined
CORRELATED = 0.98  # |correlation| above which two constants are seen only together
STEP = 0.03  # the Jacobian's finite difference, in log(constant): 3 %
ALIGN_ROUNDS = 3  # alignments on the fitted plant, each followed by a fit from there
EXPLAINED_PCT = 0.12  # rms residual of an explained recording: two LVDT steps (0.061 % each)


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
    constants = confidence(free, initial, origin, result.x, result.fun, result.jac)
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


def confidence(
    free: Sequence[str],
    initial: np.ndarray,
    origin: np.ndarray,
    x: np.ndarray,
    r: np.ndarray,
    jac: np.ndarray,
) -> list[FittedConstant]:
    """Each constant of ``free`` at the solution ``x`` (logarithms relative to ``origin``)
    with its relative standard error and whether the data determine it (the module's
    docstring); one that is not keeps its ``initial`` value. ``r`` and ``jac``: the
    residual and its Jacobian at ``x``."""
    dof = max(1, len(r) - len(free))
    s2 = float(r @ r) / dof
    jac = np.asarray(jac, dtype=float)
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
        value = float(origin[i] * math.exp(x[i])) if determined else float(initial[i])
        constants.append(FittedConstant(name, float(initial[i]), value, rse, determined, partner))
    return constants

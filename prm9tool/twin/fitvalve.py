"""A valve's twin from its own characterization (issue 31 item 2): the one implementation
behind ``--fit-twin OUT.toml --device ID``/``--emulator KEY``, ``--fit-twin … --from RUN.json``,
``Valve.fit_twin(…)`` and the service's ``fit_twin``.

:func:`twin_of_run` fits the position-loop steps of a characterization run (from any link,
or read from its JSON report) and writes the twin file; :func:`fit_valve` runs the
characterization on a rig first. :func:`fit_report` is the fit report (``--json``) and
:func:`history_details` what a ``twin`` history record keeps of it. No Qt.
"""

from __future__ import annotations

import math
import os
from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace
from pathlib import Path
from typing import TYPE_CHECKING, Any

from prm9tool.device.emulator.twinfile import write_twin
from prm9tool.twin.actuator import (
    NOT_IN_POSITION_RUN,
    PROCESS_MODE,
    fit_actuator,
    free_constants,
    from_process_run,
    kept,
)
from prm9tool.twin.breakaway import fit_with_breakaway
from prm9tool.twin.identify import FITTED, Fit, fit
from prm9tool.twin.recording import Steps, from_characterization

if TYPE_CHECKING:
    from prm9tool.analysis.profile import Profile
    from prm9tool.characterize.rig import Rig
    from prm9tool.characterize.run import Characterization


STATIC = "static_friction_n"
# Why the break-away friction is kept where its stage (twin/breakaway.py) found nothing better
# (docs/twin.md, "Static friction")
STATIC_FRICTION_KEPT = (
    "the run has no step of at most 20 %, or the break-away friction its small steps' scan "
    "found did not explain the steps better than this one: where the spool sticks it sticks "
    "and slips, and the steps' residual does not slope towards the friction: kept"
)


@dataclass(frozen=True)
class ValveTwin:
    """A twin fitted from a characterization: the run (None: fitted from a JSON report), the
    fit and the twin file written."""

    run: Characterization | None
    fit: Fit
    path: Path


def write_fitted(
    path: str | os.PathLike[str],
    recordings: Sequence[Steps],
    serial: int,
    type_key: str,
    firmware: str,
    source: str,
) -> Fit:
    """Fit ``recordings`` and write the twin file ``path``; returns the fit (:func:`fitted`)."""
    result = with_kept(fitted(recordings), type_key)
    write_twin(path, result, serial, type_key, firmware, source, recordings[0].values)
    return result


def fitted(recordings: Sequence[Steps]) -> Fit:
    """The fit of a position-loop run's ``recordings`` from the factory plant: the steps, the
    break-away friction in a stage of its own (:func:`~.breakaway.fit_with_breakaway`), then
    the joint residual with the sweep's and the triangle's windows from there."""
    from prm9tool.device.emulator.constants import PLANT

    steps = [r for r in recordings if r.kind == "step"]
    if not steps:
        return fit(recordings, free=FITTED)
    first = fit(steps, free=FITTED)
    plant, static, evaluations = fit_with_breakaway(steps, first, PLANT, STATIC_FRICTION_KEPT)
    result = fit(recordings, start=plant, free=FITTED)
    return replace(
        result,
        constants=(*result.constants, static),
        start_rms_pct=first.start_rms_pct,
        evaluations=result.evaluations + first.evaluations + evaluations,
    )


def with_kept(result: Fit, type_key: str) -> Fit:
    """A position-loop fit with what it keeps listed as not determined, and why: the static
    friction (:data:`STATIC_FRICTION_KEPT`) and on an E04 the actuator's constants
    (:data:`~.actuator.NOT_IN_POSITION_RUN`)."""
    from prm9tool.catalogue.typekey import TypeKey
    from prm9tool.catalogue.variant import Config

    have = {c.name for c in result.constants}
    extra = kept(result.plant, [STATIC] if STATIC not in have else [], STATIC_FRICTION_KEPT)
    if TypeKey.parse(type_key).variant.config is Config.E04:
        names = [n for n in free_constants(type_key) if n not in have]
        extra += kept(result.plant, names, NOT_IN_POSITION_RUN)
    return replace(result, constants=(*result.constants, *extra))


def twin_of_process_run(run: Characterization, path: str | os.PathLike[str]) -> ValveTwin:
    """The twin of an E04 whose process loop ``run`` characterized (control mode 4): its
    actuator fitted from the run's process-loop steps and flow characteristic
    (:func:`~.actuator.fit_actuator`), the spool's constants kept and said so."""
    recordings = from_process_run(run)
    result = fit_actuator(recordings)
    info = run.info
    steps = sum(r.kind == "process" for r in recordings)
    flow = any(r.kind == "flow" for r in recordings)
    source = (
        f"{steps} process-loop steps{' and the flow characteristic' if flow else ''}"
        f" of the characterization of {run.date} "
        f"({info.link or 'link'}, {info.sample_rate_hz:g} Hz)"
    )
    values = {**run.parameters, "CTRLMODE": PROCESS_MODE}
    serial, firmware = int(info.serial or 0), info.firmware or ""
    write_twin(path, result, serial, info.type_key, firmware, source, values)
    return ValveTwin(run, result, Path(path))


def twin_of_run(run: Characterization, path: str | os.PathLike[str]) -> ValveTwin:
    """The twin of the valve ``run`` characterized, written to ``path``: from the run's
    position-loop steps (with windows of its sweep and triangle), or on an E04 whose process
    loop was characterized from its process-loop steps and flow test
    (:func:`twin_of_process_run`). Prm9Error when the run has no complete step to fit."""
    if run.loop == "process":
        return twin_of_process_run(run, path)
    recordings = from_characterization(run)
    joint = any(r.kind != "step" for r in recordings)
    info = run.info
    source = (
        f"{sum(r.kind == 'step' for r in recordings)} position-loop steps"
        f"{', the sweep and the static characteristic' if joint else ''}"
        f" of the characterization of {run.date} "
        f"({info.link or 'link'}, {info.sample_rate_hz:g} Hz)"
    )
    result = write_fitted(
        path, recordings, int(info.serial or 0), info.type_key, info.firmware or "", source
    )
    return ValveTwin(run, result, Path(path))


def fit_valve(
    rig: Rig,
    path: str | os.PathLike[str],
    profile: Profile | None = None,
    progress: Callable[[str], None] | None = None,
) -> ValveTwin:
    """Characterize the valve behind ``rig`` with ``profile`` (default: the built-in one; its
    steps move the spool: the hydraulics must be safe for it), fit its twin from the run and
    write it to ``path``."""
    from prm9tool.analysis.profile import DEFAULT
    from prm9tool.characterize.run import characterize

    run = characterize(rig, profile or DEFAULT, progress)
    return twin_of_run(run, path)


def fit_report(result: Fit, path: str | os.PathLike[str]) -> dict[str, Any]:
    """The fit report (``--fit-twin … --json``): residuals and every fitted constant."""
    return {
        "twin": str(path),
        "rms_pct": result.rms_pct,
        "max_pct": result.max_pct,
        "start_rms_pct": result.start_rms_pct,
        "parts_rms_pct": dict(result.parts_rms_pct),
        "explained": result.explained,
        "evaluations": result.evaluations,
        "constants": [
            {
                "constant": c.name,
                "start": c.start,
                "value": c.value,
                "relative_se": c.relative_se if math.isfinite(c.relative_se) else None,
                "determined": c.determined,
                "correlated_with": c.correlated_with,
                "reason": c.reason,
            }
            for c in result.constants
        ],
    }


def history_outcome(result: Fit) -> str:
    """A ``twin`` record's outcome: ``explained`` or ``not-explained`` (docs/history.md)."""
    return "explained" if result.explained else "not-explained"


def history_details(result: Fit, path: str | os.PathLike[str]) -> dict[str, Any]:
    """What a ``twin`` history record keeps: the file, the residuals, each constant's value
    and whether the data determine it."""
    return {
        "twin_file": str(Path(path).resolve()),
        "rms_pct": result.rms_pct,
        "start_rms_pct": result.start_rms_pct,
        "constants": {
            c.name: {"value": c.value, "determined": c.determined, "reason": c.reason}
            for c in result.constants
        },
    }

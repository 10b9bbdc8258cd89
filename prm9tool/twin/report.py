"""A characterization run read back from its JSON report and the CSV files beside it
(``--characterize --json``: ``-step-<a>.csv``, ``-sweep.csv``, ``-bode.csv``,
``-static.csv``, an E04 process-loop run's ``-flow.csv``), so ``--fit-twin OUT.toml --from
RUN.json`` fits what ``--fit-twin --device`` fits from the run in memory — the steps, windows of
the sweep and of the static characteristic's triangle, the flow test — through the one
:func:`prm9tool.twin.fitvalve.twin_of_run`.

What an older report does not have is left out, not guessed: without the time record of the
sweep (``-sweep.csv``, written since this version) or the test settings (``tests``: where the
chirp is at which frequency) the sweep is not fitted; without ``-static.csv`` the triangle is
not; without ``-flow.csv`` an E04's process-loop run is fitted on its steps. The figures are
measured again from the records (as the run measured them), so the
twin can be characterized as the valve was and the two set side by side. No Qt.
"""

from __future__ import annotations

import csv
import json
import math
import os
from dataclasses import fields, replace
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from prm9tool.errors import Prm9Error

if TYPE_CHECKING:
    from prm9tool.characterize.run import Characterization

TIME = "time [s]"
DEMAND = "demand [%]"


def run_of_report(path: str | os.PathLike[str]) -> Characterization:
    """The run the report ``path`` describes (Prm9Error naming the file when it cannot be read
    or is not a characterization report). CSV paths are taken as written, else beside it."""
    from prm9tool.analysis.profile import DEFAULT
    from prm9tool.analysis.static import static_characteristic
    from prm9tool.characterize.procedures import BodeResult, Record, StaticResult, StepResult
    from prm9tool.characterize.rig import RigInfo
    from prm9tool.characterize.run import Characterization, figures

    where = Path(path)
    try:
        report = json.loads(where.read_text(encoding="utf-8"))
        valve, rate = report["valve"], float(report["sample_rate_hz"])
        info = RigInfo(
            str(valve["type_key"]),
            int(valve.get("serial") or 0),
            str(valve.get("firmware") or ""),
            str(report.get("link") or ""),
            rate,
        )
        parameters = {str(k): int(v) for k, v in report["parameters"].items()}
        files = [str(name) for name in report["csv"]]
        tests = report.get("tests") if isinstance(report.get("tests"), dict) else {}
        sweep = report.get("sweep") if isinstance(report.get("sweep"), dict) else {}
    except OSError as exc:
        raise Prm9Error(f"cannot read the report {where}: {exc.strerror or exc}") from None
    except (ValueError, KeyError, TypeError, AttributeError) as exc:
        raise Prm9Error(f"{where}: not a characterization report ({exc})") from None
    known = {f.name for f in fields(DEFAULT) if f.type in (float, "float")}
    settings: dict[str, Any] = {k: float(v) for k, v in tests.items() if k in known and _number(v)}
    profile = replace(DEFAULT, name=str(report.get("profile") or DEFAULT.name), **settings)
    run = Characterization(info, profile, str(report.get("date") or ""), parameters)
    run.loop = str(report.get("loop") or "position")
    tables = {name: _table(_csv_path(where, name)) for name in files}
    step_files = sorted(
        (name for name in files if "-step-" in Path(name).name), key=lambda n: _amplitude(n)
    )
    for name in step_files:
        t, columns = tables[name]
        # a process-loop step records the spool demand (position_setpoint) as well
        loop = "process" if "process_setpoint" in columns else "position"
        run.steps.append(StepResult(_amplitude(name), Record(t, columns), None, loop))
    bode_csv = _ending(files, "-bode.csv")
    sweep_csv = _ending(files, "-sweep.csv")
    if bode_csv is not None and sweep_csv is not None and settings:
        f, columns = tables[bode_csv]
        t, record = tables[sweep_csv]
        try:
            response = _response(f, columns)
        except KeyError as exc:
            raise Prm9Error(f"{bode_csv}: no column {exc} (not a -bode.csv)") from None
        limited = sweep.get("limited_to_hz")
        run.bode = BodeResult(
            profile.bode_amplitude_pct,
            0.0,
            Record(t, record),
            response,
            limited_to_hz=float(limited)
            if isinstance(limited, int | float) and _number(limited)
            else None,
            lost_samples=int(sweep.get("lost_samples") or 0),
            held_s=float(sweep.get("held_s") or 0.0),
        )
    flow_csv = _ending(files, "-flow.csv")
    if flow_csv is not None and run.loop == "process" and "PRCKP" in parameters:
        from prm9tool.characterize.flow import flow_result

        t, columns = tables[flow_csv]
        columns.pop("velocity [%/s]", None)  # derived: computed again from the record
        if {"process_actual", "position_actual"} <= columns.keys():
            run.flow = flow_result(Record(t, columns), rate, parameters["PRCKP"])
    static_csv = _ending(files, "-static.csv")
    if static_csv is not None:
        t, columns = tables[static_csv]
        demand = columns.pop(DEMAND, None)
        key = "process_actual" if "process_actual" in columns else "position_actual"
        if demand is not None and key in columns:
            characteristic = static_characteristic(demand, columns[key])
            run.static = StaticResult(Record(t, columns), characteristic, demand, key)
    run.figures = figures(run)
    return run


def _number(value: Any) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool) and math.isfinite(value)


def _amplitude(name: str) -> float:
    tail = Path(name).stem.rpartition("-step-")[2]
    try:
        return float(tail)
    except ValueError:
        raise Prm9Error(f"{name}: not a step's CSV file (-step-<amplitude>.csv)") from None


def _ending(files: list[str], ending: str) -> str | None:
    return next((name for name in files if Path(name).name.endswith(ending)), None)


def _csv_path(report: Path, name: str) -> Path:
    return Path(name) if Path(name).exists() else report.parent / Path(name).name


def _table(path: Path) -> tuple[np.ndarray, dict[str, np.ndarray]]:
    """A CSV file of the run: its first column and the others by their heads."""
    try:
        with path.open(encoding="utf-8", newline="") as stream:
            rows = list(csv.reader(stream))
        head, table = rows[0], np.array(rows[1:], dtype=float)
    except OSError as exc:
        raise Prm9Error(f"cannot read {path}: {exc.strerror or exc}") from None
    except (IndexError, ValueError) as exc:
        raise Prm9Error(f"{path}: not a table of numbers ({exc})") from None
    if table.ndim != 2 or table.shape[1] != len(head):
        raise Prm9Error(f"{path}: not a table of numbers (rows of unequal length)")
    return table[:, 0], {name: table[:, i] for i, name in enumerate(head) if i}


def _response(frequency: np.ndarray, columns: dict[str, np.ndarray]) -> Any:
    from prm9tool.analysis.frequency import FrequencyResponse

    magnitude = 10.0 ** (columns["magnitude_db"] / 20.0)
    return FrequencyResponse(frequency, magnitude, columns["phase_deg"], columns["coherence"])

"""End-of-line characterization: steps at three amplitudes, Bode, static characteristic.

:func:`characterize` runs the tests of an acceptance profile on a rig and checks every figure
against its limits; :func:`report_data` is the JSON report and :func:`write_csv_files` the raw
data. Who ran it records the result in the history (:mod:`prm9tool.service.history`).
"""

from __future__ import annotations

import csv
import math
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from datetime import UTC, datetime
from pathlib import Path
from typing import Any

from prm9tool._version import __version__
from prm9tool.analysis.profile import FIGURES, Limit, Profile
from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.catalogue.variant import Coils, Config
from prm9tool.characterize.flow import FlowResult, flow_objects_missing, flow_test
from prm9tool.characterize.frame import STEP_PRE_S
from prm9tool.characterize.procedures import (
    BodeResult,
    StaticResult,
    StepResult,
    bode_test,
    static_test,
    step_test,
)
from prm9tool.characterize.rig import LinkTooSlowError, Rig, RigInfo
from prm9tool.messages import QT_TRANSLATE_NOOP, Message

Progress = Callable[[str], None]


@dataclass(frozen=True)
class Figure:
    """One measured figure, its limit (if the profile sets one) and the verdict."""

    name: str
    label: str
    value: float
    unit: str
    limit: Limit | None
    note: Message | None = None  # what a figure that could not be measured saw instead
    above: bool = False  # the figure lies above ``value`` (not reached by the sweep's end)

    @property
    def passed(self) -> bool | None:
        """True/False against the limit; None when no limit is set. A figure known only to be
        above ``value`` passes a minimum at most ``value`` and fails any maximum (unverified)."""
        if self.limit is None:
            return None
        if self.above:
            low = self.limit.minimum is None or self.value >= self.limit.minimum
            return low and self.limit.maximum is None
        return self.limit.passed(self.value)

    @property
    def text(self) -> str:
        """The value as the command line prints it: ``29.3 Hz`` or ``above 100 Hz``."""
        shown = f"{self.value:.4g} {self.unit}".strip()
        return f"above {shown}" if self.above else shown


@dataclass
class Characterization:
    """Everything one run measured (the report's content)."""

    info: RigInfo
    profile: Profile
    date: str
    parameters: dict[str, int]
    steps: list[StepResult] = field(default_factory=list)
    bode: BodeResult | None = None
    static: StaticResult | None = None
    flow: FlowResult | None = None  # E04 in control mode 4
    figures: list[Figure] = field(default_factory=list)
    wall_s: float = 0.0
    skipped: list[Message | str] = field(default_factory=list)  # tests not run, and why
    loop: str = "position"  # the loop tested: "process" on an E04 in control mode 4

    @property
    def limits(self) -> dict[str, Limit]:
        """The limits of the tested loop's part of the profile."""
        return self.profile.for_loop(self.loop).limits

    @property
    def passed(self) -> bool:
        """True when no figure failed its limit."""
        return all(f.passed is not False for f in self.figures)

    @property
    def notes(self) -> list[Message | str]:
        """What the link limited (a sweep cut at what its sample rate allows, samples lost)
        and the tests skipped with their reason (``str()``: English, a view translates)."""
        notes: list[Message | str] = []
        bode = self.bode
        if bode is not None and bode.note:
            notes.append(bode.note)
        if bode is not None and bode.lost_samples:
            notes.append(SAMPLES_LOST(bode.lost_samples, len(bode.record.t)))
        return notes + list(self.skipped)


SAMPLES_LOST = QT_TRANSLATE_NOOP(
    "Characterize",
    "frequency response: {0} of {1} samples lost on the link, left out of the estimate",
)


def planned_s(profile: Profile, flow: bool = False) -> float:
    """Valve seconds the profile's tests play (what a progress bar counts towards): each
    step settles, records STEP_PRE_S and its window; the sweep settles 50 ms, the triangle
    0.2 s; the flow characteristic (E04 in control mode 4: the process loop's part of the
    profile) settles and steps twice."""
    profile = profile.for_loop("process" if flow else "position")
    d = profile.step_duration_s
    steps = len(profile.step_amplitudes_pct) * (max(0.1, d) + STEP_PRE_S + d)
    seconds = steps + 0.05 + profile.bode_duration_s + 0.2 + profile.static_period_s
    return seconds + (3.0 * profile.flow_duration_s if flow else 0.0)


def characterize(rig: Rig, profile: Profile, progress: Progress | None = None) -> Characterization:
    """Run the profile's tests on ``rig`` (the valve is left as it was after each test)."""
    say = progress or (lambda _text: None)
    started = time.perf_counter()
    variant = TypeKey.parse(rig.info.type_key).variant
    names = [p.mnemonic for p in CATALOGUE.file_parameters(variant)]
    result = Characterization(
        rig.info, profile, datetime.now(UTC).isoformat(timespec="seconds"), rig.read(names)
    )
    e04 = variant.config is Config.E04
    process = e04 and rig.read(["CTRLMODE"])["CTRLMODE"] == 4
    loop = "process" if process else "position"  # E04 in mode 4: the setpoint is the process's
    result.loop = loop
    profile = profile.for_loop(loop)  # the windows and limits of that loop
    for amplitude in profile.step_amplitudes_pct:
        say(f"step response {amplitude:g} %")
        result.steps.append(
            step_test(rig, amplitude, duration_s=profile.step_duration_s, loop=loop)
        )
    # a single-coil valve has one side only (manual §8.7.2: no negative signal range; its
    # spring returns the spool, or an E04's actuator): the sweep runs about twice its
    # amplitude, clear of the null, and the triangle from 0
    one_side = variant.coils is not Coils.AB
    centre = 2.0 * profile.bode_amplitude_pct if one_side else 0.0
    about = f"{centre:g} " if one_side else ""
    say(f"frequency response {about}±{profile.bode_amplitude_pct:g} %")
    result.bode = bode_test(
        rig,
        profile.bode_amplitude_pct,
        centre,
        profile.bode_f_min_hz,
        profile.bode_f_max_hz,
        profile.bode_duration_s,
        loop,
    )
    say("static characteristic")
    response = "process_actual" if process else "position_actual"
    low = 0.0 if one_side else -100.0
    result.static = static_test(rig, profile.static_period_s, low, response=response)
    if process:
        say("flow characteristic")
        why_not = flow_objects_missing(rig)
        if why_not:
            result.skipped.append(why_not)
        else:
            result.flow = flow_test(rig, profile.flow_amplitude_pct, 0.0, profile.flow_duration_s)
    result.figures = figures(result)
    refuse_undecided(result)
    result.wall_s = time.perf_counter() - started
    return result


def refuse_undecided(c: Characterization) -> None:
    """Raise LinkTooSlowError when a busy PC cut the sweep short (a setpoint held too long)
    below a minimum the profile asks: "above 3.43 Hz" against "≥ 15 Hz" says nothing about the
    valve, and failing it would be a wrong verdict on a healthy valve (issue 34 item 9)."""
    bode = c.bode
    if bode is None or bode.held_s <= 0.0:
        return
    for f in c.figures:
        low = f.limit.minimum if f.limit is not None else None
        if f.above and low is not None and f.value < low:
            raise LinkTooSlowError(
                f"this PC held the valve's setpoint {bode.held_s * 1000:.0f} ms during the "
                f"sweep, so it was used only up to {f.value:.3g} Hz: the {f.label} cannot be "
                f"judged against its minimum {low:g} {f.unit}; nothing was judged — run the "
                "test again when the PC is less busy"
            )


def figures(c: Characterization) -> list[Figure]:
    """Every figure of ``c`` with its limit from the profile (its part for ``c.loop``)."""
    limits = c.limits
    out: list[Figure] = []

    def add(
        name: str,
        label: str,
        value: float,
        base: str,
        note: Message | None = None,
        above: float = math.nan,
    ) -> None:
        """``above``: the figure was not reached up to this frequency (used when ``value`` is
        NaN: the figure is above the sweep's end)."""
        if math.isnan(value) and not math.isnan(above):
            out.append(
                Figure(name, label, above, FIGURES[base], limits.get(base), note, above=True)
            )
        else:
            out.append(Figure(name, label, value, FIGURES[base], limits.get(base), note))

    for step in c.steps:
        f = step.to_setpoint  # against the setpoint: a step that never came there fails
        a = f"{step.amplitude_pct:g}"
        nan = math.nan
        missed = f.not_reached("%") if f else None
        add(f"step_{a}_overshoot_pct", f"step {a} %: overshoot", f.overshoot if f else nan,
            "step_overshoot_pct", missed)  # fmt: skip
        add(f"step_{a}_rise_s", f"step {a} %: rise time", f.rise_time if f else nan,
            "step_rise_s", missed if f and math.isnan(f.rise_time) else None)  # fmt: skip
        add(f"step_{a}_settling_s", f"step {a} %: settling time", f.settling_time if f else nan,
            "step_settling_s", f.not_settled("%") if f else None)  # fmt: skip
    if c.bode is not None:
        r = c.bode.response
        why = c.bode.note if isinstance(c.bode.note, Message) else None  # a sweep cut short
        add("bode_bandwidth_hz", "−3 dB frequency", r.bandwidth_hz(), "bode_bandwidth_hz",
            why if math.isnan(r.bandwidth_hz()) else None, r.bandwidth_above_hz())  # fmt: skip
        add("bode_phase90_hz", "−90° frequency", r.phase_90_hz(), "bode_phase90_hz",
            why if math.isnan(r.phase_90_hz()) else None, r.phase_90_above_hz())  # fmt: skip
    if c.static is not None:
        s = c.static.characteristic
        add("static_gain", "gain", s.gain, "static_gain")
        add("static_hysteresis_pct", "hysteresis", s.hysteresis_pct, "static_hysteresis_pct")
        add("static_linearity_pct", "linearity error", s.linearity_pct, "static_linearity_pct")
        add("static_dead_band_pct", "dead band", s.dead_band_pct, "static_dead_band_pct")
    if c.flow is not None:
        flow = c.flow.characteristic
        add("flow_gain", "flow gain", flow.gain, "flow_gain")
        add("flow_dead_band_pct", "flow dead band", flow.dead_band_pct, "flow_dead_band_pct")
    return out


def _num(value: float) -> float | None:
    return None if math.isnan(value) else round(value, 6)


def report_data(c: Characterization, csv_files: list[Path] | None = None) -> dict[str, Any]:
    """The JSON report (schema: docs/tuning.md)."""
    return {
        "prm9tool": __version__,
        "date": c.date,
        "valve": {
            "type_key": c.info.type_key,
            "serial": c.info.serial,
            "firmware": c.info.firmware,
        },
        "link": c.info.link,
        "sample_rate_hz": c.info.sample_rate_hz,
        "profile": c.profile.name,
        "loop": c.loop,
        "passed": c.passed,
        "notes": [str(note) for note in c.notes],
        "figures": [
            {
                "name": f.name,
                "value": _num(f.value),
                "above": f.above,
                "unit": f.unit,
                "min": f.limit.minimum if f.limit else None,
                "max": f.limit.maximum if f.limit else None,
                "passed": f.passed,
                "note": str(f.note) if f.note is not None else None,
            }
            for f in c.figures
        ],
        "parameters": c.parameters,
        "tests": _tests(c),  # what the records were played with (``--fit-twin --from``)
        "sweep": _sweep(c.bode),
        "csv": [str(p) for p in csv_files or []],
        "wall_s": round(c.wall_s, 3),
    }


def _tests(c: Characterization) -> dict[str, float]:
    """The test settings of the run's loop: where the sweep's chirp was at which frequency,
    the triangle's period (a twin fitted from the report needs them: docs/twin.md)."""
    part = c.profile.for_loop(c.loop)
    return {
        "step_duration_s": part.step_duration_s,
        "bode_amplitude_pct": part.bode_amplitude_pct,
        "bode_f_min_hz": part.bode_f_min_hz,
        "bode_f_max_hz": part.bode_f_max_hz,
        "bode_duration_s": part.bode_duration_s,
        "static_period_s": part.static_period_s,
    }


def _sweep(bode: BodeResult | None) -> dict[str, Any] | None:
    """What limited the sweep (its record is ``-sweep.csv``); None without one."""
    if bode is None:
        return None
    return {
        "limited_to_hz": bode.limited_to_hz,
        "lost_samples": bode.lost_samples,
        "held_s": bode.held_s,
    }


def write_csv_files(c: Characterization, stem: Path) -> list[Path]:
    """Raw data: ``<stem>-step-<a>.csv``, ``<stem>-bode.csv`` (the frequency response),
    ``<stem>-sweep.csv`` (the sweep's time record), ``<stem>-static.csv``."""
    written = []
    for step in c.steps:
        path = stem.with_name(f"{stem.name}-step-{step.amplitude_pct:g}.csv")
        _table(path, step.record.t, step.record.channels)
        written.append(path)
    if c.bode is not None:
        path = stem.with_name(f"{stem.name}-bode.csv")
        r = c.bode.response
        columns = {
            "magnitude_db": r.magnitude_db,
            "phase_deg": r.phase_deg,
            "coherence": r.coherence,
        }
        _table(path, r.frequency, columns, "frequency [Hz]")
        written.append(path)
        path = stem.with_name(f"{stem.name}-sweep.csv")
        _table(path, c.bode.record.t, c.bode.record.channels)
        written.append(path)
    if c.flow is not None:
        path = stem.with_name(f"{stem.name}-flow.csv")
        channels = {**c.flow.record.channels, "velocity [%/s]": c.flow.velocity}
        _table(path, c.flow.record.t, channels)
        written.append(path)
    if c.static is not None:
        path = stem.with_name(f"{stem.name}-static.csv")
        channels = {"demand [%]": c.static.demand, **c.static.record.channels}
        _table(path, c.static.record.t, channels)
        written.append(path)
    return written


def _table(path: Path, first: Any, columns: dict[str, Any], head: str = "time [s]") -> None:
    with path.open("w", newline="", encoding="utf-8") as out:
        writer = csv.writer(out)
        writer.writerow([head, *columns])
        for i, x in enumerate(first):
            writer.writerow([f"{x:.6g}", *(f"{float(v[i]):.6g}" for v in columns.values())])

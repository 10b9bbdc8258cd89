"""The field signature (issue 31 item 5): a short run whose figures match the end-of-line test's.

A service engineer at a machine has a few seconds of motion, not the end-of-line test's
minute: the signature plays at most :data:`MOTION_LIMIT_S` of it (a small and a large step
each way, a short sweep around the bandwidth the valve had, a hysteresis loop) on any rig the
characterization runs on (USB, CANopen, emulated), through the same procedures, so its figures
carry the same names as the end-of-line test's and can be compared with them
(:mod:`prm9tool.characterize.drift`). No Qt.

How it follows the birth certificate (decisions, docs/twin.md "The birth certificate"):

- **Steps**: the reference's smallest and largest step amplitudes (the default profile's 5 %
  and 90 %), up and down, each with the reference's window. The end-of-line test steps up
  only: a step down has no birth-certificate figure and is reported, not judged.
- **Sweep**: ±the reference's amplitude, from a quarter of the reference's −3 dB frequency to
  three times it (within the reference's sweep and what the link samples), 3 s.
- **Hysteresis loop**: a triangle at the reference's rate (%/s; the hysteresis a moving spool
  shows grows with its speed) over ±R %, R chosen so the loop takes :data:`LOOP_S`; the gain,
  hysteresis, dead band and linearity come from it, with bins as wide as the end-of-line
  test's (2 % of demand) and in % of the whole range's span, as if the loop had spanned
  ±100 %: the hysteresis at a dead band's edge depends on the bin width, and a figure in % of
  a half span would be twice as large.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, replace
from datetime import UTC, datetime

from prm9tool.analysis.profile import Profile
from prm9tool.analysis.static import static_characteristic
from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.catalogue.variant import Config
from prm9tool.characterize.frame import STEP_PRE_S
from prm9tool.characterize.procedures import (
    SAMPLES_PER_PERIOD,
    StaticResult,
    bode_test,
    static_test,
    step_test,
)
from prm9tool.characterize.rig import Rig
from prm9tool.characterize.run import Characterization, Progress, figures, refuse_undecided

MOTION_LIMIT_S = 20.0  # the "≤ 20 s of motion"
SWEEP_S = 3.0  # the short sweep around the bandwidth
LOOP_S = 10.0  # the hysteresis loop at the reference's rate
SWEEP_SPAN = {"position": (4.0, 3.0), "process": (3.0, 5.0)}  # bandwidth / a … bandwidth × b
# (the E04 process loop's −90° lies at ~4.7 times its −3 dB frequency)
PROCESS_SWEEP_S = 5.0  # the E04 process loop: ~1 Hz, slower; with its 1.5 s step windows
PROCESS_LOOP_S = 4.0  # (three steps) 18.3 s in all
SWEEP_SAMPLES = 1250.0  # a slow link's sweep lasts this many samples: 1000 arrive (the fit's)


@dataclass(frozen=True)
class Plan:
    """What the signature plays (derived from the reference, see the module docstring)."""

    loop: str
    steps_pct: tuple[float, ...]  # each from 0 %
    step_duration_s: float
    sweep_amplitude_pct: float
    sweep_f_min_hz: float
    sweep_f_max_hz: float
    sweep_s: float
    loop_range_pct: float  # the triangle spans ± this
    loop_period_s: float

    @property
    def motion_s(self) -> float:
        """Valve seconds of motion it plays (settling holds included, as
        :func:`prm9tool.characterize.run.planned_s` counts them)."""
        d = self.step_duration_s
        steps = len(self.steps_pct) * (max(0.1, d) + STEP_PRE_S + d)
        return steps + 0.05 + self.sweep_s + 0.2 + self.loop_period_s


def plan(
    profile: Profile,
    loop: str = "position",
    steps_pct: tuple[float, ...] = (),
    bandwidth_hz: float | None = None,
    sample_rate_hz: float | None = None,
) -> Plan:
    """The signature of ``loop`` for a reference measured with ``profile`` (its tests part):
    its step amplitudes (``steps_pct``: the reference's own, else the profile's) and −3 dB
    frequency (None: the geometric middle of the profile's sweep); ``sample_rate_hz``: the
    link's, which may bound the sweep."""
    part = profile.for_loop(loop)
    ups = sorted({abs(a) for a in (steps_pct or part.step_amplitudes_pct) if a})
    small, large = (ups[0], ups[-1]) if ups else (5.0, 90.0)
    amplitudes: tuple[float, ...] = (
        (small, -small) if small == large else (small, -small, large, -large)
    )
    if loop == "process" and small != large:  # an actuator's 1.5 s windows: within 20 s
        amplitudes = (small, large, -large)
    f_lo, f_hi = part.bode_f_min_hz, part.bode_f_max_hz
    if bandwidth_hz is None or not math.isfinite(bandwidth_hz) or bandwidth_hz <= 0:
        bandwidth_hz = math.sqrt(f_lo * f_hi)
    below, above = SWEEP_SPAN[loop]
    f_max = min(f_hi, bandwidth_hz * above)
    if sample_rate_hz:
        f_max = min(f_max, sample_rate_hz / SAMPLES_PER_PERIOD)
    f_min = max(f_lo, min(bandwidth_hz / below, f_max / 2.5))
    process = loop == "process"
    period = PROCESS_LOOP_S if process else LOOP_S
    rate = 400.0 / part.static_period_s  # the reference triangle: −100 → 100 → −100 %
    span = min(100.0, rate * period / 4.0)
    return Plan(
        loop,
        amplitudes,
        part.step_duration_s,
        part.bode_amplitude_pct,
        f_min,
        f_max,
        max(PROCESS_SWEEP_S if process else SWEEP_S, SWEEP_SAMPLES / (sample_rate_hz or 1e9)),
        span,
        period,
    )


def full_range(static: StaticResult, range_pct: float) -> StaticResult:
    """The characteristic of a loop over ±``range_pct`` with the end-of-line test's bins (101
    over ±100 %) and its figures in % of the whole range (see the module docstring)."""
    if range_pct >= 100.0:
        return static
    bins = max(11, round(101 * range_pct / 100.0))
    s = static_characteristic(static.demand, static.record.channels[static.response_key], bins)
    k = range_pct / 100.0
    scaled = replace(
        s,
        hysteresis_pct=s.hysteresis_pct * k,
        linearity_pct=s.linearity_pct * k,
        dead_band_pct=s.dead_band_pct * k,
    )
    return replace(static, characteristic=scaled)


def run_signature(
    rig: Rig, profile: Profile, the_plan: Plan | None = None, progress: Progress | None = None
) -> Characterization:
    """Play the signature on ``rig`` (the valve left as it was after each test, as the
    end-of-line test leaves it) and return its measurement as a characterization: the same
    figures under the same names (steps down as ``step_-<a>_…``), judged against the
    profile's acceptance limits as well. ``the_plan``: from :func:`plan` (None: the profile's
    own, without a reference)."""
    say = progress or (lambda _text: None)
    started = time.perf_counter()
    variant = TypeKey.parse(rig.info.type_key).variant
    names = [p.mnemonic for p in CATALOGUE.file_parameters(variant)]
    result = Characterization(
        rig.info, profile, datetime.now(UTC).isoformat(timespec="seconds"), rig.read(names)
    )
    process = variant.config is Config.E04 and rig.read(["CTRLMODE"])["CTRLMODE"] == 4
    loop = "process" if process else "position"
    result.loop = loop
    p = the_plan if the_plan is not None and the_plan.loop == loop else None
    p = p or plan(profile, loop, sample_rate_hz=rig.info.sample_rate_hz)
    for amplitude in p.steps_pct:
        say(f"step response {amplitude:g} %")
        result.steps.append(step_test(rig, amplitude, duration_s=p.step_duration_s, loop=loop))
    say(f"frequency response ±{p.sweep_amplitude_pct:g} %, {p.sweep_f_min_hz:.3g} … "
        f"{p.sweep_f_max_hz:.3g} Hz")  # fmt: skip
    duration = max(p.sweep_s, SWEEP_SAMPLES / rig.info.sample_rate_hz)
    result.bode = bode_test(
        rig, p.sweep_amplitude_pct, 0.0, p.sweep_f_min_hz, p.sweep_f_max_hz, duration, loop
    )
    say(f"hysteresis loop ±{p.loop_range_pct:.3g} %")
    response = "process_actual" if process else "position_actual"
    period = max(p.loop_period_s, 640.0 / rig.info.sample_rate_hz)  # the static test's minimum
    result.static = full_range(
        static_test(rig, period, -p.loop_range_pct, p.loop_range_pct, response=response),
        p.loop_range_pct,
    )
    result.figures = figures(result)
    refuse_undecided(result)
    result.wall_s = time.perf_counter() - started
    return result

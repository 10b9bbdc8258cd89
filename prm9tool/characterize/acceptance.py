"""Gains checked against the acceptance profile before they are proposed (docs/tuning.md).

The autotune tunes on one step (0 → 50 % by default); the end-of-line test then checks small
and large steps and the static characteristic. :func:`check_gains` runs the profile's steps in
both directions (0 → a and 0 → −a for every amplitude on a two-coil valve and on the process
loop, 0 → a and a → 0 with one coil) and, if asked, its static triangle with
the given gains in the valve's working memory, and checks every figure against the profile's
limits; the valve's own gains are back afterwards in every case. :func:`propose` tunes with a
method, checks the proposal, and while it fails tries again with half the overshoot target,
so the gains proposed pass the profile where the method can find such gains — and say so where
it cannot. The frequency response is not part of the check (it takes the profile's sweep time
again and depends on the gains less than the steps do).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field, replace

from prm9tool.analysis.model import Targets
from prm9tool.analysis.pid import to_parameters
from prm9tool.analysis.profile import FIGURES, Profile
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.catalogue.variant import Coils
from prm9tool.characterize.autotune import AutotuneResult, model_tune, simulate_steps
from prm9tool.characterize.critical_gain import CriticalGainResult, critical_gain_tune
from prm9tool.characterize.frame import LOOPS, chain_changes, gain_names, preserved, step_window
from prm9tool.characterize.procedures import StaticResult, StepResult, _step, static_test
from prm9tool.characterize.rig import Rig
from prm9tool.characterize.run import Characterization, Figure, figures
from prm9tool.messages import QT_TRANSLATE_NOOP, Message

STRICTER = 0.5  # each new try of the model-based autotune halves the overshoot target
TRIES = 3  # proposals tried at most before the best one is shown with what it fails


@dataclass(frozen=True)
class ProfileCheck:
    """The profile's steps (rising and falling per amplitude), the static triangle (None if
    not run) and every figure with its limit, for one set of gains."""

    values: dict[str, int]
    steps: list[StepResult]
    static: StaticResult | None
    figures: list[Figure]

    @property
    def passed(self) -> bool:
        """True when no figure fails its limit."""
        return all(f.passed is not False for f in self.figures)

    @property
    def failed(self) -> list[Figure]:
        """The figures outside their limits."""
        return [f for f in self.figures if f.passed is False]


def check_gains(
    rig: Rig, loop: str, values: dict[str, int], profile: Profile, static: bool = True
) -> ProfileCheck:
    """Run the profile's steps both ways (and its static triangle) with ``values``; the
    windows and limits are those of ``loop``'s part of the profile."""
    profile = profile.for_loop(loop)
    lp = LOOPS[loop]
    steps: list[StepResult] = []
    coils = TypeKey.parse(rig.info.type_key).variant.coils
    both_ways = coils is Coils.AB or loop == "process"
    with preserved(rig, gain_names(lp), chain_changes(rig, loop)):
        rig.write(values)
        for a in profile.step_amplitudes_pct:
            steps.append(_step(rig, lp, a, 0.0, profile.step_duration_s, None, loop))
            if both_ways:  # the other coil, the other way
                steps.append(_step(rig, lp, -a, 0.0, profile.step_duration_s, None, loop))
            else:  # one coil: back to 0
                steps.append(_step(rig, lp, -a, a, profile.step_duration_s, None, loop))
    result = None
    if static:  # through the valve's own setpoint chain, as the end-of-line test runs it
        with preserved(rig, gain_names(lp), {}):
            rig.write(values)
            response = "process_actual" if loop == "process" else "position_actual"
            result = static_test(rig, profile.static_period_s, response=response)
    found = [_step_figure(s, key, profile) for s in steps for key in STEP_FIGURES]
    if result is not None:
        whole = Characterization(rig.info, profile, "", {}, static=result, loop=loop)
        found += figures(whole)
    return ProfileCheck(dict(values), steps, result, found)


STEP_FIGURES = {  # figure: (label, value of the step's figures)
    "step_overshoot_pct": ("overshoot", lambda f: f.overshoot),
    "step_rise_s": ("rise time", lambda f: f.rise_time),
    "step_settling_s": ("settling time", lambda f: f.settling_time),
}


def _step_figure(step: StepResult, key: str, profile: Profile) -> Figure:
    start = step_start(step)
    end = start + step.amplitude_pct
    label, value = STEP_FIGURES[key]
    f = step.to_setpoint  # against the setpoint: a step that never came there fails
    name = f"step_{start:g}_{end:g}_{key.removeprefix('step_')}"
    text = f"step {start:g} → {end:g} %: {label}".replace("-", "−")
    note = f.not_reached("%") if f is not None else None
    if f is not None and key == "step_settling_s":
        note = f.not_settled("%")
    found = value(f) if f else math.nan
    return Figure(name, text, found, FIGURES[key], profile.limits.get(key), note)


def step_start(step: StepResult) -> float:
    """The level a step started from (the setpoint's first sample, to 0.1 %)."""
    return round(float(step.record.channels[LOOPS[step.loop].setpoint][0]), 1) + 0.0


@dataclass(frozen=True)
class Proposal:
    """Proposed gains with everything that speaks for or against them."""

    method: AutotuneResult | CriticalGainResult
    present: dict[str, int]
    values: dict[str, int]
    before: StepResult  # the autotune's step with the present gains, measured
    after: StepResult  # ... with the proposed ones, measured
    simulated: StepResult  # ... with the proposed ones on the emulator's firmware (the dialog's)
    before_check: ProfileCheck
    after_check: ProfileCheck
    profile: Profile
    tried: list[ProfileCheck] = field(default_factory=list)  # earlier proposals that failed

    @property
    def passes(self) -> bool:
        """True when the proposal passes the acceptance profile."""
        return self.after_check.passed

    def verdict(
        self, label: Callable[[Figure], str] | None = None, name: str | None = None
    ) -> Message:
        """The profile check in one sentence (what failed, if anything); ``label`` gives a
        figure's name and value, ``name`` the profile's (a view passes its translated ones)."""
        label = label or (lambda f: f"{f.label} {_value(f)}")
        name = self.profile.name if name is None else name
        failed = self.after_check.failed
        if not failed:
            return PASSES(name)
        shown = "; ".join(label(f) for f in failed[:4])
        more = f" (+{len(failed) - 4})" if len(failed) > 4 else ""
        return FAILS(name, shown + more)


PASSES = QT_TRANSLATE_NOOP(
    "Autotune",
    "The proposal passes the acceptance profile “{0}” (its steps both ways and the static test).",
)
FAILS = QT_TRANSLATE_NOOP(
    "Autotune", "The proposal fails the acceptance profile “{0}”: {1}. Do not accept it unchecked."
)


def _value(f: Figure) -> str:
    if math.isnan(f.value):
        return "—"
    shown = f.value * 1000.0 if f.unit == "s" else f.value
    unit = "ms" if f.unit == "s" else f.unit
    return f"{shown:.3g} {unit}".rstrip()


def propose(
    rig: Rig,
    method: str,
    loop: str,
    targets: Targets,
    amplitude_pct: float,
    limit_pct: float,
    profile: Profile,
    say: Callable[[str], None] | None = None,
) -> Proposal:
    """Tune with ``method`` (``model`` or ``critical``), check the proposal against
    ``profile`` and, for the model-based method, retry with stricter targets while it fails
    (at most TRIES proposals; the first that passes, else the one failing fewest figures)."""
    note = say or (lambda _text: None)
    lp = LOOPS[loop]
    present = rig.read(gain_names(lp))
    duration = step_window(loop, targets.settling_s)
    tried: list[tuple[AutotuneResult | CriticalGainResult, ProfileCheck]] = []
    wanted, base = targets, present
    while len(tried) < TRIES:
        note(f"autotune {len(tried) + 1}")
        found: AutotuneResult | CriticalGainResult
        if method == "critical":
            found = critical_gain_tune(rig, loop, limit_pct=limit_pct)
            values = to_parameters(lp.prefix, found.gains)
        else:
            with preserved(rig, gain_names(lp), {}):  # a retry starts from the last proposal
                rig.write(base)
                found = model_tune(rig, wanted, loop, amplitude_pct, 3, limit_pct)
            values = found.proposed_values
        note("acceptance steps")
        tried.append((found, check_gains(rig, loop, values, profile, static=False)))
        if tried[-1][1].passed or method == "critical":
            break
        wanted = replace(wanted, overshoot_pct=wanted.overshoot_pct * STRICTER)
        base = values  # identified and checked: safer to step from than detuned gains
    best = next((t for t in tried if t[1].passed), min(tried, key=lambda t: len(t[1].failed)))
    found, steps_only = best
    values = steps_only.values
    note("acceptance: static test")
    after_check = check_gains(rig, loop, values, profile)
    before_check = check_gains(rig, loop, present, profile)
    if isinstance(found, AutotuneResult) and found.before_values == present:
        before, after = found.before, found.after
    else:
        from prm9tool.characterize.autotune import compare_steps

        before, after = compare_steps(rig, loop, values, amplitude_pct, duration)
    simulated = simulate_steps(rig, loop, values, amplitude_pct, duration)[1]
    earlier = [check for _, check in tried if check is not steps_only]
    return Proposal(
        found,
        present,
        values,
        before,
        after,
        simulated,
        before_check,
        after_check,
        profile,
        earlier,
    )

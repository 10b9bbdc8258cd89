"""The autotune once, for every front door: the Tuning window, ``--autotune`` and
``Valve.autotune()``.

One run (:func:`run`) tunes a loop's PIDT1 gains with the model-based method (no oscillation)
or the critical-gain method, checks the proposal against the acceptance profile's steps and
static test, and puts the valve's own gains back (``characterize/acceptance.py`` ``propose``).
The Tuning window runs it as its procedure on the connected valve's rig (``online/
tuning_runner.py``), the command line and the API through :meth:`ValveService.autotune
<prm9tool.service.valve.ValveService.autotune>`, which claims the valve's motion (a generator
running refuses it, in words) and records the run in the history — the one record
(:func:`details`) the window writes too. Applying the proposal is the caller's choice
(``--apply``, ``apply=True``, the window's Accept). No Qt.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from prm9tool.analysis.profile import Profile
    from prm9tool.characterize.acceptance import Proposal
    from prm9tool.characterize.rig import Rig
    from prm9tool.history.recorder import Details

__all__ = ["LOOP_DEFAULTS", "METHODS", "AutotuneOutcome", "AutotuneSettings", "details",
           "may_apply", "run"]  # fmt: skip

# per loop: the default step amplitude (%) and settling target (ms) of the autotune (the
# process loop's integrating actuator settles in about 0.5 s, not the spool's 40 ms)
LOOP_DEFAULTS: dict[str, tuple[float, float]] = {"position": (50.0, 40.0), "process": (20.0, 500.0)}
METHODS = ("model", "critical")


@dataclass(frozen=True)
class AutotuneSettings:
    """What to tune and towards what: the Tuning window's autotune fields.

    ``amplitude_pct``/``settling_ms`` None: the loop's defaults (:data:`LOOP_DEFAULTS`);
    ``limit_pct``: where the critical-gain method stops an oscillation (and the model-based
    one a step); ``profile``: the acceptance profile (None: the default one)."""

    loop: str = "position"
    method: str = "model"
    overshoot_pct: float = 10.0
    settling_ms: float | None = None
    amplitude_pct: float | None = None
    limit_pct: float = 60.0
    profile: Profile | None = field(default=None, compare=False)

    def checked(self) -> AutotuneSettings:
        """These settings with the loop's defaults filled in; ValueError says what is wrong."""
        if self.loop not in LOOP_DEFAULTS:
            raise ValueError(f"autotune: unknown loop {self.loop!r}: position or process")
        if self.method not in METHODS:
            raise ValueError(f"autotune: unknown method {self.method!r}: model or critical")
        amplitude, settling = LOOP_DEFAULTS[self.loop]
        done = replace(
            self,
            amplitude_pct=amplitude if self.amplitude_pct is None else self.amplitude_pct,
            settling_ms=settling if self.settling_ms is None else self.settling_ms,
        )
        for name, value, low, high in (
            ("amplitude", done.amplitude_pct, 1.0, 90.0),
            ("overshoot", done.overshoot_pct, 0.0, 50.0),
            ("settling", done.settling_ms, 2.0, 2000.0),
            ("limit", done.limit_pct, 5.0, 100.0),
        ):  # the window's fields' ranges
            if value is None or not low <= value <= high:
                raise ValueError(f"autotune: the {name} must be within {low:g} … {high:g}")
        return done


def run(rig: Rig, settings: AutotuneSettings, say: Callable[[str], None] | None = None) -> Proposal:
    """Tune ``settings.loop`` on ``rig`` and check the proposal against the profile; the
    valve's gains are back afterwards (the procedure the Tuning window runs)."""
    from prm9tool.analysis.model import Targets
    from prm9tool.analysis.profile import DEFAULT
    from prm9tool.characterize.acceptance import propose

    s = settings.checked()
    assert s.amplitude_pct is not None and s.settling_ms is not None  # checked() filled them
    targets = Targets(s.overshoot_pct, s.settling_ms / 1000.0)
    profile = s.profile if s.profile is not None else DEFAULT
    return propose(rig, s.method, s.loop, targets, s.amplitude_pct, s.limit_pct, profile, say)


def may_apply(proposal: Proposal) -> bool:
    """True when a proposal may be applied unchecked: it passes the acceptance profile and
    nothing speaks against the identification it rests on (the window then enables Accept
    without asking; otherwise it asks the user to override)."""
    from prm9tool.characterize.autotune import AutotuneResult

    found = proposal.method
    return proposal.passes and (not isinstance(found, AutotuneResult) or found.trustworthy)


def _number(value: object) -> float | None:
    """A finite figure as JSON takes it (None for NaN, missing or not a number)."""
    if isinstance(value, bool) or not isinstance(value, int | float) or not math.isfinite(value):
        return None
    return round(float(value), 6)


def step_details(step: Any) -> dict[str, Any]:
    """A step response's figures: amplitude (%), overshoot (%), rise and settling time (s)."""
    figures = getattr(step, "figures", None)
    shown: dict[str, Any] = {"amplitude_pct": _number(getattr(step, "amplitude_pct", None))}
    for key, name in (("overshoot_pct", "overshoot"), ("rise_time_s", "rise_time"),
                      ("settling_time_s", "settling_time")):  # fmt: skip
        shown[key] = _number(getattr(figures, name, None))
    return shown


def details(proposal: Proposal, applied: bool = False) -> tuple[str, Details]:
    """The history record of an autotune run, whichever door ran it: outcome ``proposed``
    (the proposal passes the acceptance profile) or ``targets-missed``; details: loop,
    method, rounds, whether the model's targets and the profile are met, the gains before →
    proposed, both measured steps, the profile and whether the proposal was applied."""
    from prm9tool.characterize.autotune import AutotuneResult

    found = proposal.method
    model = isinstance(found, AutotuneResult)
    record: Details = {
        "loop": proposal.before.loop,
        "method": "model" if model else "critical",
        "rounds": found.rounds if isinstance(found, AutotuneResult) else None,
        "meets_targets": found.meets_targets if isinstance(found, AutotuneResult) else None,
        "passes": proposal.passes,
        "profile": proposal.profile.name,
        "proposed": {mn: [proposal.present.get(mn), v] for mn, v in proposal.values.items()},
        "before": step_details(proposal.before),
        "after": step_details(proposal.after),
        "applied": applied,
    }
    return ("proposed" if proposal.passes else "targets-missed"), record


@dataclass(frozen=True)
class AutotuneOutcome:
    """An autotune run as the command line and the API return it: the proposal (its steps,
    model and checks in ``proposal``) and whether it was written to the valve."""

    proposal: Proposal = field(repr=False)
    applied: bool = False

    @property
    def loop(self) -> str:
        """``position`` or ``process``."""
        return self.proposal.before.loop

    @property
    def present(self) -> dict[str, int]:
        """The loop's gains before the run (raw, as the valve holds them)."""
        return dict(self.proposal.present)

    @property
    def proposed(self) -> dict[str, int]:
        """The proposed gains (raw)."""
        return dict(self.proposal.values)

    @property
    def passes(self) -> bool:
        """True when the proposal passes the acceptance profile."""
        return self.proposal.passes

    def verdict(self) -> str:
        """The profile check in one sentence (what failed, if anything)."""
        return str(self.proposal.verdict())

    def to_dict(self) -> dict[str, Any]:
        """What ``--autotune --json`` prints: the history record's details and the verdict."""
        outcome, record = details(self.proposal, self.applied)
        return {"outcome": outcome, "verdict": self.verdict(), **dict(record)}

    def __repr__(self) -> str:
        state = "applied" if self.applied else "not applied"
        return f"AutotuneOutcome({self.loop}, {self.proposed}, passes={self.passes}, {state})"

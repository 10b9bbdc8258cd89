"""The break-away (static) friction of a twin, in a stage of its own (issue 31 item 2).

Where the spool stands still it sticks until the net force passes ``static_friction_n``, and
then slides against ``coulomb_friction_n``: on a small step the position loop's integrator
winds up against it, the spool breaks away and overshoots, and where the break-away friction
is well above the sliding one the loop hunts in a stick-slip cycle. The least-squares fit of
the samples (:func:`~.identify.fit`) cannot follow it: where and when the spool sticks is a
chaotic function of the constants, so the residual is flat about 0.4 % rms except in a needle
narrower than 0.1 N at the true value (docs/twin.md, "Static friction").

What stick-slip leaves in a small step that does not depend on when each slip happens is the
*distribution* of the positions the spool passes: how far it overshoots, how wide it hunts.
:func:`fit_with_breakaway` therefore compares the sorted samples of the run's small steps
(:data:`SMALL_STEP_PCT`) — a loss with a basin some tenths of a newton wide about the break-away
friction — in a one-dimensional scan with the other constants fixed, refits those with the
friction found (from the previous plant and from the factory plant, the better one), and
repeats (:data:`ROUNDS`), keeping the round that explains the steps best; not where the
steps' fit explains them and the friction kept already gives the small steps' positions to
one LVDT count (:data:`AGREES`). It keeps the result only where it explains the
steps better than the default kept, and says whether the scan pins the friction
(:func:`_spread`). No Qt.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import replace
from typing import TYPE_CHECKING, Any

import numpy as np

from prm9tool.twin.identify import FITTED, Fit, FittedConstant, fit
from prm9tool.twin.replay import simulate_all

if TYPE_CHECKING:
    from prm9tool.device.emulator.constants import PlantConstants
    from prm9tool.twin.recording import Steps

STATIC = "static_friction_n"
SMALL_STEP_PCT = 20.0  # steps up to this amplitude: where the spool sticks at the start
COARSE_N = 0.05  # the scan's grid, then FINE_N about its best point
FINE_N = 0.005
SPAN = 10.0  # the scan runs from the sliding friction up to this many times the start value
ROUNDS = 3  # scan and refit; the round whose refit explains the steps best is kept
# the sorted small steps within one LVDT count (0.061 % of full scale) of the best: the range
# of break-away friction the run cannot tell apart
COUNT_PCT = 0.061
DETERMINED_SPREAD = 0.05  # half that range relative to the value: determined below it
AGREES = (
    "the steps are explained with it, and their small steps' positions agree with it to one "
    "LVDT count: the run cannot tell a better one: kept"
)


def small_steps(recordings: Sequence[Steps]) -> list[Steps]:
    """The recordings that are steps of at most :data:`SMALL_STEP_PCT` (the run's 5 % step)."""
    return [
        r
        for r in recordings
        if r.kind == "step" and abs(float(r.stimulus[-1] - r.stimulus[0])) <= SMALL_STEP_PCT
    ]


def sorted_loss(small: Sequence[Steps], plant: PlantConstants, static_n: float) -> float:
    """Rms difference (% of full scale) of the sorted samples of the small steps simulated
    with ``plant`` and a break-away friction ``static_n`` from the measured ones: their
    distributions, not when each slip happened."""
    changes: dict[str, Any] = {STATIC: max(static_n, plant.coulomb_friction_n)}
    p = replace(plant, **changes)
    total = 0.0
    for one, simulated in zip(small, simulate_all(small, p), strict=True):
        n = min(len(simulated), len(one.actual))
        total += float(np.mean((np.sort(simulated[:n]) - np.sort(one.actual[:n])) ** 2))
    return math.sqrt(total / len(small))


def scan(small: Sequence[Steps], plant: PlantConstants, top_n: float) -> dict[float, float]:
    """:func:`sorted_loss` on a grid of :data:`COARSE_N` from the sliding friction to
    ``top_n``, then of :data:`FINE_N` about its best point: {friction: loss}."""
    low = plant.coulomb_friction_n
    grid = np.arange(low, max(top_n, low + COARSE_N), COARSE_N)
    losses = {round(float(f), 4): sorted_loss(small, plant, float(f)) for f in grid}
    best = min(losses, key=losses.__getitem__)
    for f in np.arange(best - COARSE_N, best + COARSE_N + FINE_N / 2, FINE_N):
        key = round(float(f), 4)
        if key >= low and key not in losses:
            losses[key] = sorted_loss(small, plant, key)
    return losses


def _spread(losses: dict[float, float]) -> float:
    """Half the range of frictions within :data:`COUNT_PCT` of the best loss, relative to the
    best friction (inf where the range reaches the scan's ends: not pinned)."""
    best = min(losses, key=losses.__getitem__)
    near = sorted(f for f, v in losses.items() if v <= losses[best] + COUNT_PCT)
    ends = min(losses), max(losses)
    if near[0] <= ends[0] or near[-1] >= ends[1] or best <= 0.0:
        return math.inf
    return (near[-1] - near[0]) / 2.0 / best


def fit_with_breakaway(
    recordings: Sequence[Steps], stepped: Fit, start: PlantConstants, kept_reason: str
) -> tuple[PlantConstants, FittedConstant, int]:
    """The break-away friction of the valve the run's ``recordings`` are of, from the steps'
    fit ``stepped`` (its ``static_friction_n`` kept at ``start``'s): the plant to fit on from
    (the steps' constants refitted with the friction found), the friction as a fitted constant
    and the evaluations it took. Where the run has no small step, or the friction found does
    not explain the steps better than the one kept, ``stepped``'s plant and the friction kept
    with ``kept_reason``."""
    steps = [r for r in recordings if r.kind == "step"]
    small = small_steps(steps)
    initial = float(getattr(start, STATIC))
    kept = FittedConstant(STATIC, initial, initial, math.inf, False, None, kept_reason)
    if not small:
        return stepped.plant, kept, 0
    if stepped.explained and sorted_loss(small, stepped.plant, initial) <= COUNT_PCT:
        # the friction kept already gives the small steps' positions to one LVDT count: no
        # scan can tell a better one from the run (and it would cost minutes)
        return stepped.plant, replace(kept, reason=AGREES), 0
    free = [n for n in FITTED if any(c.name == n for c in stepped.constants)]
    best_plant, best_rms, best_losses = stepped.plant, stepped.rms_pct, None
    plant, evaluations = stepped.plant, 0
    for _round in range(ROUNDS):
        losses = scan(small, plant, SPAN * initial)
        found = min(losses, key=losses.__getitem__)
        # from the previous plant and from the start plant: the refit stops near where it
        # starts (the residual is rough), and either start may be the one near the valve
        changes: dict[str, Any] = {STATIC: found}
        tries = [fit(steps, replace(p, **changes), free) for p in (plant, start)]
        evaluations += sum(t.evaluations for t in tries)
        better = min(tries, key=lambda t: t.rms_pct)
        if better.rms_pct < best_rms:  # the round that explains the steps best is kept
            best_plant, best_rms, best_losses = better.plant, better.rms_pct, losses
        plant = better.plant  # the next scan with these constants (they move the basin)
    if best_losses is None:
        return stepped.plant, kept, evaluations
    value = float(getattr(best_plant, STATIC))
    spread = _spread(best_losses)
    determined = spread < DETERMINED_SPREAD
    reason = None if determined else (
        "the small steps' positions do not pin it: frictions within one LVDT count of the best"
        " reach the scan's ends or span more than ±5 %: kept"
    )  # fmt: skip
    if not determined:
        return stepped.plant, replace(kept, relative_se=spread, reason=reason), evaluations
    return best_plant, FittedConstant(STATIC, initial, value, spread, True), evaluations

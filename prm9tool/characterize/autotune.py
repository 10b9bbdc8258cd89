"""Model-based autotune: never raises the gains beyond what a model says is safe.

1. a step at the present gains (the user's safe ones) records demand, response and the
   controller's output; 2. a low-order plant is fitted from output to response
   (:func:`prm9tool.analysis.model.identify`); 3. gains are chosen on that model for the target
   overshoot and settling time, with margin (:func:`~prm9tool.analysis.model.design`); 4. the
   proposal is simulated and then measured with one step on the valve. If the measured step
   misses the targets, that step is added to the identification data and steps 2–4 repeat
   (at most ``rounds`` times). The valve's own gains are back afterwards in every case:
   accepting the proposal is the caller's decision (one undo step in the document).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from prm9tool.analysis.model import (
    MAX_FIT_ERROR_PCT,
    Design,
    PlantModel,
    Targets,
    design,
    identify,
    simulate_loop,
)
from prm9tool.analysis.pid import CYCLE_S, from_parameters, to_parameters
from prm9tool.catalogue.scale import FULL_SCALE, PERCENT, from_percent
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.catalogue.variant import Coils
from prm9tool.characterize.frame import LOOPS, chain_changes, gain_names, preserved, step_window
from prm9tool.characterize.procedures import StepResult, _step
from prm9tool.characterize.rig import Rig, write_values
from prm9tool.errors import Prm9Error
from prm9tool.messages import QT_TRANSLATE_NOOP, Message

if TYPE_CHECKING:
    from prm9tool.device.emulator import EmulatedValve


@dataclass(frozen=True)
class AutotuneResult:
    """The proposal, the model behind it and the steps before and after (measured)."""

    loop: str
    before_values: dict[str, int]
    proposed_values: dict[str, int]
    model: PlantModel
    design: Design
    before: StepResult
    after: StepResult
    simulated: np.ndarray  # the model's step response with the proposed gains, % (t from 0)
    meets_targets: bool
    rounds: int
    history: list[dict[str, int]] = field(default_factory=list)

    @property
    def doubts(self) -> list[Message]:
        """Why the proposal must not be trusted (empty: it may be accepted), see :func:`doubts`."""
        return doubts(self.model, self.before)

    @property
    def trustworthy(self) -> bool:
        """True when nothing speaks against the identification the proposal rests on."""
        return not self.doubts


def doubts(model: PlantModel, before: StepResult) -> list[Message]:
    """The reasons an identification is not trustworthy: no response to the first step, or a
    fit error above :data:`~prm9tool.analysis.model.MAX_FIT_ERROR_PCT` (docs/tuning.md)."""
    found = []
    if before.figures is None:
        found.append(
            QT_TRANSLATE_NOOP(
                "Autotune",
                "The valve did not respond to the step at the present gains: the model is fitted "
                "to no response.",
            )()
        )
    if not model.trustworthy:
        found.append(
            QT_TRANSLATE_NOOP(
                "Autotune", "The model fits the measurement badly (fit error {0} %, at most {1} %)."
            )(f"{model.fit_error:.0f}", f"{MAX_FIT_ERROR_PCT:.0f}")
        )
    return found


def meets(step: StepResult, targets: Targets) -> bool:
    """True when a measured step is within the overshoot and settling targets."""
    f = step.figures
    if f is None or not math.isfinite(f.settling_time):
        return False
    return f.overshoot <= targets.overshoot_pct and f.settling_time <= targets.settling_s


def model_tune(
    rig: Rig,
    targets: Targets,
    loop: str = "position",
    amplitude_pct: float = 50.0,
    rounds: int = 3,
    limit_pct: float | None = None,
) -> AutotuneResult:
    """Propose gains for ``loop`` (see the module docstring); the valve keeps its own gains.

    ``limit_pct``: a step whose response leaves 0 ± that band stops the procedure
    (LimitExceededError); default twice the amplitude plus 5 %.
    """
    lp = LOOPS[loop]
    names = gain_names(lp)
    duration = step_window(loop, targets.settling_s)
    two_coils = TypeKey.parse(rig.info.type_key).variant.coils is Coils.AB
    out_lo = -float(FULL_SCALE) if two_coils else 0.0
    with preserved(rig, names, chain_changes(rig, loop)) as saved:
        before = _step(rig, lp, amplitude_pct, 0.0, duration, limit_pct, loop)
        if not np.isfinite(before.record.channels[lp.output]).all():
            raise Prm9Error(
                QT_TRANSLATE_NOOP(
                    "Characterize",
                    "the model-based autotune needs the controller's output, which this link "
                    "does not sample (CANopen); use the critical-gain method",
                )()
            )
        data = [_io(before, lp.output, lp.actual)]
        t1 = from_parameters(lp.prefix, saved).t1
        step = from_percent(amplitude_pct)
        after, history = before, []
        round_no = 0
        while round_no < rounds:
            round_no += 1
            rig.check()
            model = identify(data, 1.0 / rig.info.sample_rate_hz, lp.integrating)
            try:
                chosen = design(model, targets, step, t1, out_lo=out_lo)
            except ValueError as exc:
                raise Prm9Error(
                    QT_TRANSLATE_NOOP("Characterize", "no gains found for the target: {0}")(
                        str(exc)
                    )
                ) from None
            values = to_parameters(lp.prefix, chosen.gains)
            history.append(values)
            rig.write(values)
            after = _step(rig, lp, amplitude_pct, 0.0, duration, limit_pct, loop)
            if meets(after, targets):
                break
            data.append(_io(after, lp.output, lp.actual))
    simulated = simulate_loop(model, chosen.gains, step, duration, out_lo) * PERCENT
    return AutotuneResult(
        loop,
        {k: saved[k] for k in names},
        values,
        model,
        chosen,
        before,
        after,
        simulated,
        meets(after, targets),
        round_no,
        history,
    )


def _io(step: StepResult, output: str, actual: str) -> tuple[np.ndarray, np.ndarray]:
    """Controller output and response in counts from the step onwards."""
    keep = step.record.t >= -CYCLE_S
    scale = FULL_SCALE / 100.0
    return step.record.channels[output][keep] * scale, step.record.channels[actual][keep] * scale


def compare_steps(
    rig: Rig, loop: str, proposed: dict[str, int], amplitude_pct: float, duration_s: float
) -> tuple[StepResult, StepResult]:
    """Measured steps with the present and with the ``proposed`` gains (then put back)."""
    lp = LOOPS[loop]
    with preserved(rig, gain_names(lp), chain_changes(rig, loop)):
        before = _step(rig, lp, amplitude_pct, 0.0, duration_s, None, loop)
        rig.write(proposed)
        after = _step(rig, lp, amplitude_pct, 0.0, duration_s, None, loop)
    return before, after


def simulate_steps(
    rig: Rig, loop: str, proposed: dict[str, int], amplitude_pct: float, duration_s: float
) -> tuple[StepResult, StepResult]:
    """The steps with the present and the ``proposed`` gains, simulated on the emulator's
    firmware: a fresh analog-only emulated valve of the rig's type with the rig's parameter
    set (read from it), stepped faster than real time. The valve under test is not moved."""
    from prm9tool.catalogue import CATALOGUE
    from prm9tool.device.emulator import EmulatedValve

    key = TypeKey.parse(rig.info.type_key)
    analog = TypeKey(key.size, key.spool, key.flow, key.supply, key.config, False)
    names = [p.mnemonic for p in CATALOGUE.file_parameters(analog.variant) if p.writable]
    # The control mode is no file parameter, but it says which loop the steps close (an E04
    # set to mode 2 to tune its position loop); a link without the object leaves the default.
    present = {**rig.read(["CTRLMODE"]), **rig.read(names)}
    steps = []
    for values in (present, {**present, **proposed}):
        valve = EmulatedValve(analog)
        write_values(valve, values)
        steps.append(emulated_step(valve, loop, amplitude_pct, duration_s))
    return steps[0], steps[1]


def emulated_step(
    valve: EmulatedValve, loop: str, amplitude_pct: float, duration_s: float
) -> StepResult:
    """The step the autotune measures (from 0 %, :data:`STEP_PRE_S` before it, ``duration_s``
    after it), on an emulated valve holding the values to simulate: the one measurement the
    controller dialogs show too."""
    from prm9tool.characterize.rig import EmulatorRig

    rig = EmulatorRig(valve)
    with preserved(rig, [], chain_changes(rig, loop)):
        return _step(rig, LOOPS[loop], amplitude_pct, 0.0, duration_s, None, loop)

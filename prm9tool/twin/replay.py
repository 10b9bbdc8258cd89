"""Replay recordings (:class:`~.recording.Steps`) on an emulated valve with given plant
constants (issue 31 item 2): what the least-squares fit (:mod:`.identify`) evaluates.

:func:`simulate_all` plays several recordings of one valve one after the other on one emulated
valve of its type and parameter set, each after the hold the characterization settled it
with (:func:`hold_cycles`); :func:`dither_offsets` puts the simulated dither in the phase the
measured spool showed and :func:`window_shifts` lines up a window of a long test with the
valve's latency on its link.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from prm9tool.catalogue.signals import BY_KEY
from prm9tool.characterize.frame import LOOPS, STEP_PRE_S
from prm9tool.characterize.transparent import TRANSPARENT
from prm9tool.errors import Prm9Error
from prm9tool.twin.recording import CYCLE_HZ, MAX_LAG, Steps

if TYPE_CHECKING:
    from prm9tool.device.emulator.constants import PlantConstants

BETWEEN_S = 0.1  # the hold between two recordings played on one valve
ALIGN_COARSE = 4  # cycles: the first search of a recording's dither offset
# the dither (80 Hz: 62.5 cycles) and the firmware's 1 ms task (5 cycles) repeat together
# every 125 cycles: a window's phase of both
PHASE_CYCLES = 125


def simulate(steps: Steps, plant: PlantConstants) -> np.ndarray:
    """The response of an emulated valve with ``plant`` and the recording's parameter set to
    the recording's stimulus, at the recording's sample rate."""
    return simulate_all([steps], plant)[0]


def simulate_all(
    recordings: Sequence[Steps], plant: PlantConstants, offsets: Sequence[int] | None = None
) -> list[np.ndarray]:
    """The responses to several recordings of one valve, played one after the other on one
    emulated valve (the first recording's type and parameter set), each after a hold at its
    start level (:func:`hold_cycles`: a characterization's step after its settle hold): as a characterization run moves from one test
    to the next, so the spool comes to rest where friction holds it, not at a fresh 0.
    ``offsets``: cycles added to each recording's hold (:func:`dither_offsets`), so that the
    simulated dither is in the phase the measured spool shows at the recording's start."""
    from prm9tool.catalogue.typekey import TypeKey
    from prm9tool.characterize.rig import EmulatorRig, write_values
    from prm9tool.device.emulator import EmulatedValve

    first = recordings[0]
    key = TypeKey.parse(first.type_key)
    analog = TypeKey(key.size, key.spool, key.flow, key.supply, key.config, False)
    valve = EmulatedValve(analog, plant=plant)
    write_values(valve, {**first.values, **TRANSPARENT})
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
            if steps.kind == "static":  # the triangle runs through the valve's own chain
                own = {k: first.values[k] for k in TRANSPARENT if k in first.values}
                write_values(valve, own)
            hold = hold_cycles(steps) + (offsets[i] if offsets else 0)
            samples = rig.play(
                np.concatenate([np.full(hold, played[0]), played]), [lp.setpoint, lp.actual]
            )[hold:]
            actual = measured_actual(samples, played, steps, lp)
            if steps.kind == "static":
                write_values(valve, TRANSPARENT)
            out.append(actual[per - 1 :: per])
    finally:
        rig.release()
    return out


def hold_cycles(steps: Steps) -> int:
    """The cycles :func:`simulate_all` holds a recording's start level before it: for a
    characterization's step (its measured demand, ``STEP_PRE_S`` of rest before the step) the
    hold the procedure settled it with, max(0.1 s, its window) (``frame.settle``, which
    returns after one hold when the spool is there); else :data:`BETWEEN_S`. With a
    break-away friction the spool's rest, and the integrator holding it, depend on that
    history: 0.1 s instead of the 0.15 s the default profile's steps settle with left 0.5 %
    rms on the true plant of a valve with 1.2 N of static friction, 0.000 % with it."""
    if steps.kind == "step" and steps.demand:
        return settled_cycles(steps)
    return round(BETWEEN_S * CYCLE_HZ)


def settled_cycles(steps: Steps) -> int:
    """The hold the procedure settled a measured step with (``frame.settle``, which returns
    after one hold when the loop is there): max(0.1 s, the step's window), in cycles."""
    window = len(steps.stimulus) / steps.rate_hz - STEP_PRE_S
    return round(max(0.1, window) * CYCLE_HZ)


def measured_actual(samples: np.ndarray, played: np.ndarray, steps: Steps, lp: Any) -> np.ndarray:
    """The actual value of a replayed recording in %; when the stimulus is a measured demand,
    shifted by the override's latency (the lag that best lines the demand up with it)."""
    actual = samples[:, 1] * BY_KEY[lp.actual].scale
    if steps.demand:
        demand = samples[:, 0] * BY_KEY[lp.setpoint].scale
        lag = min(
            range(MAX_LAG),
            key=lambda k: float(np.abs(demand[k:] - played[: len(played) - k]).sum()),
        )
        actual = np.concatenate([actual[lag:], np.full(lag, actual[-1])])
    return actual


def dither_frequency_hz(steps: Steps) -> float:
    """The dither frequency the recording's parameter set gives (DYNFREQ, else its default)."""
    from prm9tool.catalogue import CATALOGUE
    from prm9tool.catalogue.dither import frequency_hz

    return frequency_hz(float(steps.values.get("DYNFREQ", CATALOGUE["DYNFREQ"].default)))


def _rest(steps: Steps) -> int:
    """The samples before the recording's stimulus first moves (its rest), or 0 where they are
    shorter than one dither period or the rate too low to see the dither."""
    f = dither_frequency_hz(steps)
    moved = np.flatnonzero(np.abs(steps.stimulus - steps.stimulus[0]) > 1e-9)
    n = int(moved[0]) if len(moved) else 0
    if f <= 0.0 or steps.rate_hz < 4.0 * f or n < steps.rate_hz / f:
        return 0
    return n


def dither_offsets(recordings: Sequence[Steps], plant: PlantConstants) -> list[int]:
    """Cycles to add to each recording's hold in :func:`simulate_all` so that the simulated
    spool rests as the measured one did before each recording's stimulus moved.

    The dither runs on from the valve's power-up: a valve that ran in real time before its run
    (opened with ``prm9tool.connect``) starts each test in another phase of it than a fresh
    simulated valve, and a small step's first milliseconds depend on it (the spool at the null
    moves ±0.2 % with the dither). For each step in turn (the earlier ones played with their
    offsets), the offset within one dither period whose simulated step, with ``plant``, is
    nearest the measured one: first every :data:`ALIGN_COARSE` cycles, then each cycle around
    the best (the fit aligns on its start plant, then again on the fitted one). Zero for a
    window of the triangle and where the rest does not show the dither
    (:func:`_rest`)."""
    offsets: list[int] = []
    first_of: dict[str, tuple[int, int]] = {}  # a record's first window: (its start, cycles)
    for i, steps in enumerate(recordings):
        window = steps.kind != "step"
        per = round(CYCLE_HZ / steps.rate_hz)
        if window and steps.kind in first_of:
            # a later window of the same record: the dither and the 1 ms task are where they
            # were that many samples after the first window, as in the valve's record
            start, cycles = first_of[steps.kind]
            wanted = cycles + (steps.start - start) * per
            offsets.append((wanted - _cycles_before(recordings, offsets, i)) % PHASE_CYCLES)
            continue
        if not window and not _rest(steps):
            offsets.append(0)
            continue
        # the first window of a record: the phase of the dither and of the firmware's 1 ms task
        # it meets; a step: the dither's phase at its rest
        period = PHASE_CYCLES if window else round(CYCLE_HZ / dither_frequency_hz(steps))
        scores: dict[int, float] = {}

        def score(
            extra: int,
            i: int = i,
            steps: Steps = steps,
            period: int = period,
            scores: dict[int, float] = scores,
        ) -> float:
            extra %= period
            if extra not in scores:
                played = simulate_all(recordings[: i + 1], plant, [*offsets, extra])[-1]
                end = min(len(played), len(steps.actual) - steps.tail)
                error = played[steps.skip : end] - steps.actual[steps.skip : end]
                scores[extra] = float(np.mean(error**2))
            return scores[extra]

        best = min(range(0, period, ALIGN_COARSE), key=score)
        best = min(range(best - ALIGN_COARSE + 1, best + ALIGN_COARSE), key=score) % period
        offsets.append(best)
        if window:
            first_of[steps.kind] = (steps.start, _cycles_before(recordings, offsets, i))
    return offsets


def _cycles_before(recordings: Sequence[Steps], offsets: Sequence[int], i: int) -> int:
    """Cycles :func:`simulate_all` plays before recording ``i``'s own samples (the holds, with
    ``offsets[i]`` when it is given, and the recordings before it)."""
    cycles = 0
    for j in range(i + 1):
        cycles += hold_cycles(recordings[j]) + (offsets[j] if j < len(offsets) else 0)
        if j < i:
            cycles += len(recordings[j].stimulus) * round(CYCLE_HZ / recordings[j].rate_hz)
    return cycles


def window_shifts(
    recordings: Sequence[Steps], plant: PlantConstants, offsets: Sequence[int]
) -> list[int]:
    """Per recording, the samples by which the simulated window is moved against the measured
    one (0 for a step): the shift, up to the window's tail, that explains it best. A window
    starts in the middle of a test, and the valve's own latency from the override to the
    response on that link is not in its record; the simulated window from a hold is otherwise
    the same motion."""
    played = simulate_all(recordings, plant, offsets)
    out = []
    for steps, simulated in zip(recordings, played, strict=True):
        if steps.kind == "step" or not steps.tail:
            out.append(0)
            continue
        end = min(len(simulated), len(steps.actual)) - steps.tail
        measured = steps.actual[steps.skip : end]

        errors = {
            k: float(np.mean((simulated[steps.skip - k : end - k] - measured) ** 2))
            for k in range(-steps.tail + 1, steps.tail)
        }
        out.append(min(errors, key=errors.__getitem__))
    return out

"""Step-response figures on captured samples: a step of the reference (or of the response)
measured into rise, overshoot and settling figures, with a verdict when it cannot be; where
the reference steps is :mod:`prm9tool.scope.steps`, the cursors and CSV export
:mod:`prm9tool.scope.readout`."""

from __future__ import annotations

import math
from dataclasses import dataclass
from enum import StrEnum

import numpy as np

from prm9tool.messages import QT_TRANSLATE_NOOP, Message, Number
from prm9tool.scope.ripple import not_settled, ripple_at_end
from prm9tool.scope.steps import find_steps

NOISE_RATIO = 10.0  # a response smaller than 10 σ of its noise is no response
OVERSHOOT_NOISE = 3.0  # an overshoot within 3 σ of the noise reads as 0
SMOOTH_SAMPLES = 5  # median filter on a noisy response before peaks and crossings
SMOOTH_ABOVE = 1e-3  # noise σ (share of the step) from which the response is filtered
MIN_BEFORE = 3  # samples before a step needed to know where the response started
MIN_AFTER = 10  # samples after a step needed for any figure
TAIL_SHARE = 0.2  # the response must be at rest over the last 20 % of its segment ...
REST_SHARE = 0.5  # ... moving less than half the settling band between the tail's halves


class Verdict(StrEnum):
    """What a step-response measurement found."""

    MEASURED = "measured"  # figures of a complete step
    NO_STEP = "no step"  # nothing stepped in the window
    NO_RESPONSE = "no response"  # the reference stepped, the response stayed within its noise
    TOO_SHORT = "too short"  # the window cuts the response before it came to rest
    NO_DATA = "no data"  # the response has no sample in the window (all lost or not reported)
    NO_REFERENCE = "no reference data"  # the reference channel has no sample in the window


@dataclass(frozen=True)
class StepFigures:
    """Step-response figures; times in seconds from the step, values in the signal's units."""

    t_step: float
    initial: float
    final: float
    target: float  # level the reference stepped to (NaN without a reference)
    rise_time: float  # 10 % → 90 % of the step (NaN if not reached)
    overshoot: float  # % of the step beyond the final value
    settling_time: float  # until the response stays within ±band of the final value
    band: float = 0.02
    t_end: float = math.nan  # end of the measured segment: the next step or the window's end
    ripple: float = math.nan  # not settled: half the peak-to-peak left at the end (NaN: settled)
    ripple_hz: float = math.nan  # ... and its frequency (NaN: settled, or not periodic)
    reached: bool = True  # measured against the setpoint: False when it never came into the band
    last: float = math.nan  # the response's last sample (where a step not reached ended)

    @property
    def steady_state_error(self) -> float:
        """Target − final value (NaN without a reference)."""
        return self.target - self.final

    @property
    def settled(self) -> bool:
        """True when the response came into ±band of its final value for good."""
        return math.isfinite(self.settling_time)

    def not_settled(self, unit: str = "%") -> Message | None:
        """Why there is no settling time, with what the response did instead (None: settled),
        e.g. "did not settle within ±2 % of the step: oscillation of ±1.5 % at 24 Hz"."""
        if not self.reached:
            return self.not_reached(unit)
        if self.settled:
            return None
        return not_settled(self.band, self.ripple, self.ripple_hz, unit)

    def not_reached(self, unit: str = "%") -> Message | None:
        """For figures measured against the setpoint (:func:`step_figures_to_setpoint`): the
        sentence for a response that never came within ±band of it (None: it did), e.g.
        "not reached: the response ended at 56.5 % of the setpoint 90 %"."""
        if self.reached:
            return None
        return NOT_REACHED(
            Number(f"{self.last:.3g} {unit}".rstrip().replace("-", "−")),
            Number(f"{self.target:.3g} {unit}".rstrip().replace("-", "−")),
        )


NOT_REACHED = QT_TRANSLATE_NOOP(
    "StepFigures", "not reached: the response ended at {0} of the setpoint {1}"
)


@dataclass(frozen=True)
class StepMeasurement:
    """The outcome of :func:`measure_step`: a verdict, and figures when it is MEASURED.

    ``steps`` counts the reference's steps in the window (1 when the step was found on the
    response), ``measured`` is the index of the measured one (−1: none).
    """

    verdict: Verdict
    figures: StepFigures | None = None
    steps: int = 0
    measured: int = -1


def noise_level(y: np.ndarray) -> float:
    """Robust standard deviation of the sample noise of ``y``.

    From the median absolute deviation of the second differences: a step or a smooth curve
    moves only a few of them, white noise of σ gives them a spread of σ·√6.
    """
    if len(y) < 5:
        return 0.0
    d2 = np.diff(y, 2)
    return float(1.4826 * np.median(np.abs(d2 - np.median(d2))) / math.sqrt(6.0))


def measure_step(
    t: np.ndarray,
    y: np.ndarray,
    reference: np.ndarray | None = None,
    band: float = 0.02,
    comparable: bool = True,
) -> StepMeasurement:
    """Find the step(s) in the window and measure the first complete one.

    With a ``reference`` each of its steps owns the samples up to the next one; a step is
    complete when at least three samples show where the response started and the response is
    at rest by the end of its samples (over their last 20 % it moves less than half the
    settling band; an oscillation around its final value counts as at rest, and then has no
    settling time). Without a reference the step is found on the response itself (see
    :func:`step_figures`). The verdict is MEASURED for the first complete step that the
    response follows, otherwise TOO_SHORT when a step was cut by the window (or by the next
    step), NO_RESPONSE when the response did not follow, NO_STEP when nothing stepped.
    """
    return _measure(t, y, reference, band, comparable, strict=True)


def step_figures(
    t: np.ndarray,
    y: np.ndarray,
    reference: np.ndarray | None = None,
    band: float = 0.02,
    comparable: bool = True,
) -> StepFigures | None:
    """Figures of the first step response in the window, complete or not (None: no step, or
    the response does not follow it); :func:`measure_step` also says whether it is complete.

    Without a reference the step is taken where ``y`` leaves its initial level (the samples
    before that point) by more than ``band`` of the step, and it ends where ``y`` heads back
    across the middle of the step. The final value is the mean of the last 10 % of the step's
    samples. A noisy response is median-filtered before its peak, crossings and settling are
    taken. The response does not follow a change under 10 σ of its noise or, for a
    ``comparable`` reference (the same unit), under ``band`` of the reference's step.
    """
    return _measure(t, y, reference, band, comparable, strict=False).figures


def step_figures_to_setpoint(
    t: np.ndarray, y: np.ndarray, reference: np.ndarray, band: float = 0.02
) -> StepFigures | None:
    """Figures of the first step measured against the level the reference stepped to (the
    end-of-line test's definition), not against where the response ended: rise time from 10
    to 90 % of the way to the setpoint, overshoot beyond it, settling into ±``band`` of the
    step around it. A response that never came within that band of the setpoint (the window
    ended while it was still on its way, or it stopped short) has ``reached`` False, no
    overshoot and no settling time; its rise time only if it passed 90 %."""
    return _measure(t, y, reference, band, True, strict=False, to_target=True).figures


def _measure(
    t: np.ndarray,
    y: np.ndarray,
    reference: np.ndarray | None,
    band: float,
    comparable: bool,
    strict: bool,
    to_target: bool = False,
) -> StepMeasurement:
    if len(y) and not np.isfinite(y).any():
        return StepMeasurement(Verdict.NO_DATA)
    if reference is not None and len(reference) and not np.isfinite(reference).any():
        return StepMeasurement(Verdict.NO_REFERENCE)
    # lost samples (NaN, a link that places samples by time) are left out: the others keep
    # their times, so the figures are those of the samples that arrived
    keep = np.isfinite(y) if reference is None else np.isfinite(y) & np.isfinite(reference)
    if not keep.all():
        t, y = t[keep], y[keep]
        reference = reference[keep] if reference is not None else None
    if len(y) < MIN_AFTER:
        return StepMeasurement(Verdict.NO_STEP)
    if reference is None:
        return _measure_on_response(t, y, band, strict)
    steps = find_steps(t, reference)
    verdicts: list[Verdict] = []
    for n, step in enumerate(steps):
        begin = steps[n - 1].stop if n else 0
        end = steps[n + 1].start + 1 if n + 1 < len(steps) else len(y)
        min_size = band * abs(step.after - step.before) if comparable else 0.0
        seg = slice(begin, end)
        verdict, figures = _segment(
            t[seg], y[seg], step.time, step.after, min_size, band, strict, noise_level(y),
            to_target,
        )  # fmt: skip
        if figures is not None:
            return StepMeasurement(verdict, figures, len(steps), n)
        verdicts.append(verdict)
    if not steps:
        return StepMeasurement(Verdict.NO_STEP)
    worst = Verdict.TOO_SHORT if Verdict.TOO_SHORT in verdicts else Verdict.NO_RESPONSE
    return StepMeasurement(worst, None, len(steps))


def _measure_on_response(
    t: np.ndarray, y: np.ndarray, band: float, strict: bool
) -> StepMeasurement:
    """The step found on the response: where it leaves its initial level, up to where it
    heads back across the middle of the step (the next edge of a square wave)."""
    noise = noise_level(y)
    final = float(np.mean(y[-max(1, len(y) // 10) :]))
    t_step, initial = _detect_step(t, y, final, band, noise)
    if math.isnan(t_step):
        return StepMeasurement(Verdict.NO_STEP)
    smooth = np.abs(_smoothed(y, noise, final - initial) - initial)
    moved = smooth * (t >= t_step)
    half = 0.5 * float(np.max(moved))
    reach = int(np.argmax(moved >= half))
    back = np.flatnonzero(moved[reach:] < half)
    end = len(y)
    if len(back):
        level = float(np.median(smooth[reach : reach + back[0]]))
        near = np.flatnonzero(np.abs(smooth[reach : reach + back[0]] - level) <= band * level)
        end = reach + int(near[-1]) + 1 if len(near) else reach + int(back[0])
    verdict, figures = _segment(t[:end], y[:end], t_step, math.nan, 0.0, band, strict, noise)
    return StepMeasurement(verdict, figures, 1, 0 if figures is not None else -1)


def _segment(
    t: np.ndarray,
    y: np.ndarray,
    t_step: float,
    target: float,
    min_size: float,
    band: float,
    strict: bool,
    noise: float,
    to_target: bool = False,
) -> tuple[Verdict, StepFigures | None]:
    """Measure the step at ``t_step`` on the samples of its own segment (``to_target``:
    against ``target``, see :func:`step_figures_to_setpoint`)."""
    before, after = y[t < t_step], t >= t_step
    if (strict and len(before) < MIN_BEFORE) or np.count_nonzero(after) < MIN_AFTER:
        return Verdict.TOO_SHORT, None
    rest = before[len(before) // 2 :]  # the response's level just before the step
    initial = float(np.median(rest)) if len(rest) else float(y[0])
    ya_raw = y[after]
    final = float(np.mean(ya_raw[-max(1, len(ya_raw) // 10) :]))
    sample_noise = noise  # of the samples; a level's slow swing (hunting) does not enter it
    spread = _spread(rest)
    if spread <= 3.0 * noise_level(rest) or not len(rest) >= 5:  # a level swinging smoothly
        noise = max(noise, spread)  # (a hunting spool) is not noise: it would hide a small step
    size = final - initial
    if strict and not (_at_rest(ya_raw, size, band, noise) and _at_rest(before, size, band, noise)):
        return Verdict.TOO_SHORT, None
    if abs(size) <= max(NOISE_RATIO * noise, min_size):
        return Verdict.NO_RESPONSE, None
    ta, ya = t[after], _smoothed(y, noise, size)[after]
    goal = target if to_target and math.isfinite(target) and target != initial else final
    size = goal - initial
    t10 = _first_crossing(ta, ya, initial, goal, 0.1, t_step)
    t90 = _first_crossing(ta, ya, initial, goal, 0.9, t_step)
    excess = max(0.0, float(np.max((ya - goal) / size)))
    overshoot = excess * 100.0 if excess * abs(size) > OVERSHOOT_NOISE * sample_noise else 0.0
    settling = _settling_time(ta, ya, goal, band * abs(size), t_step)
    end = ripple_at_end(ta, ya)
    if end.amplitude > band * abs(size):  # it ends swinging beyond the band: never settled
        settling = math.nan  # (a last stretch inside it would give a time by chance)
    reached = bool(np.max((ya - initial) / size) >= 1.0 - band)
    if not reached:  # no overshoot of, no settling at a level it never came to
        overshoot, settling = math.nan, math.nan
    left = end if math.isnan(settling) and reached else None
    figures = StepFigures(
        t_step,
        initial,
        final,
        target,
        t90 - t10,
        overshoot,
        settling,
        band,
        float(t[-1]),
        left.amplitude if left else math.nan,
        left.frequency_hz if left else math.nan,
        reached,
        float(y[-1]),
    )
    return Verdict.MEASURED, figures


def _at_rest(y: np.ndarray, size: float, band: float, noise: float) -> bool:
    """True when ``y`` has stopped moving by its end: the medians of the two halves of its
    last 20 % differ by less than half the settling band (or than their noise), or it
    oscillates about a level that no longer moves (over its last half, the mean of the last
    whole period is that of the first within the same allowance: a hunting spool)."""
    tail = y[-max(2 * MIN_BEFORE, int(len(y) * TAIL_SHARE)) :]
    half = len(tail) // 2
    if half == 0:
        return True
    allowed = max(REST_SHARE * band * abs(size), 4.0 * noise / math.sqrt(half))
    if abs(float(np.median(tail[half:]) - np.median(tail[:half]))) <= allowed:
        return True
    left = ripple_at_end(np.arange(len(y), dtype=float), y)
    return left.periodic and abs(left.drift) <= allowed


def _settling_time(
    t: np.ndarray, y: np.ndarray, final: float, tolerance: float, t_step: float
) -> float:
    """Seconds from ``t_step`` until ``y`` stays within ``final ± tolerance`` (NaN: never)."""
    outside = np.flatnonzero(np.abs(y - final) > tolerance)
    if len(outside) == 0:
        return 0.0
    if outside[-1] == len(y) - 1:
        return math.nan
    return float(t[outside[-1] + 1]) - t_step


def _detect_step(
    t: np.ndarray, y: np.ndarray, final: float, band: float, noise: float
) -> tuple[float, float]:
    """Where ``y`` leaves its initial level, and that level (the samples before the step).

    The first guess of the level comes from the first 1 % of the window only, so a short
    pre-trigger does not mix samples after the step into it; the level is then taken again
    from every sample before the step found.
    """
    initial = float(np.median(y[: max(3, len(y) // 100)]))
    smooth = _smoothed(y, noise, final - initial)
    t_step = _first_crossing(t, smooth, initial, final, band, float(t[0]))
    before = y[t < t_step]
    if len(before) >= 3:
        initial = float(np.median(before))
        again = _first_crossing(t, smooth, initial, final, band, float(t[0]))
        t_step = t_step if math.isnan(again) else again
    return t_step, initial


def _spread(y: np.ndarray) -> float:
    """Robust standard deviation of a level (0 for fewer than 5 samples)."""
    if len(y) < 5:
        return 0.0
    return float(1.4826 * np.median(np.abs(y - np.median(y))))


def _smoothed(y: np.ndarray, noise: float, size: float) -> np.ndarray:
    """``y`` through a short running median when its noise is noticeable against ``size``.

    A running median leaves a monotonic response as it is, so clean responses keep their
    exact crossings; on a noisy one it removes the noise peaks without rounding the edges.
    """
    if noise <= SMOOTH_ABOVE * abs(size) or len(y) < SMOOTH_SAMPLES:
        return y
    half = SMOOTH_SAMPLES // 2
    padded = np.pad(y, half, mode="edge")
    return np.median(np.lib.stride_tricks.sliding_window_view(padded, SMOOTH_SAMPLES), axis=1)


def _first_crossing(
    t: np.ndarray, y: np.ndarray, initial: float, final: float, share: float, t_from: float
) -> float:
    """Interpolated time at which ``y`` first reaches ``initial + share·(final − initial)``."""
    size = final - initial
    progress = (y - initial) / size if size else np.zeros_like(y)
    hits = np.flatnonzero((progress >= share) & (t >= t_from))
    if len(hits) == 0:
        return math.nan
    k = int(hits[0])
    if k == 0 or progress[k - 1] >= share:
        return float(t[k])
    p0, p1 = progress[k - 1], progress[k]
    return float(t[k - 1] + (t[k] - t[k - 1]) * (share - p0) / (p1 - p0))

"""Step-response figures on windows with several steps, cut responses and no response
(issue 14 item 7): synthetic signals with known answers."""

from __future__ import annotations

import math

import numpy as np
import pytest

from prm9tool.scope import Verdict, find_steps, measure_step, step_figures

RATE = 5000.0
TAU = 0.01  # first-order response: rise τ·ln 9, settling (±2 %) τ·ln 50


def _square(period: float, duration: float, delay: float = 0.05, tau: float = TAU):
    """A 0/10 square wave starting low (first edge at ``delay``) and a first-order response."""
    n = np.arange(int(duration * RATE))
    t = n / RATE
    since = n - round(delay * RATE)
    ref = np.where(
        (since >= 0) & (np.mod(since, round(period * RATE)) < period * RATE / 2), 10.0, 0
    )
    y = np.zeros_like(t)
    a = math.exp(-1.0 / (RATE * tau))
    for k in range(1, len(t)):  # the exact discrete first-order lag of the reference
        y[k] = a * y[k - 1] + (1 - a) * ref[k - 1]
    return t, ref, y


def test_every_edge_of_a_square_wave_is_a_step_with_its_own_levels():
    t, ref, _ = _square(0.2, 1.0)
    steps = find_steps(t, ref)
    assert [round(s.time, 4) for s in steps] == [0.05, 0.15, 0.25, 0.35, 0.45, 0.55, 0.65,
                                                 0.75, 0.85, 0.95]  # fmt: skip
    assert [(s.before, s.after) for s in steps[:2]] == [(0.0, 10.0), (10.0, 0.0)]
    assert find_steps(t, np.sin(2 * np.pi * t)) == []  # a sine has no steps
    assert find_steps(t, np.ones_like(t)) == []


def test_a_square_wave_in_view_is_measured_on_its_first_complete_step():
    t, ref, y = _square(0.2, 1.0)
    result = measure_step(t, y, ref)
    assert result.verdict is Verdict.MEASURED
    assert (result.steps, result.measured) == (10, 0)
    fig = result.figures
    assert fig is not None
    assert fig.t_step == pytest.approx(0.05)
    assert fig.t_end == pytest.approx(0.15 - 1 / RATE)  # up to the next edge
    assert (fig.initial, fig.target) == (0.0, 10.0)
    assert fig.final == pytest.approx(10.0, abs=1e-3)
    assert fig.rise_time == pytest.approx(TAU * math.log(9), abs=2 / RATE)
    assert fig.settling_time == pytest.approx(TAU * math.log(50), abs=2 / RATE)
    assert fig.overshoot == pytest.approx(0.0, abs=0.05)
    assert step_figures(t, y, ref) == fig  # the lenient function agrees on a complete step


def test_a_window_starting_on_an_edge_measures_the_next_step():
    t, ref, y = _square(0.2, 1.0)
    inside = t >= 0.05  # the first edge is the window's first sample: no level before it
    result = measure_step(t[inside], y[inside], ref[inside])
    assert result.verdict is Verdict.MEASURED
    assert result.measured == 0 and result.figures is not None
    assert result.figures.t_step == pytest.approx(0.15)  # the falling edge, complete
    assert result.figures.initial == pytest.approx(10.0, abs=0.01)
    assert result.figures.rise_time == pytest.approx(TAU * math.log(9), abs=2 / RATE)


def test_a_window_cutting_the_response_is_too_short_not_nonsense():
    t, ref, y = _square(0.2, 1.0)
    for end in (0.05 + TAU, 0.05 + 2 * TAU):  # cursor B one or two τ after the step
        inside = (t >= 0.02) & (t <= end)
        result = measure_step(t[inside], y[inside], ref[inside])
        assert result.verdict is Verdict.TOO_SHORT and result.figures is None
    inside = (t >= 0.02) & (t <= 0.152)  # the whole first step and 2 ms of the second
    result = measure_step(t[inside], y[inside], ref[inside])
    assert result.verdict is Verdict.MEASURED and result.figures is not None
    assert result.figures.overshoot == pytest.approx(0.0, abs=0.05)
    assert result.figures.final == pytest.approx(10.0, abs=1e-3)


def test_a_square_wave_faster_than_the_response_is_too_short():
    t, ref, y = _square(0.02, 0.5)  # 10 ms half periods: the response never comes to rest
    assert measure_step(t, y, ref).verdict is Verdict.TOO_SHORT


def test_a_square_wave_the_valve_does_not_follow_is_no_response():
    t, ref, _ = _square(0.2, 1.0)
    flat = np.random.default_rng(2).normal(0.0, 0.02, len(t))
    result = measure_step(t, flat, ref)
    assert result.verdict is Verdict.NO_RESPONSE and result.steps == 10
    assert measure_step(t, flat, np.zeros_like(t)).verdict is Verdict.NO_STEP


def test_without_a_reference_a_square_wave_response_is_measured_on_its_first_step():
    t, _, y = _square(0.2, 1.0)
    result = measure_step(t, y)
    assert result.verdict is Verdict.MEASURED and result.figures is not None
    fig = result.figures
    assert fig.t_step == pytest.approx(0.05, abs=0.001)
    assert fig.final == pytest.approx(10.0, abs=0.01)
    assert fig.rise_time == pytest.approx(TAU * math.log(9), abs=2 / RATE)
    assert fig.overshoot == pytest.approx(0.0, abs=0.05)
    assert fig.t_end < 0.16  # it ends where the response heads back down


def _hunting_then_overshoot(rising: bool):
    """A 0 → 20 step (reference) from a level that hunts ±1.5 at 24 Hz to a quiet one, through
    a second-order response that overshoots by 1 (5 % of the step); mirrored: 20 → 0."""
    t = np.arange(int(1.0 * RATE)) / RATE
    ref = np.where(t >= 0.5, 20.0, 0.0)
    s = np.clip(t - 0.5, 0, None)
    zeta, wn = 0.69, 2 * np.pi * 40  # overshoot exp(−ζπ/√(1−ζ²)) = 5 %
    wd = wn * math.sqrt(1 - zeta**2)
    step = 1 - np.exp(-zeta * wn * s) * (
        np.cos(wd * s) + zeta / math.sqrt(1 - zeta**2) * np.sin(wd * s)
    )
    y = 20.0 * step + np.where(t < 0.5, 1.5 * np.sin(2 * np.pi * 24 * t), 0.0)
    return (t, ref, y) if rising else (t, 20.0 - ref, 20.0 - y)


@pytest.mark.parametrize("rising", [True, False])
def test_an_overshoot_after_a_hunting_level_is_measured_in_both_directions(rising):
    """Issue 25 item 2: the spool hunting at 0 % before a rising step was taken as noise of
    the response after it, so the 5 % overshoot of a 0 → 20 % step read 0.0 % while the
    falling step (from a quiet 20 %) was measured."""
    t, ref, y = _hunting_then_overshoot(rising)
    fig = measure_step(t, y, ref).figures
    assert fig is not None
    assert fig.overshoot == pytest.approx(5.0, abs=0.3)


def test_white_noise_alone_is_no_overshoot():
    rng = np.random.default_rng(7)
    t, ref, y = _square(0.2, 1.0)
    fig = measure_step(t, y + rng.normal(0, 0.05, len(y)), ref).figures
    assert fig is not None and fig.overshoot == 0.0

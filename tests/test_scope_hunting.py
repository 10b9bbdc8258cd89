"""A response that hunts instead of settling (issue 25 item 6), and the emulated null that no
longer hunts (issue 31 item 1). The emulated spool at 0 % oscillated by about ±1.5 % at
20–28 Hz (the dither clipped at 0 mA in the driven coil, and drivers that could not reverse the
coil voltage); now the dither rides on the signed current demand and the stages decay fast, so
the spool dithers at 0 % and ±5 % as it does at 20 %. The step figures must still measure a
step that never settles and say what they saw, not "window too short"."""

from __future__ import annotations

import math

import numpy as np
import pytest

from prm9tool.catalogue import CATALOGUE
from prm9tool.characterize.transparent import TRANSPARENT
from prm9tool.device.emulator import EmulatedValve
from prm9tool.scope import Verdict, measure_step
from prm9tool.scope.ripple import ripple

E02 = "PRM9-06.3Z11/30-24E02S02"
CYCLE = 200e-6
LVDT_STEP_PCT = 250.0 / 4096  # one bit of the 12-bit LVDT over ±125 %


def _square_on_the_valve(values: dict[str, int] | None = None, high: float = 20.0):
    """A 0 ↔ ``high`` % square wave of 1 s period (eight edges), as the scope captures it."""
    valve = EmulatedValve(E02)
    for mnemonic, raw in {**TRANSPARENT, **(values or {})}.items():
        param = CATALOGUE[mnemonic]
        valve.write(param.index, param.subindex, raw)
    while valve.status().booting:
        valve.advance(0.05)
    over, value = CATALOGUE["SETPOVRON"], CATALOGUE["SETPOVR"]
    valve.write(over.index, over.subindex, 1)
    valve.advance(0.3)
    valve.capture_start(["position_setpoint", "position_actual"], 1)
    for level in (0.0, high, 0.0, high, 0.0, high, 0.0, high, 0.0):
        valve.write(value.index, value.subindex, round(level * 163.84))
        for _ in range(2):  # the override's watchdog wants a USB report within 0.5 s
            valve.usb_activity()
            valve.advance(0.25)
    data = valve.capture_read() / 163.84
    return np.arange(len(data)) * CYCLE, data[:, 0], data[:, 1]


def _at_rest(t: np.ndarray, y: np.ndarray, edge_s: float):
    """The last 0.3 s of the half period that starts at ``edge_s``."""
    window = (t > edge_s + 0.2) & (t < edge_s + 0.5)
    return y[window]


@pytest.mark.parametrize("level", [0.0, 5.0, -5.0])
def test_the_emulated_spool_rests_at_the_null_and_near_it_with_the_factory_gains(level):
    """At 0 %, 5 % and −5 % (reached from 20 % and from the level's other side of the null)
    the spool settles within what the scope shows at 20 %: the dither at DYNFREQ, no slower
    oscillation, its mean on the setpoint. Before issue 31 it hunted by ±1.1 % at ~20 Hz."""
    t, _, y = _square_on_the_valve(high=20.0)
    at_20 = _at_rest(t, y, 1.5)  # at 20 %, from 0 %
    reference = ripple(np.arange(len(at_20)) * CYCLE, at_20)
    assert reference.frequency_hz == pytest.approx(80.0, rel=0.02)  # DYNFREQ
    if level:
        t, _, y = _square_on_the_valve({}, high=level)
        rest = _at_rest(t, y, 1.5)  # at the level, from 0 %
    else:
        rest = _at_rest(t, y, 1.0)  # at 0 %, from 20 %
    found = ripple(np.arange(len(rest)) * CYCLE, rest)
    assert found.frequency_hz == pytest.approx(80.0, rel=0.02)  # the dither, nothing slower
    assert found.amplitude <= reference.amplitude + LVDT_STEP_PCT
    assert abs(rest.mean() - level) < 2 * LVDT_STEP_PCT
    _, _, calm = _square_on_the_valve({"DTAMP": 0}, high=level or 20.0)
    assert np.ptp(_at_rest(t, calm, 1.0 if not level else 1.5)) < 0.5  # without dither: still


TUNED = {"POSKP": 64, "POSKI": 1512, "POSKD": 64}  # the autotune's proposal for Kp/10


def test_a_dithering_response_is_measured_and_the_verdict_says_what_it_saw():
    t, ref, y = _square_on_the_valve(TUNED)
    window = (t >= 1.2) & (t < 3.2)  # four steps in a 2 s window
    measured = measure_step(t[window], y[window], ref[window])
    assert measured.verdict is Verdict.MEASURED
    rising = measured.figures
    assert rising is not None and not rising.settled  # the dither fills the ±2 % band
    assert rising.ripple_hz == pytest.approx(80.0, rel=0.02)  # DYNFREQ
    assert str(rising.not_settled("%")).endswith("at 80 Hz")
    falling = measure_step(t[t >= 1.9], y[t >= 1.9], ref[t >= 1.9]).figures
    assert falling is not None and falling.target == 0.0
    assert falling.ripple_hz == pytest.approx(80.0, rel=0.02)  # at 0 % as at 20 %: no hunting


def test_a_hunting_response_is_measured_and_the_verdict_says_what_it_saw():
    """A valve that hunts after a falling step (what the emulator did before issue 31)."""
    t = np.arange(10000) * CYCLE
    ref = np.where(t < 1.0, 20.0, 0.0)
    fall = np.clip(t - 1.0, 0.0, None)
    y = np.where(t < 1.0, 20.0, 20.0 * np.exp(-fall / 0.004) + 1.2 * np.sin(2 * np.pi * 24 * fall))
    falling = measure_step(t, y, ref).figures
    assert falling is not None and falling.target == 0.0 and not falling.settled
    assert falling.ripple_hz == pytest.approx(24.0, rel=0.03)
    text = str(falling.not_settled("%"))
    assert text.startswith("did not settle within ±2 % of the step: oscillation of ±")
    assert text.endswith(f"at {falling.ripple_hz:.0f} Hz")


def test_a_settled_step_has_no_ripple_and_a_decaying_one_is_not_at_rest():
    t = np.arange(5000) / 5000.0
    ref = np.where(t >= 0.1, 10.0, 0.0)
    y = np.where(t >= 0.1, 10.0 * (1.0 - np.exp(-(t - 0.1) / 0.01)), 0.0)
    settled = measure_step(t, y, ref).figures
    assert settled is not None and settled.settled and settled.not_settled() is None
    assert math.isnan(settled.ripple)
    drifting = np.where(t >= 0.1, 10.0 * (1.0 - np.exp(-(t - 0.1) / 0.5)), 0.0)
    drifting += 0.5 * np.sin(2 * np.pi * 24.0 * t) * (t >= 0.1)
    assert measure_step(t, drifting, ref).verdict is Verdict.TOO_SHORT


@pytest.mark.parametrize("frequency", [24.0, 80.0])
def test_ripple_finds_amplitude_and_frequency_through_noise(frequency):
    rng = np.random.default_rng(1)
    t = np.arange(2000) / 5000.0
    y = 3.0 + 1.5 * np.sin(2 * np.pi * frequency * t) + rng.normal(0.0, 0.05, len(t))
    found = ripple(t, y)
    assert found.frequency_hz == pytest.approx(frequency, rel=0.03)
    assert found.amplitude == pytest.approx(1.5, abs=0.2)
    assert abs(found.drift) < 0.05


def test_the_end_of_line_report_says_what_a_step_that_never_settled_did():
    """The report's settling time read "not reached" (JSON: null) without a word of why."""
    from prm9tool.analysis.profile import parse_profile
    from prm9tool.characterize.rig import EmulatorRig
    from prm9tool.characterize.run import characterize, report_data

    valve = EmulatedValve(E02)
    profile = parse_profile(
        {
            "test": {
                "step_amplitudes_pct": [5, 90],
                "bode_duration_s": 1,
                "bode_f_min_hz": 5,
                "bode_f_max_hz": 50,
                "static_period_s": 1,
            }
        }
    )
    figures = {
        f["name"]: f for f in report_data(characterize(EmulatorRig(valve), profile))["figures"]
    }
    small = figures["step_5_settling_s"]
    assert small["value"] is None
    assert small["note"].startswith("did not settle within ±2 % of the step: oscillation of ±")
    assert small["note"].endswith("at 80 Hz")  # the dither (DYNFREQ) fills a 5 % step's band
    assert (
        figures["step_90_settling_s"]["value"] > 0 and figures["step_90_settling_s"]["note"] is None
    )

"""Analysis functions on synthetic signals with known answers (no valve, no Qt)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import signal

from prm9tool.analysis.frequency import frequency_response, log_chirp, sine_response
from prm9tool.analysis.model import (
    PlantModel,
    Targets,
    design,
    identify,
    loop_figures,
    simulate_loop,
)
from prm9tool.analysis.pid import (
    PidGains,
    critical_gain_rule,
    from_parameters,
    oscillation,
    to_parameters,
)
from prm9tool.analysis.static import propose_linearization, static_characteristic

FS = 5000.0


def test_first_order_lowpass_bandwidth_and_phase():
    fc = 40.0  # −3 dB and −45° at fc; a second identical lag puts −90° at fc too
    t = np.arange(int(4 * FS)) / FS
    u = log_chirp(4.0, FS, 1.0, 200.0)
    b, a = signal.butter(1, fc, fs=FS)
    y = signal.lfilter(b, a, u)
    response = frequency_response(u, y, FS, 1.0, 200.0)
    assert response.bandwidth_hz() == pytest.approx(fc, rel=0.03)
    y2 = signal.lfilter(b, a, y)
    assert frequency_response(u, y2, FS, 1.0, 200.0).phase_90_hz() == pytest.approx(fc, rel=0.05)
    assert np.all(response.coherence > 0.95)
    assert len(t) == len(u)


def test_sine_response_reads_gain_and_phase():
    t = np.arange(5000) / FS
    u = np.sin(2 * np.pi * 10 * t)
    y = 0.5 * np.sin(2 * np.pi * 10 * t - math.pi / 4) + 3.0
    h = sine_response(t, u, y, 10.0)
    assert abs(h) == pytest.approx(0.5, rel=1e-6)
    assert math.degrees(np.angle(h)) == pytest.approx(-45.0, abs=1e-4)


def test_static_characteristic_of_a_known_curve():
    x = np.concatenate([np.linspace(-100, 100, 4000), np.linspace(100, -100, 4000)])
    rising = np.gradient(x) >= 0
    bent = 0.8 * x + 10.0 * np.sin(np.pi * x / 100.0)
    y = np.where(np.abs(x) < 5.0, 0.0, bent) + np.where(rising, -1.0, 1.0)  # 2 % hysteresis
    figures = static_characteristic(x, y)
    span = np.ptp(figures.mean)
    assert figures.hysteresis_pct == pytest.approx(2.0 / span * 100.0, rel=0.05)
    assert figures.dead_band_pct == pytest.approx(5.0, abs=2.6)  # ±5 % of a 200 % span, one bin
    assert 0.8 < figures.gain < 1.0  # the sine adds a positive slope to 0.8
    assert figures.linearity_pct > 3.0


def bent(counts: np.ndarray) -> np.ndarray:
    x = counts / 163.84
    return x * (0.6 + 0.4 * np.abs(x) / 100.0)


def test_proposed_linearization_inverts_a_bend():
    lin_in = np.linspace(-16384, 16384, 20000)
    lin_out = lin_in  # no linearization yet
    response = bent(lin_out)  # progressive plant, %
    demand = lin_in / 163.84
    lin = propose_linearization(lin_in, lin_out, response, demand)
    corrected = np.interp(lin_in, lin.xs, lin.ys)
    after = bent(corrected)
    before_error = np.max(np.abs(response - demand))
    after_error = np.max(np.abs(after - demand))
    assert after_error < before_error / 5.0
    assert lin.xs[0] == -16384 and lin.xs[-1] == 16384


def test_critical_gain_rule_and_parameter_scaling():
    gains = critical_gain_rule(4.0, 0.02)
    assert gains.kp == pytest.approx(2.0)
    assert gains.kp / gains.ki == pytest.approx(0.016)  # Ti = 0.8·Tkr
    assert gains.kd / gains.kp == pytest.approx(0.0024)  # Td = 0.12·Tkr
    raw = to_parameters("POS", gains)
    assert raw == {"POSKP": 200, "POSKI": 1250, "POSKD": 480, "POST1": 24}
    back = from_parameters("POS", raw)
    assert back.kp == pytest.approx(2.0) and back.ki == pytest.approx(125.0)
    assert back.kd == pytest.approx(0.0048)


def test_parameters_are_clipped_to_the_catalogue():
    assert to_parameters("POS", PidGains(1e6, -5.0, 0.0, 0.0))["POSKP"] == 65535
    assert to_parameters("POS", PidGains(1e6, -5.0, 0.0, 0.0))["POSKI"] == 0


def test_oscillation_tells_sustained_from_decaying():
    t = np.arange(2000) / FS
    steady = np.sin(2 * np.pi * 50 * t)
    osc = oscillation(t, steady)
    assert osc.period_s == pytest.approx(0.02, rel=1e-3)
    assert osc.sustained(0.5)
    assert not oscillation(t, steady * np.exp(-t / 0.05)).sustained(0.5)


def test_identify_recovers_a_known_plant():
    true = PlantModel(1.5, 3e-3, 1e-3, 4e-4, 3, False, 0.0)
    u = np.concatenate([np.zeros(50), np.full(600, 1000.0), np.full(400, 300.0)])
    y = true.simulate(u)
    model = identify([(u, y)], 1.0 / FS)
    assert model.gain == pytest.approx(1.5, rel=0.02)
    assert model.fit_error < 0.5
    assert np.max(np.abs(model.simulate(u) - y)) < 0.01 * np.ptp(y)


def test_design_meets_the_targets_in_simulation():
    plant = PlantModel(1.45, 3e-3, 1.2e-3, 1.2e-3, 3, False, 0.0)
    chosen = design(plant, Targets(10.0, 0.04), 8192.0, 2e-4)
    over, settle = loop_figures(simulate_loop(plant, chosen.gains, 8192.0, 0.12), 8192.0)
    assert over <= 10.0 and settle <= 0.04
    assert chosen.meets_targets


def test_static_characteristic_with_bins_no_sample_fell_in():
    """Issue 25 item 17: a sweep with samples lost (a busy PC) left bins empty on both
    branches; the analysis warned "Mean of empty slice" (an error in the tests) and a gap
    inside the dead band could cut it short. Empty bins are left out of every figure."""
    x = np.concatenate([np.linspace(-100, 100, 4000), np.linspace(100, -100, 4000)])
    rising = np.gradient(x) >= 0
    y = np.where(np.abs(x) < 5.0, 0.0, 0.8 * x) + np.where(rising, -1.0, 1.0)
    full = static_characteristic(x, y)
    edges = np.linspace(-100, 100, 102)  # static_characteristic's 101 bins
    lost = ((x >= edges[70]) & (x < edges[76])) | ((x >= edges[49]) & (x < edges[51]))
    kept = ~lost  # no sample in six bins at +40 %, nor in the two bins next to 0
    gappy = static_characteristic(x[kept], y[kept])
    assert np.isnan(gappy.up).sum() == np.isnan(gappy.mean).sum() == 8
    figures = ("gain", "intercept", "hysteresis_pct", "linearity_pct", "dead_band_pct")
    for name in figures:
        assert getattr(gappy, name) == pytest.approx(getattr(full, name), abs=0.05), name


def test_the_dead_band_of_a_linear_valve_does_not_depend_on_the_sample_rate():
    """Issue 34 item 7: ``static_dead_band_pct`` of one emulated valve was 3.96 % over
    CANopen (1 kHz) and 0.99 % in-process (5 kHz): a linear response leaves the ±1 % band
    after 2 % of demand on each side, which the bins counted as one to three bins of dead band
    depending on where the hunting at 0 and the samples per bin fell. It is now the band less
    what the straight line itself needs: about 0 for a linear valve at either rate, and a real
    flat part keeps its width."""
    found = []
    for fs in (1000, 5000):
        x = np.concatenate([np.linspace(-100, 100, 2 * fs), np.linspace(100, -100, 2 * fs)])
        hunting = 1.2 * np.sin(2 * np.pi * 23.0 * np.arange(len(x)) / fs)
        found.append(static_characteristic(x, x + hunting).dead_band_pct)
    assert found[0] == pytest.approx(found[1], abs=0.5)
    assert max(found) < 0.6  # was a bin (0.99 %) of the threshold's own width
    x = np.concatenate([np.linspace(-100, 100, 4000), np.linspace(100, -100, 4000)])
    flat = np.sign(x) * np.maximum(np.abs(x) - 10.0, 0.0)  # flat within ±10 %
    assert static_characteristic(x, flat).dead_band_pct == pytest.approx(10.0, abs=0.6)

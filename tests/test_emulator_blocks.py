"""Emulator signal-chain blocks, each tested through the running firmware's measuring points."""

from __future__ import annotations

import numpy as np
import pytest

from prm9tool.device.emulator import EmulatedValve

E02 = "PRM9-06.3Z11/30-24E02S02"
E02_A = "PRM9-06.2Z51/30-24E02S02"
CYCLE = EmulatedValve.CYCLE_S
FULL = 16384


def booted(type_key: str = E02, **writes: tuple[int, int, int]) -> EmulatedValve:
    valve = EmulatedValve(type_key)
    for index, sub, value in writes.values():
        valve.write(index, sub, value)
    valve.advance(2.0)
    return valve


def chain(valve: EmulatedValve, volts: float) -> dict[str, float]:
    valve.set_input("setpoint", volts)
    valve.advance(0.002)
    keys = ("setpoint_raw", "setpoint_threshold", "setpoint_gain", "setpoint_linearized")
    return {k: valve.signal(k) for k in keys}


def test_input_type_and_polarity():
    valve = booted()
    assert chain(valve, 5.0)["setpoint_raw"] == pytest.approx(FULL / 2, abs=2)
    assert chain(valve, -10.0)["setpoint_raw"] == pytest.approx(-FULL, abs=2)
    valve.write(0x2010, 2, 1)  # inverted
    assert chain(valve, 5.0)["setpoint_threshold"] == pytest.approx(-FULL / 2, abs=2)
    valve.write(0x2010, 1, 2)  # 4…20 mA unipolar
    assert chain(valve, 12.0)["setpoint_raw"] == pytest.approx(FULL / 2, abs=8)
    valve.write(0x2010, 1, 7)  # 0…10 V bipolar: 5 V is 0 %
    valve.write(0x2010, 2, 0)
    step = 22.0 / 4096 * 2 * FULL / 10  # one A/D step (±11 V over 12 bit) on a 10 V span
    assert chain(valve, 7.5)["setpoint_raw"] == pytest.approx(FULL / 2, abs=step)


def test_threshold_suppresses_small_signals_and_passes_larger_ones_1_to_1():
    valve = booted()  # factory threshold 5 %
    below = chain(valve, 0.45)
    assert below["setpoint_raw"] > 0
    assert below["setpoint_threshold"] == 0
    above = chain(valve, -0.55)
    assert above["setpoint_threshold"] == above["setpoint_raw"] < 0


def test_gain_and_offset_per_sign():
    valve = booted(
        g=(0x6341, 0, 2 * FULL), o=(0x6343, 1, 1638), gn=(0x2011, 0, FULL // 2), on=(0x6344, 1, 819)
    )
    pos = chain(valve, 2.0)
    x = pos["setpoint_threshold"]
    assert pos["setpoint_gain"] == pytest.approx(1638 + x * 2 * (FULL - 1638) / FULL)
    neg = chain(valve, -4.0)
    x = neg["setpoint_threshold"]
    assert neg["setpoint_gain"] == pytest.approx(-819 + x * 0.5 * (FULL - 819) / FULL)
    assert chain(valve, 9.0)["setpoint_gain"] == FULL  # clamped at 100 %
    assert chain(valve, 0.0)["setpoint_gain"] == 0  # no jump at zero


def test_linearization_interpolates_the_nine_points():
    valve = booted()
    xs = [-FULL, -12288, -8192, -4096, 0, 4096, 8192, 12288, FULL]
    ys = [-FULL, -14000, -10000, -5000, 0, 2000, 4096, 10000, FULL]
    for n, y in enumerate(ys, start=1):
        valve.write(0x2001, n, y)
    off = chain(valve, 5.0)
    assert off["setpoint_linearized"] == off["setpoint_gain"]
    valve.write(0x6346, 0, -1)
    on = chain(valve, 5.0)
    assert on["setpoint_linearized"] == pytest.approx(np.interp(on["setpoint_gain"], xs, ys))
    low = chain(valve, 1.0)
    assert low["setpoint_linearized"] == pytest.approx(np.interp(low["setpoint_gain"], xs, ys))


def ramp_time(valve: EmulatedValve, volts: float) -> tuple[float, float]:
    """(seconds until the demand value reaches its new target, size of the step in %)."""
    before = valve.signal("demand")
    valve.capture_start(["demand", "setpoint_linearized"])
    valve.set_input("setpoint", volts)
    valve.advance(2.5)
    data = valve.capture_read()
    demand, target = data[:, 0], data[-1, 1]
    reached = int(np.argmax(demand == target))
    return (reached + 1) * CYCLE, abs(target - before) / FULL


@pytest.mark.parametrize("ms", [1000, 300])
def test_ramp_time_for_100_and_50_percent_steps(ms):
    # the four ramps with four different times: positive up / down, negative up / down
    pu, pd, nu, nd = ms, ms // 2, 2 * ms, 3 * ms // 2
    valve = booted(pu=(0x6332, 1, pu), pd=(0x6335, 1, pd), nu=(0x6333, 1, nu), nd=(0x6336, 1, nd))
    steps = (  # (setpoint V, step in % of 100 %, expected seconds)
        (10.0, 1.0, pu / 1000),  # 0 → +100 %: positive up
        (5.0, 0.5, pd / 1000 / 2),  # +100 → +50 %: positive down
        (0.0, 0.5, pd / 1000 / 2),  # +50 → 0 %: positive down
        (-5.0, 0.5, nu / 1000 / 2),  # 0 → −50 %: negative up
        (0.0, 0.5, nd / 1000 / 2),  # −50 → 0 %: negative down
        (-5.0, 0.5, nu / 1000 / 2),
        (5.0, 1.0, nd / 1000 / 2 + pu / 1000 / 2),  # −50 → +50 %: negative down, positive up
        (-5.0, 1.0, pd / 1000 / 2 + nu / 1000 / 2),  # +50 → −50 %: positive down, negative up
    )
    for volts, fraction, expected in steps:
        seconds, step = ramp_time(valve, volts)
        assert step == pytest.approx(fraction, abs=0.001)
        # each ramp ends with a partial step; crossing 0 costs the cycle that stops there
        assert seconds == pytest.approx(expected, abs=3 * CYCLE)


def test_zero_negative_down_ramp_means_no_ramp_on_that_side_only():
    valve = booted(nu=(0x6333, 1, 400))  # negative up 400 ms, negative down 0 = no ramp
    assert ramp_time(valve, -5.0)[0] == pytest.approx(0.2, abs=2 * CYCLE)
    assert ramp_time(valve, 0.0)[0] == pytest.approx(CYCLE, abs=CYCLE)


def test_zero_ramp_time_means_no_ramp():
    valve = booted()
    valve.set_input("setpoint", 10.0)
    valve.advance(CYCLE)
    assert valve.signal("demand") == FULL


def captured_controller(kp: int, ki: int, kd: int, t1: int) -> np.ndarray:
    """Without dither: it moves a two-coil spool at the null, and the step must find e = 0."""
    valve = booted(
        kp=(0x2020, 1, kp),
        ki=(0x2020, 2, ki),
        kd=(0x2020, 3, kd),
        t1=(0x2020, 4, t1),
        dt=(0x6361, 1, 0),
    )
    valve.capture_start(["position_deviation", "controller_output", "position_setpoint"])
    valve.set_input("setpoint", 1.0)
    valve.advance(0.02)
    return valve.capture_read()


def test_pidt1_proportional_part():
    data = captured_controller(250, 0, 0, 0)
    e, u = data[:, 0], data[:, 1]
    assert np.abs(e).max() > 100
    assert u == pytest.approx(2.5 * e)


def test_pidt1_integral_part():
    data = captured_controller(0, 500, 0, 0)
    e, u = data[:, 0], data[:, 1]
    assert np.diff(u) == pytest.approx(50.0 * CYCLE * e[1:])


def test_pidt1_derivative_part_with_lag():
    data = captured_controller(0, 0, 30, 50)  # Kd 30 × 0.01 ms = 0.3 ms, T1 50 × 0.01 ms = 0.5 ms
    e, u = data[:, 0], data[:, 1]
    # Backward Euler of Kd·s / (1 + T1·s) at dt = 200 µs:
    #   D[k] = T1/(T1+dt) · D[k−1] + Kd/(T1+dt) · (e[k] − e[k−1])
    kd, t1, dt = 0.3e-3, 0.5e-3, 200e-6
    lag, gain = t1 / (t1 + dt), kd / (t1 + dt)  # 5/7 and 3/7
    assert e[0] > 1000  # the setpoint step, from e = 0 at rest, falls on the first sample
    assert u[0] == pytest.approx(gain * e[0])
    assert u[1:] == pytest.approx(lag * u[:-1] + gain * np.diff(e))


def test_current_limit_per_coil():
    valve = booted(lim=(0x2004, 2, 600), dt=(0x6361, 1, 0))
    valve.set_input("setpoint", 10.0)
    valve.advance(0.3)
    assert valve.signal("current_setpoint_a") == 600
    assert valve.signal("current_a") == pytest.approx(600, abs=5)
    valve.write(0x2004, 3, 300)
    valve.set_input("setpoint", -10.0)
    valve.advance(0.3)
    assert valve.signal("current_setpoint_b") == 300
    assert valve.signal("current_setpoint_a") == 0


@pytest.mark.parametrize(("amp", "hz"), [(2458, 80), (8192, 200)])
def test_dither_amplitude_and_frequency_at_the_coil(amp, hz):
    valve = booted(dt=(0x6361, 1, amp), f=(0x6362, 1, hz))
    valve.set_input("setpoint", 5.0)
    valve.advance(0.3)
    valve.capture_start(["current_a", "current_setpoint_a"])
    valve.advance(1.0)
    data = valve.capture_read()
    current = data[:, 0] - data[:, 1]  # what the coil carries on top of the current setpoint
    spectrum = np.abs(np.fft.rfft(current - current.mean())) * 2 / len(current)
    freqs = np.fft.rfftfreq(len(current), CYCLE)
    peak = int(np.argmax(spectrum))
    expected_ma = amp / FULL * 0.10 * 2600  # DTAMP 100 % = 10 % of CURNORM (decision)
    assert freqs[peak] == pytest.approx(hz, abs=1.0)
    assert spectrum[peak] == pytest.approx(expected_ma, rel=0.1)


def test_single_coil_valve_ignores_the_negative_side():
    valve = booted(E02_A)
    valve.set_input("setpoint", -5.0)
    valve.advance(0.1)
    assert valve.signal("setpoint_threshold") == 0
    assert valve.signal("current_setpoint_a") == 0


# --- E04: external sensor conditioning, gain/offset on the process deviation, process PIDT1 --
E04 = "PRM9-06.3Z11/30-24E04S02"


def e04_with_sensor(volts: float, **writes: tuple[int, int, int]) -> EmulatedValve:
    """A booted E04 (process control, ±10 V sensor) whose sensor input reads ``volts``."""
    valve = booted(E04, **writes)
    valve.set_input("sensor_from_plant", 0)
    valve.set_input("sensor", volts)
    valve.advance(0.002)
    return valve


def test_e04_gain_and_offset_act_on_the_process_deviation_not_the_setpoint():
    valve = e04_with_sensor(
        1.0,
        g=(0x6341, 0, 2 * FULL),
        o=(0x6343, 1, 1638),
        gn=(0x2011, 0, FULL // 2),
        on=(0x6344, 1, 819),
    )
    pos = chain(valve, 3.0)
    assert pos["setpoint_gain"] == pos["setpoint_threshold"]  # the setpoint passes 1:1
    dev = valve.signal("process_setpoint") - valve.signal("process_actual")
    assert dev == pytest.approx(2 * FULL / 10, abs=8)
    assert valve.signal("process_deviation") == pytest.approx(1638 + dev * 2 * (FULL - 1638) / FULL)
    assert valve.read(0x6350, 1) == round(dev)  # 0x6350: the raw deviation, before gain/offset
    chain(valve, -1.0)
    dev = valve.signal("process_setpoint") - valve.signal("process_actual")
    assert dev < 0
    assert valve.signal("process_deviation") == pytest.approx(
        -819 + dev * 0.5 * (FULL - 819) / FULL
    )


def test_e04_sensor_linearization_on_and_off():
    xs = [-FULL, -12288, -8192, -4096, 0, 4096, 8192, 12288, FULL]
    ys = [-FULL, -15000, -12000, -7000, 0, 1000, 3000, 9000, FULL]
    writes = {f"x{n}": (0x2006, n, x) for n, x in enumerate(xs, start=1)}
    writes |= {f"y{n}": (0x2007, n, y) for n, y in enumerate(ys, start=1)}
    valve = e04_with_sensor(3.0, **writes)
    after_gain = valve.read(0x2100, 5)
    assert after_gain == pytest.approx(0.3 * FULL, abs=8)
    assert valve.signal("process_actual") == pytest.approx(after_gain, abs=0.5)  # lin. off
    valve.write(0x2008, 0, 1)
    valve.advance(0.002)
    expected = np.interp(after_gain, xs, ys)
    assert valve.signal("process_actual") == pytest.approx(expected, abs=1)
    assert valve.read(0x2100, 6) == pytest.approx(expected, abs=1)


def captured_process_controller(kp: int, ki: int) -> np.ndarray:
    valve = e04_with_sensor(0.0, kp=(0x2021, 1, kp), ki=(0x2021, 2, ki), t1=(0x2021, 4, 0))
    valve.capture_start(["process_deviation", "position_setpoint"])
    valve.set_input("setpoint", 1.0)
    valve.advance(0.02)
    return valve.capture_read()


def test_process_pidt1_proportional_part():
    data = captured_process_controller(250, 0)
    e, w = data[:, 0], data[:, 1]
    assert e[-1] == pytest.approx(FULL / 10, abs=8)
    assert w == pytest.approx(2.5 * e)  # the process controller's output is the spool setpoint


def test_process_pidt1_integral_part():
    data = captured_process_controller(0, 500)
    e, w = data[:, 0], data[:, 1]
    assert e[-1] > 1000
    assert np.diff(w) == pytest.approx(50.0 * CYCLE * e[1:])

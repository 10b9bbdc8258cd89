"""Closed-loop step responses of the emulated valve for E02/E04 and every coil layout."""

from __future__ import annotations

import numpy as np
import pytest

from prm9tool.device.emulator import EmulatedValve
from prm9tool.device.emulator.analysis import step_response
from prm9tool.device.records import DeviceState

CYCLE = EmulatedValve.CYCLE_S
FULL = 16384
SPOOLS = {"AB": "3Z11", "A": "2Z51", "B": "2Z61"}


def valve_for(config: str, coils: str) -> EmulatedValve:
    return EmulatedValve(f"PRM9-06.{SPOOLS[coils]}/30-24{config}S02")


@pytest.mark.parametrize("coils", ["AB", "A", "B"])
def test_factory_e02_answers_a_full_step_quickly_without_oscillation(coils):
    valve = valve_for("E02", coils)
    result = step_response(valve, 0.0, 10.0, "position_actual", seconds=0.15)
    assert result.final == pytest.approx(FULL, abs=0.01 * FULL)
    assert result.overshoot_percent < 5.0
    assert result.rise_s < 0.015
    assert result.settling_s < 0.040
    assert result.steady_ripple_percent < 2.0  # dither only: no sustained oscillation
    assert valve.status().device_state is DeviceState.DEVICE_MODE_ACTIVE


def test_e02_two_coils_steps_to_the_negative_side_with_coil_b():
    valve = valve_for("E02", "AB")
    result = step_response(valve, 0.0, -5.0, "position_actual", seconds=0.15)
    assert result.final == pytest.approx(-FULL / 2, abs=0.01 * FULL)
    assert result.settling_s < 0.040
    assert valve.signal("current_a") == 0
    assert valve.signal("current_b") > 500


def test_coil_b_valve_produces_positive_stroke_with_coil_b():
    valve = valve_for("E02", "B")
    step_response(valve, 0.0, 5.0, "position_actual", seconds=0.1)
    assert valve.signal("position_actual") == pytest.approx(FULL / 2, abs=0.01 * FULL)
    assert valve.signal("current_b") > 500


def test_factory_e04_two_coils_follows_a_process_step():
    valve = valve_for("E04", "AB")
    result = step_response(valve, 0.0, 5.0, "process_actual", seconds=1.5)
    assert result.final == pytest.approx(FULL / 2, abs=0.02 * FULL)
    assert result.overshoot_percent < 5.0
    assert result.settling_s < 0.6
    assert abs(valve.signal("position_actual")) < 0.05 * FULL  # load at rest: spool centred


@pytest.mark.parametrize(("coils", "volts"), [("A", 5.0), ("B", 7.0)])
def test_tuned_e04_single_coil_follows_a_process_step(coils, volts):
    valve = valve_for("E04", coils)
    valve.write(0x2010, 1, 6)  # 0…10 V setpoint (table 8-4 for one coil)
    valve.write(0x2005, 1, 6)  # 0…10 V sensor
    valve.write(0x2021, 2, 20)  # process Ki 2 1/s: a spring-return load needs an integral part
    result = step_response(valve, 0.0, volts, "process_actual", seconds=2.0)
    assert result.final == pytest.approx(FULL * volts / 10, abs=0.03 * FULL)
    assert result.settling_s < 1.5
    assert valve.status().active_errors == ()


def test_e04_in_position_control_mode_bypasses_the_process_loop():
    valve = valve_for("E04", "AB")
    valve.write(0x6043, 0, 2)
    result = step_response(valve, 0.0, 5.0, "position_actual", seconds=0.1)
    assert result.final == pytest.approx(FULL / 2, abs=0.01 * FULL)


def test_step_response_measures_the_capture():
    valve = valve_for("E02", "AB")
    result = step_response(valve, 0.0, 10.0, "position_actual", seconds=0.1)
    assert len(result.samples) == round(0.1 / CYCLE) + 1  # one sample before the step
    assert np.argmax(result.samples >= 0.9 * FULL) * CYCLE <= result.rise_s + 0.01


def test_e04_in_position_control_mode_still_moves_its_load_and_reads_its_sensor():
    valve = valve_for("E04", "AB")
    valve.write(0x6043, 0, 2)  # position control: the process loop is off, the load is not
    valve.advance(2.0)
    sensor_before = valve.signal("sensor_raw")
    actual_before = valve.read(0x6381, 1)
    assert sensor_before == pytest.approx(0, abs=0.01 * FULL)  # load at mid-stroke: 0 V
    valve.set_input("setpoint", 2.0)  # spool held 20 % open: the load keeps moving
    valve.advance(0.5)
    sensor = valve.signal("sensor_raw")
    assert sensor > sensor_before + 0.1 * FULL
    assert valve.signal("process_actual") == pytest.approx(sensor, abs=0.01 * FULL)
    assert valve.read(0x6381, 1) > actual_before + 0.1 * FULL
    assert valve.read(0x6350, 1) == pytest.approx(
        valve.signal("demand") - valve.signal("position_actual"), abs=0.01 * FULL
    )  # 0x6350 stays the position loop's deviation in mode 2

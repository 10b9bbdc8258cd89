"""Measuring points and the three-channel capture; input validation messages."""

from __future__ import annotations

import numpy as np
import pytest

from prm9tool.catalogue.signals import SIGNALS, signals_for
from prm9tool.device.emulator import EmulatedValve
from prm9tool.errors import ValueRangeError

E04 = "PRM9-06.3Z11/30-24E04S02"


def test_every_measuring_point_is_readable():
    valve = EmulatedValve(E04)
    valve.set_input("setpoint", 3.0)
    valve.advance(2.2)
    values = {s.key: valve.signal(s.key) for s in SIGNALS}
    assert values["supply_voltage"] == 24000
    assert values["temperature"] == pytest.approx(250, abs=2)
    assert values["process_setpoint"] == values["demand"] > 0
    assert {s.key for s in signals_for(valve.variant)} <= set(values)


def test_capture_records_every_cycle_and_drains():
    valve = EmulatedValve(E04)
    valve.capture_start(["demand", "current_a", "supply_voltage"])
    valve.advance(0.01)
    first = valve.capture_read()
    assert first.shape == (50, 3)
    assert np.all(first[:, 2] == 24000)
    assert valve.capture_read().shape == (0, 3)
    valve.advance(0.002)
    assert valve.capture_read().shape == (10, 3)


def test_capture_decimation_and_fewer_channels():
    valve = EmulatedValve(E04)
    valve.capture_start(["temperature"], decimation=5)
    valve.advance(0.1)
    data = valve.capture_read()
    assert data.shape == (100, 1)


def test_capture_matches_the_latest_signal():
    valve = EmulatedValve(E04)
    valve.set_input("setpoint", 4.0)
    valve.capture_start(["position_actual", "process_actual"])
    valve.advance(2.5)
    data = valve.capture_read()
    assert data[-1, 0] == valve.signal("position_actual")
    assert data[-1, 1] == valve.signal("process_actual")


def test_capture_stop_discards():
    valve = EmulatedValve(E04)
    valve.capture_start(["demand"])
    valve.advance(0.01)
    valve.capture_stop()
    valve.advance(0.01)
    assert valve.capture_read().size == 0


@pytest.mark.parametrize(
    ("keys", "decimation", "message"),
    [
        (["demand", "current_a", "current_b", "pwm_a"], 1, "4 measuring points requested"),
        ([], 1, "0 measuring points requested"),
        (["flux"], 1, "unknown measuring point"),
        (["demand"], 0, "decimation 0 must be at least 1"),
    ],
)
def test_capture_refuses_bad_requests(keys, decimation, message):
    with pytest.raises(ValueRangeError, match=message):
        EmulatedValve(E04).capture_start(keys, decimation)


def test_bad_inputs_are_refused_with_a_clear_message():
    valve = EmulatedValve(E04)
    with pytest.raises(ValueRangeError, match="unknown input 'pressure'; inputs are: setpoint"):
        valve.set_input("pressure", 1.0)
    with pytest.raises(ValueRangeError, match="switch_node: 16 is not a switch position"):
        valve.set_input("switch_node", 16)
    with pytest.raises(ValueRangeError, match="unknown measuring point 'flux'"):
        valve.signal("flux")
    with pytest.raises(ValueRangeError, match="is negative"):
        valve.advance(-1.0)


def test_external_sensor_from_the_input_instead_of_the_plant():
    valve = EmulatedValve(E04)
    valve.set_input("sensor_from_plant", 0)
    valve.set_input("sensor", 2.5)
    valve.advance(0.01)
    assert valve.signal("sensor_raw") == pytest.approx(16384 / 4, abs=10)
    assert valve.read(0x2100, 1) == pytest.approx(16384 / 4, abs=10)
    valve.write(0x2005, 2, 1)  # sensor inverted
    valve.write(0x2005, 3, 1000)  # zero offset
    valve.write(0x2005, 4, 32768)  # gain 2
    valve.advance(0.01)
    raw = valve.read(0x2100, 1)
    assert valve.read(0x2100, 3) == -raw
    assert valve.read(0x2100, 4) == -raw + 1000
    assert valve.read(0x2100, 5) == 2 * (-raw + 1000)
    assert valve.read(0x2100, 6) == valve.read(0x6381, 1)


def test_sensor_value_over_canopen():
    valve = EmulatedValve("PRM9-06.3Z11/30-24E04S02-CA")
    valve.write(0x2005, 1, 14)
    valve.write(0x2100, 2, -4000)
    valve.advance(0.01)
    assert valve.read(0x2100, 1) == -4000


def test_non_finite_inputs_and_unknown_faults_are_refused():
    valve = EmulatedValve(E04)
    with pytest.raises(ValueRangeError, match="setpoint: nan is not a finite number"):
        valve.set_input("setpoint", float("nan"))
    with pytest.raises(ValueRangeError, match="unknown fault 'COIL_C_OPEN'; faults are: COIL_A"):
        valve.inject("COIL_C_OPEN")  # type: ignore[arg-type]
    valve.advance(0.01)
    assert np.isfinite(valve.signal("setpoint_raw"))


def test_capture_records_from_the_very_next_cycle():
    # A capture started between cycles must see every following cycle, not only those after
    # the loop's next input change (the USB stream depends on it: 5 samples per ms).
    from prm9tool.device.emulator import EmulatedValve

    valve = EmulatedValve("PRM9-06.3Z11/30-24E02S02")
    valve.advance(2.5)  # booted and settled: inputs no longer change every millisecond
    for _ in range(20):
        valve.capture_start(["position_actual"])
        valve.advance(0.001)
        assert valve.capture_read().shape == (5, 1)
        valve.capture_stop()

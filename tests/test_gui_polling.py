"""The connection's poller against the emulator: measuring points keep their labels."""

from __future__ import annotations

import math

import pytest

from prm9tool.catalogue import CATALOGUE
from prm9tool.device.emulator import EmulatedValve
from prm9tool.device.usb.protocol import Op
from prm9tool.device.usb.session import UsbSession
from prm9tool.device.usb.transport.emulator import EmulatorTransport
from prm9tool.service.polling import Poller

E04_CA = "PRM9-10.3Z11/60-24E04S02-CA"
WATCHED = ["supply_voltage", "temperature", "current_a", "setpoint_threshold", "setpoint_raw",
           "demand"]  # fmt: skip


@pytest.fixture
def valve(tmp_path):
    valve = EmulatedValve(E04_CA, 4712, "2.3.4", nv_path=tmp_path / "nv.json")
    valve.advance(3.0)  # past the power-up timeline
    return valve


def _valve_runs_before_stream_starts(transport: EmulatorTransport, valve: EmulatedValve) -> None:
    """The valve's own real-time thread runs on between the host's last stream read and its
    STREAM_START request: the old stream sends one more report meanwhile."""
    write = transport._write

    def delayed(report: bytes) -> None:
        if report[0] == Op.STREAM_START:
            valve.advance(0.02)
        write(report)

    transport._write = delayed  # type: ignore[method-assign]


def test_watch_stream_values_keep_their_labels_when_the_chunk_changes(valve):
    transport = EmulatorTransport(valve)
    _valve_runs_before_stream_starts(transport, valve)
    supply = valve.signal("supply_voltage")
    with UsbSession(transport, "emulator:test") as session:
        poller = Poller()
        poller.reset(session.info)
        poller.watched = list(WATCHED)
        seen: list[dict[str, float]] = []
        for _ in range(8):
            seen.append(poller.poll(session, status=False, signals=True).signals)
            valve.advance(0.15)
    assert {key for values in seen for key in values} == set(WATCHED)
    for values in seen:
        for key, value in values.items():
            assert (value == pytest.approx(supply, abs=1)) == (key == "supply_voltage"), values


def test_points_outside_the_oscilloscopes_stream_say_no_value_not_an_old_one(valve):
    """Issue 25 item 1: with the oscilloscope streaming three points, the diagram's other
    measuring points were left at the value they had before (0 mA on a fresh valve) while the
    spool moved. A point the valve holds as an object (the control deviation) is read; the
    others are reported as NaN (no value now) each poll; streamed ones are live."""
    with UsbSession(EmulatorTransport(valve), "emulator:test") as session:
        poller = Poller()
        poller.reset(session.info)
        poller.watched = ["demand", "controller_output", "current_a", "pwm_a", "position_deviation"]
        poller.poll(session, status=False, signals=True)  # the watch stream runs first
        valve.advance(0.15)
        poller.start_stream(session, ["demand", "position_actual", "current_a"], 1000)
        valve.write(*CATALOGUE["SETPOVR"].key, 3277)
        valve.write(*CATALOGUE["SETPOVRON"].key, 1)
        valve.advance(0.3)
        values = poller.poll(session, status=False, signals=True).signals
        deviation = valve.read(*CATALOGUE["CTRLDEV"].key)
    assert set(values) == {
        "demand",
        "controller_output",
        "current_a",
        "pwm_a",
        "position_deviation",
    }
    assert math.isnan(values["controller_output"]) and math.isnan(values["pwm_a"])
    assert values["position_deviation"] == deviation  # an object of the valve: read, live
    assert values["demand"] == valve.signal("demand") == 3277
    assert values["current_a"] == pytest.approx(valve.signal("current_a"), abs=40)

"""Commissioning a -CA valve over any link: NMT commands on the session, the control word's
enable sequence as object writes, and the emulated valve's inputs, switches and faults
(issue 14 item 10 and 12)."""

from __future__ import annotations

import sys

import pytest
from support.canopen_rig import E02, make_rig
from support.usb_fakes import FakeHid

from prm9tool.catalogue.commissioning import (
    CONTROL_WORD,
    DISABLE_SEQUENCE,
    ENABLE_SEQUENCE,
    Blocker,
    NmtCommand,
    blocker,
)
from prm9tool.device import emulated_valves, factory
from prm9tool.device.emulator import EmulatedValve
from prm9tool.device.usb.protocol import Nmt, decode_request, encode_request
from prm9tool.device.usb.protocol.wire import MalformedReportError
from prm9tool.device.usb.session import UsbSession
from prm9tool.device.usb.transport.emulator import EmulatorTransport
from prm9tool.device.usb.transport.hidapi import HidTransport
from prm9tool.errors import DeviceDisconnectedError

CA = "PRM9-06.3Z11/30-24E02S02-CA"


@pytest.fixture
def session():
    emulated_valves.forget_emulated_valves()  # a fresh valve for each test
    opened = factory.open_session(f"emulator:{CA}:9001", paced=False)
    opened.transport.valve.advance(2.0)  # booted: pre-operational, INIT
    yield opened
    opened.close()
    emulated_valves.forget_emulated_valves()


def test_the_nmt_request_is_one_byte_and_refuses_unknown_commands():
    assert encode_request(5, Nmt(0x01))[:3] == bytes.fromhex("0d 05 01")
    assert decode_request(encode_request(5, Nmt(0x82))) == (5, Nmt(0x82))
    assert Nmt(0x01).idempotent and not Nmt(0x81).idempotent
    with pytest.raises(MalformedReportError, match="unknown NMT command 0x03"):
        decode_request(bytes.fromhex("0d 05 03") + bytes(61))


def test_a_delivered_ca_valve_waits_and_the_enable_sequence_makes_it_follow(session: UsbSession):
    status = session.status()
    assert (status.nmt_state, str(status.device_state)) == ("pre-operational", "INIT")
    assert blocker(str(status.device_state), status.nmt_state, (), False) is (
        Blocker.WAITING_FOR_MASTER
    )
    session.nmt(NmtCommand.START)
    assert session.status().nmt_state == "operational"
    states = []
    for word in ENABLE_SEQUENCE:
        session.write(CONTROL_WORD, word)
        states.append(str(session.status().device_state))
    assert states == ["INIT", "DISABLED", "HOLD", "DEVICE_MODE_ACTIVE"]
    session.write_many({"SETPOVRON": 1, "SETPOVR": 8192})  # 50 %
    session.transport.valve.advance(0.2)
    assert session.read("SETPOVRON") == 1
    position = session.transport.valve.signal("position_actual")
    assert position == pytest.approx(8192, abs=200)  # it follows
    states = []
    for word in DISABLE_SEQUENCE:
        session.write(CONTROL_WORD, word)
        states.append(str(session.status().device_state))
    assert states == ["DEVICE_MODE_ACTIVE", "HOLD", "DISABLED", "INIT"]
    session.nmt(NmtCommand.STOP)
    assert session.status().nmt_state == "stopped"


def test_nmt_over_usb_reaches_the_canopen_slave_of_a_valve_on_the_bus(request):
    rig = make_rig(request.node.name, E02)
    try:
        transport = EmulatorTransport(rig.valve)
        with UsbSession(transport, "emulator:rig") as session:
            session.nmt(NmtCommand.START)
            assert rig.slave.state.name == "OPERATIONAL"
            rig.valve.advance(1.0)
            assert "70A 05" in rig.drain()  # its heartbeat says operational
            session.nmt(NmtCommand.PRE_OPERATIONAL)
            assert session.status().nmt_state == "pre-operational"
    finally:
        rig.close()


def test_the_emulated_valve_has_inputs_switches_and_faults(session: UsbSession):
    controls = session.emulator
    assert controls is not None
    state = controls.state()
    assert state.inputs["supply_voltage"] == 24.0 and state.switches == (6, 2)
    assert "SENSOR_BREAK" not in state.faults_available  # an E02 has no external sensor
    controls.set_input("supply_voltage", 26.5)
    controls.set_input("switch_node", 0)
    controls.set_fault("COIL_A_OPEN", True)
    session.transport.valve.advance(0.1)
    state = controls.state()
    assert state.inputs["supply_voltage"] == 26.5
    assert (state.switches, state.latched) == ((6, 0), (6, 2))  # read at the next power-up
    assert state.faults == {"COIL_A_OPEN"}
    status = session.status()
    assert 0x5411 in status.active_errors and status.supply_v == pytest.approx(26.5, abs=0.01)
    controls.set_fault("COIL_A_OPEN", False)
    assert controls.state().faults == frozenset()
    controls.pull_cable()
    with pytest.raises(DeviceDisconnectedError):
        session.status()


def test_a_usb_valve_has_no_emulator_controls_but_takes_nmt(monkeypatch):
    fake = FakeHid()
    monkeypatch.setitem(sys.modules, "hid", fake.as_module())
    monkeypatch.setitem(sys.modules, "hidraw", fake.as_module())
    monkeypatch.setattr(HidTransport, "settle_s", 0.0)
    valve = EmulatedValve(CA, 321)
    fake.add(valve, b"/dev/hidraw3")
    valve.advance(2.0)
    with UsbSession(HidTransport(b"/dev/hidraw3"), "usb:/dev/hidraw3") as session:
        assert session.emulator is None  # a valve on a USB cable: no emulator behind it
        session.nmt(NmtCommand.START)
        assert valve.status().nmt_state == "operational"


@pytest.mark.parametrize(
    ("state", "nmt", "errors", "booting", "expected"),
    [
        ("NOT_READY", "initialising", (), True, Blocker.BOOTING),
        ("INIT", "pre-operational", (), False, Blocker.WAITING_FOR_MASTER),
        ("INIT", "stopped", (), False, Blocker.NMT_STOPPED),
        ("FAULT_HOLD", "operational", (0x5411,), False, Blocker.FAULT),
        ("HOLD", "operational", (), False, Blocker.HOLD),
        ("DISABLED", "off", (), False, Blocker.DISABLED),
        ("DEVICE_MODE_ACTIVE", "operational", (), False, None),
        ("DEVICE_MODE_ACTIVE", "off", (0x3410,), False, None),  # error shown, valve resumed
    ],
)
def test_why_a_valve_does_not_follow(state, nmt, errors, booting, expected):
    assert blocker(state, nmt, errors, booting) is expected

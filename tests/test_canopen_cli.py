"""``prm9tool --emulator TYPEKEY --can-interface virtual --can-channel X`` puts the valve on X.

The command line is parsed by the real parser and the session opened, then put on the bus, by
the composition root's opener and joiner (the ones the GUI's connection uses) through
prm9tool/device/factory.py; the GUI itself is not started. A ``canopen`` master on the same ``virtual`` channel then commissions the valve.
"""

from __future__ import annotations

import struct
import time

import can
import canopen
import pytest
from support.canopen_rig import TIMEOUT_S, unique_channel

from prm9tool import app
from prm9tool.app import start_plan
from prm9tool.cli import main as cli
from prm9tool.device import emulated_valves, factory
from prm9tool.errors import CanBusError

E04_CA = "PRM9-06.3Z11/30-24E04S02-CA"
SERIAL = 4711


def _wait_for(bus: can.BusABC, can_id: int, data: bytes) -> None:
    deadline = time.monotonic() + TIMEOUT_S
    while time.monotonic() < deadline:
        msg = bus.recv(0.1)
        if msg is not None and (msg.arbitration_id, bytes(msg.data)) == (can_id, data):
            return
    raise AssertionError(f"no frame {can_id:03X} {data.hex(' ')}")


def _open(argv: list[str]) -> object:
    """Open the session as the GUI does, then join the CAN bus (the session stays open)."""
    args = cli.build_parser().parse_args(argv)
    entry = factory.list_devices(start_plan.plan_from(args).emulators)[0]
    session = app._opener(args)(entry)
    try:
        app._joiner(args)(session)
    except BaseException:
        session.close()
        raise
    return session


@pytest.fixture(autouse=True)
def _forget_valves():
    yield
    emulated_valves.forget_emulated_valves()


def test_command_line_puts_the_emulated_ca_valve_on_the_chosen_virtual_channel():
    channel = unique_channel("cli")
    listener = can.Bus(interface="virtual", channel=channel)
    network = canopen.Network()
    network.connect(interface="virtual", channel=channel)
    argv = ["--emulator", f"{E04_CA}:{SERIAL}", "--can-interface", "virtual"]
    session = _open([*argv, "--can-channel", channel])
    try:
        node_id = emulated_valves.emulated_valve(E04_CA, SERIAL).node_id
        _wait_for(listener, 0x700 + node_id, b"\x00")  # boot-up, paced in real time
        node = network.add_node(node_id)
        node.sdo.RESPONSE_TIMEOUT = TIMEOUT_S
        assert struct.unpack("<I", node.sdo.upload(0x1018, 4))[0] == SERIAL
        assert struct.unpack("<I", node.sdo.upload(0x1000, 0))[0] & 0xFFFF == 408
        network.nmt.send_command(0x01)
        _wait_for(listener, 0x700 + node_id, b"\x05")  # heartbeat: operational
    finally:
        session.close()  # type: ignore[attr-defined]
        network.disconnect()
        listener.shutdown()


def test_an_unknown_can_interface_is_reported_and_the_usb_session_keeps_working():
    args = cli.build_parser().parse_args(
        ["--emulator", f"{E04_CA}:{SERIAL}", "--can-interface", "no-such-interface"]
    )
    session = app._opener(args)(factory.list_devices(start_plan.plan_from(args).emulators)[0])
    try:
        with pytest.raises(CanBusError, match="cannot open CAN bus"):
            app._joiner(args)(session)
        assert session.read("LIMTA") == 2400  # type: ignore[attr-defined]  # USB unaffected
    finally:
        session.close()  # type: ignore[attr-defined]
    assert not emulated_valves.emulated_valve(E04_CA, SERIAL).running  # nothing left running


def test_the_bus_is_released_when_the_session_closes(monkeypatch):
    opened = []
    real_bus = can.Bus

    def recording_bus(**kwargs):
        opened.append(real_bus(**kwargs))
        return opened[-1]

    monkeypatch.setattr(can, "Bus", recording_bus)
    argv = ["--emulator", f"{E04_CA}:{SERIAL}", "--can-interface", "virtual"]
    session = _open([*argv, "--can-channel", unique_channel("release")])
    assert len(opened) == 1 and not opened[0]._is_shutdown
    session.close()  # type: ignore[attr-defined]
    assert opened[0]._is_shutdown and not emulated_valves.emulated_valve(E04_CA, SERIAL).running

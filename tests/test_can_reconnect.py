"""A CANopen valve that leaves the bus and comes back (power cycle), and the tool's adapter
going bus-off and recovering (tests/support/bus_off_rig.py): the connection scans the bus for the
valve's serial number (0x1018/4) and goes online with it — also at a new node ID. Emulated -CA
valve in real time on a private virtual channel (can_link_rig)."""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from support.can_link_rig import E02, make_link_rig
from support.gui_support import session_of
from support.reconnect_links import online_window

from prm9tool.catalogue.commissioning import NmtCommand
from prm9tool.device import factory
from prm9tool.device.records import NmtState
from prm9tool.online.connection import ValveConnection
from prm9tool.service.valve_listing import default_lister

TIMEOUT = 30_000  # a lost SDO answer takes its timeout, a bus scan its round


@pytest.fixture
def rig(tmp_path, data_dir):
    rig = make_link_rig("reconnect", tmp_path, E02, switches=(6, 2))  # 500 kbit/s, node 10
    rig.valve.start()
    yield rig
    rig.valve.stop()
    rig.close()


@pytest.fixture
def connection(qtbot, rig):
    conn = ValveConnection(
        opener=lambda entry: factory.open_session(entry, can_link=rig.options),  # type: ignore[arg-type]
        lister=default_lister,
    )
    yield conn
    conn.shutdown()


def leave_and_rejoin_at(rig, node_switch: int) -> None:
    """The valve drops off the bus (its CAN side is gone), is powered up with the node-ID
    switch at ``node_switch`` and joins the same bus again."""
    import can

    rig.slave.stop()
    rig.bus.shutdown()
    rig.valve.set_input("switch_node", node_switch)
    rig.valve.restart()
    rig.bus = can.Bus(interface="virtual", channel=rig.options.channel)
    rig.slave = rig.valve.connect_can(rig.bus)


def test_the_valve_found_at_a_new_node_id_by_its_serial(qtbot, rig, connection):
    with qtbot.waitSignal(connection.online_changed, timeout=TIMEOUT):
        connection.go_online("can:10")
    first = connection.device
    assert first.serial == rig.valve.serial and first.device_id == "can:10"
    assert first.can_bus is not None
    with qtbot.waitSignal(connection.reconnecting, timeout=TIMEOUT):
        rig.slave.stop()  # off the bus: the next poll gets no answer
        rig.bus.shutdown()
    assert not connection.is_online and connection.lost_valve.device_id == "can:10"
    with qtbot.waitSignal(connection.reconnected, timeout=TIMEOUT) as back:
        leave_and_rejoin_at(rig, 3)
    assert rig.valve.node_id != 10
    assert back.args[0].serial == rig.valve.serial
    assert back.args[0].device_id == f"can:{rig.valve.node_id}"
    assert connection.is_online and connection.device.device_id == f"can:{rig.valve.node_id}"


def start_pdo_scope(qtbot, window):
    """NMT start (the commissioning panel's), then the oscilloscope on the spool position: the
    valve's TPDO1 at the tool's SYNC."""
    window.control.nmt(NmtCommand.START)
    session = session_of(window)
    qtbot.waitUntil(lambda: session.nmt_state is NmtState.OPERATIONAL, timeout=TIMEOUT)
    window.open_scope("position_actual")
    scope = window.views["scope"]
    scope.start()
    qtbot.waitUntil(lambda: scope.capture is not None and scope.capture.buffer.total > 100,
                    timeout=TIMEOUT)  # fmt: skip
    assert session.stream_source == "pdo"
    return scope


@pytest.mark.parametrize("state", ["idle", "scope"])
def test_a_bus_off_of_the_adapter_is_said_and_the_window_is_back_by_itself(
    qtbot, tmp_path, data_dir, answers, monkeypatch, state
):
    """The tool's CAN controller goes bus-off (SocketCAN's error frame, then every frame
    refused: the SDO requests and the oscilloscope's SYNC): the status bar says so and counts
    while it looks; when the adapter is back on the bus (restart-ms), the window finds the
    same valve and is online again by itself, and the oscilloscope records on."""
    with online_window(qtbot, tmp_path, "bus-off", monkeypatch) as link:
        window, adapter = link.window, link.adapter
        scope = start_pdo_scope(qtbot, window) if state == "scope" else None
        with qtbot.waitSignal(window.connection.reconnecting, timeout=TIMEOUT):
            adapter.go_bus_off()
        assert link.valve.serial == window.connection.lost_valve.serial
        message = window.status.currentMessage()
        assert message.startswith("Connection to the valve lost; looking for it… (")
        assert "The CAN adapter went bus-off" in message
        assert answers.informed == []  # no dialog in the way: the status bar says it
        mode = window.status.mode_label
        counted = []
        window.connection.reconnecting.connect(counted.append)
        qtbot.waitUntil(lambda: len(counted) >= 2, timeout=TIMEOUT)  # still off: it looks on
        assert mode.text().startswith("Mode: RECONNECTING… ") and not window.connection.is_online
        assert scope is None or not scope.running
        if state == "idle":  # docs/can-link.md's picture with PRM9TOOL_SCREENSHOTS=docs/screenshots
            folder = Path(os.environ.get("PRM9TOOL_SCREENSHOTS") or tmp_path)
            assert window.status.grab().save(str(folder / "status_bar_bus_off.png"))
        with qtbot.waitSignal(window.connection.reconnected, timeout=TIMEOUT) as back:
            adapter.recover()
        assert back.args[0].serial == link.valve.serial and back.args[0].device_id == "can:10"
        qtbot.waitUntil(lambda: window.sync.active, timeout=TIMEOUT)
        assert mode.text() == "Mode: ONLINE"
        assert window.status.currentMessage() == "Back online: document and valve agree"
        if scope is not None:
            qtbot.waitUntil(lambda: scope.running, timeout=TIMEOUT)
            before = scope.capture.buffer.total
            qtbot.waitUntil(lambda: scope.capture.buffer.total > before + 100, timeout=TIMEOUT)

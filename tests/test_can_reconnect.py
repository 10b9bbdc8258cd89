"""A CANopen valve that leaves the bus and comes back (power cycle, bus-off): the connection
scans the bus for its serial number (0x1018/4) and goes online with it — also at a new node
ID. Emulated -CA valve in real time on a private virtual channel (can_link_rig)."""

from __future__ import annotations

import pytest
from can_link_rig import E02, make_link_rig

from prm9tool.device import factory
from prm9tool.online.connection import ValveConnection
from prm9tool.online.valve_listing import default_lister

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

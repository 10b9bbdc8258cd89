"""The master's NMT state after its own NMT command (issue 30): known and confirmed at once (a
heartbeat, the first TPDO or an SDO read within a bound), not "as the last heartbeat told" a
heartbeat period later; and a node the tool stopped is NMT stopped, not an unpowered valve."""

from __future__ import annotations

import pytest
from support.can_link_rig import E04, make_link_rig

from prm9tool.catalogue.commissioning import NmtCommand
from prm9tool.device.canlink.rpdo_setpoint import RpdoSetpoint
from prm9tool.device.canlink.session import CanopenSession
from prm9tool.device.enabling import enable
from prm9tool.device.records import DeviceState, NmtState

NODE = 10


@pytest.fixture
def online(request, tmp_path, data_dir):
    """(rig, session): the valve in real time with its delivery heartbeat of 1000 ms."""
    rig = make_link_rig(request.node.name, tmp_path)
    rig.valve.start()
    session = CanopenSession(rig.options, NODE, type_key=E04)
    try:
        session.write("HEARTBEAT", 1000)
        session.write("CTRLMODE", 2)
        yield rig, session
    finally:
        session.close()
        rig.valve.stop()
        rig.close()


def test_nmt_start_enable_and_the_generator_at_once(online):
    _rig, session = online
    session.nmt(NmtCommand.START)
    assert session.nmt_state is NmtState.OPERATIONAL  # no waiting for the next heartbeat
    enable(session)
    link = RpdoSetpoint(session)
    link.begin(4000)  # refused on today's main: "node 10 is NMT pre-operational"
    link.end()


def test_each_command_is_confirmed_even_without_a_heartbeat(online):
    rig, session = online
    session.write("HEARTBEAT", 0)  # no heartbeat at all: the TPDO or an SDO read confirms
    for command, state in (
        (NmtCommand.START, NmtState.OPERATIONAL),
        (NmtCommand.PRE_OPERATIONAL, NmtState.PRE_OPERATIONAL),
        (NmtCommand.STOP, NmtState.STOPPED),
        (NmtCommand.START, NmtState.OPERATIONAL),
    ):
        session.nmt(command)
        assert session.nmt_state is state
        assert rig.valve.status().nmt_state is state


def test_a_node_the_tool_stopped_is_stopped_not_unpowered(online):
    rig, session = online
    session.nmt(NmtCommand.START)
    enable(session)
    session.nmt(NmtCommand.STOP)  # table 7-21: a fault reaction in DEVICE_MODE_ACTIVE
    status = session.status()  # a stopped node answers no SDO: no timeout here
    assert status.nmt_state is NmtState.STOPPED
    assert status.device_state is DeviceState.FAULT_HOLD
    assert rig.valve.status().device_state is DeviceState.FAULT_HOLD
    session.nmt(NmtCommand.START)
    assert session.status().device_state is DeviceState.FAULT_HOLD  # read again by SDO
    enable(session)  # the stop's fault has no cause left: the documented sequence clears it

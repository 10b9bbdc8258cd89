"""The master reads the CiA 408 status word 0x6041 as the profile defines it: bits 0…3 (R M H D)
tell the state, upper bits are flags it ignores; a refusal names the state and the word in hex.
The valve side is tests/test_emulator_states.py and the golden frames of §7.6."""

from __future__ import annotations

import pytest
from support.can_link_rig import E04, make_link_rig
from support.waiting import wait_for

from prm9tool.catalogue.commissioning import NmtCommand
from prm9tool.characterize.canrig import rig_for_session
from prm9tool.characterize.rig import ValveFaultError
from prm9tool.device.canlink.rpdo_setpoint import RpdoSetpoint, RpdoSetpointError
from prm9tool.device.canlink.session import CanopenSession
from prm9tool.device.records import DeviceState

STATUS = (0x6041, 0)


@pytest.fixture
def link(request, tmp_path, data_dir):
    rig = make_link_rig(request.node.name, tmp_path, real_valve=True)
    rig.valve.start()
    session = CanopenSession(rig.options, 10, type_key=E04)
    try:
        yield rig, session
    finally:
        session.close()
        rig.valve.stop()
        rig.close()


def answer_status_word(rig, word: int) -> None:
    """The valve answers ``word`` for 0x6041 (a manufacturer's valve with its own flags)."""
    with rig.valve.lock:
        rig.valve.firmware.od.getters[STATUS] = lambda: word


@pytest.mark.parametrize(
    ("word", "state"),
    [
        (0x000F, DeviceState.DEVICE_MODE_ACTIVE),
        (0xFE0F, DeviceState.DEVICE_MODE_ACTIVE),  # ramp running, limit, deviation, unknown …
        (0x0010 | 0x0008, DeviceState.INIT),  # local control
        (0x8009, DeviceState.DISABLED),
        (0x000B, DeviceState.HOLD),
        (0x0003, DeviceState.FAULT_HOLD),
        (0x0207, DeviceState.FAULT_REACTION),
        (0x0001, DeviceState.FAULT),
        (0x0000, DeviceState.NOT_READY),
    ],
)
def test_the_state_comes_from_bits_0_to_3_whatever_the_upper_flags(link, word, state):
    rig, session = link
    answer_status_word(rig, word)
    status = session.status()
    assert (status.device_state, status.status_word) == (state, word)


def test_an_enabled_valve_with_flags_is_driven_over_rpdo1(link):
    rig, session = link
    session.nmt(NmtCommand.START)
    wait_for(lambda: session.nmt_state == "operational")
    for word in (0x08, 0x09, 0x0B, 0x0F):
        session.write("CONTROLWORD", word)
    wait_for(lambda: rig.valve.status().device_state is DeviceState.DEVICE_MODE_ACTIVE)
    answer_status_word(rig, 0x0A0F)  # ramp running + control deviation: still enabled
    rig_for_session(session).ensure_active()  # not refused
    link_ = RpdoSetpoint(session)
    link_.begin(4000)
    link_.end()


def test_a_refusal_names_the_state_and_the_status_word(link):
    rig, session = link
    session.nmt(NmtCommand.START)
    wait_for(lambda: session.nmt_state == "operational")
    answer_status_word(rig, 0x0209)
    with pytest.raises(RpdoSetpointError, match=r"node 10 is in DISABLED \(status word 0x0209\)"):
        RpdoSetpoint(session).begin(4000)
    with pytest.raises(ValveFaultError, match=r"device state DISABLED \(status word 0x0209\)"):
        rig_for_session(session).ensure_active()
    answer_status_word(rig, 0x0002)  # bits 0…3 that CiA 408 does not define
    with pytest.raises(RpdoSetpointError, match=r"an undefined state \(status word 0x0002\)"):
        RpdoSetpoint(session).begin(4000)
    assert rig.working("POSSETP") == 0  # nothing was sent

"""Golden frames for the CiA 301 conformance defects of issue 15 (items 1-5), byte for byte.

Frames are written as in the manual: ``COB-ID data bytes`` in hex.
"""

from __future__ import annotations

import pytest
from support.canopen_rig import E04, Rig, make_rig


@pytest.fixture
def rig(request: pytest.FixtureRequest):
    rig = make_rig(request.node.name)
    yield rig
    rig.close()


def sdo_answers(rig: Rig) -> list[str]:
    """SDO answers sent since the last call (the barrier's own answer excluded)."""
    rig.barrier()
    return [f for f in rig.drain() if f.startswith("58A")]


# --- item 4: an SDO request that is not 8 bytes changes nothing (ignored, no answer) ----------
@pytest.mark.parametrize(
    ("request_frame", "index", "before"),
    [
        ("60A 2B 17 10 00", (0x1017, 0), 1000),  # padded with zeros: heartbeat would stop
        ("60A 2B 17 10 00 F4", (0x1017, 0), 1000),  # would set 244
        ("60A 2B 17 10 00 F4 01 00", (0x1017, 0), 1000),  # 7 bytes
        ("60A 23 06 10 00 10", (0x1006, 0), 0),  # would set 0x1006 = 16
        ("60A 40 18 10", (0x1018, 4), 0),  # a short upload request is not answered either
    ],
)
def test_a_short_sdo_request_is_ignored(rig: Rig, request_frame, index, before):
    value = rig.valve.read(*index)
    assert index[0] == 0x1018 or value == before
    rig.send(request_frame)
    assert sdo_answers(rig) == []
    assert rig.valve.read(*index) == value


def test_a_one_byte_download_segment_does_not_complete_the_transfer(rig: Rig):
    rig.exchange("60A 21 17 10 00 02 00 00 00", "58A 60 17 10 00 00 00 00 00")
    rig.send("60A 0B")  # last segment, 2 bytes said, none given: ignored
    assert rig.drain(settle_s=0.2) == []  # (no barrier: its request would end the transfer)
    assert rig.valve.read(0x1017, 0) == 1000
    rig.exchange("60A 0B F4 01 00 00 00 00 00", "58A 20 00 00 00 00 00 00 00")  # goes on
    assert rig.valve.read(0x1017, 0) == 500


# --- item 5: a classical CAN node ignores CAN FD frames --------------------------------------
def test_a_can_fd_frame_is_not_an_sdo_request(rig: Rig):
    rig.send("60A 2B 17 10 00 F4 01 00 00", fd=True)
    assert sdo_answers(rig) == []
    assert rig.valve.read(0x1017, 0) == 1000
    rig.exchange("60A 2B 17 10 00 F4 01 00 00", "58A 60 17 10 00 00 00 00 00")  # classical: yes
    assert rig.valve.read(0x1017, 0) == 500


def test_a_can_fd_nmt_frame_is_ignored(rig: Rig):
    rig.send("000 01 0A", fd=True)
    rig.barrier()
    assert rig.valve.status().nmt_state == "pre-operational"


# --- item 1: EMCY 8210 agrees with 0x1001 and 0x1003, and is reset ---------------------------
def test_emcy_8210_is_in_0x1001_and_0x1003_and_reset_after_a_good_rpdo(rig: Rig):
    rig.exchange("60A 2B 17 10 00 00 00 00 00", "58A 60 17 10 00 00 00 00 00")  # no heartbeat
    rig.send("000 01 0A")
    rig.barrier()
    state = rig.valve.status().device_state
    rig.drain()
    rig.send("20A 0F")  # RPDO1 maps 4 bytes: too short, not processed
    rig.barrier()
    assert [f for f in rig.drain() if f.startswith("08A")] == ["08A 10 82 11 00 00 00 00 00"]
    rig.exchange("60A 40 01 10 00 00 00 00 00", "58A 4F 01 10 00 11 00 00 00")  # = EMCY byte 2
    rig.exchange("60A 40 03 10 00 00 00 00 00", "58A 4F 03 10 00 01 00 00 00")
    rig.exchange("60A 40 03 10 01 00 00 00 00", "58A 43 03 10 01 10 82 00 00")
    assert rig.valve.status().device_state is state  # reported only: no fault reaction
    rig.send("20A 0F 00 00 00")  # the right length: the error goes, CiA 301 error reset
    rig.barrier()
    assert [f for f in rig.drain() if f.startswith("08A")] == ["08A 00 00 00 00 00 00 00 00"]
    rig.exchange("60A 40 01 10 00 00 00 00 00", "58A 4F 01 10 00 00 00 00 00")  # bit cleared
    rig.exchange("60A 40 03 10 01 00 00 00 00", "58A 43 03 10 01 10 82 00 00")  # history kept


def test_emcy_8210_is_reset_once_when_correct_rpdos_arrive_again(rig: Rig):
    rig.exchange("60A 2B 17 10 00 00 00 00 00", "58A 60 17 10 00 00 00 00 00")
    rig.send("000 01 0A")
    rig.send("20A 0F")
    rig.barrier()
    assert [f for f in rig.drain() if f.startswith("08A")] == ["08A 10 82 11 00 00 00 00 00"]
    for _ in range(3):  # correct RPDOs: one error reset, not one per frame
        rig.send("20A 0F 00 00 00")
    rig.barrier()
    assert [f for f in rig.drain() if f.startswith("08A")] == ["08A 00 00 00 00 00 00 00 00"]


def test_emcy_8210_ends_with_the_next_nmt_start(rig: Rig):
    rig.exchange("60A 2B 17 10 00 00 00 00 00", "58A 60 17 10 00 00 00 00 00")
    rig.send("000 01 0A")
    rig.send("20A 0F")
    rig.barrier()
    assert "08A 10 82 11 00 00 00 00 00" in rig.drain()
    rig.send("000 80 0A")
    rig.send("000 01 0A")
    rig.barrier()
    rig.valve.advance(11.0)
    assert "08A 00 00 00 00 00 00 00 00" in rig.drain()
    assert rig.valve.status().error_register == 0


# --- a mapping never points to an object the valve lacks ---------------------------------------
def test_an_e02_valve_has_the_sensor_objects_and_the_pdo2_mappings_of_every_valve(rig: Rig):
    """Table 7-14: 0x2005-0x2008 and 0x2100 are objects of all valves; table 7-13's 0x1601 (one
    entry) and 0x1A01 (two) hold on every -CA valve, so on an E02 too."""
    rig.exchange("60A 40 01 1A 00 00 00 00 00", "58A 4F 01 1A 00 02 00 00 00")  # 2 entries
    rig.exchange("60A 40 01 1A 01 00 00 00 00", "58A 43 01 1A 01 10 01 00 21")  # 0x2100/1
    rig.exchange("60A 40 01 1A 02 00 00 00 00", "58A 43 01 1A 02 10 06 00 21")  # 0x2100/6
    rig.exchange("60A 40 01 16 00 00 00 00 00", "58A 4F 01 16 00 01 00 00 00")  # 1 entry
    rig.exchange("60A 40 01 16 01 00 00 00 00", "58A 43 01 16 01 10 02 00 21")  # 0x2100/2
    rig.exchange("60A 40 00 21 00 00 00 00 00", "58A 4F 00 21 00 06 00 00 00")  # 0x2100: 6 subs
    rig.exchange("60A 40 00 21 01 00 00 00 00", "58A 4B 00 21 01 00 00 00 00")  # no sensor: 0
    rig.exchange("60A 40 05 20 01 00 00 00 00", "58A 4B 05 20 01 09 00 00 00")  # type 9
    rig.exchange("60A 2F 08 20 00 01 00 00 00", "58A 60 08 20 00 00 00 00 00")  # lin. on: kept
    rig.exchange("60A 40 08 20 00 00 00 00 00", "58A 4F 08 20 00 01 00 00 00")
    rig.exchange("60A 40 01 18 01 00 00 00 00", "58A 43 01 18 01 8A 02 00 00")  # PDO2 exists


def test_with_the_external_sensor_pdo2_maps_it(request: pytest.FixtureRequest):
    rig = make_rig(request.node.name, E04)
    try:
        rig.exchange("60A 40 01 1A 00 00 00 00 00", "58A 4F 01 1A 00 02 00 00 00")
        rig.exchange("60A 40 01 1A 01 00 00 00 00", "58A 43 01 1A 01 10 01 00 21")
        rig.exchange("60A 40 01 1A 02 00 00 00 00", "58A 43 01 1A 02 10 06 00 21")
        rig.exchange("60A 40 01 16 01 00 00 00 00", "58A 43 01 16 01 10 02 00 21")
    finally:
        rig.close()

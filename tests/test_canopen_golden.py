"""Golden frames: the manual's CANopen examples (chapter 7), byte for byte, against the emulator.

Frames are written as in the manual: ``COB-ID data bytes`` in hex.
"""

from __future__ import annotations

import struct

import pytest
from canopen_rig import E02, E04, Rig, make_rig

from prm9tool.device.emulator import DeviceState


@pytest.fixture
def rig(request: pytest.FixtureRequest):
    rig = make_rig(request.node.name, E02, serial=200123)
    yield rig
    rig.close()


@pytest.fixture
def rig_e04(request: pytest.FixtureRequest):
    rig = make_rig(request.node.name, E04, serial=200123)
    yield rig
    rig.close()


def test_boot_up_message_after_power_on(request: pytest.FixtureRequest):
    rig = make_rig(request.node.name, E02, boot=False)
    try:
        rig.valve.advance(1.0)
        assert rig.drain() == []  # still initialising (boot-up "within about 5 s")
        rig.valve.advance(1.0)
        assert rig.drain() == ["70A 00"]
        assert rig.valve.status().nmt_state == "pre-operational"
    finally:
        rig.close()


def test_tables_7_8_and_7_9_read_serial_number(rig: Rig):
    # 200123 = 0x00030DBB, little-endian BB 0D 03 00 (the manual prints "BB 0D 30 00": a typo)
    rig.exchange("60A 40 18 10 04 00 00 00 00", "58A 43 18 10 04 BB 0D 03 00")


def test_tables_7_10_and_7_11_write_heartbeat_1000_ms(rig: Rig):
    rig.exchange("60A 2B 17 10 00 00 00 00 00", "58A 60 17 10 00 00 00 00 00")  # heartbeat off
    rig.valve.advance(3.0)
    assert rig.drain() == []
    rig.exchange("60A 2B 17 10 00 E8 03 00 00", "58A 60 17 10 00 00 00 00 00")
    rig.valve.advance(0.999)
    assert rig.drain() == []
    rig.valve.advance(0.002)
    assert rig.drain() == ["70A 7F"]  # pre-operational
    rig.valve.advance(2.0)
    assert rig.drain() == ["70A 7F", "70A 7F"]


def test_section_7_2_6_pdo_set_up(rig: Rig):
    rig.exchange("60A 23 00 14 01 0A 02 00 00", "58A 60 00 14 01 00 00 00 00")
    rig.exchange("60A 2F 00 14 02 FF 00 00 00", "58A 60 00 14 02 00 00 00 00")
    rig.exchange("60A 23 00 18 01 8A 01 00 00", "58A 60 00 18 01 00 00 00 00")
    rig.exchange("60A 2B 00 18 05 64 00 00 00", "58A 60 00 18 05 00 00 00 00")
    rig.exchange("60A 2B 17 10 00 00 00 00 00", "58A 60 17 10 00 00 00 00 00")
    rig.send("000 01 0A")
    assert rig.receive() == "18A 00 02 00 00"  # entering OPERATIONAL: INIT (0x0200), spool at 0
    rig.valve.advance(1.0)
    tpdos = rig.drain()
    assert len(tpdos) == 10  # "every 100 ms a message with COB-ID 18Ah"
    assert all(f.startswith("18A ") and len(bytes.fromhex(f[4:])) == 4 for f in tpdos)


def test_section_7_6_commissioning_sequence_node_0x0a(rig_e04: Rig):
    rig = rig_e04
    steps = [
        ("60A 40 18 10 01 00 00 00 00", "58A 43 18 10 01 E6 00 00 00"),  # vendor ID
        ("60A 23 14 10 00 8A 00 00 00", "58A 60 14 10 00 00 00 00 00"),  # EMCY COB-ID 08Ah
        ("60A 2B 17 10 00 E8 03 00 00", "58A 60 17 10 00 00 00 00 00"),  # heartbeat 1 s
        ("60A 23 00 14 01 0A 02 00 00", "58A 60 00 14 01 00 00 00 00"),  # RPDO1 COB-ID
        ("60A 2F 00 14 02 FF 00 00 00", "58A 60 00 14 02 00 00 00 00"),  # RPDO1 asynchronous
        ("60A 23 00 18 01 8A 01 00 00", "58A 60 00 18 01 00 00 00 00"),  # TPDO1 COB-ID
        ("60A 2B 00 18 05 64 00 00 00", "58A 60 00 18 05 00 00 00 00"),  # TPDO1 every 100 ms
        ("60A 23 01 14 01 0A 03 00 00", "58A 60 01 14 01 00 00 00 00"),  # RPDO2 COB-ID
        ("60A 2F 01 14 02 FF 00 00 00", "58A 60 01 14 02 00 00 00 00"),  # RPDO2 asynchronous
        ("60A 23 01 18 01 8A 02 00 00", "58A 60 01 18 01 00 00 00 00"),  # TPDO2 COB-ID
        ("60A 2F 01 18 02 FF 00 00 00", "58A 60 01 18 02 00 00 00 00"),  # TPDO2 asynchronous
        ("60A 2B 01 18 05 64 00 00 00", "58A 60 01 18 05 00 00 00 00"),  # TPDO2 every 100 ms
    ]
    for request, response in steps:
        rig.exchange(request, response)
    rig.send("000 01 00")  # the whole bus to OPERATIONAL
    first = [rig.receive(), rig.receive()]
    assert sorted(f[:3] for f in first if f) == ["18A", "28A"]
    rig.send("000 01 0A")  # only the valve: it is already OPERATIONAL, nothing changes
    assert rig.drain() == []
    assert rig.valve.status().nmt_state == "operational"
    rig.valve.advance(1.05)
    frames = rig.drain()
    assert [f[:3] for f in frames].count("18A") == 10
    assert [f[:3] for f in frames].count("28A") == 10
    assert "70A 05" in frames  # heartbeat: OPERATIONAL


def test_figure_7_13_state_machine_to_device_mode_active(rig: Rig):
    rig.send("000 01 0A")
    rig.barrier()
    rig.drain()
    expected = [
        (0x08, DeviceState.INIT),
        (0x09, DeviceState.DISABLED),
        (0x0B, DeviceState.HOLD),
        (0x0F, DeviceState.DEVICE_MODE_ACTIVE),
    ]
    for word, state in expected:
        rig.exchange(f"60A 2B 40 60 00 {word:02X} 00 00 00", "58A 60 40 60 00 00 00 00 00")
        assert rig.valve.device_state is state
        status = struct.unpack("<H", rig.sdo_read(0x6041, 0))[0]
        assert status >> 8 == list(DeviceState).index(state) + 1


def _operational_and_active(rig: Rig) -> None:
    rig.exchange("60A 2B 00 18 05 64 00 00 00", "58A 60 00 18 05 00 00 00 00")
    rig.send("000 01 0A")
    assert (rig.receive() or "").startswith("18A ")  # TPDO1 on entering OPERATIONAL
    for word in (0x08, 0x09, 0x0B, 0x0F):
        rig.exchange(f"60A 2B 40 60 00 {word:02X} 00 00 00", "58A 60 40 60 00 00 00 00 00")
    rig.drain()
    assert rig.valve.device_state is DeviceState.DEVICE_MODE_ACTIVE


@pytest.mark.parametrize(
    ("rpdo", "target"),
    [("20A 0F 00 40 1F 00 00 00 00", 8000), ("20A 0F 00 C0 E0 00 00 00 00", -8000)],
)
def test_figure_7_14_setpoint_plus_minus_50_percent_by_rpdo(rig: Rig, rpdo: str, target: int):
    _operational_and_active(rig)
    rig.send(rpdo)
    rig.barrier()
    assert rig.valve.read(0x6300, 1) == target
    rig.valve.advance(0.5)  # the spool moves
    position = rig.valve.read(0x6301, 1)
    assert position == pytest.approx(target, abs=0.03 * 16384)
    rig.drain()
    rig.valve.advance(0.1)
    tpdo = rig.drain()[-1]
    status, actual = struct.unpack("<Hh", bytes.fromhex(tpdo[4:]))
    assert tpdo.startswith("18A ")
    assert status == 0x0507  # DEVICE_MODE_ACTIVE, D H M confirmed
    assert actual == pytest.approx(target, abs=0.03 * 16384)
    assert actual == rig.valve.read(0x6301, 1)

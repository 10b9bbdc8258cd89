"""Golden frames: the manual's CANopen examples (chapter 7), byte for byte, against the emulator.

Frames are written as in the manual: ``COB-ID data bytes`` in hex.
"""

from __future__ import annotations

import re
import struct
from pathlib import Path

import pytest
from support.canopen_rig import E02, Rig, make_rig

from prm9tool.device.records import DeviceState

DOC = Path(__file__).resolve().parent.parent / "docs" / "canopen.md"
FRAME = re.compile(r"[0-9A-F]{3}( [0-9A-F]{2}){0,8}")  # "COB-ID data bytes" as the manual writes
# TPDO2 of an E02 -CA: table 7-13 maps the external sensor 0x2100/1 and /6 on every -CA valve;
# the E02 has no sensor input, so both read 0 (decision, docs/canopen.md)
TPDO2_E02 = "28A 00 00 00 00"
TESTED_ELSEWHERE = {  # walkthrough frames outside the §7.6 sequence: tests in test_canopen_slave.py
    "60A 23 10 10 01 73 61 76 65": "test_store_and_restore_use_the_cia_301_signatures",
    "60A 23 11 10 01 6C 6F 61 64": "test_store_and_restore_use_the_cia_301_signatures",
    "60A 2F 43 60 00 02 00 00 00": "test_mapping_follows_the_control_mode",
}


@pytest.fixture
def rig(request: pytest.FixtureRequest):
    rig = make_rig(request.node.name, E02, serial=200123)
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
    assert rig.receive() == "18A 08 00 00 00"  # entering OPERATIONAL: INIT (0x0008), spool at 0
    assert rig.receive() == TPDO2_E02  # TPDO2 by its defaults (table 7-13): at once, then 5 s
    rig.valve.advance(1.0)
    tpdos = [f for f in rig.drain() if f.startswith("18A ")]
    assert len(tpdos) == 10  # "every 100 ms a message with COB-ID 18Ah"
    assert all(len(bytes.fromhex(f[4:])) == 4 for f in tpdos)
    assert rig.log.count(TPDO2_E02) == 1  # 0x1801/5 = 1388h: the next one after 5000 ms
    rig.valve.advance(4.0)
    assert rig.drain().count(TPDO2_E02) == 1


CONFIGURATION = [  # §7.6 "Příklad konfigurace s Node ID Ah", answered in full on every -CA valve
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
ENABLE = [  # figure 7-13: control word R, D, H, M in turn; TPDO1 = status word + position
    (0x08, "18A 08 00 00 00"),  # INIT: outputs off, the spool rests at 0
    (0x09, "18A 09 00 00 00"),  # DISABLED
    # HOLD and DEVICE_MODE_ACTIVE control the spool at 0 with the dither on the coils: it
    # moves ±0.37 % at 80 Hz, and every 100 ms (8 dither periods) TPDO1 samples it at −40
    # (−0.24 %; the manual's figure shows 0, a valve without dither)
    (0x0B, "18A 0B 00 D8 FF"),  # HOLD
    (0x0F, "18A 0F 00 D8 FF"),  # DEVICE_MODE_ACTIVE
]
SETPOINTS = [("20A 0F 00 40 1F 00 00 00 00", 8000), ("20A 0F 00 C0 E0 00 00 00 00", -8000)]


def _commission(rig: Rig) -> None:
    """§7.6 on an E02 -CA valve (as the manual), node 0x0A: configuration, NMT start, figure
    7-13, figure 7-14. Simulated time: TPDO1 and TPDO2 every 100 ms, heartbeat every 1000 ms.
    TPDO2 carries the external sensor 0x2100/1 and /6 (table 7-13), which read 0 on an E02."""
    for request, response in CONFIGURATION:
        rig.exchange(request, response)
    rig.send("000 01 00")  # the whole bus to OPERATIONAL
    rig.expect("18A 08 00 00 00")  # TPDO1 at once: INIT, spool at 0
    rig.expect(TPDO2_E02)  # TPDO2 at once: external sensor raw and linearized, 0 on an E02
    rig.send("000 01 0A")  # only the valve: it is already OPERATIONAL, nothing changes
    rig.barrier()
    assert rig.drain() == []
    rig.valve.advance(1.05)
    frames = rig.drain()
    # heartbeat: OPERATIONAL
    assert sorted(frames) == ["18A 08 00 00 00"] * 10 + [TPDO2_E02] * 10 + ["70A 05"]
    for word, tpdo in ENABLE:
        rig.exchange(f"60A 2B 40 60 00 {word:02X} 00 00 00", "58A 60 40 60 00 00 00 00 00")
        rig.valve.advance(0.1)
        assert rig.drain() == [tpdo, TPDO2_E02]
    assert rig.valve.device_state is DeviceState.DEVICE_MODE_ACTIVE
    for rpdo, target in SETPOINTS:
        rig.send(rpdo)
        rig.barrier()
        assert rig.valve.read(0x6300, 1) == target
        rig.valve.advance(0.5)
        frames = rig.drain()
        assert frames.count(TPDO2_E02) == 5  # the sensor stays 0 while the spool moves
        tpdos = [f for f in frames if f.startswith("18A ")]
        assert len(tpdos) == 5 and all(f.startswith("18A 0F 00 ") for f in tpdos)  # active
        actual = struct.unpack("<h", bytes.fromhex(tpdos[-1][10:]))[0]
        assert actual == rig.valve.read(0x6301, 1) == pytest.approx(target, abs=0.02 * 16384)


def test_section_7_6_commissioning_sequence_node_0x0a(rig: Rig):
    _commission(rig)
    assert {f[:3] for f in rig.log} == {"000", "20A", "60A", "58A", "18A", "28A", "70A"}
    assert {f for f in rig.log if f.startswith("28A")} == {TPDO2_E02}


def _walkthrough_frames() -> list[str]:
    """Every frame docs/canopen.md's commissioning walkthrough shows (inline or in a block)."""
    text = DOC.read_text(encoding="utf-8")
    section = text.split("## Commissioning walkthrough")[1].split("\n## ")[0]
    pieces = re.findall(r"`([^`]+)`", section)
    pieces += [
        p
        for line in section.splitlines()
        if line.startswith("       ")
        for p in re.split(r"\s{2,}|→", line)
    ]
    return [p.strip() for p in pieces if FRAME.fullmatch(p.strip())]


def test_the_walkthrough_in_the_docs_shows_what_the_valve_sends(rig: Rig):
    shown = _walkthrough_frames()
    assert len(shown) > 20
    _commission(rig)
    missing = [f for f in shown if f not in rig.log and f not in TESTED_ELSEWHERE]
    assert missing == [], "docs/canopen.md shows frames the §7.6 sequence does not produce"


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
        assert status == word  # CiA 408: R M H D of the state, here equal to the command

"""CiA 301 behaviour of the emulated valve's CANopen slave beyond the manual's worked examples."""

from __future__ import annotations

import struct

import can
import pytest
from support.canopen_rig import E02, E04, Rig, make_rig, unique_channel

from prm9tool.device.emulator import EmulatedValve, Fault
from prm9tool.device.records import DeviceState
from prm9tool.errors import AccessDeniedError


@pytest.fixture
def rig(request: pytest.FixtureRequest):
    rig = make_rig(request.node.name, E02)
    yield rig
    rig.close()


@pytest.fixture
def rig_e04(request: pytest.FixtureRequest):
    rig = make_rig(request.node.name, E04)
    yield rig
    rig.close()


def _start(rig: Rig) -> list[str]:
    rig.send("000 01 0A")
    rig.barrier()
    return rig.drain()


def _without_tpdo2(frames: list[str]) -> list[str]:
    """The frames but TPDO2 (0x28A): every -CA valve sends it by its defaults (table 7-13),
    at once when OPERATIONAL and then every 5000 ms; tests about other objects leave it out."""
    return [f for f in frames if not f.startswith("28A")]


# --- NMT and service availability (table 7-4) -------------------------------------------------
def test_pre_operational_answers_sdo_but_ignores_rpdo_and_sends_no_tpdo(rig: Rig):
    rig.send("20A 0F 00 40 1F 00 00 00 00")
    rig.barrier()
    assert rig.valve.read(0x6300, 1) == 0
    rig.valve.advance(0.5)
    assert rig.drain() == []


def test_stopped_answers_only_nmt(rig: Rig):
    rig.send("000 02 0A")
    rig.wait_for_nmt_state("stopped")
    rig.send("60A 40 00 10 00 00 00 00 00")
    assert rig.receive(0.3) is None  # no SDO while STOPPED
    rig.valve.advance(1.0)
    assert rig.drain() == ["70A 04"]
    rig.send("000 80 00")  # broadcast: back to PRE-OPERATIONAL
    rig.exchange("60A 40 00 10 00 00 00 00 00", "58A 43 00 10 00 98 01 00 00")


def test_nmt_for_another_node_is_ignored(rig: Rig):
    rig.send("000 01 0B")
    rig.barrier()
    assert rig.valve.status().nmt_state == "pre-operational"


def test_heartbeat_reports_each_nmt_state(rig: Rig):
    states = []
    for command, code, state in (
        ("01", "05", "operational"),
        ("02", "04", "stopped"),
        ("80", "7F", "pre-operational"),
    ):
        rig.send(f"000 {command} 0A")
        rig.wait_for_nmt_state(state)
        rig.drain()
        rig.valve.advance(1.0)
        states.append((code, [f for f in rig.drain() if f.startswith("70A")]))
    assert all(frames == [f"70A {code}"] for code, frames in states)


def test_stop_in_device_mode_active_is_a_fault_reaction(rig: Rig):
    _start(rig)
    rig.exchange("60A 2B 40 60 00 0F 00 00 00", "58A 60 40 60 00 00 00 00 00")
    assert rig.valve.device_state is DeviceState.DEVICE_MODE_ACTIVE
    rig.send("000 02 0A")  # table 7-21: C5/C8 -> FAULT_REACTION
    rig.wait_for_nmt_state("stopped")
    assert rig.valve.device_state is DeviceState.FAULT_REACTION


def test_reset_node_boots_again_with_stored_values(rig: Rig):
    rig.exchange("60A 2B 17 10 00 F4 01 00 00", "58A 60 17 10 00 00 00 00 00")  # 500 ms, unsaved
    rig.send("000 81 0A")
    rig.wait_for_nmt_state("initialising")
    assert rig.receive(0.3) is None  # initialising: nothing yet
    rig.valve.advance(2.0)
    assert rig.drain() == ["70A 00"]
    assert rig.valve.read(0x1017, 0) == 1000


def test_reset_communication_reloads_only_communication_objects(rig: Rig):
    rig.exchange("60A 2B 17 10 00 F4 01 00 00", "58A 60 17 10 00 00 00 00 00")
    rig.exchange("60A 2B 45 63 01 00 08 00 00", "58A 60 45 63 01 00 00 00 00")  # threshold
    rig.send("000 82 0A")
    rig.expect("70A 00")  # boot-up at once: the device does not restart
    assert rig.valve.read(0x1017, 0) == 1000
    assert rig.valve.read(0x6345, 1) == 0x800


def test_nmt_startup_0_goes_operational_by_itself(tmp_path, request: pytest.FixtureRequest):
    rig = make_rig(request.node.name, E02, nv_path=tmp_path / "nv.json")
    try:
        rig.exchange("60A 23 80 1F 00 00 00 00 00", "58A 60 80 1F 00 00 00 00 00")
        rig.exchange("60A 23 10 10 01 73 61 76 65", "58A 60 10 10 01 00 00 00 00")
        rig.valve.restart()
        rig.valve.advance(2.0)
        # boot-up, then OPERATIONAL: TPDO1 and TPDO2 at once (E02: the sensor objects read 0)
        assert rig.drain() == ["70A 00", "18A 08 00 00 00", "28A 00 00 00 00"]
        assert rig.valve.status().nmt_state == "operational"
    finally:
        rig.close()


# --- store 0x1010 / restore 0x1011 -----------------------------------------------------------
def test_store_and_restore_use_the_cia_301_signatures(tmp_path, request: pytest.FixtureRequest):
    nv = tmp_path / "nv.json"
    rig = make_rig(request.node.name, E02, nv_path=nv)
    try:
        rig.exchange("60A 2B 17 10 00 FA 00 00 00", "58A 60 17 10 00 00 00 00 00")
        rig.exchange("60A 23 10 10 01 73 61 76 66", "58A 80 10 10 01 20 00 00 08")  # not "save"
        rig.exchange("60A 23 10 10 01 73 61 76 65", "58A 60 10 10 01 00 00 00 00")  # "save"
    finally:
        rig.close()
    rig = make_rig(request.node.name, E02, nv_path=nv)  # another power-up from the same EEPROM
    try:
        assert rig.valve.read(0x1017, 0) == 250
        rig.exchange("60A 23 11 10 01 6C 6F 61 64", "58A 60 11 10 01 00 00 00 00")  # "load"
        assert rig.valve.read(0x1017, 0) == 250  # effective after the reset only
        rig.send("000 81 0A")
        rig.wait_for_nmt_state("initialising")
        rig.valve.advance(2.0)
        assert rig.drain() == ["70A 00"]
        assert rig.valve.read(0x1017, 0) == 1000
    finally:
        rig.close()


# --- EMCY ---------------------------------------------------------------------------------------
def test_emcy_on_fault_history_and_zero_emcy_when_cleared(rig: Rig):
    rig.exchange("60A 2B 17 10 00 00 00 00 00", "58A 60 17 10 00 00 00 00 00")
    rig.valve.inject(Fault.COIL_A_OPEN)
    rig.valve.advance(0.1)
    assert rig.drain() == ["08A 11 54 03 00 00 00 00 00"]  # 5411h, register: generic + current
    rig.exchange("60A 40 01 10 00 00 00 00 00", "58A 4F 01 10 00 03 00 00 00")
    rig.exchange("60A 40 03 10 00 00 00 00 00", "58A 4F 03 10 00 01 00 00 00")
    rig.exchange("60A 40 03 10 01 00 00 00 00", "58A 43 03 10 01 11 54 00 00")
    rig.valve.clear(Fault.COIL_A_OPEN)
    rig.valve.advance(11.0)  # the error stays shown ~10 s after it went away (§5.5)
    assert rig.drain() == ["08A 00 00 00 00 00 00 00 00"]
    rig.exchange("60A 2F 03 10 00 00 00 00 00", "58A 60 03 10 00 00 00 00 00")  # clear history
    rig.exchange("60A 40 03 10 00 00 00 00 00", "58A 4F 03 10 00 00 00 00 00")


@pytest.mark.parametrize("case", ["stopped", "invalid"])
def test_no_emcy_while_stopped_and_none_when_invalid(rig: Rig, case: str):
    rig.exchange("60A 2B 17 10 00 00 00 00 00", "58A 60 17 10 00 00 00 00 00")  # no heartbeat
    if case == "stopped":
        rig.send("000 02 0A")  # table 7-4: no EMCY while STOPPED
        rig.wait_for_nmt_state("stopped")
    else:
        rig.exchange("60A 23 14 10 00 8A 00 00 80", "58A 60 14 10 00 00 00 00 00")  # bit 31
    rig.valve.inject(Fault.COIL_A_OPEN)
    rig.valve.advance(0.1)
    assert rig.valve.status().error_code == 0x5411  # the error is there, only not sent
    assert rig.drain() == []


# --- PDO communication parameters -----------------------------------------------------------
def test_sdo_requests_keep_the_setpoint_override_alive_as_usb_reports_do(rig: Rig):
    """Over CAN the scope's generator keeps SETPOVR written; the override used to drop after
    500 ms (only a USB report fed its watchdog) and the spool stopped following."""
    _start(rig)
    rig.send("60A 2F 50 20 01 01 00 00 00")  # SETPOVRON = 1
    rig.barrier()
    assert rig.valve.read(0x2050, 1) == 1
    for _ in range(10):
        rig.valve.advance(0.1)
        rig.barrier()  # one SDO request (a read of 0x1000) every 100 ms
    assert rig.valve.read(0x2050, 1) == 1
    rig.valve.advance(0.6)  # the master went silent
    assert rig.valve.read(0x2050, 1) == 0


def test_cob_id_writable_only_outside_operational(rig: Rig):
    _start(rig)
    rig.exchange("60A 23 00 18 01 91 01 00 00", "58A 80 00 18 01 22 00 00 08")
    rig.send("000 80 0A")
    rig.exchange("60A 23 00 18 01 91 01 00 00", "58A 60 00 18 01 00 00 00 00")
    rig.exchange("60A 23 00 18 01 81 05 00 00", "58A 80 00 18 01 30 00 09 06")  # SDO's ID
    rig.exchange("60A 23 00 18 01 91 01 00 20", "58A 80 00 18 01 30 00 09 06")  # 29 bit
    rig.exchange("60A 2F 00 18 02 F1 00 00 00", "58A 80 00 18 02 30 00 09 06")  # type 241
    assert {f[:3] for f in _without_tpdo2(_start(rig))} == {"191"}


def test_invalid_bit_silences_a_tpdo(rig: Rig):
    rig.exchange("60A 23 00 18 01 8A 01 00 80", "58A 60 00 18 01 00 00 00 00")
    rig.exchange("60A 2B 00 18 05 0A 00 00 00", "58A 60 00 18 05 00 00 00 00")
    _start(rig)
    rig.valve.advance(0.1)
    assert [f for f in rig.drain() if f.startswith("18A")] == []


def test_tpdo_every_second_sync_and_acyclic_on_change(rig: Rig):
    rig.exchange("60A 2F 00 18 02 02 00 00 00", "58A 60 00 18 02 00 00 00 00")
    rig.exchange("60A 2B 17 10 00 00 00 00 00", "58A 60 17 10 00 00 00 00 00")
    assert _without_tpdo2(_start(rig)) == []
    answers = []
    for _ in range(4):
        rig.send("080")
        rig.barrier()
        answers.append(len(_without_tpdo2(rig.drain())))
    assert answers == [0, 1, 0, 1]
    rig.send("000 80 0A")
    rig.exchange("60A 2F 00 18 02 00 00 00 00", "58A 60 00 18 02 00 00 00 00")
    _start(rig)
    sent = []
    for word in (None, None, 0x0F, None):
        if word is not None:
            rig.exchange(f"60A 2B 40 60 00 {word:02X} 00 00 00", "58A 60 40 60 00 00 00 00 00")
        rig.send("080")
        rig.barrier()
        sent.append(len(_without_tpdo2(rig.drain())))
    assert sent == [1, 0, 1, 0]  # type 0: after a SYNC, only when the data changed


def test_synchronous_rpdo_takes_effect_at_the_next_sync(rig: Rig):
    rig.exchange("60A 2F 00 14 02 01 00 00 00", "58A 60 00 14 02 00 00 00 00")
    _start(rig)
    rig.send("20A 0F 00 40 1F 00 00 00 00")
    rig.barrier()
    assert rig.valve.read(0x6300, 1) == 0
    rig.send("080")
    rig.barrier()
    assert rig.valve.read(0x6300, 1) == 8000


def test_short_rpdo_is_refused_with_emcy_8210(rig: Rig):
    _start(rig)
    rig.send("20A 0F 00 40")
    rig.barrier()
    assert rig.drain() == ["08A 10 82 11 00 00 00 00 00"]  # 0x1001: generic + communication
    assert rig.valve.read(0x6300, 1) == 0


def test_sync_timeout_is_a_communication_error(rig: Rig):
    rig.exchange("60A 23 06 10 00 10 27 00 00", "58A 60 06 10 00 00 00 00 00")  # 10 ms
    rig.exchange("60A 2B 17 10 00 00 00 00 00", "58A 60 17 10 00 00 00 00 00")
    _start(rig)
    rig.send("080")
    rig.barrier()
    rig.valve.advance(0.014)
    assert rig.drain() == []
    rig.valve.advance(0.002)
    assert rig.drain() == ["08A 00 81 11 00 00 00 00 00"]  # 8100h, register: communication
    assert rig.valve.status().leds[1].pattern == "triple_flash"  # table 7-18: SYNC error
    rig.send("000 01 0A")  # the master starts the node again: the error goes (after ~10 s)
    rig.barrier()
    rig.valve.advance(11.0)
    assert [f for f in rig.drain() if f.startswith("08A")] == ["08A 00 00 00 00 00 00 00 00"]


def test_rpdo_event_timer_is_a_reception_deadline(rig: Rig):
    rig.exchange("60A 2B 00 14 05 64 00 00 00", "58A 60 00 14 05 00 00 00 00")  # 100 ms
    rig.exchange("60A 2B 17 10 00 00 00 00 00", "58A 60 17 10 00 00 00 00 00")
    rig.exchange("60A 23 00 18 01 8A 01 00 80", "58A 60 00 18 01 00 00 00 00")  # no TPDO1
    _start(rig)
    rig.valve.advance(1.0)
    assert (
        _without_tpdo2(rig.drain()) == []
    )  # CiA 301: the deadline is armed by the first reception
    for _ in range(3):
        rig.send("20A 08 00 00 00 00 00 00 00")
        rig.barrier()
        rig.valve.advance(0.1)
    assert _without_tpdo2(rig.drain()) == []
    rig.valve.advance(0.002)
    assert _without_tpdo2(rig.drain()) == [
        "08A 00 81 11 00 00 00 00 00"
    ]  # 8100h, register: communication
    assert rig.valve.status().leds[1].pattern == "quadruple_flash"  # table 7-18: event timer
    rig.valve.advance(1.0)
    assert _without_tpdo2(rig.drain()) == []  # one event per loss
    rig.send("000 01 0A")  # the master starts the node again: the error goes (after ~10 s)
    rig.barrier()
    rig.valve.advance(11.0)
    assert _without_tpdo2(rig.drain()) == ["08A 00 00 00 00 00 00 00 00"]


def test_error_present_at_power_up_is_announced_after_boot_up(request: pytest.FixtureRequest):
    rig = make_rig(request.node.name, E02, boot=False)
    try:
        rig.valve.inject(Fault.POSITION_SENSOR_BREAK)
        rig.valve.advance(2.0)
        assert rig.drain() == ["70A 00", "08A 00 73 81 00 00 00 00 00"]
    finally:
        rig.close()


# --- control mode, external sensor (E04) and the TPDO2 decision --------------------------------
def test_mapping_follows_the_control_mode(rig_e04: Rig):
    rig = rig_e04
    rig.exchange("60A 40 00 16 02 00 00 00 00", "58A 43 00 16 02 10 01 80 63")
    rig.exchange("60A 40 00 1A 02 00 00 00 00", "58A 43 00 1A 02 10 01 81 63")
    rig.exchange("60A 2F 43 60 00 02 00 00 00", "58A 60 43 60 00 00 00 00 00")
    rig.exchange("60A 40 00 16 02 00 00 00 00", "58A 43 00 16 02 10 01 00 63")
    rig.exchange("60A 2F 43 60 00 04 00 00 00", "58A 60 43 60 00 00 00 00 00")
    _start(rig)
    rig.send("20A 0F 00 00 F0 00 00 00 00")
    rig.barrier()
    assert rig.valve.read(0x6380, 1) == -4096


def test_tpdo2_carries_the_sensor_after_linearization(rig_e04: Rig):
    rig = rig_e04
    valve = rig.valve
    valve.set_input("sensor_from_plant", 0)
    valve.set_input("sensor", 5.0)  # +50 % on the default ±10 V input
    for sub, y in ((6, 12288), (7, 14000)):  # bend the curve: YF/YG above the diagonal
        valve.write(0x2007, sub, y)
    valve.write(0x2008, 0, 1)
    rig.exchange("60A 2B 01 18 05 0A 00 00 00", "58A 60 01 18 05 00 00 00 00")
    _start(rig)
    valve.advance(0.05)
    tpdo2 = [f for f in rig.drain() if f.startswith("28A")][-1]
    raw, linearized = struct.unpack("<hh", bytes.fromhex(tpdo2[4:]))
    assert raw == valve.read(0x2100, 1)
    assert linearized == valve.read(0x2100, 6) != valve.read(0x2100, 5)


def test_rpdo2_carries_the_external_sensor_value_over_can(rig_e04: Rig):
    rig = rig_e04
    rig.exchange("60A 2B 05 20 01 0E 00 00 00", "58A 60 05 20 01 00 00 00 00")  # SENSTYPE 14
    rig.exchange("60A 2B 01 18 05 0A 00 00 00", "58A 60 01 18 05 00 00 00 00")  # TPDO2 10 ms
    assert _start(rig) == ["18A 08 00 00 00", "28A 00 00 00 00"]
    rig.send("30A 60 F0")  # RPDO2 (default COB-ID 0x300 + node): 0x2100/2 = 0xF060 = -4000
    rig.barrier()
    rig.valve.advance(0.01)  # the sensor chain takes it in the next 1 ms cycle
    assert (rig.valve.read(0x2100, 1), rig.valve.read(0x2100, 6)) == (-4000, -4000)
    assert "28A 60 F0 60 F0" in rig.drain()  # TPDO2: raw and linearized value


def test_an_e02_valve_sends_tpdo2_with_its_sensor_objects_at_0(rig: Rig):
    """Table 7-13's TPDO2 holds on every -CA valve; the E02 has no external sensor input, so
    0x2100/1 and /6 read 0 whatever the sensor set-up (decision, docs/canopen.md)."""
    rig.exchange("60A 2B 01 18 05 0A 00 00 00", "58A 60 01 18 05 00 00 00 00")  # TPDO2 10 ms
    rig.exchange("60A 2B 05 20 03 00 10 00 00", "58A 60 05 20 03 00 00 00 00")  # offset 25 %
    assert _start(rig) == ["18A 08 00 00 00", "28A 00 00 00 00"]
    rig.valve.advance(0.1)
    tpdo2 = [f for f in rig.drain() if f.startswith("28A")]
    assert tpdo2 == ["28A 00 00 00 00"] * 10


def test_rpdo2_on_an_e02_valve_is_taken_without_effect(rig: Rig):
    rig.exchange("60A 2B 05 20 01 0E 00 00 00", "58A 60 05 20 01 00 00 00 00")  # SENSTYPE 14
    _start(rig)
    rig.send("30A 60 F0")  # RPDO2: 0x2100/2 = -4000; the E02 has no sensor chain to feed
    rig.barrier()
    rig.valve.advance(0.01)
    assert rig.drain() == []  # no EMCY: a frame of the mapped length is accepted
    assert [rig.valve.read(0x2100, sub) for sub in (1, 3, 4, 5, 6)] == [0] * 5
    assert rig.valve.read(0x6301, 1) == 0  # nor does the spool move


# --- SDO protocol ---------------------------------------------------------------------------
def test_segmented_upload_of_the_type_key(rig: Rig):
    rig.exchange("60A 40 41 20 00 00 00 00 00", "58A 41 41 20 00 1B 00 00 00")
    rig.exchange("60A 60 00 00 00 00 00 00 00", "58A 00 50 52 4D 39 2D 30 36")  # PRM9-06
    rig.exchange("60A 70 00 00 00 00 00 00 00", "58A 10 2E 33 5A 31 31 2F 33")  # .3Z11/3
    rig.exchange("60A 60 00 00 00 00 00 00 00", "58A 00 30 2D 32 34 45 30 32")  # 0-24E02
    rig.exchange("60A 70 00 00 00 00 00 00 00", "58A 13 53 30 32 2D 43 41 00")  # S02-CA, last


def test_device_name_and_versions(rig: Rig):
    rig.exchange("60A 40 08 10 00 00 00 00 00", "58A 43 08 10 00 50 52 4D 39")  # "PRM9"
    rig.exchange("60A 40 09 10 00 00 00 00 00", "58A 43 09 10 00 31 2E 30 30")  # "1.00"
    rig.exchange("60A 40 0A 10 00 00 00 00 00", "58A 41 0A 10 00 05 00 00 00")  # "1.0.0"
    rig.exchange("60A 60 00 00 00 00 00 00 00", "58A 05 31 2E 30 2E 30 00 00")


def test_segmented_download_and_toggle_error(rig: Rig):
    rig.exchange("60A 21 17 10 00 02 00 00 00", "58A 60 17 10 00 00 00 00 00")
    rig.exchange("60A 0B E8 03 00 00 00 00 00", "58A 20 00 00 00 00 00 00 00")
    rig.exchange("60A 21 17 10 00 02 00 00 00", "58A 60 17 10 00 00 00 00 00")
    rig.exchange("60A 1B E8 03 00 00 00 00 00", "58A 80 17 10 00 00 00 03 05")


def test_expedited_download_without_size_takes_the_objects_own_length(rig: Rig):
    # CiA 301 e = 1, s = 0 ("22"): the data length is not given; the rest is padding
    rig.exchange("60A 22 17 10 00 F4 01 AA 55", "58A 60 17 10 00 00 00 00 00")
    assert rig.valve.read(0x1017, 0) == 500
    rig.exchange("60A 22 00 14 02 FE 12 34 56", "58A 60 00 14 02 00 00 00 00")
    assert rig.valve.read(0x1400, 2) == 254
    rig.exchange("60A 22 00 18 01 8B 01 00 00", "58A 60 00 18 01 00 00 00 00")  # U32: all 4
    assert rig.valve.read(0x1800, 1) == 0x18B


def test_stalled_segmented_upload_is_aborted_after_one_second(rig: Rig):
    rig.exchange("60A 40 41 20 00 00 00 00 00", "58A 41 41 20 00 1B 00 00 00")
    rig.exchange("60A 60 00 00 00 00 00 00 00", "58A 00 50 52 4D 39 2D 30 36")
    rig.valve.advance(0.9)  # simulated time: the client is quiet
    assert [f for f in rig.drain() if f.startswith("58A")] == []
    rig.valve.advance(0.2)
    assert [f for f in rig.drain() if f.startswith("58A")] == ["58A 80 41 20 00 00 00 04 05"]
    rig.exchange("60A 70 00 00 00 00 00 00 00", "58A 80 00 00 00 01 00 04 05")  # gone


def test_stalled_segmented_download_is_aborted_and_writes_nothing(rig: Rig):
    before = rig.valve.read(0x1017, 0)
    rig.exchange("60A 21 17 10 00 02 00 00 00", "58A 60 17 10 00 00 00 00 00")
    rig.valve.advance(1.1)
    assert [f for f in rig.drain() if f.startswith("58A")] == ["58A 80 17 10 00 00 00 04 05"]
    rig.exchange("60A 0B F4 01 00 00 00 00 00", "58A 80 00 00 00 01 00 04 05")
    assert rig.valve.read(0x1017, 0) == before != 500


def test_a_segmented_transfer_that_keeps_talking_does_not_time_out(rig: Rig):
    rig.exchange("60A 40 41 20 00 00 00 00 00", "58A 41 41 20 00 1B 00 00 00")
    rig.valve.advance(0.8)
    assert [f for f in rig.drain() if f.startswith("58A")] == []
    rig.exchange("60A 60 00 00 00 00 00 00 00", "58A 00 50 52 4D 39 2D 30 36")
    rig.valve.advance(0.8)  # 1.6 s since the start, 0.8 s since the last segment
    assert [f for f in rig.drain() if f.startswith("58A")] == []
    rig.exchange("60A 70 00 00 00 00 00 00 00", "58A 10 2E 33 5A 31 31 2F 33")


@pytest.mark.parametrize(
    ("request_frame", "abort"),
    [
        ("60A 40 34 12 00 00 00 00 00", "80 34 12 00 00 00 02 06"),  # no such object
        ("60A 40 18 10 09 00 00 00 00", "80 18 10 09 11 00 09 06"),  # no such sub-index
        ("60A 23 00 10 00 00 00 00 00", "80 00 10 00 02 00 01 06"),  # read-only
        ("60A 23 17 10 00 E8 03 00 00", "80 17 10 00 12 00 07 06"),  # 4 bytes into U16
        ("60A 2B 45 63 01 01 40 00 00", "80 45 63 01 31 00 09 06"),  # 16385 > 100 %
        ("60A 2F 03 10 00 01 00 00 00", "80 03 10 00 30 00 09 06"),  # 0x1003/0: only 0
        ("60A C0 18 10 04 00 00 00 00", "80 18 10 04 01 00 04 05"),  # block upload
        ("60A 60 00 00 00 00 00 00 00", "80 00 00 00 01 00 04 05"),  # segment, no transfer
    ],
)
def test_abort_codes(rig: Rig, request_frame: str, abort: str):
    rig.exchange(request_frame, f"58A {abort}")


# --- switches ---------------------------------------------------------------------------------
def test_interface_switch_0_means_no_canopen(request: pytest.FixtureRequest):
    rig = make_rig(request.node.name, E02, boot=False, switches=(0, 2))
    try:
        rig.valve.advance(2.0)
        rig.send("60A 40 00 10 00 00 00 00 00")
        assert rig.receive(0.3) is None
        assert rig.valve.status().nmt_state == "off"
    finally:
        rig.close()


def test_switches_are_read_at_power_up_only(tmp_path, request: pytest.FixtureRequest):
    rig = make_rig(request.node.name, E02, switches=(9, 3))  # 20 k + terminator, node 15
    try:
        assert (rig.slave.node_id, rig.slave.bitrate) == (15, 20_000)
        rig.valve.set_input("switch_node", 0)  # node ID from 0x2030/1 ...
        rig.exchange("60F 2F 30 20 01 20 00 00 00", "58F 60 30 20 01 00 00 00 00")
        rig.exchange("60F 2F 30 20 02 03 00 00 00", "58F 60 30 20 02 00 00 00 00")  # 250 k
        rig.exchange("60F 23 10 10 01 73 61 76 65", "58F 60 10 10 01 00 00 00 00")  # "save"
        rig.valve.restart()  # ... once the valve is powered up again
        rig.valve.advance(2.0)
        assert rig.drain() == ["720 00"]
        assert (rig.slave.node_id, rig.slave.bitrate) == (0x20, 250_000)
    finally:
        rig.close()


def test_valve_without_ca_has_no_can():
    valve = EmulatedValve("PRM9-06.3Z11/30-24E02S02")
    bus = can.Bus(interface="virtual", channel=unique_channel("noca"))
    try:
        with pytest.raises(AccessDeniedError, match="no CANopen interface"):
            valve.connect_can(bus)
    finally:
        bus.shutdown()


def test_paced_valve_sends_heartbeats_in_real_time(rig: Rig):
    rig.exchange("60A 2B 17 10 00 14 00 00 00", "58A 60 17 10 00 00 00 00 00")  # 20 ms
    rig.valve.start()
    try:
        assert [rig.receive(), rig.receive()] == ["70A 7F", "70A 7F"]
    finally:
        rig.valve.stop()


def test_pdo_parameters_written_over_usb_take_effect(rig: Rig):
    rig.exchange("60A 2B 17 10 00 00 00 00 00", "58A 60 17 10 00 00 00 00 00")
    _start(rig)
    rig.valve.write(0x1800, 5, 20)  # event timer 20 ms, as the USB firmware would write it
    rig.valve.advance(0.2)
    assert 9 <= len([f for f in rig.drain() if f.startswith("18A")]) <= 10


def test_save_of_a_set_the_catalogue_rejects_is_refused(rig: Rig):
    rig.exchange("60A 2B 00 20 01 10 27 00 00", "58A 60 00 20 01 00 00 00 00")  # SETPLINXA
    rig.exchange("60A 23 10 10 01 73 61 76 65", "58A 80 10 10 01 20 00 00 08")  # 0x08000020

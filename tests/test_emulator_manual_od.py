"""``--od manual``: the emulated valve answers over CANopen exactly the objects the manual's
tables 7-13, 7-14 and 7-16 list, and keeps what is written (§7.2.2, no 0x1010/0x1011).

Frames in the manual's notation (``COB-ID data bytes``, hex).
"""

from __future__ import annotations

import pytest
from support.canopen_rig import E02, E04, Rig, make_rig

from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.manual_od import MANUAL_OBJECTS, in_manual
from prm9tool.cli.main import main
from prm9tool.device import emulated_valves


@pytest.fixture
def manual(request: pytest.FixtureRequest, tmp_path):
    rig = make_rig(request.node.name, E04, nv_path=tmp_path / "nv.json", od="manual")
    yield rig
    rig.close()


@pytest.mark.parametrize(
    ("request_frame", "answer"),
    [
        ("60A 40 10 10 01 00 00 00 00", "58A 80 10 10 01 00 00 02 06"),  # no store command
        ("60A 40 11 10 01 00 00 00 00", "58A 80 11 10 01 00 00 02 06"),  # no restore command
        ("60A 40 41 20 00 00 00 00 00", "58A 80 41 20 00 00 00 02 06"),  # no type key object
        ("60A 40 20 20 01 00 00 00 00", "58A 80 20 20 01 00 00 02 06"),  # no controller gains
        ("60A 40 50 20 01 00 00 00 00", "58A 80 50 20 01 00 00 02 06"),  # no setpoint override
        ("60A 40 00 14 05 00 00 00 00", "58A 80 00 14 05 11 00 09 06"),  # no RPDO event timer
        ("60A 40 00 14 00 00 00 00 00", "58A 4F 00 14 00 02 00 00 00"),  # RPDO1: subs 0…2
        ("60A 40 00 18 00 00 00 00 00", "58A 4F 00 18 00 05 00 00 00"),  # TPDO1: 0…2, 5
        ("60A 40 18 10 01 00 00 00 00", "58A 43 18 10 01 E6 00 00 00"),  # what it lists: yes
        ("60A 40 04 20 01 00 00 00 00", "58A 4B 04 20 01 28 0A 00 00"),  # CURNORM 2600 mA
    ],
)
def test_the_manual_valve_answers_only_what_the_tables_list(manual: Rig, request_frame, answer):
    manual.exchange(request_frame, answer)


def test_every_object_the_tables_list_for_the_variant_answers(manual: Rig):
    listed = [p for p in CATALOGUE.for_variant(manual.valve.variant) if in_manual(*p.key)]
    assert len(listed) > 100
    for param in listed:
        index, sub = param.key
        manual.send(f"60A 40 {index & 0xFF:02X} {index >> 8:02X} {sub:02X} 00 00 00 00")
        answer = manual.receive()
        assert answer is not None, param.mnemonic
        missing = answer.endswith(("00 00 02 06", "11 00 09 06"))  # no object / sub-index
        assert not missing, (param.mnemonic, answer)
    assert all(index in MANUAL_OBJECTS for index, _ in (p.key for p in listed))


def test_the_manual_e02_has_the_sensor_objects_and_pdo2_mappings_of_all_valves(
    request: pytest.FixtureRequest, tmp_path
):
    """Tables 7-13 and 7-14 hold on an E02 -CA too: 0x2005-0x2008, 0x2100 (read 0: no sensor
    input) and both PDO2 mappings; a sensor set-up written is kept like any other write."""
    rig = make_rig(request.node.name, E02, nv_path=tmp_path / "nv.json", od="manual")
    try:
        for index in (0x1601, 0x1A01, 0x2005, 0x2006, 0x2007, 0x2008, 0x2100):
            for sub in MANUAL_OBJECTS[index]:
                if sub == 2 and index == 0x2100:
                    continue  # write-only: the sensor value over CANopen
                data = rig.sdo_read(index, sub)
                if index == 0x2100 and sub:
                    assert data == b"\x00\x00", sub
        rig.exchange("60A 40 01 1A 00 00 00 00 00", "58A 4F 01 1A 00 02 00 00 00")
        rig.exchange("60A 40 01 16 00 00 00 00 00", "58A 4F 01 16 00 01 00 00 00")
        rig.exchange("60A 2B 05 20 03 00 10 00 00", "58A 60 05 20 03 00 00 00 00")  # offset 25 %
        rig.valve.restart()
        rig.valve.advance(2.0)
        rig.drain()
        rig.exchange("60A 40 05 20 03 00 00 00 00", "58A 4B 05 20 03 00 10 00 00")  # kept
        rig.exchange("60A 40 00 21 04 00 00 00 00", "58A 4B 00 21 04 00 00 00 00")  # still 0
    finally:
        rig.close()


def test_the_full_valve_still_has_the_projects_objects(request: pytest.FixtureRequest):
    rig = make_rig(request.node.name, E04)
    try:
        rig.exchange("60A 40 10 10 01 00 00 00 00", "58A 43 10 10 01 01 00 00 00")
    finally:
        rig.close()


def test_a_write_is_kept_over_a_power_cycle_without_a_store(manual: Rig):
    manual.exchange("60A 2B 32 63 01 E8 03 00 00", "58A 60 32 63 01 00 00 00 00")  # ramp 1000
    manual.valve.restart()
    manual.valve.advance(2.0)
    manual.drain()
    manual.exchange("60A 40 32 63 01 00 00 00 00", "58A 4B 32 63 01 E8 03 00 00")


def test_the_full_valve_forgets_an_unstored_write(request: pytest.FixtureRequest, tmp_path):
    rig = make_rig(request.node.name, E04, nv_path=tmp_path / "nv.json")
    try:
        rig.exchange("60A 2B 32 63 01 E8 03 00 00", "58A 60 32 63 01 00 00 00 00")
        rig.valve.restart()
        rig.valve.advance(2.0)
        rig.drain()
        rig.exchange("60A 40 32 63 01 00 00 00 00", "58A 4B 32 63 01 00 00 00 00")
    finally:
        rig.close()


def test_a_write_that_breaks_a_rule_is_refused_and_nothing_changes(manual: Rig):
    # setpoint linearization XB = -7000 would pass XC (-8192): the curve must go one way
    manual.exchange("60A 2B 00 20 02 A8 E4 00 00", "58A 80 00 20 02 43 00 04 06")
    manual.exchange("60A 40 00 20 02 00 00 00 00", "58A 4B 00 20 02 00 D0 00 00")  # -12288
    manual.valve.restart()
    manual.valve.advance(2.0)
    manual.drain()
    manual.exchange("60A 40 00 20 02 00 00 00 00", "58A 4B 00 20 02 00 D0 00 00")


def test_e02_manual_valve(request: pytest.FixtureRequest):
    rig = make_rig(request.node.name, E02, od="manual")
    try:
        rig.exchange("60A 40 10 10 00 00 00 00 00", "58A 80 10 10 00 00 00 02 06")
    finally:
        rig.close()


def test_the_option_reaches_the_emulated_valves_of_the_process(tmp_path, monkeypatch, capsys):
    monkeypatch.setenv("PRM9TOOL_DATA_DIR", str(tmp_path))
    emulated_valves.forget_emulated_valves()
    try:
        emulated_valves.set_emulator_od("manual")
        assert emulated_valves.emulated_valve(E04, 99).od == "manual"
    finally:
        emulated_valves.set_emulator_od("full")
        emulated_valves.forget_emulated_valves()
    assert main(["--od", "manual", "--list-devices"]) == 2
    assert "--od chooses the object dictionary of --emulator or --serve-emulator" in (
        capsys.readouterr().err
    )

"""The device factory: emulator specs, per-serial EEPROM files, pacing, CAN wiring."""

from __future__ import annotations

import re
import time

import can
import pytest

from prm9tool.catalogue.typekey import DEFAULT_EMULATOR_TYPE_KEY
from prm9tool.device import emulated_valves, factory
from prm9tool.errors import Prm9Error, TypeKeyError

E02 = "PRM9-06.3Z11/30-24E02S02"
E04CA = "PRM9-06.3Z11/30-24E04S02-CA"


@pytest.fixture(autouse=True)
def _fresh_emulators(monkeypatch):
    for name in ("hid", "hidraw"):  # no USB on the test machine
        monkeypatch.setitem(__import__("sys").modules, name, None)
    yield
    emulated_valves.forget_emulated_valves()


def test_nv_path_follows_the_data_dir(tmp_path, monkeypatch):
    monkeypatch.setenv("PRM9TOOL_DATA_DIR", str(tmp_path / "elsewhere"))
    assert emulated_valves.emulator_nv_path(42) == tmp_path / "elsewhere" / "emulator" / "42.json"


@pytest.mark.parametrize(
    ("spec", "expected"),
    [
        ("", (DEFAULT_EMULATOR_TYPE_KEY, 7)),  # the one default of GUI, CLI and docs
        (E04CA, (E04CA, 7)),
        ("prm9-06.3z11/30-24e04s02-ca:12", (E04CA, 12)),
    ],
)
def test_emulator_specs(spec, expected):
    assert factory.parse_emulator_spec(spec, default_serial=7) == expected


@pytest.mark.parametrize(
    ("spec", "message"),
    [(f"{E02}:x", "serial 'x' must be a number"), ("PRM9-06.3Z11/31-24E02S02", "flow '31'")],
)
def test_bad_emulator_specs_name_the_problem(spec, message):
    with pytest.raises(TypeKeyError, match=message):
        factory.parse_emulator_spec(spec)


def test_specs_without_serial_get_the_lowest_free_ones():
    entries = factory.list_devices([E02, f"{E04CA}:1", ""])
    assert [(e.type_key, e.serial) for e in entries] == [
        (E02, 2),
        (E04CA, 1),
        (DEFAULT_EMULATOR_TYPE_KEY, 3),
    ]
    assert entries[0].device_id == f"emulator:{E02}:2"
    assert entries[0].description == f"emulated {E02}, serial 2"
    with pytest.raises(TypeKeyError, match="two emulated valves with serial 4"):
        factory.list_devices([f"{E02}:4", f"{E02}:4"])


def test_a_serial_whose_image_is_of_another_type_is_not_given_to_a_spec_without_serial():
    with factory.open_session(f"emulator:{E02}:1", paced=False) as session:
        session.store()  # a valve of an earlier run left its EEPROM image
    emulated_valves.forget_emulated_valves()
    entries = factory.list_devices([E04CA, E02])
    assert [(e.type_key, e.serial) for e in entries] == [(E04CA, 2), (E02, 1)]


def test_one_serial_is_one_valve_of_one_type():
    factory.list_devices([f"{E02}:5"])
    with pytest.raises(Prm9Error, match=re.escape(f"emulated valve 5 is a {E02}")):
        factory.list_devices([f"{E04CA}:5"])


def test_stored_parameters_survive_the_process(tmp_path):
    entry = factory.list_devices([f"{E02}:6"])[0]
    with factory.open_session(entry, paced=False) as session:
        session.write("LIMTA", 1777)
        session.store()
    emulated_valves.forget_emulated_valves()  # as if the process ended
    assert emulated_valves.emulator_nv_path(6).exists()
    with factory.open_session(f"emulator:{E02}:6", paced=False) as session:
        assert session.read("LIMTA") == 1777


def test_paced_session_runs_the_valve_in_real_time_until_closed():
    entry = factory.list_devices([f"{E02}:8"])[0]
    valve = emulated_valves.emulated_valve(E02, 8)
    with factory.open_session(entry) as session:
        assert valve.running
        second = factory.open_session(entry)
        session.stream_start(["supply_voltage"], rate_hz=1000)
        time.sleep(0.1)
        block = session.stream_read()
        assert block.shape[1] == 1 and len(block) > 0
        assert block[-1, 0] == pytest.approx(24000, abs=50)
        second.close()
        assert valve.running  # one paced session is still open
    assert not valve.running


def test_unknown_device_id():
    with pytest.raises(Prm9Error, match="unknown device 'com3'"):
        factory.open_session("com3")


def test_can_options_put_an_emulated_ca_valve_on_the_bus():
    listener = can.Bus(interface="virtual", channel="factory-test")
    try:
        entry = factory.list_devices([f"{E04CA}:9"])[0]
        options = factory.CanOptions("virtual", "factory-test")
        with factory.open_session(entry, paced=False, can=options):
            emulated_valves.emulated_valve(E04CA, 9).advance(6.0)  # past the boot-up
            frames = []
            while (frame := listener.recv(0.05)) is not None:
                frames.append(frame.arbitration_id)
        node = emulated_valves.emulated_valve(E04CA, 9).node_id
        assert 0x700 + node in frames  # boot-up / heartbeat of that node
    finally:
        listener.shutdown()


def test_can_options_from_the_command_line_fill_in_what_was_not_given():
    from prm9tool.cli.main import build_parser

    parse = build_parser().parse_args
    assert factory.CanOptions.from_args(parse([])) == factory.CanOptions("virtual", "prm9tool")
    given = parse(
        ["--can-interface", "socketcan", "--can-channel", "can0", "--can-bitrate", "250000"]
    )
    assert factory.CanOptions.from_args(given) == factory.CanOptions("socketcan", "can0", 250000)

"""Emulator object dictionary: access rules and CiA 301 abort codes, identity, encodings."""

from __future__ import annotations

import pytest

from prm9tool.catalogue import CATALOGUE
from prm9tool.device.emulator import EmulatedValve
from prm9tool.device.records import DeviceState
from prm9tool.errors import AbortCode, SdoAbortError

E02_CA = "PRM9-06.3Z11/30-24E02S02-CA"
E02 = "PRM9-06.3Z11/30-24E02S02"
E04_A = "PRM9-06.2Z51/30-24E04S02"


def abort_code(valve: EmulatedValve, call: str, *args: object) -> int:
    with pytest.raises(SdoAbortError) as info:
        getattr(valve, call)(*args)
    return info.value.code


@pytest.fixture
def valve() -> EmulatedValve:
    return EmulatedValve(E02_CA, serial=4711, firmware_version="2.3.4")


def test_identity_objects(valve):
    assert valve.read(0x1000, 0) == 0x198
    assert valve.read(0x1018, 1) == 0xE6
    assert valve.read(0x1018, 4) == 4711
    assert valve.read(0x1018, 3) == 0x020304
    assert valve.read(0x1008, 0) == "PRM9"
    assert valve.read(0x2041, 0) == E02_CA
    assert valve.read(0x100A, 0) == "2.3.4"


def test_factory_defaults_come_from_the_catalogue(valve):
    for mnemonic in ("THRESETP", "LIMTA", "DTAMP", "DYNFREQ", "POSKP", "MONDELAY"):
        param = CATALOGUE[mnemonic]
        assert valve.read(param.index, param.subindex) == param.default


def test_e04_control_mode_default_is_process_control():
    assert EmulatedValve("PRM9-06.3Z11/30-24E04S02").read(0x6043, 0) == 4
    assert EmulatedValve(E02).read(0x6043, 0) == 2


def test_sub0_of_records_gives_the_highest_subindex(valve):
    assert valve.read(0x2000, 0) == 9
    assert valve.read(0x6300, 0) == 1
    assert valve.read(0x2004, 0) == 3
    assert abort_code(valve, "write", 0x2000, 0, 9) == AbortCode.READ_ONLY


@pytest.mark.parametrize(
    ("args", "code"),
    [
        ((0x5FFF, 0), AbortCode.NO_SUCH_OBJECT),
        ((0x6332, 7), AbortCode.NO_SUCH_SUBINDEX),
        ((0x6381, 1), AbortCode.NO_SUCH_OBJECT),  # process control: E04 only
    ],
)
def test_missing_objects_abort(valve, args, code):
    assert abort_code(valve, "read", *args) == code


def test_the_sensor_objects_are_on_every_ca_valve_only():
    """Table 7-14: objects of all valves (an E02 -CA has them); an E02 without CANopen has
    no sensor at all."""
    assert abort_code(EmulatedValve(E02), "read", 0x2100, 1) == AbortCode.NO_SUCH_OBJECT
    assert EmulatedValve(E02_CA).read(0x2100, 1) == 0


@pytest.mark.parametrize("type_key", ["PRM9-06.3Z11/30-24E04S02-CA", E02_CA])
def test_write_only_object_cannot_be_read(type_key):
    valve = EmulatedValve(type_key)
    assert abort_code(valve, "read", 0x2100, 2) == AbortCode.WRITE_ONLY
    valve.write(0x2100, 2, 1234)  # accepted


@pytest.mark.parametrize(
    ("index", "sub", "value", "code"),
    [
        (0x6301, 1, 0, AbortCode.READ_ONLY),
        (0x1000, 0, 1, AbortCode.READ_ONLY),
        (0x6332, 1, 40001, AbortCode.VALUE_TOO_HIGH),
        (0x6345, 1, -1, AbortCode.VALUE_TOO_LOW),
        (0x2010, 1, 12, AbortCode.INVALID_VALUE),  # not a signal-type code
        (0x6332, 1, "100", AbortCode.WRONG_LENGTH),
        (0x1003, 0, 1, AbortCode.INVALID_VALUE),  # only 0 clears the history (CiA 301)
        (0x1010, 1, 0x12345678, AbortCode.CANNOT_STORE),  # not "save"
        (0x2004, 2, 2601, AbortCode.VALUE_TOO_HIGH),  # LIMIT A above CURNORM (table 7-14)
    ],
)
def test_write_aborts(valve, index, sub, value, code):
    before = valve.read(index, sub) if index not in (0x1010,) else None
    assert abort_code(valve, "write", index, sub, value) == code
    if before is not None:
        assert valve.read(index, sub) == before


def test_canopen_setpoint_type_needs_a_ca_valve():
    assert abort_code(EmulatedValve(E02), "write", 0x2010, 1, 14) == AbortCode.INVALID_VALUE
    valve = EmulatedValve(E02_CA)
    valve.write(0x2010, 1, 14)
    assert valve.read(0x2010, 1) == 14


def test_single_coil_valve_has_no_coil_b_objects():
    valve = EmulatedValve(E04_A)
    assert abort_code(valve, "read", 0x2004, 3) == AbortCode.NO_SUCH_SUBINDEX
    assert abort_code(valve, "read", 0x6336, 1) == AbortCode.NO_SUCH_OBJECT


def test_bytes_are_encoded_per_catalogue_type(valve):
    assert valve.read_bytes(0x1000, 0) == bytes.fromhex("98010000")
    assert valve.read_bytes(0x6345, 1) == (819).to_bytes(2, "little")
    valve.write_bytes(0x1017, 0, bytes.fromhex("E803"))
    assert valve.read(0x1017, 0) == 1000
    valve.write_bytes(0x6300, 1, (-8000).to_bytes(2, "little", signed=True))
    assert valve.read(0x6300, 1) == -8000


def test_wrong_lengths_abort(valve):
    assert abort_code(valve, "write_bytes", 0x1017, 0, b"\x01") == AbortCode.LENGTH_TOO_LOW
    assert abort_code(valve, "write_bytes", 0x1017, 0, b"\x01\x02\x03") == (
        AbortCode.LENGTH_TOO_HIGH
    )
    assert abort_code(valve, "write_bytes", 0x6301, 1, b"\x00\x00") == AbortCode.READ_ONLY


def test_device_mode_cannot_change_in_device_mode_active(valve):
    valve.advance(2.0)
    for word in (0x08, 0x09, 0x0B, 0x0F):
        valve.write(0x6040, 0, word)
    assert valve.status().device_state is DeviceState.DEVICE_MODE_ACTIVE
    assert abort_code(valve, "write", 0x6043, 0, 2) == AbortCode.CANNOT_STORE_DEVICE_STATE
    valve.write(0x6040, 0, 0x0B)
    valve.write(0x6043, 0, 2)


def test_e02_has_no_process_control_mode():
    assert abort_code(EmulatedValve(E02), "write", 0x6043, 0, 4) == AbortCode.INVALID_VALUE


def test_live_values(valve):
    valve.set_input("supply_voltage", 23.5)
    valve.set_input("ambient_temperature", 40.0)
    valve.advance(0.01)
    assert valve.read(0x2003, 0) == 23500
    assert valve.read(0x2002, 0) == 40
    assert valve.read(0x2031, 1) == 6  # delivery switch positions (table 7-22)
    assert valve.read(0x2031, 2) == 2
    assert valve.read(0x2040, 0) == 0
    assert valve.read(0x1001, 0) == 0


def test_pdo_mapping_entry_2_follows_the_control_mode_over_every_interface():
    # Table 7-13: RPDO1/TPDO1 entry 2 is 0x6300/0x6301 in control mode 2, 0x6380/0x6381 in 4.
    from prm9tool.device.emulator import EmulatedValve

    valve = EmulatedValve("PRM9-06.3Z11/30-24E04S02-CA")
    assert valve.read(0x6043, 0) == 4
    assert (valve.read(0x1600, 2), valve.read(0x1A00, 2)) == (0x63800110, 0x63810110)
    valve.write(0x6043, 0, 2)
    assert (valve.read(0x1600, 2), valve.read(0x1A00, 2)) == (0x63000110, 0x63010110)

"""Loopback with the ``canopen`` package as the master, using the EDS prm9tool exports.

The master knows the valve only through the exported EDS; every expectation (types, limits,
access) comes from that EDS, so these tests check the EDS and the emulator against each other.
"""

from __future__ import annotations

import queue
import struct
import time
from collections.abc import Iterator
from pathlib import Path

import can
import canopen
import pytest
from canopen.objectdictionary import ODArray, ODRecord, ODVariable, datatypes
from support.canopen_rig import BOOT_S, TIMEOUT_S, unique_channel

from prm9tool.catalogue import CATALOGUE, LOAD_SIGNATURE, SAVE_SIGNATURE
from prm9tool.catalogue.pdo import mapping_for_control_mode
from prm9tool.cli.main import main
from prm9tool.device.emulator import EmulatedValve, Fault
from prm9tool.errors import AbortCode, SdoAbortError

TYPE_KEYS = (
    "PRM9-06.3Z11/30-24E02S02-CA",
    "PRM9-06.3Z11/30-24E04S02-CA",
    "PRM9-10.2Z51/60-24E02S02-CA",  # one coil (A): no coil-B objects
)
NODE = 10
NATURAL = {
    datatypes.BOOLEAN: (0, 1),
    datatypes.INTEGER8: (-(2**7), 2**7 - 1),
    datatypes.INTEGER16: (-(2**15), 2**15 - 1),
    datatypes.INTEGER32: (-(2**31), 2**31 - 1),
    datatypes.UNSIGNED8: (0, 2**8 - 1),
    datatypes.UNSIGNED16: (0, 2**16 - 1),
    datatypes.UNSIGNED32: (0, 2**32 - 1),
}
COB_IDS = {(0x1005, 0), (0x1014, 0), (0x1400, 1), (0x1401, 1), (0x1800, 1), (0x1801, 1)}
TRANSMISSION_TYPES = {(0x1400, 2), (0x1401, 2), (0x1800, 2), (0x1801, 2)}
SIGNATURES = {(0x1010, 1): SAVE_SIGNATURE, (0x1011, 1): LOAD_SIGNATURE}
CONTROL_WORD = (0x6040, 0)
# 0x6043: an E02 valve accepts only control mode 2 (it has no process sensor), which the EDS
# cannot express (limits 2..4 are those of the object); the valid write keeps the mode.
CONTROL_MODE = (0x6043, 0)
MAPPING_ENTRIES = {(0x1600, 2), (0x1A00, 2)}  # follow the control mode 0x6043
ERROR_COUNT = (0x1003, 0)  # CiA 301: only 0 (clear the history); 1 is an invalid value


def _export(tmp_path: Path, type_key: str) -> Path:
    path = tmp_path / "valve.eds"
    assert main(["--export-eds", type_key, "-o", str(path)]) == 0
    return path


def _variables(od: canopen.ObjectDictionary) -> Iterator[ODVariable]:
    for obj in od.values():
        if isinstance(obj, (ODRecord, ODArray)):
            yield from obj.values()
        else:
            yield obj


class Master:
    """canopen Network + RemoteNode on a virtual channel, the valve on the other end."""

    def __init__(self, type_key: str, eds: Path, name: str) -> None:
        channel = unique_channel(name)
        self.valve = EmulatedValve(type_key)
        self.valve_bus = can.Bus(interface="virtual", channel=channel)
        self.slave = self.valve.connect_can(self.valve_bus)
        self.network = canopen.Network()
        self.network.NOTIFIER_CYCLE = 0.05  # quick disconnect at teardown
        self.network.connect(interface="virtual", channel=channel)
        self.node = canopen.RemoteNode(NODE, str(eds))
        self.node.sdo.RESPONSE_TIMEOUT = TIMEOUT_S
        self.network.add_node(self.node)
        self.heartbeats: queue.Queue[int] = queue.Queue()
        self.emcys: queue.Queue[tuple[int, int]] = queue.Queue()
        self.node.nmt.add_heartbeat_callback(self.heartbeats.put)
        self.node.emcy.add_callback(lambda e: self.emcys.put((e.code, e.register)))
        self.valve.advance(BOOT_S)
        assert self.heartbeats.get(timeout=TIMEOUT_S) == 0  # boot-up

    def expected_read(self, var: ODVariable) -> int | str:
        """What the emulator's dictionary holds (raises SdoAbortError like the valve would)."""
        key = (var.index, var.subindex)
        if key in MAPPING_ENTRIES:
            self.valve.read(*key)
            param = CATALOGUE.by_address(*key)
            assert param is not None
            return mapping_for_control_mode(param, int(self.valve.read(0x6043, 0)))
        return self.valve.read(*key)

    def close(self) -> None:
        self.network.disconnect()
        self.slave.stop()
        self.valve_bus.shutdown()


@pytest.fixture(params=TYPE_KEYS)
def master(request: pytest.FixtureRequest, tmp_path: Path):
    m = Master(request.param, _export(tmp_path, request.param), request.node.name)
    yield m
    m.close()


def _upload(node: canopen.RemoteNode, var: ODVariable) -> int | str | AbortCode:
    """Read through SDO and decode with the EDS data type."""
    try:
        return var.decode_raw(node.sdo.upload(var.index, var.subindex))
    except canopen.SdoAbortedError as exc:
        return AbortCode(exc.code)


def _download(node: canopen.RemoteNode, var: ODVariable, data: bytes) -> AbortCode | None:
    try:
        node.sdo.download(var.index, var.subindex, data)
    except canopen.SdoAbortedError as exc:
        return AbortCode(exc.code)
    return None


def test_every_readable_object_reads_as_the_emulator_holds_it(master: Master):
    readable = [v for v in _variables(master.node.object_dictionary) if v.readable]
    assert len(readable) > 60
    for var in readable:
        try:
            expected: int | str | AbortCode = master.expected_read(var)
        except SdoAbortError as exc:
            expected = AbortCode(exc.code)
        assert _upload(master.node, var) == expected, f"0x{var.index:04X}/{var.subindex}"


def _valid_values(master: Master, var: ODVariable) -> list[int]:
    """Values the valve must accept: both EDS limits, unless CiA 301 or the valve's state
    restricts the object further."""
    key = (var.index, var.subindex)
    if key in SIGNATURES:
        return [SIGNATURES[key]]
    if key == CONTROL_WORD:
        return [0x08]  # R only: the device stays in INIT, device-mode objects stay writable
    if key == ERROR_COUNT:
        return [0]
    current = master.valve.read(*key) if var.readable else None
    if key == CONTROL_MODE:
        assert isinstance(current, int)
        return [current]
    if key in COB_IDS:
        assert isinstance(current, int)
        return [current ^ 0x80000000]  # toggle the valid bit
    low, high = _limits(var)
    return [low, high]


def _limits(var: ODVariable) -> tuple[int, int]:
    low, high = NATURAL[var.data_type]
    return (low if var.min is None else var.min, high if var.max is None else var.max)


def _invalid_write(var: ODVariable) -> tuple[bytes, AbortCode]:
    """A value the EDS says is not allowed, and the abort code CiA 301 prescribes for it."""
    key = (var.index, var.subindex)
    low, high = _limits(var)
    natural_low, natural_high = NATURAL[var.data_type]
    if key in SIGNATURES:
        return var.encode_raw(SIGNATURES[key] ^ 1), AbortCode.CANNOT_STORE
    if key in COB_IDS:
        return var.encode_raw(0x20000181), AbortCode.INVALID_VALUE  # 29-bit identifier
    if key in TRANSMISSION_TYPES:
        return var.encode_raw(241), AbortCode.INVALID_VALUE  # reserved (table 7-12)
    if key == ERROR_COUNT:
        return var.encode_raw(1), AbortCode.INVALID_VALUE
    if high < natural_high:
        return struct.pack(_format(var), high + 1), AbortCode.VALUE_TOO_HIGH
    if low > natural_low:
        return struct.pack(_format(var), low - 1), AbortCode.VALUE_TOO_LOW
    return var.encode_raw(low) + b"\x00", AbortCode.LENGTH_TOO_HIGH


def _format(var: ODVariable) -> str:
    return {1: "<B", 2: "<b", 3: "<h", 4: "<i", 5: "<B", 6: "<H", 7: "<I"}[var.data_type]


def test_every_writable_object_takes_a_valid_value_and_aborts_an_invalid_one(master: Master):
    variables = list(_variables(master.node.object_dictionary))
    writable = [v for v in variables if v.writable]
    assert len(writable) > 30
    for var in writable:
        where = f"0x{var.index:04X}/{var.subindex}"
        data, code = _invalid_write(var)
        assert _download(master.node, var, data) == code, where
        for value in _valid_values(master, var):
            assert _download(master.node, var, var.encode_raw(value)) is None, f"{where}={value}"
            if var.readable and (var.index, var.subindex) not in SIGNATURES:
                assert _upload(master.node, var) == value, where
    for var in variables:
        if not var.writable:
            payload = b"x" if var.data_type not in NATURAL else var.encode_raw(var.default or 0)
            code = _download(master.node, var, payload)
            assert code == AbortCode.READ_ONLY, f"0x{var.index:04X}/{var.subindex}"


def test_eds_identity_is_what_the_valve_answers(master: Master):
    """Vendor, product code, revision (0x1018/1..3) and firmware version 0x100A: the EDS
    defaults and [DeviceInfo] come from the firmware version the emulator runs."""
    od = master.node.object_dictionary
    info = od.device_information
    identity = (info.vendor_number, info.product_number, info.revision_number)
    answers = [_upload(master.node, od[0x1018][sub]) for sub in (1, 2, 3)]
    assert answers == [od[0x1018][sub].default for sub in (1, 2, 3)] == list(identity)
    assert info.revision_number == 0x00010000  # firmware 1.0.0: major << 16 | minor << 8 | patch
    assert _upload(master.node, od[0x100A]) == od[0x100A].default == master.valve.firmware_version


def test_nmt_state_changes_are_seen_in_heartbeats(master: Master):
    for command, state in (("OPERATIONAL", 0x05), ("STOPPED", 0x04), ("PRE-OPERATIONAL", 0x7F)):
        master.node.nmt.state = command
        deadline = time.monotonic() + TIMEOUT_S  # the valve applies it in its receive thread
        while master.valve.status().nmt_state != command.lower():
            assert time.monotonic() < deadline
            time.sleep(0.001)
        while not master.heartbeats.empty():
            master.heartbeats.get()
        master.valve.advance(1.0)
        assert master.heartbeats.get(timeout=TIMEOUT_S) == state
        assert master.node.nmt.state == command


def test_emcy_on_an_injected_fault_and_zero_emcy_when_it_clears(master: Master):
    master.valve.inject(Fault.POSITION_SENSOR_BREAK)
    master.valve.advance(0.1)
    assert master.emcys.get(timeout=TIMEOUT_S) == (0x7300, 0x81)  # generic + manufacturer
    assert master.node.sdo[0x1003][1].raw == 0x7300
    master.valve.clear(Fault.POSITION_SENSOR_BREAK)
    master.valve.advance(11.0)
    assert master.emcys.get(timeout=TIMEOUT_S) == (0, 0)


@pytest.mark.parametrize("type_key", TYPE_KEYS)
def test_the_eds_describes_exactly_the_objects_the_emulator_answers_to(
    tmp_path: Path, type_key: str
):
    od = canopen.import_od(str(_export(tmp_path, type_key)), NODE)
    valve = EmulatedValve(type_key)
    described = {(v.index, v.subindex): v for v in _variables(od)}
    for (index, subindex), var in described.items():
        data = _read_or_abort(valve, index, subindex)
        if isinstance(data, AbortCode):  # 0x1003 entries beyond the count: "no data"
            expected = AbortCode.NO_DATA if var.readable else AbortCode.WRITE_ONLY
            assert data == expected, f"0x{index:04X}/{subindex}"
        elif var.data_type in NATURAL:
            assert len(data) == struct.calcsize(_format(var)), f"0x{index:04X}/{subindex}"
    indices = {index for index, _ in described}
    for index in [*range(0x1000, 0x2200), *range(0x6000, 0x6400)]:
        if index in indices:
            highest = max(sub for i, sub in described if i == index)
            for sub in range(highest + 2):
                if (index, sub) not in described:
                    _assert_abort(valve, index, sub, AbortCode.NO_SUCH_SUBINDEX)
        else:
            _assert_abort(valve, index, 0, AbortCode.NO_SUCH_OBJECT)


def _read_or_abort(valve: EmulatedValve, index: int, subindex: int) -> bytes | AbortCode:
    try:
        return valve.read_bytes(index, subindex)
    except SdoAbortError as exc:
        return AbortCode(exc.code)


def _assert_abort(valve: EmulatedValve, index: int, subindex: int, code: AbortCode) -> None:
    with pytest.raises(SdoAbortError) as info:
        valve.read_bytes(index, subindex)
    assert info.value.code == code, f"0x{index:04X}/{subindex}"


def test_eds_node_relative_defaults_resolve_to_the_node_id(tmp_path: Path):
    od = canopen.import_od(str(_export(tmp_path, TYPE_KEYS[1])), 0x22)
    assert od[0x1800][1].default == 0x1A2
    assert od[0x1400][1].default == 0x40000222
    assert od[0x1014].default == 0xA2
    assert od[0x1600][2].default == 0x63800110  # E04: control mode 4
    assert od[0x1A01][2].default == 0x21000610  # TPDO2: sensor after linearization
    assert od.device_information.vendor_number == 0xE6
    assert od.device_information.allowed_baudrates == {
        20_000,
        50_000,
        125_000,
        250_000,
        500_000,
        800_000,
        1_000_000,
    }


def test_the_master_reads_the_pdo_configuration_without_complaint(
    master: Master, caplog: pytest.LogCaptureFixture
):
    """canopen's ``pdo.read()`` reads every mapping through SDO and looks each entry up in the
    EDS; an entry pointing to an object the valve lacks is logged as a warning and dropped."""
    with caplog.at_level("WARNING", logger="canopen"):
        master.node.tpdo.read()
        master.node.rpdo.read()
    assert [r.getMessage() for r in caplog.records if r.name.startswith("canopen")] == []
    assert 0x2100 in master.node.object_dictionary  # table 7-14: on every valve, E02 too
    for map_index, entries in ((0x1601, 1), (0x1A01, 2)):  # table 7-13, on every -CA valve
        count = master.node.sdo.upload(map_index, 0)[0]
        assert count == entries
        for sub in range(1, count + 1):
            value = struct.unpack("<I", master.node.sdo.upload(map_index, sub))[0]
            assert value >> 16 in master.node.object_dictionary
    assert len(master.node.tpdo[2].map) == 2
    assert len(master.node.rpdo[2].map) == 1

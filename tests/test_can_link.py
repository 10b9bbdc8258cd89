"""The valve session over CANopen (device/canlink) against the emulated -CA valve on a virtual
bus: identity, download, objects a real valve lacks, a node that stops answering, two masters,
other nodes, type keys, a missing adapter. The upload contract every link shares (write, verify,
store, a refusal) is tests/test_upload_contract.py."""

from __future__ import annotations

import contextlib
import threading
import time

import can
import canopen
import pytest
from canopen.sdo.exceptions import SdoError
from support.can_link_rig import E02, E04, LinkRig, make_link_rig
from support.waiting import wait_for

from prm9tool.catalogue import CATALOGUE
from prm9tool.device.canlink import bus as bus_module
from prm9tool.device.canlink.bus import CanOptions, open_bus
from prm9tool.device.canlink.session import CanopenSession, NotAPrm9Error
from prm9tool.device.canlink.typekeys import TypeKeyNeededError, remember
from prm9tool.device.session import NotAvailableError
from prm9tool.errors import AbortCode, CanAdapterError, DeviceTimeoutError, TypeKeyError

NODE = 10


@pytest.fixture
def rig(tmp_path, request):
    rig = make_link_rig(request.node.name, tmp_path)
    yield rig
    rig.close()


def open_can(rig: LinkRig, **kwargs: object) -> CanopenSession:
    return CanopenSession(rig.options, NODE, **kwargs)  # type: ignore[arg-type]


def changed(session: CanopenSession) -> dict[str, int | str]:
    """The valve's file set with a few values changed within the catalogue's rules (the valve
    refuses to store a set that breaks them)."""
    values = session.download()
    values.update(LIMTA=1500, LIMTB=1600, DYNFREQ=120, DTAMP=1000)
    return values


def test_identify_reads_the_manual_objects(rig, data_dir):
    with open_can(rig) as session:
        assert session.info.type_key == E04  # from 0x2041 (the emulated valve has it)
        assert session.info.serial == rig.valve.serial
        assert session.info.device_id == "can:10"
        assert session.read("SNV") == rig.valve.serial
        assert session.info.stream_rate_limit_hz == pytest.approx(1000.0)  # the 1 ms SYNC


def test_download_gives_the_valves_file_set(rig, data_dir):
    with open_can(rig) as session:
        values = session.download()
    params = CATALOGUE.file_parameters(rig.valve.variant)
    assert set(values) == {p.mnemonic for p in params}
    assert all(values[p.mnemonic] == rig.valve.read(*p.key) for p in params)


def test_objects_a_real_valve_lacks_are_skipped_with_their_names(tmp_path, data_dir):
    rig = make_link_rig("real", tmp_path, real_valve=True)
    try:
        with open_can(rig, type_key=E04) as session:
            values = changed(session)
            assert "POSKP" not in values  # 0x2020/1: the object is this project's decision
            values["POSKP"] = CATALOGUE["POSKP"].default
            result = session.upload(values)
            with pytest.raises(NotAvailableError, match=r"not available over CANopen.*POSKP"):
                session.write("POSKP", 5)
        assert result.stored and "POSKP" in result.skipped
        assert set(result.skipped) <= {p.mnemonic for p in CATALOGUE if not p.address_from_manual}
        assert rig.stored_set()["LIMTA"] == values["LIMTA"]
    finally:
        rig.close()


def test_a_node_that_stops_answering_mid_upload_keeps_its_stored_set(rig, data_dir):
    with open_can(rig, timeout_s=0.05) as session:
        stored_before = rig.stored_set()
        values = changed(session)
        rig.go_silent_after(2)  # 2 of the 4 writes (the snapshot is the values just read;
        # values the valve holds already are not sent)
        with pytest.raises(DeviceTimeoutError) as caught:
            session.upload(values)
    message = str(caught.value)
    assert "upload failed while writing the parameters (step 1 of 3)" in message
    assert "no SDO answer" in message and "nothing was stored" in message
    assert rig.stored_set() == stored_before


def test_two_masters_on_one_bus_never_leave_a_mixed_stored_set(rig, data_dir):
    other = canopen.Network()
    other.connect(interface="virtual", channel=rig.options.channel)
    node = other.add_node(NODE, canopen.ObjectDictionary())
    node.sdo.RESPONSE_TIMEOUT = 0.05
    stop = threading.Event()

    def meddle() -> None:
        while not stop.is_set():
            with contextlib.suppress(SdoError):
                node.sdo.upload(0x1018, 4)

    thread = threading.Thread(target=meddle, daemon=True)
    try:
        with open_can(rig, timeout_s=0.1) as session:
            stored_before = rig.stored_set()
            values = changed(session)
            thread.start()
            try:
                result = session.upload(values)
                stored = result.stored
            except Exception:
                stored = False
    finally:
        stop.set()
        thread.join(2)
        other.disconnect()
    after = rig.stored_set()
    if stored:
        assert all(after[m] == v for m, v in values.items() if m in after)
    else:
        assert after == stored_before


def test_a_node_that_is_not_a_prm9_is_refused(tmp_path, data_dir):
    from support.can_link_rig import unique_channel
    from support.canopen_rig import foreign_node

    channel = unique_channel("other")
    network = foreign_node(channel, NODE, vendor=0x123)
    try:
        with pytest.raises(NotAPrm9Error, match=r"not a PRM9 .device type 0x191, vendor 0x123."):
            CanopenSession(CanOptions("virtual", channel), NODE)
    finally:
        network.disconnect()


def test_without_0x2041_the_key_is_derived_given_and_remembered(tmp_path, data_dir):
    rig = make_link_rig("nokey", tmp_path, type_key=E04, real_valve=True)
    try:
        with pytest.raises(TypeKeyNeededError, match="tell E04 -CA: give the type key"):
            open_can(rig)
        with pytest.raises(TypeKeyError, match="is an E02 valve, the valve's objects say E04"):
            open_can(rig, type_key=E02)
        remember(data_dir, rig.valve.serial, E04)
        with open_can(rig) as session:
            assert session.info.type_key == E04
    finally:
        rig.close()


def test_status_reads_state_errors_and_heartbeat(rig, data_dir):
    with open_can(rig) as session:
        session.write("HEARTBEAT", 20)
        rig.valve.advance(0.1)
        status = session.status()
    assert status.device_state == "INIT"
    assert status.nmt_state == "pre-operational"
    assert status.leds[2].pattern == "2.5Hz"  # LED3 as table 7-18 shows pre-operational
    assert status.supply_v == pytest.approx(24.0, abs=0.5)


def test_a_missing_adapter_names_the_interface_and_what_to_check():
    options = CanOptions("socketcan", "prm9nosuch0", 500000)
    with pytest.raises(CanAdapterError) as caught:
        open_bus(options)
    text = str(caught.value)
    assert "cannot open the CAN interface 'socketcan', channel 'prm9nosuch0'" in text
    assert "ip link show prm9nosuch0" in text


def test_an_unknown_interface_is_a_clear_error():
    with pytest.raises(CanAdapterError, match=r"'nosuchbackend'.*adapter is plugged in"):
        open_bus(CanOptions("nosuchbackend", "0"))


def test_no_answer_on_an_empty_bus_is_a_timeout_naming_the_bit_rate(tmp_path, data_dir):
    from support.can_link_rig import unique_channel

    bus = can.Bus(interface="virtual", channel=unique_channel("empty"))
    try:
        with pytest.raises(DeviceTimeoutError, match="node 10: does not answer"):
            CanopenSession(
                CanOptions("virtual", bus.channel_info.split()[-1]), NODE, timeout_s=0.05
            )
    finally:
        bus.shutdown()


def test_missing_object_abort_codes_are_the_cia_301_ones():
    from prm9tool.device.canlink.sdo import MISSING

    assert {AbortCode.NO_SUCH_OBJECT, AbortCode.NO_SUCH_SUBINDEX} == MISSING


def test_commissioning_over_can_as_the_gui_does_it(tmp_path, data_dir):
    """NMT start and the control word in turn (online/valve_control.py), on the CAN link."""
    from prm9tool.catalogue.commissioning import (
        CONTROL_WORD,
        DISABLE_SEQUENCE,
        ENABLE_SEQUENCE,
        NmtCommand,
    )

    rig = make_link_rig("commission", tmp_path)
    rig.valve.start()  # the state machine steps in real time
    try:
        with open_can(rig) as session:
            session.write("HEARTBEAT", 20)
            session.nmt(NmtCommand.START)
            wait_for(lambda: session.status().nmt_state == "operational")
            for word in ENABLE_SEQUENCE:
                session.write(CONTROL_WORD, word)
                time.sleep(0.01)
            wait_for(lambda: session.status().device_state == "DEVICE_MODE_ACTIVE")
            for word in DISABLE_SEQUENCE:
                session.write(CONTROL_WORD, word)
                time.sleep(0.01)
            session.nmt(NmtCommand.PRE_OPERATIONAL)
            wait_for(lambda: session.status().device_state == "INIT")
            wait_for(lambda: session.status().nmt_state == "pre-operational")
    finally:
        rig.valve.stop()
        rig.close()


def test_the_scope_takes_tpdo1_at_its_own_sync_when_the_node_is_operational(tmp_path, data_dir):
    rig = make_link_rig("pdo-scope", tmp_path)
    rig.valve.start()
    try:
        with open_can(rig) as session:
            session.write("HEARTBEAT", 20)
            session.write("CTRLMODE", 2)  # TPDO1 entry 2 = actual position 0x6301
            session.stream_start(["position_actual"], 200)
            assert session.stream_source == "sdo"  # pre-operational: no PDOs
            session.stream_stop()
            type_before = session.sdo.upload(0x1800, 2)
            session.nmt(0x01)
            deadline = time.monotonic() + 2
            while rig.valve.status().nmt_state != "operational" or (
                session._shared.node_seen(10).nmt_state != "operational"
            ):
                assert time.monotonic() < deadline
                time.sleep(0.01)
            session.stream_start(["position_actual"], 200)
            assert session.stream_source == "pdo"
            time.sleep(0.5)
            block = session.stream_read()
            rate = session.sample_rate_hz
            session.stream_stop()
            assert session.sdo.upload(0x1800, 2) == type_before  # put back
        assert 60 <= len(block) <= 110  # 200 Hz for 0.5 s, as the SYNCs went out
        assert 120 <= rate <= 210
    finally:
        rig.valve.stop()
        rig.close()


def test_sampled_actual_values_are_read_where_the_catalogue_puts_them():
    """The SDO sampler read 0x6301/0 and 0x6381/0 (the records' entry count, 1): over CAN the
    scope showed the spool fixed at 0.006104 % whatever it did."""
    from prm9tool.device.canlink.sampler import SdoSampler

    reads: list[tuple[int, int]] = []

    def read(index: int, subindex: int) -> bytes:
        reads.append((index, subindex))
        return (-4096).to_bytes(2, "little", signed=True)  # -25 %

    sampler = SdoSampler(read, ["position_actual", "process_actual"], 100)  # samples in a thread
    try:
        shown = [sampler._sample(k) for k in ("position_actual", "process_actual")]
    finally:
        sampler.stop()
    assert shown == [-4096, -4096]
    assert set(reads) == {(0x6301, 1), (0x6381, 1)}
    assert set(reads) == {CATALOGUE[m].key for m in ("POSACT", "PRCACT")}


def test_the_sampler_reads_every_measuring_point_the_catalogue_gives_an_object():
    """The sampler had a table of its own without the demand value 0x6310 and the control
    deviation 0x6350 (manual table 7-14 lists both, readable): over CAN they showed no data.
    It reads what ``catalogue.signals.SIGNAL_OBJECTS`` says, signed as the catalogue's type."""
    from prm9tool.catalogue.signals import SIGNAL_OBJECTS, signal_at_index
    from prm9tool.device.canlink.sampler import SdoSampler

    def read(index: int, subindex: int) -> bytes:
        size = next(p.dtype.size for p in CATALOGUE if p.key == (index, subindex))
        return (-2 if size == 1 else 0xFFFE if index == 0x2003 else -4096).to_bytes(
            size, "little", signed=index != 0x2003
        )

    keys = list(SIGNAL_OBJECTS)
    shown = {}
    for first in range(0, len(keys), 3):
        sampler = SdoSampler(read, keys[first : first + 3], 100)
        try:
            shown.update({k: sampler._sample(k) for k in keys[first : first + 3]})
        finally:
            sampler.stop()
    assert shown == {
        "position_actual": -4096,
        "process_actual": -4096,
        "demand": -4096,
        "position_deviation": -4096,
        "supply_voltage": 0xFFFE,
        "temperature": -20.0,
    }  # fmt: skip  (-2 °C in 0.1 °C)
    assert signal_at_index(0x6301) == "position_actual"  # TPDO1 entry 2 (table 7-13)
    assert signal_at_index(0x6381) == "process_actual" and signal_at_index(0x6300) is None


def test_the_sync_period_keeps_the_scope_under_half_of_a_slow_bus():
    from prm9tool.device.canlink.pdo_scope import min_period_s

    assert min_period_s(None) == min_period_s(500_000) == 0.001
    assert min_period_s(125_000) == pytest.approx(0.002112)  # 132 bits / 125 kbit/s / 0.5


def test_a_wrong_bit_rate_shows_as_error_frames_in_the_message(tmp_path, data_dir):
    from support.can_link_rig import unique_channel

    channel = unique_channel("errors")
    noise = can.Bus(interface="virtual", channel=channel)
    options = CanOptions("virtual", channel)
    shared = bus_module.acquire(options)  # the tool's master, listening
    try:
        for _ in range(3):  # what a controller at another bit rate reports
            noise.send(can.Message(is_error_frame=True, arbitration_id=0, is_extended_id=False))
        deadline = time.monotonic() + 2
        while shared.error_frames < 3:
            assert time.monotonic() < deadline
            time.sleep(0.01)
        with pytest.raises(DeviceTimeoutError) as caught:
            CanopenSession(options, NODE, timeout_s=0.05)
    finally:
        bus_module.release(shared)
        noise.shutdown()
    assert "the bus saw 3 error frames: check that the bit rate is the valve's" in str(caught.value)


def test_a_valve_reset_mid_upload_keeps_its_stored_set(tmp_path, data_dir):
    rig = make_link_rig("reset", tmp_path)
    rig.valve.start()
    try:
        with open_can(rig, timeout_s=0.1) as session:
            stored_before = rig.stored_set()
            values = changed(session)
            rig.reset_after(3)  # during the writes (4 values change; the rest are held)
            with pytest.raises(DeviceTimeoutError) as caught:
                session.upload(values)
        message = str(caught.value)
        assert "upload failed while writing the parameters (step 1 of 3)" in message
        assert "nothing was stored" in message
        assert rig.stored_set() == stored_before
        wait_for(lambda: rig.valve.status().nmt_state == "pre-operational", 5.0)
        assert rig.working("LIMTA") == stored_before.get("LIMTA", CATALOGUE["LIMTA"].default)
    finally:
        rig.valve.stop()
        rig.close()

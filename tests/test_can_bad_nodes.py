"""The CANopen master against nodes that misbehave (issue 29), on raw python-can frames in one
process (the virtual interface; the two-process run where timing matters is
tests/test_can_bad_nodes_processes.py): one broken node never takes the healthy valve beside
it down, uploads are bounded and exact, values that decide what is written are checked."""

from __future__ import annotations

import struct
from collections.abc import Iterator
from contextlib import contextmanager

import can
import canopen
import pytest
from support.bad_node import FIRMWARE, TYPE_KEY, Fault, Flood, prm9_objects, serving_node
from support.can_link_rig import E04, make_link_rig
from support.canopen_rig import unique_channel

from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.cli.main import main
from prm9tool.device.canlink import bus as canbus
from prm9tool.device.canlink.discovery import identify_node
from prm9tool.device.canlink.sdo import STRING_MAX_BYTES, SdoChannel, SdoTransferError
from prm9tool.errors import AbortCode, DeviceTimeoutError
from prm9tool.files.prmfile import PrmContents, write_file


@pytest.fixture
def rig(tmp_path, request):
    rig = make_link_rig(request.node.name, tmp_path)
    yield rig
    rig.close()


def bus_args(channel: str) -> list[str]:
    return ["--can-interface", "virtual", "--can-channel", channel]


def tuned_file(tmp_path, key: str = E04) -> str:
    contents = PrmContents.factory(TypeKey.parse(key))
    contents.values.update(LIMTA=1500)
    path = tmp_path / "tuned.prm"
    write_file(contents, path)
    return str(path)


@contextmanager
def channel_to(channel: str, node_id: int, timeout_s: float = 0.5) -> Iterator[SdoChannel]:
    shared = canbus.acquire(canbus.CanOptions("virtual", channel))
    node = canopen.RemoteNode(node_id, canopen.ObjectDictionary())
    shared.network.add_node(node)
    try:
        yield SdoChannel(node, timeout_s, shared)
    finally:
        del shared.network[node_id]
        canbus.release(shared)


def no_traceback(err: str) -> None:
    assert "Traceback" not in err and "Error:" not in err.split("prm9tool:")[0], err


# --- one broken node beside a healthy valve ----------------------------------------------
def test_a_node_answering_0x1000_only_is_listed_as_such_beside_the_healthy_valve(
    rig, data_dir, capsys
):
    with serving_node(rig.options.channel, 11, Fault.ANSWERS_1000_ONLY):
        code = main(["--list-devices", *bus_args(rig.options.channel)])
    out, err = capsys.readouterr()
    no_traceback(err)
    assert code == 0, err
    assert f"can:10\t{E04}\tserial {rig.valve.serial}" in out
    assert "can:11\tnot identified\tnode 11: answers 0x1000 only: not identified" in out


def test_batch_to_the_healthy_valve_succeeds_beside_a_broken_node(rig, data_dir, tmp_path, capsys):
    with serving_node(rig.options.channel, 11, Fault.ANSWERS_1000_ONLY):
        code = main(
            ["--batch", tuned_file(tmp_path), "--device", "can:10", *bus_args(rig.options.channel)]
        )
    err = capsys.readouterr().err
    no_traceback(err)
    assert code == 0, err
    assert rig.stored_set()["LIMTA"] == 1500


def test_two_nodes_at_one_id_are_named_and_neither_is_written(data_dir, tmp_path, capsys):
    channel = unique_channel("dup")
    with (
        serving_node(channel, 12, Fault.NONE) as first,
        serving_node(channel, 12, Fault.NONE, objects=prm9_objects(777002), delay_s=0.004),
    ):
        listed = main(["--list-devices", *bus_args(channel)])
        out, err = capsys.readouterr()
        batch = main(
            ["--batch", tuned_file(tmp_path, TYPE_KEY), "--device", "can:12", *bus_args(channel)]
        )
        batch_err = capsys.readouterr().err
        download = main(["--batch", "--download", str(tmp_path / "o.prm"), *bus_args(channel)])
        download_err = capsys.readouterr().err
    for text in (err, batch_err, download_err):
        no_traceback(text)
    assert listed == 4  # no usable valve
    assert "can:12\tnot identified\tnode 12: two nodes answer at this ID" in out
    assert batch != 0 and "two nodes answer at this ID" in batch_err
    assert download != 0 and not (tmp_path / "o.prm").exists()
    assert first.writes == []  # neither was written to


@pytest.mark.parametrize(
    ("fault", "kwargs", "listed"),
    [
        (Fault.ABORTS, {}, "can:11\tnot identified\tnode 11: answers 0x1000 only: not identified"),
        (Fault.LATE, {"delay_s": 0.6}, "can:11\tnot identified\tnode 11: answers 0x1000 only"),
        (
            Fault.NONE,
            {"objects": {**prm9_objects(), (0x1000, 0): (0x191).to_bytes(4, "little")}},
            "can:11\tnot a PRM9\tnode 11: not a PRM9 (device type 0x191, vendor 0xE6)",
        ),
    ],
    ids=["random-aborts", "late-answers", "not-a-valve"],
)
def test_a_node_that_aborts_answers_late_or_is_no_valve_is_listed_and_refused(
    rig, data_dir, tmp_path, capsys, fault, kwargs, listed
):
    channel = rig.options.channel
    with serving_node(channel, 11, fault, **kwargs) as node:
        code = main(["--list-devices", *bus_args(channel)])
        out, err = capsys.readouterr()
        refused = main(["--batch", tuned_file(tmp_path), "--device", "can:11", *bus_args(channel)])
        refused_err = capsys.readouterr().err
        served = main(["--batch", tuned_file(tmp_path), "--device", "can:10", *bus_args(channel)])
        served_err = capsys.readouterr().err
    for text in (err, refused_err, served_err):
        no_traceback(text)
    assert code == 0 and listed in out and f"can:10\t{E04}" in out, out
    assert refused != 0
    assert served == 0, served_err
    assert node.writes == []  # nothing was written to it


@pytest.mark.parametrize(
    ("fault", "says"),
    [
        (Fault.REFUSES_STORE, "abort 0x08000020"),
        (Fault.CLAMPS, "LIMTA: wrote 1500, got 750"),
        (Fault.RESETS, "nothing was stored"),
    ],
    ids=["refused-store", "clamped-read-back", "reset-mid-upload"],
)
def test_a_refused_store_or_a_clamped_read_back_fails_the_batch_and_stores_nothing(
    data_dir, tmp_path, capsys, fault, says
):
    channel = unique_channel("store")
    with serving_node(channel, 11, fault, objects=prm9_objects(parameters=True)) as node:
        code = main(
            ["--batch", tuned_file(tmp_path, TYPE_KEY), "--device", "can:11", *bus_args(channel)]
        )
    err = capsys.readouterr().err
    no_traceback(err)
    assert code != 0 and says in err, err
    assert node.stored is None  # the node never stored a set
    if fault is Fault.REFUSES_STORE:  # and its working values were put back
        limta = CATALOGUE["LIMTA"].key
        assert node.objects[limta] == prm9_objects(parameters=True)[limta]


@pytest.mark.parametrize(
    ("can_id", "data"),
    [(0x70B, b"\x05"), (0x08B, bytes([0x00, 0x10, 0x01, 0, 0, 0, 0, 0])), (0x001, bytes(8))],
    ids=["heartbeat-flood", "emcy-flood", "high-priority-flood"],
)
def test_a_flood_beside_the_healthy_valve_does_not_stop_its_batch(
    rig, data_dir, tmp_path, capsys, can_id, data
):
    bus = can.Bus(interface="virtual", channel=rig.options.channel)
    flood = Flood(bus, can_id, data).start()
    try:
        code = main(
            ["--batch", tuned_file(tmp_path), "--device", "can:10", *bus_args(rig.options.channel)]
        )
    finally:
        flood.stop()
        bus.shutdown()
    err = capsys.readouterr().err
    no_traceback(err)
    assert code == 0, err
    assert flood.sent > 0 and rig.stored_set()["LIMTA"] == 1500


@pytest.mark.parametrize(
    ("first", "other", "evidence"),
    [
        (b"\x05", b"\x7f", "its heartbeats alternate between two NMT states"),
        (b"\x00", None, "two boot-ups less than 0.5 s apart"),
    ],
    ids=["alternating-heartbeats", "boot-ups"],
)
def test_two_nodes_at_one_id_are_found_by_their_heartbeats(
    data_dir, capsys, first, other, evidence
):
    channel = unique_channel("twin-heartbeats")
    bus = can.Bus(interface="virtual", channel=channel)
    flood = Flood(bus, 0x70D, first, other, period_s=0.02)
    with serving_node(channel, 13, Fault.NONE):
        flood.start()
        try:
            code = main(["--list-devices", *bus_args(channel)])
        finally:
            flood.stop()
            bus.shutdown()
    out, err = capsys.readouterr()
    no_traceback(err)
    assert code == 4
    assert f"can:13\tnot identified\tnode 13: two nodes answer at this ID ({evidence})" in out


# --- bounded, exact uploads ----------------------------------------------------------------
@pytest.mark.parametrize("fault", [Fault.ENDLESS_NO_SIZE, Fault.ENDLESS_HUGE])
def test_an_endless_upload_ends_at_its_size_bound_with_the_abort_naming_the_object(fault):
    channel = unique_channel("endless")
    with (
        serving_node(channel, 11, fault) as node,
        channel_to(channel, 11) as sdo,
        pytest.raises(SdoTransferError) as caught,
    ):
        sdo.upload(0x100A, 0)
    assert caught.value.code is AbortCode.OUT_OF_MEMORY
    assert node.segments_sent <= STRING_MAX_BYTES // 7 + 1
    index_and_code = node.aborts[-1][1:4], node.aborts[-1][4:8]
    assert index_and_code == (b"\x0a\x10\x00", struct.pack("<I", 0x05040005))


@pytest.mark.parametrize(
    ("fault", "code"),
    [
        (Fault.SHORT, AbortCode.LENGTH_TOO_LOW),
        (Fault.LONG, AbortCode.LENGTH_TOO_HIGH),
        (Fault.NO_TOGGLE, AbortCode.TOGGLE_BIT),
        (Fault.OTHER_OBJECT, AbortCode.GENERAL_ERROR),
    ],
)
def test_an_upload_that_breaks_the_protocol_is_an_error_never_a_value(fault, code):
    channel = unique_channel("exact")
    with (
        serving_node(channel, 11, fault) as node,
        channel_to(channel, 11) as sdo,
        pytest.raises(SdoTransferError) as caught,
    ):
        sdo.upload(0x100A, 0)
    assert caught.value.code is code
    assert node.aborts[-1][:4] == b"\x80\x0a\x10\x00"
    assert "is the valve powered" not in str(caught.value)


@pytest.mark.parametrize("fault", [Fault.SHORT, Fault.NO_TOGGLE, Fault.LONG, Fault.ENDLESS_HUGE])
def test_a_node_whose_uploads_break_is_listed_not_identified_never_with_a_value(
    fault, data_dir, capsys
):
    channel = unique_channel("listing")
    with serving_node(channel, 11, fault):
        code = main(["--list-devices", *bus_args(channel)])
    out, err = capsys.readouterr()
    no_traceback(err)
    assert code == 4
    assert "can:11\tnot identified\tnode 11: not identified: 0x100A/0:" in out
    assert "serial 0" not in out and FIRMWARE[:10] + "\t" not in out


def test_an_answer_to_another_request_is_named_not_a_timeout():
    channel = unique_channel("other")
    with (
        serving_node(channel, 11, Fault.OTHER_OBJECT),
        channel_to(channel, 11) as sdo,
        pytest.raises(SdoTransferError, match="an answer to another request"),
    ):
        sdo.upload(0x1018, 4)


def test_a_timeout_after_answers_names_what_happened_and_aborts_with_the_index():
    channel = unique_channel("stopped")
    with (
        serving_node(channel, 11, Fault.ANSWERS_1000_ONLY) as node,
        channel_to(channel, 11, 0.1) as sdo,
    ):
        assert sdo.read_u32(0x1000, 0) == 0x198
        with pytest.raises(DeviceTimeoutError) as caught:
            sdo.upload(0x1018, 1)
    assert "no SDO answer for 0x1018/1" in str(caught.value)
    assert node.aborts[-1] == b"\x80\x18\x10\x01" + struct.pack("<I", 0x05040000)


def test_short_answer_frames_are_errors():
    channel = unique_channel("short-frames")
    with (
        serving_node(channel, 11, Fault.SHORT_FRAMES),
        channel_to(channel, 11) as sdo,
        pytest.raises(SdoTransferError, match="an answer of 3 bytes"),
    ):
        sdo.upload(0x1018, 4)


# --- values that decide what is written ----------------------------------------------------
def test_a_control_mode_no_prm9_has_is_refused_before_anything_is_written(
    data_dir, tmp_path, capsys
):
    channel = unique_channel("mode")
    with serving_node(channel, 11, Fault.NONE, objects=prm9_objects(control_mode=127)) as node:
        before = dict(node.objects)
        code = main(
            ["--batch", tuned_file(tmp_path, TYPE_KEY), "--device", "can:11", *bus_args(channel)]
        )
    err = capsys.readouterr().err
    no_traceback(err)
    assert code != 0
    assert "0x6043 = 127 is no control mode of a PRM9 (manual table 7-16)" in err
    assert node.objects == before and node.writes == []


@pytest.mark.parametrize(
    ("objects", "problem"),
    [
        ({(0x1018, 4): bytes(4)}, "serial number 0x1018/4 = 0 is no serial number"),
        (
            {(0x2041, 0): b"PRM9-what/ever"},
            "type key 0x2041 = 'PRM9-what/ever' is no PRM9 type key",
        ),
        ({(0x2041, 0): b"PRM9-06.3Z11/30-24E02S02"}, "has no -CA, but the valve speaks CANopen"),
        (
            {(0x6043, 0): b"\x04", (0x2041, 0): TYPE_KEY.encode()},
            "E02 valve, the valve's objects say E04",
        ),
    ],
    ids=["serial-0", "type-key", "no-CA", "mode-4-on-E02"],
)
def test_values_no_prm9_holds_make_the_node_not_identified(objects, problem):
    channel = unique_channel("values")
    shared = canbus.acquire(canbus.CanOptions("virtual", channel))
    try:
        with serving_node(channel, 11, Fault.NONE, objects={**prm9_objects(), **objects}):
            info = identify_node(shared, 11)
    finally:
        canbus.release(shared)
    assert not info.usable and problem in info.problem, info


def test_a_well_behaved_raw_node_is_identified():
    channel = unique_channel("good")
    shared = canbus.acquire(canbus.CanOptions("virtual", channel))
    try:
        with serving_node(channel, 11, Fault.NONE):
            info = identify_node(shared, 11)
    finally:
        canbus.release(shared)
    assert info.usable, info.problem
    assert (info.serial, info.firmware, info.type_key) == (777001, FIRMWARE, TYPE_KEY)
    assert CATALOGUE["FWVER"].is_string


def test_a_padded_answer_with_garbage_is_no_value_of_the_type(data_dir):
    from prm9tool.device.canlink.session import CanopenSession
    from prm9tool.errors import ProtocolError

    channel = unique_channel("padding")
    limta = CATALOGUE["LIMTA"]
    objects = {**prm9_objects(), limta.key: b"\x60\x09\x12\x34"}  # 2400, then garbage
    with (
        serving_node(channel, 11, Fault.NONE, objects=objects) as node,
        CanopenSession(canbus.CanOptions("virtual", channel), 11) as session,
    ):
        with pytest.raises(ProtocolError, match="is no UNSIGNED16"):
            session.read("LIMTA")
        node.objects[limta.key] = b"\x60\x09\x00\x00"  # zero padding: the value
        assert session.read("LIMTA") == 2400


@pytest.mark.parametrize("fault", [Fault.SHORT, Fault.NO_TOGGLE])
def test_a_download_from_a_node_whose_uploads_break_writes_no_file(
    fault, data_dir, tmp_path, capsys
):
    channel = unique_channel("download")
    out = tmp_path / "valve.prm"
    with serving_node(channel, 11, fault):
        code = main(["--batch", "--download", str(out), "--device", "can:11", *bus_args(channel)])
    err = capsys.readouterr().err
    no_traceback(err)
    assert code != 0 and not out.exists()
    assert "not identified: 0x100A/0:" in err

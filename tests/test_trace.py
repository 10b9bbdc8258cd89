"""Recording and decoding CAN traces (prm9tool.trace, docs/trace.md): a golden trace recorded
from two emulated valves commissioned by a ``canopen`` PLC, the same trace rewritten by
python-can in other formats, hand-written frames for what the valves do not do (block
transfers, remapping, other nodes), malformed files."""

from __future__ import annotations

import json
from pathlib import Path

import can
import pytest
from hypothesis import given
from hypothesis import strategies as st
from support.trace_rig import DEADLINE_MS, record_commissioning

import prm9tool.trace as trace
from prm9tool.catalogue import CATALOGUE
from prm9tool.trace.decoder import Decoder
from prm9tool.trace.events import Kind


@pytest.fixture(scope="module")
def golden(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, object]:
    path = tmp_path_factory.mktemp("trace") / "commissioning.asc"
    recorder = record_commissioning(path, "golden")
    return path, recorder


@pytest.fixture(scope="module")
def decoded(golden):
    return trace.read(golden[0])


def _texts(decoded, node: int, kind: Kind) -> list[str]:
    return [e.text for e in decoded.events if e.node == node and e.kind is kind]


def _states(decoded, node: int) -> list[str]:
    return [
        t.split("device state ")[1].split(" (")[0].split(" → ")[-1]
        for t in _texts(decoded, node, Kind.STATE)
        if t.startswith("device state")
    ]


def test_the_recorder_wrote_every_frame_on_the_bus(golden, decoded):
    _path, recorder = golden
    assert recorder.frames == recorder.written > 1000
    assert decoded.frames == recorder.written


def test_the_enable_sequence_decodes_as_state_transitions(decoded):
    assert _states(decoded, 15) == ["INIT", "DISABLED", "HOLD", "DEVICE_MODE_ACTIVE"]
    words = [t for t in _texts(decoded, 15, Kind.STATE) if t.startswith("control word")]
    assert [w.split("→ ")[-1].split()[0] if "→" in w else w.split()[2] for w in words] == [
        "0x0008", "0x0009", "0x000B", "0x000F",
    ]  # fmt: skip


def test_the_rpdo_deadline_fault_is_found_with_what_followed(decoded):
    assert _states(decoded, 10)[0] == "DEVICE_MODE_ACTIVE"
    assert _states(decoded, 10)[-1] in ("FAULT_HOLD", "FAULT", "FAULT_REACTION")
    emcy = _texts(decoded, 10, Kind.EMCY)
    assert len(emcy) == 1 and emcy[0].startswith("EMCY 0x8100: ")
    assert "RPDO not received within its event timer" in emcy[0]
    found = [i.what for i in decoded.incidents if i.node == 10]
    assert any(w.startswith("node 10: EMCY 0x8100") and "then device state" in w for w in found)
    assert any(w.startswith("node 10 left DEVICE_MODE_ACTIVE") for w in found)
    deadline = [t for t in _texts(decoded, 10, Kind.SDO) if "0x1400/5" in t]
    assert deadline == [
        f"SDO write (expedited) 0x1400/5: RPDO1 event timer (reception deadline, 0 = off) RPDO1TIMER = {DEADLINE_MS} ms"
    ]


def test_sdo_transfers_are_reassembled_with_names_values_and_aborts(decoded):
    sdo10, sdo15 = _texts(decoded, 10, Kind.SDO), _texts(decoded, 15, Kind.SDO)
    assert "SDO read (expedited) 0x1018/1: Vendor ID VENDORID = 230 (0xE6)" in sdo10
    firmware = CATALOGUE["FWVER"].default
    assert f"SDO read (segmented) 0x100A/0: Firmware version = {firmware!r}" in sdo10
    assert (
        "SDO read 0x1234/0 aborted: 0x06020000 object does not exist in the object dictionary"
        in sdo15
    )
    assert "SDO write (expedited) 0x1017/0: Producer heartbeat time HEARTBEAT = 100 ms" in sdo15


def test_pdos_are_decoded_by_the_mapping_in_force(decoded):
    """Node 15 was switched to control mode 4: its RPDO1 carries PRCSETP (table 7-13)."""
    rpdo10 = [e for e in decoded.events if e.node == 10 and e.text.startswith("RPDO1")]
    rpdo15 = [e for e in decoded.events if e.node == 15 and e.text.startswith("RPDO1")]
    assert {name for e in rpdo10 for name, _ in e.values} == {"CONTROLWORD", "POSSETP"}
    assert {name for e in rpdo15 for name, _ in e.values} == {"CONTROLWORD", "PRCSETP"}
    assert dict(rpdo15[-1].values)["PRCSETP"] == pytest.approx(8000 * 100 / 16384)
    tpdo10 = [dict(e.values) for e in decoded.events if e.node == 10 and e.text.startswith("TPDO1")]
    assert max(v["POSACT"] for v in tpdo10) > 10.0  # the spool followed the ramp


def test_every_frame_is_accounted_for(decoded):
    covered = {n for e in decoded.events for n in e.frames}
    assert covered == set(range(decoded.frames))
    assert decoded.not_understood == []
    assert decoded.sync.count == 400
    assert decoded.nodes == {10: "PRM9", 15: "PRM9"}


@pytest.mark.parametrize("suffix", [".blf", ".log", ".trc"])
def test_the_same_trace_written_by_python_can_decodes_the_same(golden, decoded, tmp_path, suffix):
    other = tmp_path / f"copy{suffix}"
    with can.Logger(str(other)) as logger:
        for msg in can.LogReader(str(golden[0])):
            logger.on_message_received(msg)
    again = trace.read(other)
    assert [(e.node, e.kind, e.text) for e in again.events] == [
        (e.node, e.kind, e.text) for e in decoded.events
    ]


# --- hand-written frames -------------------------------------------------------------------
def _decode(frames: list[str], eds=None):
    decoder = Decoder("frames", eds)
    for k, text in enumerate(frames):
        head, *data = text.split()
        decoder.feed(
            can.Message(
                timestamp=k * 0.001,
                arbitration_id=int(head, 16),
                data=bytes.fromhex("".join(data)),
                is_extended_id=False,
            )
        )
    return decoder.result()


def test_a_block_download_and_a_block_upload_are_reassembled():
    payload = bytes(range(10))  # 10 bytes: two segments, the last with 4 bytes unused
    frames = [
        "60A C6 08 10 00 0A 00 00 00",  # initiate block download, size 10
        "58A A4 08 10 00 7F 00 00 00",  # response, blksize 127
        "60A 01 " + payload[:7].hex(" "),
        "60A 82 " + (payload[7:] + bytes(4)).hex(" "),  # last segment of the block
        "58A A2 02 7F 00 00 00 00 00",  # block ack
        "60A D1 00 00 00 00 00 00 00",  # end, n = 4 bytes without data
        "58A A1 00 00 00 00 00 00 00",
        "60A A0 0A 10 00 7F 00 00 00",  # initiate block upload 0x100A
        "58A C6 0A 10 00 05 00 00 00",  # size 5
        "60A A3 00 00 00 00 00 00 00",  # start
        "58A 81 31 2E 30 2E 30 00 00",  # one segment, last
        "60A A2 01 7F 00 00 00 00 00",  # ack
        "58A C9 00 00 00 00 00 00 00",  # end, n = 2
        "60A A1 00 00 00 00 00 00 00",
    ]
    result = _decode(frames)
    texts = [e.text for e in result.events]
    assert texts[0] == "SDO write (block) 0x1008/0: Manufacturer device name = " + repr(
        payload.decode("latin-1")
    )
    assert texts[1] == "SDO read (block) 0x100A/0: Firmware version = '1.0.0'"
    assert [e.frames for e in result.events] == [tuple(range(7)), tuple(range(7, 14))]


def test_sdo_writes_in_the_trace_change_the_pdo_mapping():
    frames = [
        "18A 0F 00 40 1F",  # default TPDO1: status word, actual position
        "60A 23 00 18 01 8A 01 00 80",
        "58A 60 00 18 01 00 00 00 00",  # TPDO1 invalid
        "60A 2F 00 1A 00 00 00 00 00",
        "58A 60 00 1A 00 00 00 00 00",  # no entries
        "60A 23 00 1A 01 10 01 01 63",
        "58A 60 00 1A 01 00 00 00 00",  # entry 1: 0x6301/1
        "60A 2F 00 1A 00 01 00 00 00",
        "58A 60 00 1A 00 00 00 00 00",
        "60A 23 00 18 01 8A 01 00 00",
        "58A 60 00 18 01 00 00 00 00",  # valid again
        "18A 40 1F",
    ]
    pdos = [e for e in _decode(frames).events if e.kind is Kind.PDO]
    assert [dict(e.values) for e in pdos] == [
        {"STATUSWORD": 15, "POSACT": pytest.approx(48.828125)},
        {"POSACT": pytest.approx(48.828125)},
    ]


def test_nmt_lss_emcy_and_frames_nobody_uses_are_named():
    result = _decode(
        [
            "000 81 0A",
            "7E5 04 01",
            "7E4 11 00",
            "08A 10 32 01 00 00 00 00 00",
            "7F0 01",
            "70A 05 05",
        ]
    )
    texts = [e.text for e in result.events]
    assert texts[0] == "NMT reset node → node 10"
    assert texts[1] == "LSS master: switch state global → configuration"
    assert texts[2] == "LSS slave: configure node-ID done"
    assert texts[3].startswith("EMCY 0x3210: voltage inside the device (0x3210)")
    assert [e.kind for e in result.events[4:]] == [Kind.NOT_UNDERSTOOD] * 2


def test_a_node_that_is_no_prm9_is_raw_or_decoded_by_its_eds(tmp_path):
    from prm9tool.files.eds import export_eds

    frames = [
        "605 40 00 10 00 00 00 00 00",
        "585 43 00 10 00 91 01 00 00",
        "605 40 17 10 00 00 00 00 00",
        "585 4B 17 10 00 E8 03 00 00",
    ]
    raw = _decode(frames)
    assert raw.nodes == {5: "raw"}
    assert raw.events[1].text == "SDO read (expedited) 0x1017/0 = E8 03"
    eds = tmp_path / "other.eds"
    eds.write_text(export_eds("PRM9-06.3Z11/30-24E02S02-CA"), encoding="utf-8")
    named = _decode(frames, {None: eds})
    assert named.nodes == {5: "EDS other.eds"}
    assert named.events[1].text.startswith("SDO read (expedited) 0x1017/0: ")
    assert "= 1000" in named.events[1].text


# --- malformed files -----------------------------------------------------------------------
def test_a_malformed_candump_log_names_its_line(tmp_path):
    path = tmp_path / "bad.log"
    path.write_text("(1.000000) can0 70A#05\n(1.001000) can0 70A#05\n(1.002000) can0 garbage\n")
    with pytest.raises(trace.TraceFormatError) as info:
        trace.read(path)
    assert info.value.line == 3
    assert "line 3 (2 frames read before it)" in str(info.value)


def test_an_unknown_format_is_refused(tmp_path):
    with pytest.raises(trace.TraceFormatError, match=r"unknown trace format '\.txt'"):
        trace.read(tmp_path / "x.txt")


# --- the command line ----------------------------------------------------------------------
def test_the_cli_prints_the_trace_and_its_incidents(golden, capsys):
    from prm9tool.cli.main import main

    assert main(["--decode", str(golden[0])]) == 0
    out = capsys.readouterr().out
    assert "SDO read (segmented) 0x100A/0: Firmware version" in out
    assert "node 10: decoded as PRM9" in out
    assert "incidents: " in out and "left DEVICE_MODE_ACTIVE" in out
    assert main(["--decode", str(golden[0]), "--fail-on-incident"]) == 1


@pytest.mark.parametrize("suffix", [".log", ".asc"])
def test_the_cli_says_an_empty_trace_holds_no_frame(tmp_path, capsys, suffix):
    """Issue 34: an empty trace printed "events: " with nothing after it."""
    from prm9tool.cli.main import main

    path = tmp_path / f"empty{suffix}"
    path.write_text("", encoding="utf-8")
    assert main(["--decode", str(path)]) == 0
    out = capsys.readouterr().out
    assert out.splitlines()[0] == "0 frames; events: none (the trace holds no frame)"


def test_the_cli_writes_json_and_csv(golden, tmp_path, capsys):
    from prm9tool.cli.main import main

    out_json, out_csv = tmp_path / "t.json", tmp_path / "t.csv"
    assert main(["--decode", str(golden[0]), "--json", str(out_json), "--csv", str(out_csv)]) == 0
    data = json.loads(out_json.read_text())
    assert data["frames"] == len({n for e in data["events"] for n in e["frames"]})
    assert data["nodes"] == {"10": "PRM9", "15": "PRM9"}
    lines = out_csv.read_text().splitlines()
    assert lines[0] == "time_s,node,kind,text,frames,values"
    assert len(lines) == len(data["events"]) + 1


def test_the_cli_reports_a_malformed_trace_without_a_traceback(tmp_path, capsys):
    from prm9tool.cli.main import main

    path = tmp_path / "bad.log"
    path.write_text("(1.000000) can0 70A#05\n(1.0 can0\n")
    assert main(["--decode", str(path)]) == 3
    err = capsys.readouterr().err
    assert "line 2" in err and "Traceback" not in err


@pytest.mark.parametrize(
    ("argv", "problem"),
    [
        (["--csv", "x.csv"], "--csv belongs to --decode"),
        (["--duration", "3"], "--duration belongs to --record"),
        (
            ["--decode", "t.asc", "--batch", "x.prm"],
            "--decode reads a trace file and takes no --batch",
        ),
        (["--record", "t.txt"], "t.txt: a trace is one of"),
        (["--decode", "t.asc", "--eds", "200=x.eds"], "NODE=FILE with a node ID"),
        (["--speed", "2"], "--speed belongs to --replay"),
        (["--record", "t.asc", "--check", "x.prm"], "--record records a CAN bus beside"),
        (["--replay", "t.asc", "--only-node", "0"], "--only-node 0: CANopen node IDs are 1…127"),
        (["--replay", "t.asc", "--batch", "x.prm"], "--replay drives a bus from a trace"),
        (
            ["--decode", "t.asc", "--replay", "t.asc"],
            "--decode reads a trace file and takes no --replay",
        ),
    ],
)
def test_the_cli_refuses_options_that_do_not_fit(argv, problem, capsys):
    from prm9tool.cli.main import main

    assert main(argv) == 2
    assert problem in capsys.readouterr().err


def test_the_cli_records_the_bus_for_a_duration(tmp_path):
    from support.canopen_rig import unique_channel

    from prm9tool.cli.main import main

    channel = unique_channel("cli-record")
    path = tmp_path / "bus.log"
    sender = can.Bus(interface="virtual", channel=channel)
    try:
        import threading

        done = threading.Event()

        def send() -> None:
            while not done.is_set():
                sender.send(can.Message(arbitration_id=0x70A, data=b"\x05", is_extended_id=False))
                done.wait(0.01)

        thread = threading.Thread(target=send)
        thread.start()
        try:
            code = main(
                [
                    "--record",
                    str(path),
                    "--duration",
                    "0.3",
                    "--can-interface",
                    "virtual",
                    "--can-channel",
                    channel,
                ]
            )
        finally:
            done.set()
            thread.join()
    finally:
        sender.shutdown()
    assert code == 0
    result = trace.read(path)
    assert result.frames > 0 and {e.text for e in result.events} == {"heartbeat: operational"}


# --- replay --------------------------------------------------------------------------------
def test_a_replay_drives_an_emulated_valve_and_compares_its_answers(golden):
    """The PLC's frames to node 15 drive a fresh E04 valve: its SDO answers are the recorded
    ones, and it ends in DEVICE_MODE_ACTIVE as the recorded valve did."""
    from support.canopen_rig import unique_channel
    from support.trace_rig import SWITCHES, TYPE_KEYS
    from support.waiting import wait_for

    from prm9tool.device.canlink.bus import CanOptions
    from prm9tool.device.emulator import EmulatedValve
    from prm9tool.trace.replay import replay

    channel = unique_channel("replay")
    bus = can.Bus(interface="virtual", channel=channel)
    valve = EmulatedValve(TYPE_KEYS[15], serial=3015, switches=SWITCHES[15])
    slave = valve.connect_can(bus)
    valve.start()  # real time, as a valve on a desk
    try:
        wait_for(lambda: valve.status().nmt_state == "pre-operational", timeout_s=30)
        result = replay(golden[0], CanOptions("virtual", channel), only_node=15)
    finally:
        valve.stop()
        slave.stop()
        bus.shutdown()
    assert result.sent > 300
    assert [d for d in result.differences if d.what in ("SDO", "EMCY")] == []
    states = [e.text for e in result.replayed.events if e.kind is Kind.STATE and e.node == 15]
    assert states and "DEVICE_MODE_ACTIVE" in states[-1]


# --- recording beside a session -------------------------------------------------------------
def test_a_recording_shares_the_bus_of_a_session_and_sees_what_it_sends(tmp_path, request):
    """The recorder is a listener on the master a CANopen session uses (one bus): the trace
    holds the session's own SDO requests (sent, python-can does not receive them) and the
    valve's answers, decoded to the values the session read."""
    from support.can_link_rig import make_link_rig

    from prm9tool.device.canlink.bus import acquire, release
    from prm9tool.device.canlink.session import CanopenSession

    rig = make_link_rig(request.node.name, tmp_path)
    path = tmp_path / "session.asc"
    try:
        with trace.record(path, rig.options) as recorder:
            session = CanopenSession(rig.options, 10)
            try:
                shared = acquire(rig.options)
                assert shared.users == 3  # the recorder, the session, this look: one bus
                release(shared)
                heartbeat = session.read("HEARTBEAT")
            finally:
                session.close()
    finally:
        rig.close()
    assert recorder.frames == recorder.written
    decoded = trace.read(path)
    reads = [e.text for e in decoded.events if e.kind is Kind.SDO and "0x1017/0" in e.text]
    assert reads == [
        f"SDO read (expedited) 0x1017/0: Producer heartbeat time HEARTBEAT = {heartbeat} ms"
    ]
    assert decoded.not_understood == []


def test_the_api_names_stay_functions_when_their_modules_are_loaded():
    import prm9tool.trace.decoder
    import prm9tool.trace.recorder
    import prm9tool.trace.replay  # noqa: F401

    assert callable(trace.record) and callable(trace.read)


def test_the_cli_replay_reports_answers_that_did_not_come(golden, capsys):
    """Nobody on the bus: the replay sends the master's frames to node 15, waits for each SDO
    answer in vain and reports the missing answers (exit 1)."""
    from support.canopen_rig import unique_channel

    from prm9tool.cli.main import main

    channel = unique_channel("cli-replay")
    argv = ["--replay", str(golden[0]), "--only-node", "15", "--speed", "4"]
    code = main([*argv, "--can-interface", "virtual", "--can-channel", channel])
    out = capsys.readouterr().out
    assert code == 1
    assert "frames sent on virtual channel" in out
    assert "node 15, SDO: recorded ['SDO read (expedited) 0x1018/1" in out


def test_a_truncated_blf_is_an_error_not_a_shorter_trace(golden, tmp_path):
    whole = tmp_path / "whole.blf"
    with can.Logger(str(whole)) as logger:
        for msg in can.LogReader(str(golden[0])):
            logger.on_message_received(msg)
    data = whole.read_bytes()
    cut = tmp_path / "cut.blf"
    cut.write_bytes(data[: len(data) // 2])
    with pytest.raises(trace.TraceFormatError) as info:
        trace.read(cut)
    assert "cut.blf: not a valid BLF trace after frame " in str(info.value)
    assert f"the file is truncated: its header gives {len(data)} bytes" in str(info.value)


def test_a_trc_line_python_can_drops_is_an_error_with_its_line(golden, tmp_path):
    good = tmp_path / "good.trc"
    with can.Logger(str(good)) as logger:
        for msg in can.LogReader(str(golden[0])):
            logger.on_message_received(msg)
    lines = good.read_text().splitlines()
    first = next(k for k, line in enumerate(lines) if not line.startswith(";"))
    lines.insert(first + 3, "      7        30.000 DT")  # too few columns
    bad = tmp_path / "bad.trc"
    bad.write_text("\n".join(lines) + "\n")
    with pytest.raises(trace.TraceFormatError) as info:
        trace.read(bad)
    assert info.value.line == first + 4
    assert "Failed to parse message" in str(info.value)


# --- any frames at all ---------------------------------------------------------------------
_COBS = st.one_of(
    st.sampled_from([0x000, 0x080, 0x100, 0x7E4, 0x7E5, 0x08A, 0x18A, 0x20A, 0x28A, 0x30A]),
    st.sampled_from([0x58A, 0x60A, 0x70A, 0x58F, 0x60F]),
    st.integers(0, 0x7FF),
)
_FRAMES = st.lists(st.tuples(_COBS, st.binary(max_size=8), st.booleans()), max_size=40)


@given(_FRAMES)
def test_any_frames_decode_without_an_exception_and_every_frame_is_accounted_for(frames):
    decoder = Decoder("fuzz")
    for k, (cob, data, remote) in enumerate(frames):
        decoder.feed(can.Message(timestamp=k * 0.001, arbitration_id=cob, data=data,
                                 is_extended_id=False, is_remote_frame=remote and not data))  # fmt: skip
    result = decoder.result()
    assert {n for e in result.events for n in e.frames} == set(range(len(frames)))
    assert all(e.text for e in result.events)


def test_the_cli_records_beside_list_devices_on_its_bus(tmp_path, request, capsys):
    """``--record`` beside ``--list-devices``: one bus; the trace holds the scan's SDO requests
    (sent by prm9tool) and the valve's answers."""
    from support.can_link_rig import make_link_rig

    from prm9tool.cli.main import main

    rig = make_link_rig(request.node.name, tmp_path)
    path = tmp_path / "scan.log"
    bus = ["--can-interface", "virtual", "--can-channel", rig.options.channel]
    try:
        code = main(["--record", str(path), "--list-devices", *bus])
    finally:
        rig.close()
    assert code == 0 and "can:10" in capsys.readouterr().out
    decoded = trace.read(path)
    requests = {e.node for e in decoded.events if e.kind is Kind.SDO}
    assert 10 in requests and len(requests) > 100  # the scan asked every node ID
    assert decoded.nodes == {10: "PRM9"}  # the nodes heard: the one that answered
    assert any(
        e.text.startswith("SDO read (expedited) 0x1000/0") and e.node == 10 for e in decoded.events
    )


def test_a_bus_that_cannot_be_opened_leaves_the_chosen_file_as_it_was(tmp_path):
    """Record… on a PC without the adapter: no empty trace is left, an existing file is kept."""
    from prm9tool.device.canlink.bus import CanOptions
    from prm9tool.errors import CanAdapterError
    from prm9tool.trace.recorder import Recorder

    fresh, kept = tmp_path / "new.asc", tmp_path / "kept.asc"
    kept.write_text("an earlier trace\n", encoding="utf-8")
    for path in (fresh, kept):
        with pytest.raises(CanAdapterError):
            Recorder(path, CanOptions("no-such-interface", "x", None)).start()
    assert not fresh.exists()
    assert kept.read_text(encoding="utf-8") == "an earlier trace\n"

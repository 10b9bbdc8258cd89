"""Golden frames of the USB protocol: every message as the exact bytes on the wire.

The same frames appear in docs/usb-protocol.md; a change here is a protocol change.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

from prm9tool.device.emulator import EmulatedValve, Fault
from prm9tool.device.emulator.usb_firmware import UsbFirmware
from prm9tool.device.usb.protocol import (
    AbortReply,
    Done,
    Identify,
    IdentifyReply,
    MalformedReportError,
    Op,
    ReadEntries,
    ReadReply,
    Restart,
    RestoreFactory,
    SegmentRead,
    SegmentReadReply,
    SegmentWrite,
    SegmentWriteReply,
    StatusReply,
    StatusRequest,
    Store,
    StreamData,
    StreamStart,
    StreamStarted,
    StreamStop,
    WriteEntries,
    WriteReply,
    decode_request,
    decode_response,
    encode_request,
    encode_response,
    encode_stream,
    malformed_answer,
    pack_reads,
    pack_writes,
    segments,
)
from prm9tool.errors import AbortCode, ProtocolError


def frame(text: str) -> bytes:
    """Hex bytes, zero-padded to one 64-byte report."""
    data = bytes.fromhex(text)
    assert len(data) <= 64
    return data.ljust(64, b"\x00")


REQUESTS = [
    (1, Identify(), "01 01"),
    (7, ReadEntries(((0x1018, 4), (0x6301, 1))), "02 07 02 18 10 04 01 01 63 01 01"),
    (
        8,
        ReadEntries(((0x2000, 1), (0x2000, 2), (0x2000, 3), (0x6345, 1))),
        "02 08 02 00 20 01 03 45 63 01 01",
    ),
    (
        8,
        WriteEntries(((0x6345, 1, b"\x60\x09"), (0x2012, 0, b"\x05"))),
        "03 08 02 45 63 01 01 02 60 09 12 20 00 01 01 05",
    ),
    (
        9,
        WriteEntries(((0x6345, 1, b"\x60\x09"), (0x6345, 2, b"\x61\x09"))),
        "03 09 01 45 63 01 02 02 60 09 02 61 09",
    ),
    (9, SegmentRead(0x2041, 0, 56), "04 09 41 20 00 38 00"),
    (10, SegmentWrite(0x1008, 0, 4, 0, b"PRM9"), "05 0a 08 10 00 04 00 00 00 04 50 52 4d 39"),
    (11, Store(), "06 0b 73 61 76 65"),
    (12, RestoreFactory(), "07 0c 6c 6f 61 64"),
    (13, Restart(), "08 0d 62 6f 6f 74"),
    (14, StatusRequest(20), "09 0e 14"),
    (15, StreamStart((10, 15, 13), 1), "0a 0f 01 00 03 0a 0f 0d"),
    (16, StreamStop(), "0b 10"),
]


@pytest.mark.parametrize(("seq", "request_", "wire"), REQUESTS)
def test_request_golden_frames(seq, request_, wire):
    assert encode_request(seq, request_) == frame(wire)
    assert decode_request(frame(wire)) == (seq, request_)


ANSWERS = [
    (
        Op.IDENTIFY,
        1,
        IdentifyReply(1, 4242, "PRM9-06.3Z11/30-24E02S02", "1.0.0"),
        "81 01 00 01 92 10 00 00 88 13 18"
        + b"PRM9-06.3Z11/30-24E02S02".hex()
        + "05 31 2e 30 2e 30",
    ),
    (
        Op.READ,
        7,
        ReadReply((b"\x92\x10\x00\x00", int(AbortCode.NO_SUCH_OBJECT))),
        "82 07 00 02 04 92 10 00 00 ff 00 00 02 06",
    ),
    (Op.WRITE, 8, WriteReply(2), "83 08 00 02"),
    (
        Op.WRITE,
        8,
        AbortReply(AbortCode.VALUE_TOO_HIGH, 0x6345, 1, 0),
        "83 08 01 31 00 09 06 45 63 01 00",
    ),
    (Op.SEGMENT_READ, 9, SegmentReadReply(60, 56, b"abcd"), "84 09 00 3c 00 38 00 04 61 62 63 64"),
    (Op.SEGMENT_WRITE, 10, SegmentWriteReply(4, True), "85 0a 00 04 00 01"),
    (Op.STORE, 11, Done(), "86 0b 00"),
    (Op.STREAM_START, 15, StreamStarted(10), "8a 0f 00 0a"),
    (
        Op.STATUS,
        14,
        StatusReply(
            "DEVICE_MODE_ACTIVE",
            0x5411,
            0x81,
            False,
            False,
            "operational",
            (("red", "on", True), ("off", "off", False), ("green", "1Hz", False)),
            45.5,
            24.0,
            (0x5411,),
            3,
            0,
            b"abc",
        ),
        "89 0e 00 04 11 54 81 00 03 84 01 00 00 02 02 c6 11 c0 5d 01 11 54 03 00 03 61 62 63",
    ),
]


@pytest.mark.parametrize(("op", "seq", "answer", "wire"), ANSWERS)
def test_answer_golden_frames(op, seq, answer, wire):
    assert encode_response(op, seq, answer) == frame(wire)
    assert decode_response(frame(wire)) == (op, seq, answer)


def test_stream_golden_frame():
    data = StreamData(0x0102, 3, np.array([(1, -1, 16384), (2, -2, -16384)], dtype=np.int16))
    wire = frame("c0 02 01 c2 01 00 ff ff 00 40 02 00 fe ff 00 c0")
    assert encode_stream(data) == wire
    assert decode_response(wire) == data


def test_three_channels_at_5_khz_fit_one_report_per_two_milliseconds():
    assert StreamData.capacity(3) == 10  # 10 samples × 3 channels × 2 bytes + 4 header bytes
    assert StreamData.capacity(1) == 30


def test_malformed_request_gets_an_error_answer_naming_the_request():
    report = frame("02 05 00")  # READ with zero entries
    with pytest.raises(MalformedReportError, match="count 0"):
        decode_request(report)
    try:
        decode_request(report)
    except MalformedReportError as exc:
        answer = malformed_answer(report, exc)
    assert answer == frame("82 05 01 01 00 04 05 00 00 00 ff")


def test_unknown_opcode_is_answered_with_the_error_opcode():
    report = frame("7e 09 01 02")
    try:
        decode_request(report)
    except MalformedReportError as exc:
        answer = malformed_answer(report, exc)
    assert answer[:3] == bytes([0xFF, 0x09, 0x01])
    assert decode_response(answer) == (0xFF, 9, AbortReply(AbortCode.INVALID_COMMAND))


@pytest.mark.parametrize(
    ("wire", "reason"),
    [
        ("06 01 73 61 76 66", "wrong signature"),
        ("01 01 00 01", "non-zero bytes"),
        ("02 01 15", "count 21"),
        ("03 01 01 00 20 00 01 3c 01", "past the end"),
    ],
)
def test_request_checks(wire, reason):
    with pytest.raises(MalformedReportError, match=reason):
        decode_request(frame(wire))


def test_short_report_is_malformed():
    with pytest.raises(MalformedReportError, match="3 bytes, expected 64"):
        decode_request(b"\x01\x01\x00")


def test_invalid_answer_raises_protocol_error_with_the_bytes():
    with pytest.raises(ProtocolError, match=r"invalid report .*result code 7"):
        decode_response(frame("81 01 07"))
    with pytest.raises(ProtocolError, match="is not an answer"):
        decode_response(frame("01 01"))


def test_pack_reads_fills_reports_up_to_the_answer_room():
    run = [(0x2000, n, 2) for n in range(1, 46)]  # 45 16-bit values of one index
    assert [len(b.addresses) for b in pack_reads(run)] == [20, 20, 5]  # 60 answer bytes
    scattered = [(0x2000 + i, 1, 2) for i in range(45)]  # one run header each
    assert [len(b.addresses) for b in pack_reads(scattered)] == [15, 15, 15]
    big = [(0x2000, n, 4) for n in range(1, 16)]  # 4-byte values: 5 bytes per answer entry
    assert [len(b.addresses) for b in pack_reads(big)] == [12, 3]


def test_pack_writes_fills_reports():
    run = [(0x2000, n, b"\x01\x02") for n in range(1, 26)]  # 4 + 3 per entry
    assert [len(b.entries) for b in pack_writes(run)] == [19, 6]
    scattered = [(0x2000 + i, 1, b"\x01\x02") for i in range(25)]  # 7 bytes per entry
    batches = pack_writes(scattered)
    assert [len(b.entries) for b in batches] == [8, 8, 8, 1]
    for batch in batches:
        assert decode_request(encode_request(1, batch)) == (1, batch)


def test_run_past_subindex_255_is_malformed():
    with pytest.raises(MalformedReportError, match="passes subindex 255"):
        decode_request(frame("02 01 01 00 20 ff 02"))


def test_segments_split_long_values():
    data = bytes(range(120))
    parts = segments(0x1008, 0, data)
    assert [(p.offset, len(p.data)) for p in parts] == [(0, 54), (54, 54), (108, 12)]
    assert b"".join(p.data for p in parts) == data
    assert segments(0x1008, 0, b"") == [SegmentWrite(0x1008, 0, 0, 0, b"")]


def test_requests_know_whether_a_retry_is_safe():
    assert ReadEntries(((1, 1),)).idempotent and Store().idempotent
    assert not Restart().idempotent and not SegmentWrite(1, 1, 1, 0, b"x").idempotent


DOC = Path(__file__).parents[1] / "docs" / "usb-protocol.md"
FRAME_LINE = re.compile(r"([→←]) ((?:[0-9a-f]{2}(?: |$))+)(.*)")
CONTINUATION = re.compile(r"  ((?:[0-9a-f]{2}(?: |$))+)$")


def documented_frames() -> list[tuple[str, bytes]]:
    """The complete example frames of docs/usb-protocol.md (those shortened with … left out)."""
    frames: list[tuple[str, str, bool]] = []
    for block in re.findall(r"```\n(.*?)```", DOC.read_text(encoding="utf-8"), re.S):
        for line in block.splitlines():
            if match := FRAME_LINE.match(line):
                frames.append((match[1], match[2], match[3].lstrip().startswith("…")))
            elif frames and (match := CONTINUATION.match(line)):
                direction, text, shortened = frames[-1]
                frames[-1] = (direction, f"{text} {match[1]}", shortened)
    return [(d, bytes.fromhex(t).ljust(64, b"\x00")) for d, t, short in frames if not short]


def test_the_documented_frames_are_valid_and_canonical():
    frames = documented_frames()
    assert len(frames) >= 20
    for direction, report in frames:
        if direction == "→":
            seq, request = decode_request(report)
            assert encode_request(seq, request) == report
            continue
        decoded = decode_response(report)
        if isinstance(decoded, StreamData):
            assert encode_stream(decoded) == report
        else:
            assert encode_response(*decoded) == report, report.hex(" ")


def test_every_opcode_is_documented():
    text = DOC.read_text(encoding="utf-8")
    for op in Op:
        assert f"| `0x{op:02X}` | {op.name} |" in text


def documented_exchanges() -> list[list[tuple[str, bytes]]]:
    """The example blocks of docs/usb-protocol.md that send requests: their frames in order."""
    blocks = []
    for block in re.findall(r"```\n(.*?)```", DOC.read_text(encoding="utf-8"), re.S):
        frames: list[list[str]] = []
        for line in block.splitlines():
            if match := FRAME_LINE.match(line):
                frames.append([match[1], match[2]])
            elif frames and (match := CONTINUATION.match(line)):
                frames[-1][1] += f" {match[1]}"
        if any(direction == "→" for direction, _ in frames):
            blocks.append([(d, bytes.fromhex(t).ljust(64, b"\x00")) for d, t in frames])
    return blocks


def _status_example_valve(valve: EmulatedValve) -> None:
    """The situation the STATUS example shows (said in the document above it)."""
    valve.advance(3.0)
    valve.set_input("supply_voltage", 17.0)
    valve.inject(Fault.COIL_A_OPEN)
    valve.advance(0.5)


SITUATIONS = {Op.STATUS: _status_example_valve}


@pytest.mark.parametrize("block", documented_exchanges(), ids=lambda b: f"op{b[0][1][0]:02x}")
def test_the_documented_exchanges_are_what_the_firmware_answers(block):
    valve = EmulatedValve("PRM9-06.3Z11/30-24E04S02-CA", 4711, "1.0.0")
    SITUATIONS.get(block[0][1][0], lambda _valve: None)(valve)
    firmware = UsbFirmware.of(valve)
    answer = None
    for direction, report in block:
        if direction == "→":
            answer = firmware.handle(report)
        else:
            assert answer == report, f"the firmware answers {answer.rstrip(bytes(1)).hex(' ')}"
            answer = None
    assert answer is None, "a documented request without its answer"


def test_every_request_type_has_a_documented_exchange():
    sent = {report[0] for block in documented_exchanges() for d, report in block if d == "→"}
    assert sent >= {int(op) for op in Op}

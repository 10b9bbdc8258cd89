"""Encode and decode whole 64-byte reports: pure functions, used by host and firmware alike."""

from __future__ import annotations

import numpy as np

from prm9tool.device.usb.protocol.requests import (
    ERROR_OP,
    REQUEST_PARSERS,
    RESPONSE_FLAG,
    RESULT_ABORT,
    RESULT_OK,
    STREAM_DATA_OP,
    STREAM_MAX_CHANNELS,
    Request,
)
from prm9tool.device.usb.protocol.responses import (
    RESPONSE_PARSERS,
    AbortReply,
    Response,
    StreamData,
)
from prm9tool.device.usb.protocol.wire import MalformedReportError, Reader, Writer
from prm9tool.errors import AbortCode, ProtocolError


# --- codec -----------------------------------------------------------------------------------
def encode_request(seq: int, request: Request) -> bytes:
    """The 64-byte report of ``request`` with sequence number ``seq`` (0…255)."""
    w = Writer().u8(request.op).u8(seq)
    request.encode(w)
    return w.report()


def decode_request(report: bytes) -> tuple[int, Request]:
    """Parse a request report; raises :class:`MalformedReportError` saying what is wrong."""
    r = Reader(report, exact=True)
    op, seq = r.u8(), r.u8()
    parse = REQUEST_PARSERS.get(op)
    if parse is None:
        raise MalformedReportError(f"unknown opcode 0x{op:02X}", op, seq)
    try:
        request = parse(r)
        r.end()
    except MalformedReportError as exc:
        raise MalformedReportError(str(exc), op, seq) from None
    return seq, request


def encode_response(op: int, seq: int, response: Response) -> bytes:
    """The 64-byte answer to request ``op``/``seq`` (``op`` = ERROR_OP for junk)."""
    if isinstance(response, AbortReply):
        w = Writer().u8(op | RESPONSE_FLAG).u8(seq).u8(RESULT_ABORT)
    else:
        w = Writer().u8(op | RESPONSE_FLAG).u8(seq).u8(RESULT_OK)
    response.encode(w)
    return w.report()


def encode_stream(data: StreamData) -> bytes:
    """The 64-byte stream report of ``data``."""
    count = len(data.samples)
    if not 1 <= data.channels <= STREAM_MAX_CHANNELS or count > StreamData.capacity(data.channels):
        raise ValueError(f"{count} samples × {data.channels} channels do not fit one report")
    w = Writer().u8(STREAM_DATA_OP).u16(data.sequence & 0xFFFF)
    w.u8(data.channels << 6 | count)
    samples = np.asarray(data.samples)
    if samples.shape != (count, data.channels):
        raise ValueError(f"samples of shape {samples.shape}, expected ({count}, {data.channels})")
    w.raw(samples.astype("<i2").tobytes())
    return w.report()


def decode_response(report: bytes) -> tuple[int, int, Response] | StreamData:
    """Parse a valve report into ``(op, seq, response)`` or :class:`StreamData`.

    ``op`` is the request opcode the answer belongs to (``ERROR_OP`` for the answer to an
    unparseable report). Raises :class:`ProtocolError` for anything that is not a valid report.
    """
    r = Reader(report, exact=True)
    first = r.u8()
    try:
        if first == STREAM_DATA_OP:
            return _decode_stream(r)
        if not first & RESPONSE_FLAG:
            raise MalformedReportError(f"byte 0 = 0x{first:02X} is not an answer")
        op = ERROR_OP if first == ERROR_OP else first & ~RESPONSE_FLAG
        seq, result = r.u8(), r.u8()
        response = _decode_answer(op, result, r)
        r.end()
    except MalformedReportError as exc:
        raise ProtocolError(
            f"the valve sent an invalid report ({exc}): {report.hex(' ')}"
        ) from None
    return op, seq, response


def _decode_answer(op: int, result: int, r: Reader) -> Response:
    if result == RESULT_ABORT:
        return AbortReply.decode(r)
    if result != RESULT_OK or op == ERROR_OP:
        raise MalformedReportError(f"result code {result}")
    parse = RESPONSE_PARSERS.get(op)
    if parse is None:
        raise MalformedReportError(f"answer to unknown opcode 0x{op:02X}")
    return parse(r)


def _decode_stream(r: Reader) -> StreamData:
    sequence, shape = r.u16(), r.u8()
    channels, count = shape >> 6, shape & 0x3F
    if channels == 0 or count > StreamData.capacity(channels):
        raise MalformedReportError(f"stream shape {channels} channels × {count} samples")
    raw = r.raw(2 * channels * count)
    r.end()
    samples = np.frombuffer(raw, dtype="<i2").reshape(count, channels)
    return StreamData(sequence, channels, samples)


def malformed_answer(report: bytes, reason: MalformedReportError) -> bytes:
    """The answer the valve gives to a report it cannot parse (always well formed)."""
    seq = report[1] if len(report) > 1 else 0
    op = reason.op if reason.op in REQUEST_PARSERS else ERROR_OP
    return encode_response(op, seq, AbortReply(AbortCode.INVALID_COMMAND))

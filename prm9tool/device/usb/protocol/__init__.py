"""The prm9tool USB HID protocol: 64-byte reports ↔ messages, as pure functions.

Every report is 64 bytes. A request (host → valve) is ``[opcode, seq, body…]``; its answer
(valve → host) is ``[opcode | 0x80, seq, result, body…]`` with the same ``seq``. A report the
valve cannot parse is answered with opcode ``0xFF``. Stream data travel unsolicited as
``[0xC0, seq16, channels << 6 | samples, int16 samples…]``. Unused bytes are zero and must be
zero. Multi-byte numbers are little-endian. The byte-by-byte layout with examples is in
``docs/usb-protocol.md``. Nothing outside this package knows the wire format, so a different
protocol can replace it without touching the session, the transports' logic or the emulator.
"""

from prm9tool.device.usb.protocol.codec import (
    decode_request,
    decode_response,
    encode_request,
    encode_response,
    encode_stream,
    malformed_answer,
)
from prm9tool.device.usb.protocol.packing import pack_reads, pack_writes, segments
from prm9tool.device.usb.protocol.requests import (
    ERROR_OP,
    MAX_SEGMENTED_LENGTH,
    PROTOCOL_VERSION,
    SEGMENT_READ_CHUNK,
    SEGMENT_WRITE_CHUNK,
    STREAM_BASE_RATE_HZ,
    STREAM_DATA_OP,
    STREAM_MAX_CHANNELS,
    Identify,
    Nmt,
    Op,
    ReadEntries,
    Reload,
    Request,
    Restart,
    RestoreFactory,
    SegmentRead,
    SegmentWrite,
    Store,
    StreamStart,
    StreamStop,
    WriteEntries,
)
from prm9tool.device.usb.protocol.responses import (
    AbortReply,
    Done,
    IdentifyReply,
    ReadReply,
    Response,
    SegmentReadReply,
    SegmentWriteReply,
    StreamData,
    StreamStarted,
    WriteReply,
)
from prm9tool.device.usb.protocol.status import StatusReply, StatusRequest
from prm9tool.device.usb.protocol.wire import BODY_SIZE, REPORT_SIZE, MalformedReportError

__all__ = [
    "BODY_SIZE",
    "ERROR_OP",
    "MAX_SEGMENTED_LENGTH",
    "PROTOCOL_VERSION",
    "REPORT_SIZE",
    "SEGMENT_READ_CHUNK",
    "SEGMENT_WRITE_CHUNK",
    "STREAM_BASE_RATE_HZ",
    "STREAM_DATA_OP",
    "STREAM_MAX_CHANNELS",
    "AbortReply",
    "Done",
    "Identify",
    "IdentifyReply",
    "MalformedReportError",
    "Nmt",
    "Op",
    "ReadEntries",
    "ReadReply",
    "Reload",
    "Request",
    "Response",
    "Restart",
    "RestoreFactory",
    "SegmentRead",
    "SegmentReadReply",
    "SegmentWrite",
    "SegmentWriteReply",
    "StatusReply",
    "StatusRequest",
    "Store",
    "StreamData",
    "StreamStart",
    "StreamStarted",
    "StreamStop",
    "WriteEntries",
    "WriteReply",
    "decode_request",
    "decode_response",
    "encode_request",
    "encode_response",
    "encode_stream",
    "malformed_answer",
    "pack_reads",
    "pack_writes",
    "segments",
]

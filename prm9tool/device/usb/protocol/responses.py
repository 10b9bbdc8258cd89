"""Answers of the USB protocol (valve → host) and the unsolicited stream report."""

from __future__ import annotations

import struct
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from prm9tool.device.usb.protocol.requests import (
    ABORT_ENTRY,
    MAX_READ_ENTRIES,
    NO_POSITION,
    SEGMENT_READ_CHUNK,
    STREAM_BASE_RATE_HZ,
    STREAM_SAMPLE_BYTES,
    Op,
)
from prm9tool.device.usb.protocol.status import StatusReply
from prm9tool.device.usb.protocol.wire import Reader, Writer
from prm9tool.errors import AbortCode

_ABORTED = struct.Struct("<BI")  # a READ answer entry refused: ABORT_ENTRY, abort code


# --- responses -------------------------------------------------------------------------------
@dataclass(frozen=True)
class IdentifyReply:
    """Who the valve is."""

    protocol_version: int
    serial: int
    type_key: str
    firmware: str
    stream_base_hz: int = STREAM_BASE_RATE_HZ

    def encode(self, w: Writer) -> None:
        """Write the body: version, serial (u32), base rate (u16), type key, firmware."""
        w.u8(self.protocol_version).u32(self.serial).u16(self.stream_base_hz)
        w.text(self.type_key).text(self.firmware)

    @classmethod
    def decode(cls, r: Reader) -> IdentifyReply:
        """Parse the body."""
        version, serial, base = r.u8(), r.u32(), r.u16()
        return cls(version, serial, r.text(), r.text(), base)


@dataclass(frozen=True)
class ReadReply:
    """Values in request order: bytes, or an int CiA 301 abort code for a refused entry.

    The valve answers as many entries as fit in one report; the host asks again for the rest.
    """

    values: tuple[bytes | int, ...]

    def encode(self, w: Writer) -> None:
        """Write the body: count, then length + data, or 0xFF + abort code (u32), per entry."""
        # Built in one buffer, not field by field: an upload answers ~140 entries (the ranges
        # are still checked: bytearray refuses a count or length > 255, struct a code > u32).
        body = bytearray((len(self.values),))
        for value in self.values:
            if isinstance(value, int):
                try:
                    body += _ABORTED.pack(ABORT_ENTRY, value)
                except struct.error as exc:
                    raise ValueError(f"{value!r} does not fit an abort code ({exc})") from None
            else:
                body.append(len(value))
                body += value
        w.raw(body)

    @classmethod
    def decode(cls, r: Reader) -> ReadReply:
        """Parse the body."""
        values: list[bytes | int] = []
        for _ in range(r.count(0, MAX_READ_ENTRIES)):
            length = r.u8()
            values.append(r.u32() if length == ABORT_ENTRY else r.raw(length))
        return cls(tuple(values))

    @staticmethod
    def entry_size(value: bytes | int) -> int:
        """Bytes one entry takes in the answer."""
        return 5 if isinstance(value, int) else 1 + len(value)


@dataclass(frozen=True)
class WriteReply:
    """How many entries the valve wrote (all of them: a refusal is an :class:`AbortReply`)."""

    count: int

    def encode(self, w: Writer) -> None:
        """Write the body: count."""
        w.u8(self.count)

    @classmethod
    def decode(cls, r: Reader) -> WriteReply:
        """Parse the body."""
        return cls(r.u8())


@dataclass(frozen=True)
class SegmentReadReply:
    """``data`` = bytes ``offset``… of a value ``total`` bytes long."""

    total: int
    offset: int
    data: bytes

    def encode(self, w: Writer) -> None:
        """Write the body: total (u16), offset (u16), length, data."""
        w.u16(self.total).u16(self.offset).u8(len(self.data)).raw(self.data)

    @classmethod
    def decode(cls, r: Reader) -> SegmentReadReply:
        """Parse the body."""
        total, offset = r.u16(), r.u16()
        return cls(total, offset, r.raw(r.count(0, SEGMENT_READ_CHUNK)))


@dataclass(frozen=True)
class SegmentWriteReply:
    """Bytes received so far; ``complete`` once the value has been written."""

    received: int
    complete: bool

    def encode(self, w: Writer) -> None:
        """Write the body: received (u16), complete (u8)."""
        w.u16(self.received).u8(int(self.complete))

    @classmethod
    def decode(cls, r: Reader) -> SegmentWriteReply:
        """Parse the body."""
        return cls(r.u16(), bool(r.flag()))


@dataclass(frozen=True)
class Done:
    """Plain acknowledgement (store, restore factory, restart, reload, stream stop)."""

    def encode(self, w: Writer) -> None:
        """Write the body (empty)."""

    @classmethod
    def decode(cls, r: Reader) -> Done:
        """Parse the body."""
        return cls()


@dataclass(frozen=True)
class StreamStarted:
    """The stream runs; each stream report carries ``samples_per_report`` samples per channel."""

    samples_per_report: int

    def encode(self, w: Writer) -> None:
        """Write the body: samples per report."""
        w.u8(self.samples_per_report)

    @classmethod
    def decode(cls, r: Reader) -> StreamStarted:
        """Parse the body."""
        return cls(r.u8())


@dataclass(frozen=True)
class AbortReply:
    """The request was refused: CiA 301 ``code``, the entry it concerns and its position."""

    code: int
    index: int = 0
    subindex: int = 0
    position: int = NO_POSITION

    def encode(self, w: Writer) -> None:
        """Write the body: code (u32), index (u16), subindex, position."""
        w.u32(self.code).u16(self.index).u8(self.subindex).u8(self.position)

    @classmethod
    def decode(cls, r: Reader) -> AbortReply:
        """Parse the body."""
        return cls(r.u32(), r.u16(), r.u8(), r.u8())

    @property
    def text(self) -> str:
        """The abort code's explanation."""
        try:
            return AbortCode(self.code).text
        except ValueError:
            return "unknown abort code"


@dataclass(frozen=True, eq=False)
class StreamData:
    """One stream report: ``samples`` = int16 array of shape (instants, channels), raw values.

    An array, not tuples: at 3 × 5 kHz the host must not build a Python object per sample.
    """

    sequence: int
    channels: int
    samples: np.ndarray

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, StreamData):
            return NotImplemented
        return (
            (self.sequence, self.channels) == (other.sequence, other.channels)
            and self.samples.shape == other.samples.shape
            and bool(np.array_equal(self.samples, other.samples))
        )

    __hash__ = None  # type: ignore[assignment]

    @staticmethod
    def capacity(channels: int) -> int:
        """Samples per channel that fit in one report."""
        return STREAM_SAMPLE_BYTES // (2 * channels)


Response = (
    IdentifyReply
    | ReadReply
    | WriteReply
    | SegmentReadReply
    | SegmentWriteReply
    | Done
    | StatusReply
    | StreamStarted
    | AbortReply
)
RESPONSE_PARSERS: dict[int, Callable[[Reader], Response]] = {
    Op.IDENTIFY: IdentifyReply.decode,
    Op.READ: ReadReply.decode,
    Op.WRITE: WriteReply.decode,
    Op.SEGMENT_READ: SegmentReadReply.decode,
    Op.SEGMENT_WRITE: SegmentWriteReply.decode,
    Op.STORE: Done.decode,
    Op.RESTORE_FACTORY: Done.decode,
    Op.RESTART: Done.decode,
    Op.STATUS: StatusReply.decode,
    Op.STREAM_START: StreamStarted.decode,
    Op.STREAM_STOP: Done.decode,
    Op.RELOAD: Done.decode,
    Op.NMT: Done.decode,
}

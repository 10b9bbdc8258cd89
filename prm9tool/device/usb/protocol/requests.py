"""Requests of the USB protocol (host → valve): one dataclass per opcode, body codec included.

Each request knows its opcode, whether the transport may repeat it after a lost answer
(``idempotent``), and how its body is written and parsed. Layouts: docs/usb-protocol.md.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from enum import IntEnum

from prm9tool.catalogue.commissioning import NmtCommand
from prm9tool.device.usb.protocol.status import StatusRequest
from prm9tool.device.usb.protocol.wire import BODY_SIZE, MalformedReportError, Reader, Writer

PROTOCOL_VERSION = 1
RESPONSE_FLAG = 0x80
ERROR_OP = 0xFF  # answer to a report whose opcode the valve does not know or cannot parse
STREAM_DATA_OP = 0xC0
ABORT_ENTRY = 0xFF  # length byte of a READ answer entry that carries an abort code instead
RESULT_OK, RESULT_ABORT = 0, 1
NO_POSITION = 0xFF
MAX_RUNS = (BODY_SIZE - 1) // 4  # runs of consecutive subindices in one READ/WRITE (15)
MAX_READ_ENTRIES = BODY_SIZE - 2  # entries one READ answer can carry (1 length byte each)
SEGMENT_READ_CHUNK = BODY_SIZE - 6  # data bytes in one SEGMENT_READ answer (56)
SEGMENT_WRITE_CHUNK = BODY_SIZE - 8  # data bytes in one SEGMENT_WRITE request (54)
MAX_SEGMENTED_LENGTH = 1024  # longest value a segmented transfer carries (decision)
STREAM_BASE_RATE_HZ = 5000  # one sample per 200 µs controller cycle
STREAM_MAX_CHANNELS = 3
STREAM_SAMPLE_BYTES = BODY_SIZE - 2  # 60 bytes of int16 samples after the stream header
SIGNATURES = {  # CiA 301 style (0x1010 "save", 0x1011 "load")
    "store": b"save",
    "restore": b"load",
    "restart": b"boot",
    "reload": b"rvrt",
}


class Op(IntEnum):
    """Request opcodes (byte 0 of a request; the answer carries ``op | 0x80``)."""

    IDENTIFY = 0x01
    READ = 0x02
    WRITE = 0x03
    SEGMENT_READ = 0x04
    SEGMENT_WRITE = 0x05
    STORE = 0x06
    RESTORE_FACTORY = 0x07
    RESTART = 0x08
    STATUS = 0x09
    STREAM_START = 0x0A
    STREAM_STOP = 0x0B
    RELOAD = 0x0C
    NMT = 0x0D


# --- request messages --------------------------------------------------------------------------------
@dataclass(frozen=True)
class Identify:
    """Ask for type key, serial number, firmware version and protocol version."""

    op = Op.IDENTIFY
    idempotent = True

    def encode(self, w: Writer) -> None:
        """Write the body (empty)."""

    @classmethod
    def decode(cls, r: Reader) -> Identify:
        """Parse the body."""
        return cls()


def runs(keys: Sequence[tuple[int, int]]) -> list[tuple[int, int, int]]:
    """Group addresses into runs ``(index, first subindex, count)`` of consecutive subindices."""
    groups: list[tuple[int, int, int]] = []
    for index, subindex in keys:
        if groups:
            last_index, first, count = groups[-1]
            if last_index == index and first + count == subindex and count < 255:
                groups[-1] = (index, first, count + 1)
                continue
        groups.append((index, subindex, 1))
    return groups


def _read_run(r: Reader) -> tuple[int, int, int]:
    index, first, count = r.run(1)
    if first + count > 256:
        raise MalformedReportError(f"run 0x{index:04X}/{first} × {count} passes subindex 255")
    return index, first, count


@dataclass(frozen=True)
class ReadEntries:
    """Read several object-dictionary entries: ``addresses`` = ((index, subindex), …).

    On the wire, consecutive subindices of one index travel as one run (index, first, count).
    """

    addresses: tuple[tuple[int, int], ...]
    op = Op.READ
    idempotent = True

    def encode(self, w: Writer) -> None:
        """Write the body: run count, then index (u16), first subindex, count per run."""
        groups = runs(self.addresses)
        w.u8(len(groups))
        for index, first, count in groups:
            w.run(index, first, count)

    @classmethod
    def decode(cls, r: Reader) -> ReadEntries:
        """Parse the body."""
        addresses = []
        for _ in range(r.count(1, MAX_RUNS)):
            index, first, count = _read_run(r)
            addresses += [(index, first + n) for n in range(count)]
        if len(addresses) > MAX_READ_ENTRIES:
            raise MalformedReportError(f"{len(addresses)} entries; at most {MAX_READ_ENTRIES}")
        return cls(tuple(addresses))


@dataclass(frozen=True)
class WriteEntries:
    """Write several entries: ``entries`` = ((index, subindex, encoded value), …).

    On the wire, consecutive subindices of one index travel as one run: index, first
    subindex, count, then length + data per entry.
    """

    entries: tuple[tuple[int, int, bytes], ...]
    op = Op.WRITE
    idempotent = True  # absolute values: writing the same report twice leaves the same state

    def encode(self, w: Writer) -> None:
        """Write the body: run count, then per run index, first, count, (length, data)…"""
        groups = runs([(index, subindex) for index, subindex, _ in self.entries])
        w.u8(len(groups))
        values = iter(self.entries)
        for index, first, count in groups:
            w.run(index, first, count)
            for _ in range(count):
                w.sized(next(values)[2])

    @classmethod
    def decode(cls, r: Reader) -> WriteEntries:
        """Parse the body."""
        entries = []
        for _ in range(r.count(1, MAX_RUNS)):
            index, first, count = _read_run(r)
            entries += [(index, first + n, r.sized()) for n in range(count)]
        return cls(tuple(entries))


@dataclass(frozen=True)
class SegmentRead:
    """Read ``SEGMENT_READ_CHUNK`` bytes of a long value, starting at ``offset``."""

    index: int
    subindex: int
    offset: int = 0
    op = Op.SEGMENT_READ
    idempotent = True

    def encode(self, w: Writer) -> None:
        """Write the body: index, subindex, offset (u16)."""
        w.u16(self.index).u8(self.subindex).u16(self.offset)

    @classmethod
    def decode(cls, r: Reader) -> SegmentRead:
        """Parse the body."""
        return cls(r.u16(), r.u8(), r.u16())


@dataclass(frozen=True)
class SegmentWrite:
    """One piece of a long value; the valve writes the value when ``total`` bytes arrived."""

    index: int
    subindex: int
    total: int
    offset: int
    data: bytes
    op = Op.SEGMENT_WRITE
    idempotent = False  # the valve's assembly buffer has state

    def encode(self, w: Writer) -> None:
        """Write the body: index, subindex, total (u16), offset (u16), length, data."""
        w.u16(self.index).u8(self.subindex).u16(self.total).u16(self.offset)
        w.u8(len(self.data)).raw(self.data)

    @classmethod
    def decode(cls, r: Reader) -> SegmentWrite:
        """Parse the body."""
        index, subindex, total, offset = r.u16(), r.u8(), r.u16(), r.u16()
        return cls(index, subindex, total, offset, r.raw(r.count(0, SEGMENT_WRITE_CHUNK)))


@dataclass(frozen=True)
class _Signed:
    """A command guarded by a 4-byte signature, so that junk can never trigger it."""

    name = ""

    def encode(self, w: Writer) -> None:
        """Write the signature."""
        w.raw(SIGNATURES[self.name])

    @classmethod
    def decode(cls, r: Reader) -> _Signed:
        """Parse and check the signature."""
        if r.raw(4) != SIGNATURES[cls.name]:
            raise MalformedReportError(f"{cls.name}: wrong signature")
        return cls()


@dataclass(frozen=True)
class Store(_Signed):
    """Copy the working parameters to non-volatile memory (signature ``save``)."""

    name = "store"
    op = Op.STORE
    idempotent = True  # storing the same RAM twice gives the same non-volatile image


@dataclass(frozen=True)
class RestoreFactory(_Signed):
    """Reset the non-volatile image to factory values (effective after restart; ``load``)."""

    name = "restore"
    op = Op.RESTORE_FACTORY
    idempotent = True


@dataclass(frozen=True)
class Restart(_Signed):
    """Power-cycle the electronics (signature ``boot``); answered before the restart."""

    name = "restart"
    op = Op.RESTART
    idempotent = False


@dataclass(frozen=True)
class Reload(_Signed):
    """Working parameters ← the stored non-volatile image, without a restart (``rvrt``).

    The valve keeps running (a restart would move the spool); used after a failed upload so
    that the valve does not go on with a half-written parameter set.
    """

    name = "reload"
    op = Op.RELOAD
    idempotent = True  # reloading the same image twice gives the same working values


@dataclass(frozen=True)
class StreamStart:
    """Stream measuring points ``codes`` (signals.py codes) at 5000 Hz / ``decimation``."""

    codes: tuple[int, ...]
    decimation: int = 1
    op = Op.STREAM_START
    idempotent = False  # restarts the stream sequence numbers

    def encode(self, w: Writer) -> None:
        """Write the body: decimation (u16), count, one code byte per channel."""
        w.u16(self.decimation).u8(len(self.codes))
        for code in self.codes:
            w.u8(code)

    @classmethod
    def decode(cls, r: Reader) -> StreamStart:
        """Parse the body."""
        decimation = r.u16()
        count = r.count(1, STREAM_MAX_CHANNELS)
        return cls(tuple(r.u8() for _ in range(count)), decimation)


@dataclass(frozen=True)
class StreamStop:
    """Stop streaming."""

    op = Op.STREAM_STOP
    idempotent = True

    def encode(self, w: Writer) -> None:
        """Write the body (empty)."""

    @classmethod
    def decode(cls, r: Reader) -> StreamStop:
        """Parse the body."""
        return cls()


NMT_COMMANDS = frozenset(int(c) for c in NmtCommand)


@dataclass(frozen=True)
class Nmt:
    """An NMT command for the valve itself, as if its CANopen master had sent it on the bus
    (CiA 301 command specifier: 01h start, 02h stop, 80h pre-operational, 81h reset node,
    82h reset communication)."""

    command: int
    op = Op.NMT

    @property
    def idempotent(self) -> bool:
        """Start, stop and pre-operational may be repeated; a reset may not."""
        return self.command in (NmtCommand.START, NmtCommand.STOP, NmtCommand.PRE_OPERATIONAL)

    def encode(self, w: Writer) -> None:
        """Write the body: the command specifier (u8)."""
        w.u8(self.command)

    @classmethod
    def decode(cls, r: Reader) -> Nmt:
        """Parse the body; an unknown command specifier is malformed."""
        command = r.u8()
        if command not in NMT_COMMANDS:
            raise MalformedReportError(f"unknown NMT command 0x{command:02X}")
        return cls(command)


Request = (
    Identify
    | ReadEntries
    | WriteEntries
    | SegmentRead
    | SegmentWrite
    | Store
    | RestoreFactory
    | Restart
    | Reload
    | StatusRequest
    | StreamStart
    | StreamStop
    | Nmt
)
REQUEST_PARSERS: dict[int, Callable[[Reader], Request]] = {
    Op.IDENTIFY: Identify.decode,
    Op.READ: ReadEntries.decode,
    Op.WRITE: WriteEntries.decode,
    Op.SEGMENT_READ: SegmentRead.decode,
    Op.SEGMENT_WRITE: SegmentWrite.decode,
    Op.STORE: Store.decode,  # type: ignore[dict-item]
    Op.RESTORE_FACTORY: RestoreFactory.decode,  # type: ignore[dict-item]
    Op.RESTART: Restart.decode,  # type: ignore[dict-item]
    Op.STATUS: StatusRequest.decode,
    Op.STREAM_START: StreamStart.decode,
    Op.STREAM_STOP: StreamStop.decode,
    Op.RELOAD: Reload.decode,  # type: ignore[dict-item]
    Op.NMT: Nmt.decode,
}

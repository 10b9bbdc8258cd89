"""Byte-level helpers of the USB protocol: fixed 64-byte reports, little-endian fields."""

from __future__ import annotations

import struct

from prm9tool.errors import ProtocolError

REPORT_SIZE = 64  # USB full-speed HID interrupt report
HEADER_SIZE = 2  # opcode, sequence number
BODY_SIZE = REPORT_SIZE - HEADER_SIZE  # 62
_FIELDS = {fmt: struct.Struct("<" + fmt) for fmt in "BHhI"}  # compiled once: a report is
_B, _H, _h, _I = (_FIELDS[fmt] for fmt in "BHhI")  # built and parsed field by field
_RUN = struct.Struct("<HBB")  # index, first subindex, count: one run of consecutive entries


class MalformedReportError(ProtocolError):
    """A report that does not follow the protocol; ``op``/``seq`` as far as they were read."""

    def __init__(self, reason: str, op: int = -1, seq: int = 0) -> None:
        super().__init__(reason)
        self.op = op
        self.seq = seq


class Writer:
    """Builds one report; every field is range-checked (a host bug fails loudly)."""

    def __init__(self) -> None:
        self._data = bytearray()

    def _pack(self, field: struct.Struct, value: int) -> Writer:
        try:
            self._data += field.pack(value)
        except struct.error as exc:
            raise ValueError(f"{value!r} does not fit the field ({exc})") from None
        return self

    def u8(self, value: int) -> Writer:
        """Append an unsigned byte."""
        return self._pack(_B, value)

    def u16(self, value: int) -> Writer:
        """Append an unsigned 16-bit number."""
        return self._pack(_H, value)

    def i16(self, value: int) -> Writer:
        """Append a signed 16-bit number."""
        return self._pack(_h, value)

    def u32(self, value: int) -> Writer:
        """Append an unsigned 32-bit number."""
        return self._pack(_I, value)

    def run(self, index: int, first: int, count: int) -> Writer:
        """Append a run of entries: index (u16), first subindex and count (u8 each)."""
        try:
            self._data += _RUN.pack(index, first, count)
        except struct.error as exc:
            raise ValueError(f"run {index!r}/{first!r} × {count!r} does not fit ({exc})") from None
        return self

    def sized(self, data: bytes) -> Writer:
        """Append a length byte and the bytes."""
        if len(data) > 0xFF:
            raise ValueError(f"{len(data)} bytes do not fit a length byte")
        self._data.append(len(data))
        self._data += data
        return self

    def raw(self, data: bytes | bytearray) -> Writer:
        """Append bytes as they are."""
        self._data += data
        return self

    def text(self, value: str) -> Writer:
        """Append a length byte and the UTF-8 text."""
        data = value.encode("utf-8")
        return self.u8(len(data)).raw(data)

    def report(self) -> bytes:
        """The finished report, zero-padded to 64 bytes."""
        if len(self._data) > REPORT_SIZE:
            raise ValueError(f"report of {len(self._data)} bytes exceeds {REPORT_SIZE}")
        return bytes(self._data.ljust(REPORT_SIZE, b"\x00"))


class Reader:
    """Reads fields from a report; any inconsistency raises :class:`MalformedReportError`."""

    def __init__(self, data: bytes, *, exact: bool = True) -> None:
        if exact and len(data) != REPORT_SIZE:
            raise MalformedReportError(f"report has {len(data)} bytes, expected {REPORT_SIZE}")
        self._data = bytes(data)
        self._pos = 0

    def _unpack(self, field: struct.Struct) -> int:
        position = self._pos
        end = position + field.size
        if end > len(self._data):
            raise MalformedReportError(f"field at byte {position} runs past the end of the report")
        self._pos = end
        return int(field.unpack_from(self._data, position)[0])

    def u8(self) -> int:
        """Next unsigned byte."""
        position = self._pos
        if position >= len(self._data):
            raise MalformedReportError(f"field at byte {position} runs past the end of the report")
        self._pos = position + 1
        return self._data[position]

    def u16(self) -> int:
        """Next unsigned 16-bit number."""
        return self._unpack(_H)

    def i16(self) -> int:
        """Next signed 16-bit number."""
        return self._unpack(_h)

    def u32(self) -> int:
        """Next unsigned 32-bit number."""
        return self._unpack(_I)

    def raw(self, size: int) -> bytes:
        """Next ``size`` bytes."""
        end = self._pos + size
        if end > len(self._data):
            raise MalformedReportError(f"field at byte {self._pos} runs past the end of the report")
        chunk = self._data[self._pos : end]
        self._pos = end
        return chunk

    def run(self, lowest: int) -> tuple[int, int, int]:
        """Next run of entries: index (u16), first subindex, count (``lowest``…255)."""
        position = self._pos
        end = position + _RUN.size
        if end > len(self._data):
            raise MalformedReportError(f"field at byte {position} runs past the end of the report")
        self._pos = end
        index, first, count = _RUN.unpack_from(self._data, position)
        if count < lowest:
            raise MalformedReportError(f"byte {position + 3}: count {count} not in {lowest}…255")
        return index, first, count

    def sized(self) -> bytes:
        """Next length byte and that many bytes."""
        position = self._pos
        data = self._data
        if position >= len(data):
            raise MalformedReportError(f"field at byte {position} runs past the end of the report")
        end = position + 1 + data[position]
        if end > len(data):
            raise MalformedReportError(f"field at byte {position} runs past the end of the report")
        self._pos = end
        return data[position + 1 : end]

    def count(self, lowest: int, highest: int) -> int:
        """Next byte as a count that must lie in ``lowest…highest``."""
        position = self._pos
        value = self.u8()
        if not lowest <= value <= highest:
            raise MalformedReportError(f"byte {position}: count {value} not in {lowest}…{highest}")
        return value

    def flag(self) -> int:
        """Next byte as a 0/1 flag."""
        return self.count(0, 1)

    def text(self) -> str:
        """Next length-prefixed UTF-8 text."""
        data = self.raw(self.u8())
        try:
            return data.decode("utf-8")
        except UnicodeDecodeError:
            raise MalformedReportError("text is not UTF-8") from None

    def end(self) -> None:
        """Check that the rest of the report is zero padding."""
        rest = self._data[self._pos :]
        if rest.strip(b"\x00"):
            raise MalformedReportError(f"non-zero bytes after the message at byte {self._pos}")

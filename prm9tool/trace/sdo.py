"""Reassembling SDO transfers (CiA 301 §7.2.4): expedited, segmented and block, downloads and
uploads, and aborts, from the requests (0x600 + node) and responses (0x580 + node) of one
node. Every frame of a transfer belongs to the one finished transfer it is part of. No Qt."""

from __future__ import annotations

from dataclasses import dataclass, field

DOWNLOAD, UPLOAD = "write", "read"


@dataclass(frozen=True)
class Transfer:
    """A finished (or abandoned) SDO transfer."""

    direction: str  # "write" or "read"
    index: int
    subindex: int
    data: bytes
    frames: tuple[int, ...]
    time: float
    how: str  # "expedited", "segmented", "block"
    abort: int | None = None  # the abort code, None: completed
    incomplete: str = ""  # why it did not complete (a new request, the trace ended)


@dataclass
class _Open:
    direction: str
    index: int
    subindex: int
    time: float
    how: str
    frames: list[int] = field(default_factory=list)
    data: bytearray = field(default_factory=bytearray)
    size: int | None = None
    in_block: bool = False  # block transfer: sub-block segments flowing
    block_done: bool = False  # the last segment of the data was seen (c bit / block's last)
    last_n: int = 0  # block end: bytes of the last segment without data


class SdoTracker:
    """The SDO conversation of one node, fed frame by frame."""

    def __init__(self) -> None:
        self._open: _Open | None = None

    def feed(self, number: int, time: float, data: bytes, request: bool) -> list[Transfer | int]:
        """Take one SDO frame; returns the transfers it completes, and its own number when it
        belongs to no transfer (not understood)."""
        data = data + bytes(8 - len(data)) if len(data) < 8 else data
        current = self._open
        if current is not None and current.in_block and _block_segment(current, request):
            current.frames.append(number)
            seq_last = bool(data[0] & 0x80)
            current.data += data[1:8]
            if seq_last:
                current.block_done = True
            return []
        cs = data[0] >> 5
        if cs == 4:  # abort, either side
            return self._abort(number, time, data)
        if request:
            return self._request(number, time, data, cs)
        return self._response(number, data, cs)

    def finish(self, why: str) -> list[Transfer | int]:
        """The transfer still open when the trace ends (listed as incomplete)."""
        return self._close(why)

    # --- requests (client → server) -------------------------------------------------
    def _request(self, number: int, time: float, data: bytes, cs: int) -> list[Transfer | int]:
        index, sub = int.from_bytes(data[1:3], "little"), data[3]
        current = self._open
        if cs == 1:  # initiate download
            done = self._close("a new request came before its end")
            opened = _Open(
                DOWNLOAD, index, sub, time, "expedited" if data[0] & 0x02 else "segmented"
            )
            opened.frames.append(number)
            if data[0] & 0x02:
                n = (data[0] >> 2) & 3 if data[0] & 0x01 else 0
                opened.data += data[4 : 8 - n]
            elif data[0] & 0x01:
                opened.size = int.from_bytes(data[4:8], "little")
            self._open = opened
            return done
        if cs == 2:  # initiate upload
            done = self._close("a new request came before its end")
            self._open = _Open(UPLOAD, index, sub, time, "expedited", [number])
            return done
        if cs == 6 and data[0] & 0x01 == 0:  # block download initiate
            done = self._close("a new request came before its end")
            opened = _Open(DOWNLOAD, index, sub, time, "block", [number])
            if data[0] & 0x02:
                opened.size = int.from_bytes(data[4:8], "little")
            self._open = opened
            return done
        if cs == 5 and data[0] & 0x03 == 0:  # block upload initiate
            done = self._close("a new request came before its end")
            self._open = _Open(UPLOAD, index, sub, time, "block", [number])
            return done
        if current is None:
            return [number]
        if cs == 0 and current.direction == DOWNLOAD:  # download segment
            current.frames.append(number)
            n = (data[0] >> 1) & 7
            current.data += data[1 : 8 - n]
            current.block_done = bool(data[0] & 0x01)  # c: the last segment
            return []
        if cs == 3 and current.direction == UPLOAD:  # upload segment request
            current.frames.append(number)
            return []
        if cs == 6 and current.how == "block" and current.direction == DOWNLOAD:  # end
            current.frames.append(number)
            current.last_n = (data[0] >> 2) & 7
            return []
        if cs == 5 and current.how == "block" and current.direction == UPLOAD:
            current.frames.append(number)
            sub_cs = data[0] & 0x03
            if sub_cs == 3:  # start upload: the server sends a sub-block
                current.in_block, current.block_done = True, False
            elif sub_cs == 2:  # ack of a sub-block: another follows unless the data ended
                current.in_block = not current.block_done
            elif sub_cs == 1:  # end response: done
                return self._complete()
            return []
        return [number]

    # --- responses (server → client) -------------------------------------------------
    def _response(self, number: int, data: bytes, cs: int) -> list[Transfer | int]:
        current = self._open
        if current is None:
            return [number]
        current.frames.append(number)
        if current.direction == DOWNLOAD:
            if cs == 3:  # initiate download response
                return self._complete() if current.how == "expedited" else []
            if cs == 1:  # download segment response
                return self._complete() if current.block_done else []
            if cs == 5 and current.how == "block":
                sub_cs = data[0] & 0x03
                if sub_cs == 0:  # initiate response: the client sends a sub-block
                    current.in_block = True
                elif sub_cs == 2:  # block ack
                    current.in_block = not current.block_done
                elif sub_cs == 1:  # end response
                    if current.last_n:
                        del current.data[len(current.data) - current.last_n :]
                    return self._complete()
                return []
        else:
            if cs == 2:  # initiate upload response
                if data[0] & 0x02:
                    n = (data[0] >> 2) & 3 if data[0] & 0x01 else 0
                    current.data += data[4 : 8 - n]
                    return self._complete()
                current.how = "segmented"
                current.size = int.from_bytes(data[4:8], "little") if data[0] & 0x01 else None
                return []
            if cs == 0:  # upload segment response
                n = (data[0] >> 1) & 7
                current.data += data[1 : 8 - n]
                return self._complete() if data[0] & 0x01 else []
            if cs == 6 and current.how == "block":
                if data[0] & 0x01 == 0:  # initiate response with the size (ss = bit 0)
                    if data[0] & 0x02:
                        current.size = int.from_bytes(data[4:8], "little")
                    return []
                if data[0] & 0x01:  # end: bytes of the last segment without data
                    n = (data[0] >> 2) & 7
                    if n:
                        del current.data[len(current.data) - n :]
                    return []
        current.frames.pop()
        return [number]

    def _abort(self, number: int, time: float, data: bytes) -> list[Transfer | int]:
        code = int.from_bytes(data[4:8], "little")
        index, sub = int.from_bytes(data[1:3], "little"), data[3]
        current = self._open
        self._open = None
        if current is None:
            return [Transfer(DOWNLOAD, index, sub, b"", (number,), time, "abort", code)]
        frames = (*current.frames, number)
        return [
            Transfer(current.direction, current.index, current.subindex, bytes(current.data),
                     frames, current.time, current.how, code)
        ]  # fmt: skip

    def _complete(self) -> list[Transfer | int]:
        current = self._open
        assert current is not None
        self._open = None
        data = bytes(current.data)
        if current.size is not None and current.how != "expedited":
            data = data[: current.size]
        return [
            Transfer(current.direction, current.index, current.subindex, data,
                     tuple(current.frames), current.time, current.how)
        ]  # fmt: skip

    def _close(self, why: str) -> list[Transfer | int]:
        current = self._open
        if current is None:
            return []
        self._open = None
        return [
            Transfer(current.direction, current.index, current.subindex, bytes(current.data),
                     tuple(current.frames), current.time, current.how, incomplete=why)
        ]  # fmt: skip


def _block_segment(current: _Open, request: bool) -> bool:
    """Whether a frame is a sub-block segment: from the client in a block download, from the
    server in a block upload."""
    return request == (current.direction == DOWNLOAD)

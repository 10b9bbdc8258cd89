"""CiA 301 SDO server protocol: expedited and segmented upload/download, abort codes.

Pure protocol, no bus and no valve: :class:`SdoServer` turns one request (8 data bytes) into
the response bytes, calling ``read``/``write`` for the object-dictionary access. Block
transfer is not supported (answered with "command specifier not valid"). A segmented transfer
whose client goes quiet is aborted with "SDO protocol timed out" after :data:`SEGMENT_TIMEOUT_MS`
of the caller's clock (the slave passes simulated time, see :meth:`SdoServer.expire`).
"""

from __future__ import annotations

import logging
import struct
from collections.abc import Callable
from dataclasses import dataclass

from prm9tool.errors import AbortCode, SdoAbortError

log = logging.getLogger(__name__)

Reader = Callable[[int, int], bytes]
Writer = Callable[[int, int, bytes], None]

# client command specifiers (bits 7..5 of byte 0)
CCS_DOWNLOAD_SEGMENT = 0
CCS_INITIATE_DOWNLOAD = 1
CCS_INITIATE_UPLOAD = 2
CCS_UPLOAD_SEGMENT = 3
CCS_ABORT = 4
RESPONSE_DOWNLOAD = 0x60
RESPONSE_UPLOAD_SEGMENTED = 0x41
RESPONSE_ABORT = 0x80
SEGMENT_TIMEOUT_MS = 1000  # decision: CiA 301 leaves the value to the device; manual silent
SDO_FRAME_LENGTH = 8  # CiA 301: SDO frames always carry 8 bytes; others are ignored


@dataclass
class _Transfer:
    """A segmented transfer in progress."""

    index: int
    subindex: int
    upload: bool
    data: bytearray
    size: int | None
    toggle: int = 0
    last_ms: int = 0  # when the client last spoke in this transfer


def abort_frame(index: int, subindex: int, code: int) -> bytes:
    """The 8 data bytes of an SDO abort."""
    return struct.pack("<BHBI", RESPONSE_ABORT, index, subindex, code)


class SdoServer:
    """One SDO server channel (the PRM9 has exactly one: 0x600/0x580 + node ID)."""

    def __init__(self, read: Reader, write: Writer, timeout_ms: int = SEGMENT_TIMEOUT_MS) -> None:
        self._read = read
        self._write = write
        self._timeout_ms = timeout_ms
        self._transfer: _Transfer | None = None

    @property
    def busy(self) -> bool:
        """True while a segmented transfer is in progress."""
        return self._transfer is not None

    def reset(self) -> None:
        """Forget a transfer in progress (NMT reset, state change)."""
        self._transfer = None

    def expire(self, now_ms: int) -> bytes | None:
        """Abort a segmented transfer idle for longer than the timeout: the abort frame, or None.

        ``now_ms`` is the same clock as the one given to :meth:`handle`.
        """
        transfer = self._transfer
        if transfer is None or now_ms - transfer.last_ms <= self._timeout_ms:
            return None
        self._transfer = None
        return abort_frame(transfer.index, transfer.subindex, AbortCode.SDO_TIMEOUT)

    def handle(self, request: bytes, now_ms: int = 0) -> bytes | None:
        """The response to ``request``, or None when the protocol requires no answer.

        ``now_ms`` (any monotonic millisecond clock) starts the segment timeout. A request that
        is not exactly 8 bytes (CiA 301: every SDO frame has DLC 8) is ignored: no answer, no
        change, a segmented transfer in progress goes on (decision, as CANopenNode does).
        """
        if len(request) != SDO_FRAME_LENGTH:
            log.info("SDO request of %d bytes ignored: %s", len(request), bytes(request).hex(" "))
            return None
        data = bytes(request)
        ccs = data[0] >> 5
        index, subindex = struct.unpack_from("<HB", data, 1)
        try:
            response = self._dispatch(ccs, data, index, subindex)
            if self._transfer is not None:
                self._transfer.last_ms = now_ms
            return response
        except SdoAbortError as exc:
            self._transfer = None
            return abort_frame(exc.index, exc.subindex, exc.code)
        except Exception:  # a firmware bug must not kill the server: CiA 301 "general error"
            log.exception("SDO request %s failed", data.hex(" "))
            self._transfer = None
            return abort_frame(index, subindex, AbortCode.GENERAL_ERROR)

    def _dispatch(self, ccs: int, data: bytes, index: int, subindex: int) -> bytes | None:
        if ccs == CCS_ABORT:
            self._transfer = None
            return None
        if ccs == CCS_INITIATE_UPLOAD:
            return self._initiate_upload(index, subindex)
        if ccs == CCS_INITIATE_DOWNLOAD:
            return self._initiate_download(data, index, subindex)
        if ccs == CCS_UPLOAD_SEGMENT:
            return self._upload_segment(data)
        if ccs == CCS_DOWNLOAD_SEGMENT:
            return self._download_segment(data)
        raise self._abort(index, subindex, AbortCode.INVALID_COMMAND)

    def _abort(self, index: int, subindex: int, code: AbortCode) -> SdoAbortError:
        return SdoAbortError(index, subindex, int(code))

    # --- upload (server -> client) -------------------------------------------------------
    def _initiate_upload(self, index: int, subindex: int) -> bytes:
        self._transfer = None
        value = self._read(index, subindex)
        if 0 < len(value) <= 4:
            command = 0x43 | ((4 - len(value)) << 2)
            return struct.pack("<BHB", command, index, subindex) + value.ljust(4, b"\x00")
        self._transfer = _Transfer(index, subindex, True, bytearray(value), len(value))
        return struct.pack("<BHBI", RESPONSE_UPLOAD_SEGMENTED, index, subindex, len(value))

    def _upload_segment(self, data: bytes) -> bytes:
        transfer = self._current(upload=True)
        toggle = (data[0] >> 4) & 1
        if toggle != transfer.toggle:
            raise self._abort(transfer.index, transfer.subindex, AbortCode.TOGGLE_BIT)
        chunk = bytes(transfer.data[:7])
        del transfer.data[:7]
        last = not transfer.data
        command = (toggle << 4) | ((7 - len(chunk)) << 1) | (1 if last else 0)
        transfer.toggle ^= 1
        if last:
            self._transfer = None
        return bytes([command]) + chunk.ljust(7, b"\x00")

    # --- download (client -> server) -----------------------------------------------------
    def _initiate_download(self, data: bytes, index: int, subindex: int) -> bytes:
        self._transfer = None
        expedited, size_indicated = bool(data[0] & 0x02), bool(data[0] & 0x01)
        if expedited:
            if size_indicated:
                length = 4 - ((data[0] >> 2) & 0x03)
            else:
                length = self._natural_length(index, subindex)
            self._write(index, subindex, data[4 : 4 + length])
        else:
            size = struct.unpack_from("<I", data, 4)[0] if size_indicated else None
            self._transfer = _Transfer(index, subindex, False, bytearray(), size)
        return struct.pack("<BHBI", RESPONSE_DOWNLOAD, index, subindex, 0)

    def _natural_length(self, index: int, subindex: int) -> int:
        """Bytes an expedited download without size (CiA 301: e = 1, s = 0) carries: the
        object's own size when it is shorter than 4 (the rest of the frame is padding)."""
        try:
            size = len(self._read(index, subindex))
        except SdoAbortError:
            return 4  # unreadable (write-only or missing): the write itself decides
        return size if 0 < size < 4 else 4

    def _download_segment(self, data: bytes) -> bytes:
        transfer = self._current(upload=False)
        toggle = (data[0] >> 4) & 1
        if toggle != transfer.toggle:
            raise self._abort(transfer.index, transfer.subindex, AbortCode.TOGGLE_BIT)
        unused = (data[0] >> 1) & 0x07
        transfer.data += data[1 : 8 - unused]
        transfer.toggle ^= 1
        if data[0] & 0x01:
            self._transfer = None
            if transfer.size is not None and transfer.size != len(transfer.data):
                raise self._abort(transfer.index, transfer.subindex, AbortCode.WRONG_LENGTH)
            self._write(transfer.index, transfer.subindex, bytes(transfer.data))
        return bytes([0x20 | (toggle << 4)]) + bytes(7)

    def _current(self, upload: bool) -> _Transfer:
        transfer = self._transfer
        if transfer is None or transfer.upload != upload:
            self._transfer = None
            raise self._abort(0, 0, AbortCode.INVALID_COMMAND)
        return transfer

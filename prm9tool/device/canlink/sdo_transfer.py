"""Exact, bounded CiA 301 SDO client transfers (expedited and segmented) on one SDO channel.

The ``canopen`` package's SDO client reads a segmented upload for as long as the server sends
segments, takes an upload that ends before its declared size as the value, and aborts with the
multiplexer 0000:00 (its ``SdoClient.abort`` packs no index). Its knobs (``RESPONSE_TIMEOUT``,
``MAX_RETRIES``) bound one answer, never a transfer. So the master runs the protocol itself on
the frames: the ``canopen`` client only delivers the answers (its ``responses`` queue, fed by
the network's subscription to 0x580 + node ID) — :class:`CanopenPort`.

Every transfer here is bounded and exact (docs/can-link.md "Bounded, exact SDO transfers"):

- **size**: at most ``max_bytes`` (the catalogue's size of the object, a stated default for
  others); a declared size above it is aborted before the first segment (0x05040005), an
  undeclared one as soon as the data passes it (0x05040005); data past a declared size is
  aborted with 0x06070012, a last segment short of it with 0x06070013 — never a value;
- **time**: ``answer_s`` per answer and ``deadline_s`` for the whole transfer (0x05040000);
- **protocol**: a toggle bit not alternated (0x05030000), an unknown command specifier
  (0x05040001), an answer for another object (0x08000000) end the transfer with an error.

Every client abort carries the aborted transfer's index and sub-index (CiA 301 §7.2.4.3.17).
The client never starts a block transfer, so a server cannot make it run one.
"""

from __future__ import annotations

import queue
import struct
import time
from dataclasses import dataclass
from typing import TYPE_CHECKING, NoReturn, Protocol

from prm9tool.errors import AbortCode, DeviceTimeoutError, ProtocolError, SdoAbortError

if TYPE_CHECKING:
    import canopen

DEFAULT_MAX_BYTES = 4096  # an object the catalogue does not know (the OD browser's reads)
SEGMENT_ALLOWANCE_S = 0.05  # what each segment adds to a transfer's deadline
FRAME = 8  # CiA 301: every SDO frame has 8 data bytes

# command specifiers (CiA 301 §7.2.4.3), client -> server and server -> client
CCS_DOWNLOAD_SEGMENT, CCS_INITIATE_DOWNLOAD, CCS_INITIATE_UPLOAD = 0x00, 0x20, 0x40
CCS_UPLOAD_SEGMENT, CS_ABORT = 0x60, 0x80
SCS_UPLOAD_SEGMENT, SCS_DOWNLOAD_SEGMENT, SCS_INITIATE_UPLOAD = 0x00, 0x20, 0x40
SCS_INITIATE_DOWNLOAD = 0x60
TOGGLE, EXPEDITED, SIZE_GIVEN, LAST = 0x10, 0x02, 0x01, 0x01
_MUX = struct.Struct("<BHB")


class SdoTransferError(ProtocolError):
    """The client aborted a transfer (``code``: the CiA 301 abort code it sent)."""

    def __init__(self, index: int, subindex: int, code: AbortCode, reason: str) -> None:
        self.index, self.subindex, self.code = index, subindex, code
        super().__init__(
            f"0x{index:04X}/{subindex}: {reason}; prm9tool aborted the transfer "
            f"(0x{int(code):08X}, {code.text})"
        )


class SdoPort(Protocol):
    """Where the client's frames go and the server's answers come from."""

    def send(self, data: bytes) -> None:
        """Send one request frame (8 bytes) to the server."""

    def receive(self, timeout_s: float) -> bytes | None:
        """The next answer frame, or None when none came within ``timeout_s``."""

    def drain(self) -> int:
        """Drop the answers nobody asked for; returns how many there were."""


class CanopenPort:
    """An :class:`SdoPort` over a ``canopen.RemoteNode``'s SDO client (its COB-IDs and queue)."""

    def __init__(self, node: canopen.RemoteNode) -> None:
        self._sdo = node.sdo

    def send(self, data: bytes) -> None:
        """On 0x600 + node ID."""
        self._sdo.network.send_message(self._sdo.rx_cobid, data)

    def receive(self, timeout_s: float) -> bytes | None:
        """From 0x580 + node ID."""
        try:
            return bytes(self._sdo.responses.get(timeout=max(timeout_s, 0.0)))
        except queue.Empty:
            return None

    def drain(self) -> int:
        """Empty the answer queue."""
        stale = 0
        answers: queue.Queue[bytes] = self._sdo.responses
        while True:
            try:
                answers.get_nowait()
            except queue.Empty:
                return stale
            stale += 1


@dataclass
class TransferStats:
    """What the last transfers cost (memory and frame bounds, the duplicate-ID check)."""

    frames: int = 0  # answers received by the last transfer
    latency_s: float = 0.0  # the first answer of the last transfer came this late
    strays: int = 0  # answers that arrived when none was asked for (since created)
    timeouts: int = 0  # transfers that ended without an answer (since created)


class SdoTransfer:
    """One SDO client on ``port``: :meth:`upload` and :meth:`download`, exact and bounded."""

    def __init__(self, port: SdoPort, node_id: int) -> None:
        self.port = port
        self.node_id = node_id
        self.stats = TransferStats()

    # --- upload -------------------------------------------------------------------------
    def upload(self, index: int, subindex: int, max_bytes: int, answer_s: float) -> bytes:
        """The object's bytes, exactly as many as the server declared; SdoAbortError when
        the server aborts, SdoTransferError when the client had to, DeviceTimeoutError."""
        run = _Run(self, index, subindex, answer_s, max_bytes)
        answer = run.ask(bytes(_MUX.pack(CCS_INITIATE_UPLOAD, index, subindex)) + bytes(4))
        command = answer[0]
        if command & 0xE0 != SCS_INITIATE_UPLOAD:
            run.fail(AbortCode.INVALID_COMMAND, f"answer 0x{command:02X} is no upload answer")
        run.check_mux(answer)
        if command & EXPEDITED:
            size = 4 - ((command >> 2) & 3) if command & SIZE_GIVEN else 4
            return answer[4 : 4 + size]
        declared = int.from_bytes(answer[4:8], "little") if command & SIZE_GIVEN else None
        if declared is not None and declared > max_bytes:
            run.fail(
                AbortCode.OUT_OF_MEMORY,
                f"the node declares {declared} bytes, more than the {max_bytes} this object "
                "can hold",
            )
        return run.segments(declared)

    # --- download -----------------------------------------------------------------------
    def download(self, index: int, subindex: int, data: bytes, answer_s: float) -> None:
        """Write ``data`` (expedited up to 4 bytes, else segmented with its size)."""
        run = _Run(self, index, subindex, answer_s, len(data))
        size = len(data)
        if 0 < size <= 4:
            command = CCS_INITIATE_DOWNLOAD | EXPEDITED | SIZE_GIVEN | ((4 - size) << 2)
            request = _MUX.pack(command, index, subindex) + data.ljust(4, b"\0")
        else:
            command = CCS_INITIATE_DOWNLOAD | SIZE_GIVEN
            request = _MUX.pack(command, index, subindex) + size.to_bytes(4, "little")
        answer = run.ask(bytes(request))
        if answer[0] != SCS_INITIATE_DOWNLOAD:
            run.fail(AbortCode.INVALID_COMMAND, f"answer 0x{answer[0]:02X} is no download answer")
        run.check_mux(answer)
        if not 0 < size <= 4:
            run.send_segments(data)


class _Run:
    """One transfer's state: its object, bounds, toggle and deadline."""

    def __init__(
        self, client: SdoTransfer, index: int, subindex: int, answer_s: float, max_bytes: int
    ) -> None:
        self.client, self.index, self.subindex = client, index, subindex
        self.answer_s = answer_s
        self.max_bytes = max_bytes
        self.start = time.monotonic()
        segments = max_bytes // 7 + 1
        self.deadline_s = 2 * answer_s + segments * SEGMENT_ALLOWANCE_S
        self.deadline = self.start + self.deadline_s
        self.toggle = 0
        client.stats.frames = 0
        client.stats.latency_s = 0.0

    def ask(self, request: bytes) -> bytes:
        """Send ``request``, return the server's answer (8 bytes; a server abort raised)."""
        port = self.client.port
        self.client.stats.strays += port.drain()
        sent = time.monotonic()
        port.send(request)
        left = min(self.answer_s, self.deadline - sent)
        answer = port.receive(left)
        if answer is None:
            self._timeout()
        stats = self.client.stats
        if not stats.frames:
            stats.latency_s = time.monotonic() - sent
        stats.frames += 1
        if answer[:1] == bytes([CS_ABORT]) and len(answer) >= FRAME:
            raise SdoAbortError(self.index, self.subindex, int.from_bytes(answer[4:8], "little"))
        if len(answer) != FRAME:
            self.fail(AbortCode.INVALID_COMMAND, f"an answer of {len(answer)} bytes, not 8")
        return answer

    def check_mux(self, answer: bytes) -> None:
        """The answer must be for this object (else it answers another request)."""
        _, index, subindex = _MUX.unpack_from(answer)
        if (index, subindex) != (self.index, self.subindex):
            self.fail(
                AbortCode.GENERAL_ERROR,
                f"the node answered for 0x{index:04X}/{subindex}: an answer to another request "
                "(another SDO client on this channel, or two nodes at this node ID)",
            )

    def segments(self, declared: int | None) -> bytes:
        """The segmented upload's data, bounded by ``declared`` or ``max_bytes``."""
        data = bytearray()
        while True:
            answer = self.ask(bytes([CCS_UPLOAD_SEGMENT | self.toggle]) + bytes(7))
            command = answer[0]
            if command & 0xE0 != SCS_UPLOAD_SEGMENT:
                self.fail(AbortCode.INVALID_COMMAND, f"answer 0x{command:02X} is no segment")
            self._check_toggle(command)
            segment = answer[1 : 8 - ((command >> 1) & 7)]
            if not segment and not command & LAST:  # so at most max_bytes + 1 segments
                self.fail(AbortCode.INVALID_COMMAND, "a segment without data that is not the last")
            data += segment
            self._check_length(len(data), declared)
            if command & LAST:
                if declared is not None and len(data) != declared:
                    self.fail(
                        AbortCode.LENGTH_TOO_LOW,
                        f"the upload ended after {len(data)} of the {declared} bytes the node "
                        "declared",
                    )
                return bytes(data)

    def send_segments(self, data: bytes) -> None:
        """The segmented download's segments, each acknowledged with the right toggle."""
        for start in range(0, max(len(data), 1), 7):  # an empty value: one empty segment
            chunk = data[start : start + 7]
            last = start + 7 >= len(data)
            command = CCS_DOWNLOAD_SEGMENT | self.toggle | ((7 - len(chunk)) << 1) | last
            answer = self.ask(bytes([command]) + chunk.ljust(7, b"\0"))
            if answer[0] & 0xE0 != SCS_DOWNLOAD_SEGMENT:
                self.fail(AbortCode.INVALID_COMMAND, f"answer 0x{answer[0]:02X} is no segment")
            self._check_toggle(answer[0])

    def _check_toggle(self, command: int) -> None:
        if command & TOGGLE != self.toggle:
            self.fail(AbortCode.TOGGLE_BIT, "the node did not alternate the toggle bit")
        self.toggle ^= TOGGLE

    def _check_length(self, length: int, declared: int | None) -> None:
        if declared is not None and length > declared:
            self.fail(
                AbortCode.LENGTH_TOO_HIGH,
                f"the node sends more than the {declared} bytes it declared",
            )
        if length > self.max_bytes:
            self.fail(
                AbortCode.OUT_OF_MEMORY,
                f"the node sends more than the {self.max_bytes} bytes this object can hold "
                "and does not end the upload",
            )

    def _timeout(self) -> NoReturn:
        self.client.stats.timeouts += 1  # its answer may still come: a stray, not a twin
        whole = time.monotonic() - self.start
        self.abort(AbortCode.SDO_TIMEOUT)
        if time.monotonic() >= self.deadline and whole > self.answer_s:
            raise DeviceTimeoutError(
                f"node {self.client.node_id}: the SDO transfer of 0x{self.index:04X}/"
                f"{self.subindex} did not end within its bound of {self.deadline_s:g} s "
                f"({self.client.stats.frames} answers); prm9tool aborted it (0x05040000)"
            )
        raise DeviceTimeoutError(
            f"node {self.client.node_id}: no SDO answer for 0x{self.index:04X}/{self.subindex} "
            f"within {self.answer_s:g} s"
            + (f" (after {self.client.stats.frames} answers)" if self.client.stats.frames else "")
        )

    def abort(self, code: AbortCode) -> None:
        """Send the abort frame with this transfer's multiplexer."""
        frame = _MUX.pack(CS_ABORT, self.index, self.subindex) + int(code).to_bytes(4, "little")
        self.client.port.send(bytes(frame))

    def fail(self, code: AbortCode, reason: str) -> NoReturn:
        """Abort the transfer with ``code`` and raise SdoTransferError with ``reason``."""
        self.abort(code)
        raise SdoTransferError(self.index, self.subindex, code, reason)

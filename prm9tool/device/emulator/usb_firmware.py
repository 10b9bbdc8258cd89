"""The valve firmware's USB handler: answers the protocol's reports from an EmulatedValve.

Every request report gets exactly one answer report, built with the same codec the host uses,
so host and firmware agree byte for byte. Junk gets a well-formed error answer, never an
exception; the guarded commands (store, restore, restart, reload) need their 4-byte signature, so
random reports cannot change the stored parameters. Stream samples are collected every
millisecond of simulated time into an outbox of reports, as the USB interrupt endpoint would
send them whether or not the host reads.
"""

from __future__ import annotations

import logging
import weakref
from collections import deque
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from prm9tool.catalogue.signals import BY_CODE, signals_for
from prm9tool.device.usb.protocol import (
    MAX_SEGMENTED_LENGTH,
    PROTOCOL_VERSION,
    REPORT_SIZE,
    SEGMENT_READ_CHUNK,
    STREAM_BASE_RATE_HZ,
    AbortReply,
    Done,
    Identify,
    IdentifyReply,
    MalformedReportError,
    Nmt,
    ReadEntries,
    ReadReply,
    Reload,
    Request,
    Response,
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
    encode_response,
    encode_stream,
    malformed_answer,
)
from prm9tool.device.usb.protocol.packing import READ_ANSWER_ROOM
from prm9tool.device.usb.protocol.status import MAX_ACTIVE_ERRORS, MAX_TEXT_BYTES
from prm9tool.errors import AbortCode, Prm9Error, SdoAbortError

if TYPE_CHECKING:
    from prm9tool.device.emulator import EmulatedValve

log = logging.getLogger("prm9tool.device.emulator.usb")
OUTBOX_REPORTS = 256  # stream reports buffered for the host (hidraw keeps 64; assumption)
FLUSH_S = 0.010  # a partly filled stream report is sent after 10 ms (scope latency at low rates)
_FIRMWARES: weakref.WeakKeyDictionary[EmulatedValve, UsbFirmware] = weakref.WeakKeyDictionary()


@dataclass
class _Assembly:
    """A segmented write in progress."""

    index: int
    subindex: int
    total: int
    data: bytearray


@dataclass
class _Stream:
    """A running stream: channel codes, pending samples, sequence counter."""

    codes: tuple[int, ...]
    capacity: int
    pending: np.ndarray  # int16 (instants, channels) not yet sent
    sequence: int = 0
    oldest: float = 0.0


class UsbFirmware:
    """The USB side of one emulated valve (one per valve: use :meth:`of`)."""

    def __init__(self, valve: EmulatedValve) -> None:
        self._valve = valve
        self._last: tuple[bytes, bytes] | None = None
        self._assembly: _Assembly | None = None
        self._stream: _Stream | None = None
        self.outbox: deque[tuple[float, bytes]] = deque(maxlen=OUTBOX_REPORTS)
        self.internal_errors = 0  # exceptions the handler had to swallow (a bug if > 0)
        valve.add_restart_listener(self._on_restart)

    @classmethod
    def of(cls, valve: EmulatedValve) -> UsbFirmware:
        """The firmware handler of ``valve`` (created on first use)."""
        with valve.lock:
            firmware = _FIRMWARES.get(valve)
            if firmware is None:
                firmware = _FIRMWARES[valve] = cls(valve)
            return firmware

    @property
    def streaming(self) -> bool:
        """True while a stream runs."""
        return self._stream is not None

    @property
    def stream_sequence(self) -> int:
        """Sequence number of the next stream report (= reports sent since STREAM_START)."""
        return self._stream.sequence if self._stream is not None else 0

    def handle(self, report: bytes) -> bytes:
        """Answer one request report (always exactly one 64-byte answer, never an exception)."""
        report = bytes(report)
        with self._valve.lock:
            self._valve.usb_activity()
            if self._last is not None and self._last[0] == report:
                return self._last[1]  # a repeated report: answer again, do not execute again
            try:
                seq, request = decode_request(report)
            except MalformedReportError as exc:
                return malformed_answer(report, exc)
            answer = self._encode(request, seq, self._execute(request))
            self._last = (report, answer)
            if isinstance(request, Restart):
                self._valve.restart()
                self._last = (report, answer)  # a repeated RESTART is answered, not executed
            return answer

    def _encode(self, request: Request, seq: int, response: Response) -> bytes:
        try:
            return encode_response(request.op, seq, response)
        except ValueError:  # an answer that does not fit a report is a firmware bug
            self.internal_errors += 1
            log.exception("USB firmware cannot encode its answer %r", response)
            return encode_response(request.op, seq, AbortReply(AbortCode.GENERAL_ERROR))

    # --- requests --------------------------------------------------------------------------
    def _execute(self, request: Request) -> Response:
        try:
            return self._dispatch(request)
        except SdoAbortError as exc:
            return AbortReply(exc.code, exc.index, exc.subindex)
        except Prm9Error as exc:
            log.info("USB request %s refused: %s", type(request).__name__, exc)
            code = AbortCode.CANNOT_STORE if isinstance(request, Store) else AbortCode.GENERAL_ERROR
            return AbortReply(code)
        except Exception:  # the firmware must answer whatever happens
            self.internal_errors += 1
            log.exception("USB firmware failed on %r", request)
            return AbortReply(AbortCode.GENERAL_ERROR)

    def _dispatch(self, request: Request) -> Response:
        valve = self._valve
        if isinstance(request, Identify):
            key = str(valve.type_key)
            firmware = _truncate_utf8(valve.firmware_version, identify_firmware_room(key))
            return IdentifyReply(PROTOCOL_VERSION, valve.serial, key, firmware.decode("utf-8"))
        if isinstance(request, ReadEntries):
            return self._read(request)
        if isinstance(request, WriteEntries):
            return self._write(request)
        if isinstance(request, SegmentRead):
            return self._segment_read(request)
        if isinstance(request, SegmentWrite):
            return self._segment_write(request)
        if isinstance(request, StatusRequest):
            return self._status(request.text_offset)
        if isinstance(request, StreamStart):
            return self._stream_start(request)
        if isinstance(request, StreamStop):
            self._stream_stop()
        elif isinstance(request, Store):
            valve.store()
        elif isinstance(request, RestoreFactory):
            valve.restore_factory()
        elif isinstance(request, Reload):
            valve.reload()
        elif isinstance(request, Nmt):
            valve.nmt_command(request.command)
        return Done()  # Restart: executed in handle() after the answer is built

    def _read(self, request: ReadEntries) -> ReadReply:
        values = self._valve.read_encoded(request.addresses, READ_ANSWER_ROOM)
        if not values and request.addresses:  # too long for any READ answer: read it segmented
            values = [int(AbortCode.LENGTH_TOO_HIGH)]
        return ReadReply(tuple(values))

    def _write(self, request: WriteEntries) -> Response:
        for position, (index, subindex, data) in enumerate(request.entries):
            try:
                self._valve.write_bytes(index, subindex, data)
            except SdoAbortError as exc:
                return AbortReply(exc.code, index, subindex, position)
        return WriteReply(len(request.entries))

    def _segment_read(self, request: SegmentRead) -> Response:
        data = self._valve.read_bytes(request.index, request.subindex)[:MAX_SEGMENTED_LENGTH]
        if request.offset > len(data):
            return AbortReply(AbortCode.LENGTH_TOO_LOW, request.index, request.subindex)
        chunk = data[request.offset : request.offset + SEGMENT_READ_CHUNK]
        return SegmentReadReply(len(data), request.offset, chunk)

    def _segment_write(self, request: SegmentWrite) -> Response:
        key = (request.index, request.subindex)
        if request.offset == 0:
            self._assembly = _Assembly(*key, request.total, bytearray())
        current = self._assembly
        if current is None or (current.index, current.subindex, current.total) != (
            *key,
            request.total,
        ):
            return AbortReply(AbortCode.TOGGLE_BIT, *key)  # segment without a first segment
        if request.offset != len(current.data):
            self._assembly = None
            return AbortReply(AbortCode.TOGGLE_BIT, *key)  # segment out of sequence
        current.data += request.data
        if request.total > MAX_SEGMENTED_LENGTH or len(current.data) > request.total:
            self._assembly = None
            return AbortReply(AbortCode.LENGTH_TOO_HIGH, *key)
        if len(current.data) < request.total:
            return SegmentWriteReply(len(current.data), False)
        self._assembly = None
        self._valve.write_bytes(request.index, request.subindex, bytes(current.data))
        return SegmentWriteReply(len(current.data), True)

    def _status(self, offset: int) -> StatusReply:
        status = self._valve.status()
        active = tuple(status.active_errors[:MAX_ACTIVE_ERRORS])
        text = _truncate_utf8(status.error_text, MAX_TEXT_BYTES)
        offset = min(offset, len(text))
        chunk = text[offset : offset + StatusReply.chunk_room(len(active))]
        return StatusReply(
            str(status.device_state), status.error_code, status.error_register,
            status.warning, status.booting, status.nmt_state,
            tuple((led.color, led.pattern, led.lit) for led in status.leds),
            status.temperature_c, status.supply_v, active, len(text), offset, chunk,
        )  # fmt: skip

    # --- streaming ------------------------------------------------------------------------
    def _stream_start(self, request: StreamStart) -> Response:
        available = {s.code for s in signals_for(self._valve.variant)}
        for position, code in enumerate(request.codes):
            if code not in available:
                return AbortReply(AbortCode.INVALID_VALUE, 0, code, position)
        if not 1 <= request.decimation <= STREAM_BASE_RATE_HZ:
            return AbortReply(AbortCode.INVALID_VALUE)
        self._stream_stop()
        self._valve.capture_start([BY_CODE[c].key for c in request.codes], request.decimation)
        capacity = StreamData.capacity(len(request.codes))
        empty = np.empty((0, len(request.codes)), dtype=np.int16)
        self._stream = _Stream(request.codes, capacity, empty, oldest=self._valve.time)
        self._valve.add_cycle_listener(self._on_cycle)  # only while streaming (see fasttick)
        return StreamStarted(capacity)

    def _stream_stop(self) -> None:
        if self._stream is not None:
            self._stream = None
            self._valve.remove_cycle_listener(self._on_cycle)
            self._valve.capture_stop()

    def _on_cycle(self, sim_time: float) -> None:
        stream = self._stream
        if stream is None:
            return
        block = self._valve.capture_read()
        if len(block):
            if not len(stream.pending):
                stream.oldest = sim_time
            clipped = np.clip(np.rint(block), -32768, 32767).astype(np.int16)
            stream.pending = np.concatenate((stream.pending, clipped))
        while len(stream.pending) >= stream.capacity:
            self._emit(stream, sim_time, stream.capacity)
        if len(stream.pending) and sim_time - stream.oldest >= FLUSH_S - 1e-9:
            self._emit(stream, sim_time, len(stream.pending))

    def _emit(self, stream: _Stream, sim_time: float, count: int) -> None:
        samples, stream.pending = stream.pending[:count], stream.pending[count:]
        data = StreamData(stream.sequence, len(stream.codes), samples)
        self.outbox.append((sim_time, encode_stream(data)))  # a full outbox drops the oldest
        stream.sequence = (stream.sequence + 1) & 0xFFFF
        stream.oldest = sim_time

    def _on_restart(self) -> None:
        self._last = None
        self._assembly = None
        if self._stream is not None:
            self._stream = None
            self._valve.remove_cycle_listener(self._on_cycle)
        self.outbox.clear()


def identify_firmware_room(type_key: str) -> int:
    """Bytes of firmware text an IDENTIFY answer has room for next to ``type_key`` (the
    firmware cuts a longer text there: 25 bytes beside a 27-byte -CA type key)."""
    fixed = 3 + 1 + 4 + 2 + 1 + len(type_key.encode("utf-8")) + 1  # header … firmware length
    return max(0, REPORT_SIZE - fixed)


def _truncate_utf8(text: str, limit: int) -> bytes:
    data = text.encode("utf-8")[:limit]
    return data.decode("utf-8", errors="ignore").encode("utf-8")

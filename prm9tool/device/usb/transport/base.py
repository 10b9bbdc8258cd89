"""The abstract transport: request/answer matching, timeouts, retries and logging.

A backend implements three small hooks — write one report, read one report with a timeout,
close — and inherits everything else (the template-method shape of python-can's ``BusABC``).
"""

from __future__ import annotations

import logging
import threading
import time
from abc import ABC, abstractmethod
from collections import deque
from dataclasses import dataclass

from prm9tool.device.usb.protocol import (
    ERROR_OP,
    Op,
    Request,
    Response,
    StreamData,
    decode_response,
    encode_request,
)
from prm9tool.errors import DeviceDisconnectedError, DeviceTimeoutError, ProtocolError

log = logging.getLogger("prm9tool.device.usb.transport")
STREAM_BACKLOG = 65536  # stream reports kept for the reader; older ones are dropped (and counted)


@dataclass
class LinkStats:
    """Counters of one transport (for benchmarks, logs and tests)."""

    reports_out: int = 0
    reports_in: int = 0
    retries: int = 0
    discarded: int = 0  # answers that matched no outstanding request (late or duplicated)
    stream_reports: int = 0


class Transport(ABC):
    """One open link to one valve.

    ``request`` sends a request and returns the matching answer. Answers are matched by
    sequence number and opcode; stray answers (late, duplicated) are discarded. Idempotent
    requests are repeated with the same sequence number when no answer arrives within
    ``timeout_s``; the others fail at once with :class:`DeviceTimeoutError`.
    """

    def __init__(self, *, timeout_s: float = 0.25, retries: int = 3, name: str = "") -> None:
        self.timeout_s = timeout_s
        self.retries = retries
        self.name = name or type(self).__name__
        self.stats = LinkStats()
        self._lock = threading.RLock()
        self._seq = 0
        self._stream: deque[StreamData] = deque(maxlen=STREAM_BACKLOG)
        self._broken: DeviceDisconnectedError | None = None
        self._closed = False

    # --- the template --------------------------------------------------------------------
    def request(self, message: Request) -> Response:
        """Send ``message`` and return the valve's answer (an ``AbortReply`` if refused)."""
        with self._lock:
            self._check_open()
            self._seq = self._seq % 255 + 1
            report = encode_request(self._seq, message)
            attempts = 1 + (self.retries if message.idempotent else 0)
            for attempt in range(attempts):
                if attempt:
                    self.stats.retries += 1
                    log.info("%s: no answer to %s, retry %d", self.name, _name(message), attempt)
                self._send(report)
                answer = self._await(self._seq, message.op)
                if answer is not None:
                    return answer
            raise DeviceTimeoutError(
                f"the valve did not answer {_name(message)} within {self.timeout_s:g} s"
                + (f" ({attempts} attempts)" if attempts > 1 else "")
            )

    def poll_stream(self) -> list[StreamData]:
        """Every stream report received so far (reads whatever the link holds, never waits)."""
        with self._lock:
            self._check_open()
            while (raw := self._receive(0.0)) is not None:
                self._dispatch(raw, -1, -1)
            reports = list(self._stream)
            self._stream.clear()
            return reports

    def drop_stream(self) -> None:
        """Forget the stream reports received so far, without reading the link."""
        with self._lock:
            self._stream.clear()

    def close(self) -> None:
        """Close the link (idempotent)."""
        with self._lock:
            if not self._closed:
                self._closed = True
                self._close()

    def reconnect(self) -> None:
        """Find the valve again after it restarted; the base only forgets the old stream."""
        with self._lock:
            self._stream.clear()

    @property
    def closed(self) -> bool:
        """True once :meth:`close` was called."""
        return self._closed

    # --- backend hooks -------------------------------------------------------------------
    @abstractmethod
    def _write(self, report: bytes) -> None:
        """Put one 64-byte report on the link; raise DeviceDisconnectedError if it is gone."""

    @abstractmethod
    def _read(self, timeout_s: float) -> bytes | None:
        """One report from the valve, or None after ``timeout_s``; raise if disconnected."""

    @abstractmethod
    def _close(self) -> None:
        """Release the backend's resources."""

    def _now(self) -> float:
        """The clock timeouts run on (a backend with simulated time overrides it)."""
        return time.monotonic()

    # --- internals -----------------------------------------------------------------------
    def _check_open(self) -> None:
        if self._closed:
            raise DeviceDisconnectedError(f"{self.name}: the connection is closed")
        if self._broken is not None:
            raise DeviceDisconnectedError(str(self._broken))

    def _send(self, report: bytes) -> None:
        if log.isEnabledFor(logging.DEBUG):
            log.debug("%s TX %s", self.name, report.hex(" "))
        try:
            self._write(report)
        except DeviceDisconnectedError as exc:
            self._broken = exc
            raise
        self.stats.reports_out += 1

    def _receive(self, timeout_s: float) -> bytes | None:
        try:
            raw = self._read(timeout_s)
        except DeviceDisconnectedError as exc:
            self._broken = exc
            raise
        if raw is not None:
            self.stats.reports_in += 1
            if log.isEnabledFor(logging.DEBUG):
                log.debug("%s RX %s", self.name, raw.hex(" "))
        return raw

    def _await(self, seq: int, op: int) -> Response | None:
        deadline = self._now() + self.timeout_s
        while (remaining := deadline - self._now()) > 0:
            raw = self._receive(remaining)
            if raw is None:
                continue
            answer = self._dispatch(raw, seq, op)
            if answer is not None:
                return answer
        return None

    def _dispatch(self, raw: bytes, seq: int, op: int) -> Response | None:
        decoded = decode_response(raw)
        if isinstance(decoded, StreamData):
            self.stats.stream_reports += 1
            self._stream.append(decoded)
            return None
        answer_op, answer_seq, answer = decoded
        if answer_seq != seq or answer_op not in (op, ERROR_OP):
            self.stats.discarded += 1
            log.debug("%s: discarded a stray answer (op 0x%02X seq %d)", self.name, answer_op, seq)
            return None
        if answer_op == ERROR_OP:
            raise ProtocolError(
                f"the valve did not understand request {_op_name(op)}; "
                "it probably speaks a different protocol version"
            )
        return answer


def _op_name(op: int) -> str:
    try:
        return Op(op).name
    except ValueError:
        return f"0x{op:02X}"


def _name(message: Request) -> str:
    return _op_name(message.op)

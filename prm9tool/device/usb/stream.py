"""Receiving the measuring-point stream: sequence numbers, lost-sample count, numpy blocks."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

import numpy as np

from prm9tool.catalogue.signals import BY_KEY
from prm9tool.device.usb.protocol import (
    STREAM_BASE_RATE_HZ,
    STREAM_MAX_CHANNELS,
    Done,
    StreamStart,
    StreamStarted,
    StreamStop,
)
from prm9tool.device.usb.transport import Transport
from prm9tool.errors import ValueRangeError

_STALE = 0x8000  # a sequence number this far "behind" is a duplicate, not a gap


class StreamReceiver:
    """The host side of one stream: starts and stops it, collects samples, counts gaps."""

    def __init__(self, call: Callable[..., Any], transport: Transport) -> None:
        self._call = call
        self._transport = transport
        self.keys: tuple[str, ...] = ()
        self.running = False
        self.lost = 0
        self._expected = 0
        self._capacity = 0

    def start(self, keys: Sequence[str], rate_hz: int) -> None:
        """Start streaming ``keys`` at ``rate_hz`` (5000 Hz divided by a whole number)."""
        codes = tuple(_code(key) for key in keys)
        if not 1 <= len(codes) <= STREAM_MAX_CHANNELS:
            raise ValueRangeError(
                f"stream 1 to {STREAM_MAX_CHANNELS} measuring points, not {len(codes)}"
            )
        decimation = _decimation(rate_hz)
        self._transport.poll_stream()  # forget reports of an earlier stream
        reply = self._call(StreamStart(codes, decimation), StreamStarted)
        self._transport.drop_stream()  # reports that came before the answer are of the old stream
        self.keys, self.running, self.lost = tuple(keys), True, 0
        self._expected, self._capacity = 0, reply.samples_per_report

    def read(self) -> np.ndarray:
        """Samples received since the last call, shape (n, channels), raw values."""
        width = max(len(self.keys), 1)
        if not self.running:
            return np.empty((0, width))
        blocks: list[np.ndarray] = []
        for report in self._transport.poll_stream():
            gap = (report.sequence - self._expected) & 0xFFFF
            if gap >= _STALE or report.channels != len(self.keys):
                continue  # a duplicate or a report of an earlier stream
            self.lost += gap * self._capacity
            self._expected = (report.sequence + 1) & 0xFFFF
            blocks.append(report.samples)
        if not blocks:
            return np.empty((0, width))
        return np.concatenate(blocks).astype(np.float64)

    def stop(self) -> None:
        """Stop the stream."""
        self.running = False
        self._call(StreamStop(), Done)

    def forget(self) -> None:
        """The valve restarted: its stream is gone."""
        self.running = False


def _code(key: str) -> int:
    signal = BY_KEY.get(key)
    if signal is None:
        raise ValueRangeError(f"{key!r} is not a measuring point")
    return signal.code


def _decimation(rate_hz: int) -> int:
    if rate_hz <= 0 or STREAM_BASE_RATE_HZ % rate_hz:
        raise ValueRangeError(
            f"stream rate {rate_hz} Hz: use {STREAM_BASE_RATE_HZ} Hz divided by a whole number "
            "(5000, 2500, 1000, 500, …)"
        )
    return STREAM_BASE_RATE_HZ // rate_hz

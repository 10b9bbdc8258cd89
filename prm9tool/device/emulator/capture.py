"""Capture of up to three measuring points at every cycle, into a flat float buffer.

The loop appends with one C-level ``array.extend(itemgetter(values))`` per captured sample,
so capturing costs a fraction of a microsecond per cycle (docs/PERFORMANCE.md).
"""

from __future__ import annotations

from array import array
from collections.abc import Sequence
from operator import itemgetter

import numpy as np

from prm9tool.catalogue.signals import MAX_CHANNELS
from prm9tool.device.emulator.loopstate import SIGNAL_ORDER, LoopState
from prm9tool.errors import ValueRangeError

MAX_ROWS = 200_000  # 40 s at full rate; older samples are dropped when nobody reads


class Capture:
    """Owns the buffer the loop writes into while a capture runs."""

    def __init__(self, loop: LoopState) -> None:
        self.loop = loop
        self.keys: tuple[str, ...] = ()
        self.buffer = array("d")
        self.dropped_rows = 0

    def start(self, keys: Sequence[str], decimation: int = 1) -> None:
        """Start recording ``keys`` every ``decimation`` cycles (restarts a running capture)."""
        keys = tuple(keys)
        if not 1 <= len(keys) <= MAX_CHANNELS:
            raise ValueRangeError(
                f"capture: {len(keys)} measuring points requested; 1 to {MAX_CHANNELS} allowed"
            )
        unknown = [k for k in keys if k not in SIGNAL_ORDER]
        if unknown:
            raise ValueRangeError(f"capture: unknown measuring point(s) {', '.join(unknown)}")
        if decimation < 1:
            raise ValueRangeError(f"capture: decimation {decimation} must be at least 1")
        index = [SIGNAL_ORDER.index(k) for k in keys]
        index += [index[0]] * (MAX_CHANNELS - len(index))
        self.keys = keys
        self.buffer = array("d")
        self.dropped_rows = 0
        self.loop.capture = (  # the reference loop uses the first three, the compiled one the rest
            self.buffer.extend,
            itemgetter(*index),
            int(decimation),
            self.buffer,
            tuple(index),
        )
        self.loop.inputs_version += 1  # the loop picks the capture up in its next cycle

    def read(self) -> np.ndarray:
        """Drain: an array of shape (n, len(keys)) with the samples since the last read."""
        if not self.keys:
            return np.empty((0, 0))
        data = np.array(self.buffer, dtype=float).reshape(-1, MAX_CHANNELS)
        del self.buffer[:]
        return np.ascontiguousarray(data[:, : len(self.keys)])

    def trim(self) -> None:
        """Drop the oldest rows beyond MAX_ROWS (called after every batch)."""
        excess = len(self.buffer) // MAX_CHANNELS - MAX_ROWS
        if excess > 0:
            del self.buffer[: excess * MAX_CHANNELS]
            self.dropped_rows += excess

    def stop(self) -> None:
        """Stop recording and discard the buffer."""
        self.loop.capture = None
        self.loop.inputs_version += 1
        self.keys = ()
        self.buffer = array("d")

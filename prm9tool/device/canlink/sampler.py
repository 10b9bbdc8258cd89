"""Measuring points over CANopen: sampled by SDO at a fixed period in a thread of its own.

A measuring point with an object in the valve's dictionary (the catalogue's
``signals.SIGNAL_OBJECTS``: actual position 0x6301, demand value 0x6310, control deviation
0x6350, process actual value 0x6381, supply 0x2003, temperature 0x2002) is read each period; the demand value (``position_setpoint``/``process_setpoint``) is the setpoint this tool
sends in RPDO1 while it drives the valve (``demand``; the valve does not report its own); the
others have no object on a real valve and give NaN (shown as no data, never a made-up curve).
The stream has one row per period: a period whose reads did not finish in time is a NaN row
at its time and counts as lost, so the time axis stays true and the scope's "lost" figure and
the real sample rate (:attr:`SdoSampler.achieved_hz`) say how much the bus delivered; nothing
is interpolated.
"""

from __future__ import annotations

import logging
import threading
import time
from collections.abc import Callable, Sequence

import numpy as np

from prm9tool.catalogue.signals import SETPOINT_SIGNALS, signal_object
from prm9tool.errors import Prm9Error, ValueRangeError

log = logging.getLogger(__name__)
MAX_CHANNELS = 3


Reader = Callable[[int, int], bytes]
Demand = Callable[[str], float]  # measuring-point key -> the setpoint this tool sends (NaN: none)
DEMAND_KEYS = tuple(SETPOINT_SIGNALS)  # the setpoint the tool sends in RPDO1 (not read back)


class SdoSampler:
    """Samples up to three measuring points at ``rate_hz`` by SDO until stopped."""

    def __init__(
        self, read: Reader, keys: Sequence[str], rate_hz: float, demand: Demand | None = None
    ) -> None:
        if not 1 <= len(keys) <= MAX_CHANNELS:
            raise ValueRangeError(f"stream 1 to {MAX_CHANNELS} measuring points, not {len(keys)}")
        if rate_hz <= 0:
            raise ValueRangeError(f"sample rate {rate_hz} Hz")
        self.keys = tuple(keys)
        self.period_s = 1.0 / rate_hz
        self.lost = 0
        self.samples = 0
        self.error: Prm9Error | None = None
        self._read = read
        self._demand = demand
        # measuring point -> its object's address, sign and factor (the catalogue's table)
        self._objects = {k: _address(k) for k in self.keys}
        self._rows: list[list[float]] = []
        self._lock = threading.Lock()
        self._stop = threading.Event()
        self._started = time.monotonic()
        self._thread = threading.Thread(target=self._run, name="prm9tool-can-sampler", daemon=True)
        self._thread.start()

    @property
    def achieved_hz(self) -> float:
        """Samples per second actually taken since the start."""
        elapsed = time.monotonic() - self._started
        return self.samples / elapsed if elapsed > 0 else 0.0

    def read(self) -> np.ndarray:
        """Rows taken since the last call (n, channels); raises the link error that ended it."""
        with self._lock:
            rows, self._rows = self._rows, []
        if self.error is not None and not rows:
            raise self.error
        return np.asarray(rows, dtype=np.float64).reshape(len(rows), len(self.keys))

    def stop(self) -> None:
        """Stop sampling (waits for the thread)."""
        self._stop.set()
        if self._thread is not threading.current_thread():
            self._thread.join(timeout=2.0)

    def _run(self) -> None:
        due = time.monotonic()
        while not self._stop.is_set():
            try:
                row = [self._sample(key) for key in self.keys]
            except Prm9Error as exc:
                self.error = exc
                return
            with self._lock:
                self._rows.append(row)
            self.samples += 1
            due += self.period_s
            behind = time.monotonic() - due
            if behind > 0:  # the reads took longer than a period: those samples are lost
                missed = int(behind / self.period_s) + 1
                self.lost += missed
                due += missed * self.period_s
                with self._lock:  # gaps at their time, so the time axis stays true
                    self._rows.extend([[float("nan")] * len(self.keys)] * missed)
            self._stop.wait(max(due - time.monotonic(), 0.0))

    def _sample(self, key: str) -> float:
        obj = self._objects[key]
        if obj is None:
            return self._demand(key) if key in DEMAND_KEYS and self._demand else float("nan")
        index, subindex, signed, factor = obj
        data = self._read(index, subindex)
        return int.from_bytes(data, "little", signed=signed) * factor


def _address(key: str) -> tuple[int, int, bool, float] | None:
    """Index, sub-index, signedness and factor of the object that holds ``key`` (None)."""
    found = signal_object(key)
    if found is None:
        return None
    param, factor = found
    return param.index, param.subindex, param.dtype.natural_range[0] < 0, factor

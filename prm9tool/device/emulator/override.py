"""A setpoint waveform applied to the override object SETPOVR by the valve's own loop.

The host hands the emulated valve a function from times (s since the program started) to
SETPOVR raw values; the firmware applies it at the cycle it is due, splitting its batches of
control cycles where the value changes. So a waveform runs on the valve's own clock, exact to
its 200 µs cycle, whether the emulation is paced to the wall clock or stepped faster than real
time. It takes effect while SETPOVRON = 1, like a value written over the link.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from prm9tool.device.emulator import config
from prm9tool.device.emulator.constants import CYCLE_S

Source = Callable[[np.ndarray], np.ndarray]
BLOCK_CYCLES = 250  # the source is evaluated 50 ms ahead at a time


class OverrideProgram:
    """The values of a :data:`Source` on the cycle grid, from cycle ``start`` on."""

    def __init__(self, source: Source, start: int) -> None:
        self._source = source
        self._start = start
        self._first = 0
        self._values = np.empty(0, dtype=np.int64)
        self._changes = np.empty(0, dtype=np.int64)  # positions in _values where it changes
        self.chain: tuple[int, config.SetpointChain] | None = None  # (loop version, chain)

    def value_and_span(self, cycle: int) -> tuple[int, int]:
        """SETPOVR at ``cycle`` and for how many cycles from there on it stays so (≥ 1)."""
        k = cycle - self._start
        if not self._first <= k < self._first + len(self._values):
            self._evaluate(k)
        i = k - self._first
        following = int(np.searchsorted(self._changes, i, side="right"))
        end = int(self._changes[following]) if following < len(self._changes) else len(self._values)
        return int(self._values[i]), end - i

    def upcoming(self, cycle: int, limit: int) -> np.ndarray:
        """SETPOVR at ``cycle`` and the cycles after it: at least 1, at most ``limit`` values."""
        k = cycle - self._start
        if not self._first <= k < self._first + len(self._values):
            self._evaluate(k)
        i = k - self._first
        return self._values[i : i + limit]

    def _evaluate(self, k: int) -> None:
        times = np.arange(k, k + BLOCK_CYCLES, dtype=np.float64) * CYCLE_S
        values = np.asarray(self._source(times), dtype=np.int64)
        if values.shape != (BLOCK_CYCLES,):
            raise ValueError(f"setpoint source returned shape {values.shape}")
        self._first, self._values = k, values
        self._changes = np.flatnonzero(np.diff(values)) + 1

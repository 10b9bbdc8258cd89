"""Pacing the simulation to a wall clock: drift-free, in batches, catching up after a stall.

The pacer never accumulates sleep errors: the number of cycles due is always computed from
the absolute time since :meth:`Pacer.reset`, so a late wake-up is followed by a bigger batch
and a stall by a run of back-to-back batches until the simulation has caught up. A lag longer
than ``max_lag_s`` (the process was suspended, a debugger held it) is dropped instead of
replayed, and counted in ``dropped_cycles``. How far and how often it fell behind (more than
``LATE_S``) is kept for a report (:meth:`Pacer.take_lateness`, the serve log).
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass

LATE_S = 0.010  # behind by more than this: counted as a late episode (a batch is 2 ms)
# A valve paced in a group by the bus's receive thread (--serve-emulator) runs its batch once
# this many cycles (0.4 ms) are due, not 10: the simulation then runs between frames, and a
# SYNC finds at most a few cycles to run before its TPDO (EmulatedValve.run_due_by) instead of
# a whole millisecond of every valve's, and the state is 0.4 ms behind at most while it keeps
# up. On a quiet 2-core PC, 32 valves at a 2 ms SYNC: TPDO1 within 1 ms better in 4 of 5
# paired runs (median +2 points), 16 at 1 ms unchanged (docs/PERFORMANCE.md, "issue 30,
# fourth stop").
GROUPED_MIN_BATCH = 2
CATCH_UP = 10  # a SYNC runs at most this many due cycles; more: behind, the batches catch up


@dataclass(frozen=True)
class Lateness:
    """How the simulation kept up since the last report."""

    episodes: int  # times it fell more than LATE_S behind the wall clock
    worst_s: float  # the largest lag seen
    dropped_cycles: int  # cycles skipped instead of replayed (a lag beyond max_lag_s)


class Pacer:
    """Decides how many control cycles are due at the current wall-clock time."""

    def __init__(
        self,
        cycle_s: float,
        clock: Callable[[], float] = time.monotonic,
        min_batch: int = 10,
        max_batch: int = 50,
        max_lag_s: float = 5.0,
    ) -> None:
        self.cycle_s = cycle_s
        self.clock = clock
        self.min_batch = min_batch
        self.catch_up = CATCH_UP
        self.max_batch = max_batch
        self.max_lag_cycles = int(max_lag_s / cycle_s)
        self.max_lag_s = max_lag_s
        self.start = clock()
        self.cycles_done = 0
        self.dropped_cycles = 0
        self._late = False
        self._episodes = 0
        self._worst_s = 0.0
        self._dropped_reported = 0

    def reset(self) -> None:
        """Start a new time base at the current wall-clock time."""
        self.start = self.clock()
        self.cycles_done = 0
        self.dropped_cycles = 0
        self._dropped_reported = 0

    def due(self) -> int:
        """Cycles to run now (0 if fewer than ``min_batch`` are due), at most ``max_batch``."""
        target = int((self.clock() - self.start) / self.cycle_s + 1e-6)
        lag = target - self.cycles_done
        self._note_lag(lag * self.cycle_s)
        if lag > self.max_lag_cycles:
            skipped = lag - self.max_lag_cycles
            self.cycles_done += skipped
            self.dropped_cycles += skipped
            lag = self.max_lag_cycles
        if lag < self.min_batch:
            return 0
        return min(lag, self.max_batch)

    def due_by(self, at: float) -> int:
        """Cycles of the batch in progress due by ``at`` (a time of ``clock``): the lag then if
        it is at most :data:`CATCH_UP` (the simulation keeping up), else 0 (it is behind: the
        batches catch up, :meth:`due`)."""
        lag = int((at - self.start) / self.cycle_s + 1e-6) - self.cycles_done
        return lag if 0 < lag <= self.catch_up else 0

    def _note_lag(self, lag_s: float) -> None:
        late = lag_s > LATE_S
        if late and not self._late:
            self._episodes += 1
        self._late = late
        if lag_s > self._worst_s:
            self._worst_s = lag_s

    def take_lateness(self) -> Lateness:
        """Episodes, worst lag and dropped cycles since the last call (then starts afresh)."""
        report = Lateness(
            self._episodes, self._worst_s, self.dropped_cycles - self._dropped_reported
        )
        self._episodes, self._worst_s = 0, 0.0
        self._dropped_reported = self.dropped_cycles
        return report

    def done(self, cycles: int) -> None:
        """Record that ``cycles`` cycles were run."""
        self.cycles_done += cycles

    def batch_due_at(self) -> float:
        """When (a time of ``clock``) the next batch of ``min_batch`` cycles is due."""
        return self.start + (self.cycles_done + self.min_batch) * self.cycle_s

    def wait_s(self) -> float:
        """Seconds until the next batch of ``min_batch`` cycles is due (0 if already due)."""
        return max(0.0, self.batch_due_at() - self.clock())

    def lag_s(self) -> float:
        """How far the simulation is behind the wall clock, in seconds."""
        return (self.clock() - self.start) - self.cycles_done * self.cycle_s

"""SYNC produced by the tool, and the samples that answer it placed by their SYNC's number.

The valve sends a synchronous TPDO in answer to each SYNC (manual §7.2.5, table 7-12: a SYNC is
a frame without data, so it carries no counter). The tool therefore counts its SYNCs itself:
:class:`SyncClock` sends SYNC number ``k`` at ``k`` periods after its start, from a thread of
its own, and a sample's time is its SYNC's number times the period — never the moment the PC
happened to read the frame. A tick the thread reaches more than half a period late (a busy PC)
is skipped: no SYNC goes out for it and its sample is lost, so the others keep their place; a
SYNC held up while being sent counts as lost too.

Which SYNC a received frame answers is told by its reception time stamp (the interface's, taken
when the frame arrived, not when Python read it — python-can gives seconds since the epoch):
the last SYNC sent before it. Samples are kept by that number (:class:`SlotSamples`); one that
does not arrive is NaN in its place — a gap, never a shifted curve.
"""

from __future__ import annotations

import bisect
import math
import threading
import time
from collections.abc import Callable

import numpy as np

SYNC_COB_ID = 0x80  # table 7-13: 0x1005 default
LATE_SHARE_OF_PERIOD = 0.5  # a tick reached later than this share of a period is skipped
VOID_PERIODS = 1.0  # a SYNC whose sending ended this many periods after its time is void

Send = Callable[[int, bytes], None]  # (COB-ID, data): the bus's send


class SyncClock:
    """SYNC every ``period_s`` from a thread; ``before_sync(k)`` runs just before SYNC ``k``
    (the characterization sends the tick's setpoint there, so it travels with its SYNC)."""

    def __init__(
        self,
        send: Send,
        period_s: float,
        before_sync: Callable[[int], None] | None = None,
        cob_id: int = SYNC_COB_ID,
        limit: int | None = None,
    ) -> None:
        self.period_s = period_s
        self.limit = limit  # the clock stops by itself after this many ticks (None: never)
        self.skipped = 0  # ticks not sent because the thread came too late
        self.error: Exception | None = None  # what stopped the thread (the bus refused)
        self._send, self._before, self._cob_id = send, before_sync, cob_id
        self._ticks: list[int] = []  # numbers of the SYNCs sent, ascending
        self._stamps: list[float] = []  # epoch time just before each was sent
        self._void: set[int] = set()  # ticks whose SYNC went out too late: answers dropped
        self._next = 0  # the number of the next tick
        self._lock = threading.Lock()
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._run, name="prm9tool-sync", daemon=True)

    def start(self) -> None:
        """Start sending (tick 0 at once)."""
        self._thread.start()

    def stop(self) -> None:
        """Stop sending (waits for the thread)."""
        self._stop.set()
        if self._thread.is_alive() and self._thread is not threading.current_thread():
            self._thread.join()

    @property
    def ticks(self) -> int:
        """Ticks elapsed so far, sent or skipped."""
        return self._next

    @property
    def sent(self) -> int:
        """SYNCs sent so far."""
        with self._lock:
            return len(self._ticks)

    def tick_of(self, timestamp: float) -> int | None:
        """The number of the SYNC a frame received at ``timestamp`` (epoch s) answers: the
        last one sent before it (None: before the first)."""
        with self._lock:
            k = bisect.bisect_right(self._stamps, timestamp) - 1
            return self._ticks[k] if k >= 0 else None

    @property
    def voided(self) -> int:
        """SYNCs sent too late to count so far."""
        with self._lock:
            return len(self._void)

    def void(self, tick: int) -> bool:
        """True when SYNC ``tick`` went out more than :data:`VOID_PERIODS` late (its answer
        would describe another moment than its number says; it counts as lost)."""
        with self._lock:
            return tick in self._void

    def wait_ticks(self, count: int, timeout_s: float) -> bool:
        """Wait at most ``timeout_s`` for ``count`` ticks to elapse; True once they have (or
        the clock stopped: it will not get there)."""
        deadline = time.perf_counter() + timeout_s
        while self._next < count and self._thread.is_alive():
            left = deadline - time.perf_counter()
            if left <= 0:
                return False
            self._stop.wait(min(left, max(self.period_s, (count - self._next) * self.period_s)))
        return True

    def _run(self) -> None:
        period = self.period_s
        start = time.perf_counter()
        k = 0
        while not self._stop.is_set() and (self.limit is None or k < self.limit):
            due = start + k * period
            wait = due - time.perf_counter()
            if wait > 0:
                time.sleep(wait)
            late = time.perf_counter() - due
            if late > LATE_SHARE_OF_PERIOD * period:  # on to the first tick still in time
                elapsed = time.perf_counter() - start
                resume = max(k + 1, math.ceil(elapsed / period - LATE_SHARE_OF_PERIOD))
                if self.limit is not None:
                    resume = min(resume, self.limit)
                self.skipped += resume - k
                k = self._next = resume
                continue
            with self._lock:  # before sending: an answer may come back at once
                self._ticks.append(k)
                self._stamps.append(time.time())
            try:
                if self._before is not None:
                    self._before(k)
                self._send(self._cob_id, b"")
            except Exception as exc:  # the owner raises it to the user
                self.error = exc
                return
            if time.perf_counter() - due > VOID_PERIODS * period:
                with self._lock:  # held up while sending: its answer is not of its time
                    self._void.add(k)
            k += 1
            self._next = k


class SlotSamples:
    """Values by the number of the SYNC they answer; what did not arrive is NaN."""

    def __init__(self, clock: SyncClock, channels: int = 1) -> None:
        self.clock = clock
        self.channels = channels
        self.received = 0  # frames placed
        self.late = 0  # frames that came after their slot was handed out (dropped)
        self._slots: dict[int, list[float]] = {}
        self._given = 0  # slots before this one have been handed out by take()
        self._lock = threading.Lock()

    def put(self, timestamp: float, values: list[float]) -> None:
        """A frame received at ``timestamp`` carrying ``values`` (one per channel)."""
        k = self.clock.tick_of(timestamp)
        if k is None:
            return
        with self._lock:
            if k < self._given:
                self.late += 1
                return
            if k not in self._slots:
                self.received += 1
            self._slots[k] = values  # two answers in one slot: the newer counts

    @property
    def given(self) -> int:
        """The first slot the next :meth:`take` hands out."""
        return self._given

    def wait_for(self, tick: int, timeout_s: float) -> None:
        """Wait at most ``timeout_s`` for the answer to SYNC ``tick`` (the last of a test)."""
        deadline = time.perf_counter() + timeout_s
        while tick not in self._slots and time.perf_counter() < deadline:
            time.sleep(min(0.001, self.clock.period_s))

    def take(self, until: int) -> np.ndarray:
        """The slots from the last call up to ``until`` (exclusive), shape (n, channels)."""
        with self._lock:
            start, self._given = self._given, max(self._given, until)
            rows = np.full((max(0, until - start), self.channels), np.nan)
            for k in range(start, until):
                values = self._slots.pop(k, None)
                if values is not None and not self.clock.void(k):
                    rows[k - start] = values
        return rows

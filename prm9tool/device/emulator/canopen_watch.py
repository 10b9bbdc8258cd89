"""The emulated valve's CANopen timing watches, judged at the time frames arrived on the bus.

Two watches of CiA 301 the manual's valve has: the SYNC consumer (0x1006 ≠ 0: a SYNC missing
for 1.5 periods is the SYNC error 8100h of table 7-18; the manual lists no 0x1007 window) and
the reception deadline of an RPDO (its event timer 0x1400/5, 0x1401/5: the event-timer error
8100h). A real valve judges both on its own clock at the moment a frame arrives.

The emulated valve's simulation is paced to the wall clock in batches and falls behind on a
busy PC, then catches up in a burst while the receive thread waits for the valve's lock. Its
simulated time is therefore no clock for these watches: the burst would look like a gap. So
while the valve runs in real time (:meth:`EmulatedValve.start`) every watch works in
wall-clock milliseconds (``time.monotonic``): a frame counts at its reception time stamp
(python-can's ``Message.timestamp``, the kernel's on udp_multicast and SocketCAN), and a
deadline is missed only when a frame stamped after it arrives first, or when the bus stayed
quiet past it (the receive thread's ``recv`` timed out, so the kernel held no frame). Under
:meth:`EmulatedValve.advance` (tests stepping faster than real time) there is no wall clock
to follow and the watches judge simulated milliseconds, as the loop's 1 ms task sees them.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable, Sequence
from typing import Protocol

from prm9tool.device.emulator.fasttick import MAX_TICKS

SYNC_TIMEOUT_FACTOR = 1.5  # decision: SYNC missing for 1.5 x 0x1006 = SYNC error (8100h)
RX_POLL_S = 0.1  # the receive thread looks at its stop flag at least this often
MAX_AGE_S = 5.0  # a time stamp older than this (or in the future) is not a reception time
# decision: a SYNC the paced valve gets to more than this, and more than LATE_SYNC_PERIODS of
# the SYNC's interval, after it arrived (the PC fell behind the bus: frames queued in its
# socket) is counted but answered with no TPDO (CanopenSlave); at a slow SYNC a steady delay
# of a few ms is still answered
LATE_SYNC_MS = 10.0
LATE_SYNC_PERIODS = 2.0
QUIET_FOREVER = MAX_TICKS  # no deadline armed: no 1 ms task judges anything


class Deadline(Protocol):
    """The part of an RPDO channel the deadline watch needs (:class:`.canopen_pdo.PdoChannel`)."""

    event_timer: int
    deadline_ms: float | None

    @property
    def valid(self) -> bool:
        """False while bit 31 of the COB-ID marks the PDO invalid."""
        ...


class TimingWatches:
    """SYNC and RPDO-deadline watches on one time base (wall clock when paced, else simulated).

    ``period_us`` reads 0x1006; ``report(event)`` raises ``sync_error`` / ``rpdo_timeout``.
    Every method is called with the valve's lock held.
    """

    def __init__(
        self,
        rpdos: Sequence[Deadline],
        period_us: Callable[[], int],
        report: Callable[[str], None],
        clock: Callable[[], float] = time.monotonic,
    ) -> None:
        self._rpdos = rpdos
        self._period_us = period_us
        self._report = report
        self._clock = clock
        self.paced = False
        self.last_sync_ms: float | None = None  # None: not armed (no SYNC since NMT start)

    # --- time base ---------------------------------------------------------------------
    def wall_ms(self) -> float:
        """The wall clock in ms (the paced time base)."""
        return self._clock() * 1000.0

    def now_ms(self, sim_ms: float) -> float:
        """The present moment on the watches' time base."""
        return self.wall_ms() if self.paced else sim_ms

    def arrival_ms(self, timestamp: float, sim_ms: float) -> float:
        """When a frame received at ``timestamp`` (``time.time``'s epoch; 0: none) arrived, on
        the watches' time base (its time stamp when paced)."""
        if not self.paced:
            return sim_ms
        age = time.time() - timestamp if timestamp else 0.0
        if not 0.0 <= age <= MAX_AGE_S:
            age = 0.0  # no usable time stamp: it arrives now
        return self.wall_ms() - age * 1000.0

    def follow(self, paced: bool, sim_ms: float) -> None:
        """Switch the time base when the valve starts or stops running in real time; armed
        watches restart from now on the new base (nothing is judged across the switch)."""
        if paced == self.paced:
            return
        self.paced = paced
        now = self.now_ms(sim_ms)
        if self.last_sync_ms is not None:
            self.last_sync_ms = now
        for channel in self._rpdos:
            if channel.deadline_ms is not None:
                channel.deadline_ms = now + channel.event_timer

    # --- the watches --------------------------------------------------------------------
    def disarm(self) -> None:
        """Entering OPERATIONAL: the SYNC watch waits for the first SYNC."""
        self.last_sync_ms = None

    def sync_received(self, at_ms: float) -> None:
        """A SYNC arrived at ``at_ms`` (judge first: a late SYNC still was a gap)."""
        self.last_sync_ms = at_ms

    def rpdo_received(self, channel: Deadline, at_ms: float) -> None:
        """An RPDO arrived at ``at_ms``: its next frame is due an event time later."""
        if channel.event_timer:
            channel.deadline_ms = at_ms + channel.event_timer

    def judge(self, now_ms: float) -> None:
        """Report every deadline that passed before ``now_ms`` with no frame (once per loss)."""
        period_us = self._period_us()
        last = self.last_sync_ms
        if period_us and last is not None and now_ms - last > SYNC_TIMEOUT_FACTOR * period_us / 1e3:
            self.last_sync_ms = None  # one event per loss of SYNC
            self._report("sync_error")
        for channel in self._rpdos:
            deadline = channel.deadline_ms
            if deadline is not None and channel.valid and now_ms > deadline:
                channel.deadline_ms = None  # one event per loss; the next reception arms it
                self._report("rpdo_timeout")

    def _earliest_due(self) -> float | None:
        """The earliest deadline armed (ms on the present time base), or None."""
        due = [c.deadline_ms for c in self._rpdos if c.deadline_ms is not None and c.valid]
        period_us = self._period_us()
        if period_us and self.last_sync_ms is not None:
            due.append(self.last_sync_ms + SYNC_TIMEOUT_FACTOR * period_us / 1e3)
        return min(due) if due else None

    def wait_s(self) -> float:
        """How long the receive thread may wait for a frame before it must judge (paced)."""
        if not self.paced:
            return RX_POLL_S
        due = self._earliest_due()
        if due is None:
            return RX_POLL_S
        return min(RX_POLL_S, max(0.0, (due - self.wall_ms()) / 1000.0 + 1e-4))

    def quiet_ticks(self, first_ms: int) -> int:
        """In simulated time: how many of the 1 ms tasks at ``first_ms``, ``first_ms`` + 1, …
        would judge nothing (the first after a deadline reports it; one fewer, against
        rounding)."""
        due = self._earliest_due()
        return QUIET_FOREVER if due is None else max(0, math.floor(due) - first_ms)

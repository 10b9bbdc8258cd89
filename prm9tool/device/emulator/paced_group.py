"""One paced thread for many emulated valves (``--serve-emulator`` with a machine's worth).

Each valve's own paced thread (:meth:`EmulatedValve.start`) wakes every 2 ms of wall time to
run its batch; sixteen of them wake 8 000 times a second and compete for the GIL with the
thread that receives the bus's frames, which must answer a SYNC within a millisecond. A
:class:`PacedGroup` runs every valve's due batch in turn (:meth:`EmulatedValve.paced_step`):
the same simulation, drift-free per valve (each keeps its own :class:`~.pacing.Pacer`).

Given a *driver* (:class:`~.canopen_hub.SharedBus`), the group has no thread at all: the bus's
receive thread runs the batches due at that moment between frames (:meth:`PacedGroup.step_one`).
With a thread of its own, every datagram the receive thread takes off the socket (two system
calls, each releasing the GIL) handed the GIL to the paced thread for up to a switch interval
while its batch ran: at 16 valves the receive thread fell behind and the kernel dropped 35 000
datagrams in 5 s (docs/PERFORMANCE.md, "The PLC rig"). One thread has no one to hand it to.
"""

from __future__ import annotations

import logging
import math
import threading
import time
from collections.abc import Sequence
from typing import TYPE_CHECKING, Protocol

if TYPE_CHECKING:
    from prm9tool.device.emulator.valve import EmulatedValve

log = logging.getLogger(__name__)

# Every valve whose batch is due runs in one call, for at most BUDGET_S (frames wait no
# longer); a valve whose cycles a SYNC ran meanwhile (EmulatedValve.run_due_by) is only
# rescheduled, without a call or its lock: at a 1 ms SYNC nearly every batch found nothing to
# run, and 16 valves woke the thread 10 000 times a second for it (docs/PERFORMANCE.md).
BUDGET_S = 0.0002


class PaceDriver(Protocol):
    """A thread that runs a group's batches between its own work (the bus's receive thread)."""

    def pace(self, group: PacedGroup | None) -> None:
        """Run ``group``'s batches from now on (None: no longer; returns when none runs)."""
        ...


class PacedGroup:
    """Paces ``valves`` to the wall clock, in a thread of its own or in ``driver``'s."""

    def __init__(self, valves: Sequence[EmulatedValve], driver: PaceDriver | None = None) -> None:
        self.valves = tuple(valves)
        self._pacers = tuple(valve.pacer for valve in self.valves)
        self._driver = driver
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None
        self._running = False
        self._due = [0.0] * len(self.valves)  # time.monotonic when each valve's batch is due
        self.next_due = math.inf  # the earliest of them (inf: not pacing)

    def start(self) -> None:
        """Start pacing (each valve's time base begins now)."""
        if self._running:
            return
        for valve in self.valves:
            valve.paced_by_group(True)
        self._running = True
        self._due = [0.0] * len(self.valves)
        self.next_due = 0.0
        if self._driver is not None:
            self._driver.pace(self)
            return
        self._stop.clear()
        self._thread = threading.Thread(target=self._run, name="prm9-paced-group", daemon=True)
        self._thread.start()

    def stop(self) -> None:
        """Stop pacing (returns when no batch runs any more)."""
        if not self._running:
            return
        if self._driver is not None:
            self._driver.pace(None)
        elif self._thread is not None:
            self._stop.set()
            self._thread.join()
            self._thread = None
        self._running = False
        self.next_due = math.inf
        for valve in self.valves:
            valve.paced_by_group(False)

    def step_one(self) -> float:
        """Run the batches of the valves due now, the one due longest first, for at most
        :data:`BUDGET_S` of this thread's time; returns the seconds until the next batch of
        any valve is due (0: one is due now)."""
        now = time.monotonic()
        due = self._due
        earliest = min(due, default=math.inf)  # min and index of a list: no Python per valve
        until = now + BUDGET_S
        while earliest <= now:
            index = due.index(earliest)
            ready_at = self._pacers[index].batch_due_at()  # a SYNC may have run its cycles
            if ready_at > now:  # nothing due yet: no call, no lock
                due[index] = ready_at
            else:
                try:
                    wait = self.valves[index].paced_step()
                except Exception:  # a firmware bug must not stop the thread that runs the rest
                    log.exception("paced batch of valve %d failed", self.valves[index].serial)
                    wait = 0.1
                now = time.monotonic()
                due[index] = now + wait
                if now >= until:
                    earliest = min(due)
                    break
            earliest = min(due)
        self.next_due = earliest
        return max(0.0, earliest - now)

    def _run(self) -> None:
        while not self._stop.is_set():
            wait = self.step_one()
            if wait:
                self._stop.wait(wait)

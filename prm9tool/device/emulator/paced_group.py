"""One paced thread for many emulated valves (``--serve-emulator`` with a machine's worth).

Each valve's own paced thread (:meth:`EmulatedValve.start`) wakes every 2 ms of wall time to
run its batch; sixteen of them wake 8 000 times a second and compete for the GIL with the
thread that receives the bus's frames, which must answer a SYNC within a millisecond. A
:class:`PacedGroup` runs every valve's due batch in turn from one thread
(:meth:`EmulatedValve.paced_step`) and sleeps until the earliest next batch: the same
simulation, drift-free per valve (each keeps its own :class:`~.pacing.Pacer`), with one
wake-up where there were sixteen.
"""

from __future__ import annotations

import threading
from collections.abc import Sequence
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from prm9tool.device.emulator.valve import EmulatedValve


class PacedGroup:
    """Paces ``valves`` to the wall clock in one background thread."""

    def __init__(self, valves: Sequence[EmulatedValve]) -> None:
        self.valves = tuple(valves)
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None

    def start(self) -> None:
        """Start pacing (each valve's time base begins now)."""
        if self._thread is not None:
            return
        for valve in self.valves:
            valve.paced_by_group(True)
        self._stop.clear()
        self._thread = threading.Thread(target=self._run, name="prm9-paced-group", daemon=True)
        self._thread.start()

    def stop(self) -> None:
        """Stop pacing (returns when the thread has ended)."""
        if self._thread is None:
            return
        self._stop.set()
        self._thread.join()
        self._thread = None
        for valve in self.valves:
            valve.paced_by_group(False)

    def _run(self) -> None:
        while not self._stop.is_set():
            wait = min(valve.paced_step() for valve in self.valves)
            if wait:
                self._stop.wait(wait)

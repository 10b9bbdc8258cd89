"""An emulated -CA valve in this process stepped by the master's SYNC instead of paced to the
wall clock, so sample ``k`` of a SYNC-paced run is the valve at exactly ``k`` periods whatever
the PC's load. Paced, the emulator's firmware runs in batches of 2–10 ms, and SYNCs 1 ms apart
found one state twice (repeated samples no real valve gives).

The proof of a twin of a valve measured over CAN characterizes the twin this way
(:func:`prm9tool.twin.proof.characterize_twin`), and the tests step their CAN valves with it.

A SYNC carries no number (manual §7.2.5), and on a loaded PC its time stamp does not tell it
either (a thread waits for Python's GIL for milliseconds): the master's clock made by
:attr:`SyncStepper.clock` (a :class:`~prm9tool.device.canlink.sync_clock.SyncClock` that
behaves as it) notes the number of each SYNC it sends. At SYNC ``k`` of a play the valve runs
up to ``k`` periods from the play's first SYNC (through the ticks the master skipped), then
takes the SYNC: its synchronous RPDO takes effect and its TPDO1 answers with the state at that
SYNC (CiA 301). The answer carries the SYNC's time stamp plus 1 µs — a real valve answers at
once and the master's interface stamps the frame on reception — not the moment this process's
receive thread got to it, so the master places it by the SYNC it answers. Between plays the
valve does not run (nothing records it then). What the master's path still loses on a busy PC
(a tick its thread reached too late is skipped, a SYNC sent too late is void) it loses as with
a real valve. No Qt.
"""

from __future__ import annotations

import collections
import time
from collections.abc import Callable
from typing import TYPE_CHECKING

import can

from prm9tool.device.canlink.sync_clock import SYNC_COB_ID, Send, SyncClock

if TYPE_CHECKING:
    from prm9tool.device.emulator import EmulatedValve

ANSWER_DELAY_S = 1e-6  # a TPDO1's stamp after the SYNC it answers


class SyncStepper:
    """``valve`` on ``bus`` (a python-can bus that keeps the time stamps it is given:
    ``preserve_timestamps=True`` on a virtual one) stepped by the master's SYNC of
    ``period_s``, once :meth:`attach` ed. The master must produce its SYNC with a clock of
    the class :attr:`clock`."""

    def __init__(self, valve: EmulatedValve, bus: can.BusABC, period_s: float) -> None:
        self.valve, self.bus, self.period_s = valve, bus, period_s
        self.syncs = 0  # SYNCs the valve took
        self.skipped = 0  # ticks the master did not send (the valve ran through them)
        self._tick = 0  # the tick of the play the valve is at
        self._answer_at: float | None = None  # the stamp for the answer to the SYNC taken
        self._numbers: collections.deque[int] = collections.deque()
        self.clock = _numbered_clock(self._numbers)

    def attach(self) -> SyncStepper:
        """Stop the valve's paced thread (if any) and step it by SYNC from now on: the frames
        its CANopen slave receives from ``bus`` after this are seen first. Attach before
        :meth:`~prm9tool.device.emulator.EmulatedValve.connect_can` (or before the first
        SYNC), so no receive call in progress misses one."""
        self.valve.stop()
        recv: Callable[[float | None], can.Message | None] = self.bus.recv
        send = self.bus.send
        cob_id = SYNC_COB_ID
        numbers = self._numbers

        def stepped(timeout: float | None = None) -> can.Message | None:
            self._answer_at = None  # the last frame is handled: its answers are sent
            msg = recv(timeout)
            if msg is None or msg.arbitration_id != cob_id or msg.dlc:
                return msg
            tick = numbers.popleft() if numbers else self._tick + 1  # another master's SYNC
            periods = 1 if tick == 0 else tick - self._tick  # tick 0: a play's first
            self.skipped += max(0, periods - 1)
            self._tick = tick
            self.syncs += 1
            self.valve.advance(max(1, periods) * self.period_s)
            self._answer_at = msg.timestamp + ANSWER_DELAY_S
            return msg  # the slave takes it: RPDO1 in effect, TPDO1 sent (stamped below)

        def stamped(msg: can.Message, timeout: float | None = None) -> None:
            answer = self._answer_at
            msg.timestamp = answer if answer is not None else time.time()
            send(msg, timeout)

        self.bus.recv = stepped  # type: ignore[method-assign]  # the slave's receive thread's
        self.bus.send = stamped  # type: ignore[method-assign]
        return self


def _numbered_clock(numbers: collections.deque[int]) -> type[SyncClock]:
    """A SyncClock that appends the number of each SYNC to ``numbers`` just before sending it
    (after the tick's setpoint frame), and otherwise is the master's own."""

    class NumberedClock(SyncClock):
        def __init__(
            self,
            send: Send,
            period_s: float,
            before_sync: Callable[[int], None] | None = None,
            cob_id: int = SYNC_COB_ID,
            limit: int | None = None,
        ) -> None:
            def numbered(k: int) -> None:
                if before_sync is not None:
                    before_sync(k)
                numbers.append(k)  # the SYNC follows at once

            super().__init__(send, period_s, numbered, cob_id, limit)

    return NumberedClock

"""A PacedGroup in the bus's receive thread (``--serve-emulator`` with many valves): every
valve whose batch is due runs in one call, and a valve whose cycles a SYNC already ran is not
called at all (at a 1 ms SYNC that was nearly every batch: docs/PERFORMANCE.md)."""

from __future__ import annotations

import time

from prm9tool.device.emulator.paced_group import PacedGroup
from prm9tool.device.emulator.pacing import Pacer


class _Valve:
    """What the group uses of an EmulatedValve: its pacer and its paced step (counted)."""

    def __init__(self, serial: int) -> None:
        self.serial = serial
        self.pacer = Pacer(0.0002)
        self.steps = 0

    def paced_by_group(self, grouped: bool) -> None:
        if grouped:
            self.pacer.reset()

    def paced_step(self) -> float:
        self.steps += 1
        due = self.pacer.due()
        if due:
            self.pacer.done(due)
            return 0.0
        return self.pacer.wait_s()

    def sync(self) -> None:
        """A SYNC ran every cycle due by now (EmulatedValve.run_due_by)."""
        pacer = self.pacer
        self.pacer.done(int((time.monotonic() - pacer.start) / pacer.cycle_s) - pacer.cycles_done)


class _Driver:
    def pace(self, group):  # the test calls step_one itself, as the receive thread would
        pass


def _until_due(pacers, extra_s=0.0):
    deadline = max(p.batch_due_at() for p in pacers) + extra_s
    while time.monotonic() < deadline:
        time.sleep(max(0.0, deadline - time.monotonic()))


def test_every_due_valve_runs_in_one_call():
    valves = [_Valve(n) for n in range(4)]
    group = PacedGroup(valves, driver=_Driver())  # type: ignore[arg-type]
    group.start()
    _until_due([v.pacer for v in valves])
    group.step_one()
    assert [v.steps for v in valves] == [1, 1, 1, 1]  # was one valve per call
    assert all(v.pacer.cycles_done >= v.pacer.min_batch for v in valves)


def test_a_valve_a_sync_kept_up_is_not_called():
    valves = [_Valve(n) for n in range(4)]
    group = PacedGroup(valves, driver=_Driver())  # type: ignore[arg-type]
    group.start()
    _until_due([v.pacer for v in valves])
    group.step_one()  # every batch ran; each is due again in a batch's time
    ran = [v.steps for v in valves]
    for _ in range(3):
        deadline = group.next_due + 0.0005  # past the time the group would call them
        while time.monotonic() < deadline:
            time.sleep(max(0.0, deadline - time.monotonic()))
        for valve in valves:
            valve.sync()  # a SYNC ran their cycles meanwhile
        group.step_one()
    assert [v.steps for v in valves] == ran  # rescheduled without a call
    assert group.next_due > time.monotonic()  # to when the SYNC-run cycles make a batch due
    valves[0].paced_step = lambda: (_ for _ in ()).throw(RuntimeError("firmware bug"))  # type: ignore[method-assign]
    _until_due([valves[0].pacer])
    assert group.step_one() >= 0.0  # a failing valve is logged; the rest go on


def test_a_grouped_valve_runs_small_batches_and_a_sync_still_catches_up_a_whole_one():
    from prm9tool.device.emulator import EmulatedValve
    from prm9tool.device.emulator.pacing import CATCH_UP, GROUPED_MIN_BATCH

    valve = EmulatedValve("PRM9-06.3Z11/30-24E02S02-CA", 8101)
    valve.advance(2.0)
    own = valve.pacer.min_batch
    valve.paced_by_group(True)
    try:
        assert valve.pacer.min_batch == GROUPED_MIN_BATCH < own  # between frames, not on a SYNC
        start = valve.pacer.start
        deadline = start + (GROUPED_MIN_BATCH + 0.5) * valve.pacer.cycle_s
        while time.monotonic() < deadline:
            time.sleep(max(0.0, deadline - time.monotonic()))
        assert valve.paced_step() == 0.0  # a batch ran (with 10 cycles it would have waited)
        assert valve.pacer.cycles_done >= GROUPED_MIN_BATCH
        # a SYNC after a stall of CATCH_UP cycles still samples the moment it came
        done = valve.pacer.cycles_done
        assert valve.pacer.due_by(start + (done + CATCH_UP) * valve.pacer.cycle_s) == CATCH_UP
    finally:
        valve.paced_by_group(False)
    assert valve.pacer.min_batch == own  # its own paced thread's batch again

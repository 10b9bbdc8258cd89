"""Served valves' simulation runs in the bus's receive thread (``--serve-emulator``): a paced
thread of its own took the GIL from the receive thread at each of its system calls, and at 16
valves the kernel dropped a third of the frames (docs/PERFORMANCE.md, "The PLC rig")."""

from __future__ import annotations

import threading
import time

import can
import pytest
from support.waiting import wait_for

from prm9tool.device.emulator import EmulatedValve
from prm9tool.device.emulator.canopen_hub import SharedBus
from prm9tool.device.emulator.paced_group import PacedGroup

E02_CA = "PRM9-06.3Z11/30-24E02S02-CA"


@pytest.fixture
def hub_and_valves():
    bus = can.Bus(interface="virtual", channel=f"prm9tool-pacing-{time.monotonic_ns()}")
    hub = SharedBus(bus)
    valves = [EmulatedValve(E02_CA, serial) for serial in (8101, 8102)]
    for valve in valves:
        valve.advance(2.0)
        hub.attach(valve.connect_can(bus, receive=False))
    try:
        yield hub, valves
    finally:
        hub.stop()
        bus.shutdown()


def test_the_receive_thread_runs_every_valve_s_batches(hub_and_valves):
    hub, valves = hub_and_valves
    threads: dict[int, set[str]] = {valve.serial: set() for valve in valves}
    for valve in valves:
        valve.add_cycle_listener(
            lambda _t, s=valve.serial: threads[s].add(threading.current_thread().name)
        )
    group = PacedGroup(valves, driver=hub)
    group.start()
    try:
        assert all(valve.running for valve in valves)  # the watches judge wall-clock time
        before = [valve.time for valve in valves]
        wait_for(lambda: all(v.time - t > 0.05 for v, t in zip(valves, before, strict=True)))
        names = {thread.name for thread in threading.enumerate()}
    finally:
        group.stop()
    assert "prm9-paced-group" not in names  # no thread of its own
    assert threads == {valve.serial: {"prm9-canopen-hub"} for valve in valves}
    assert not any(valve.running for valve in valves)


def test_after_stop_no_batch_runs(hub_and_valves):
    hub, valves = hub_and_valves
    group = PacedGroup(valves, driver=hub)
    group.start()
    wait_for(lambda: all(valve.time > 2.05 for valve in valves))
    group.stop()
    stopped = [valve.time for valve in valves]
    hub_thread_waits = 0.05  # the receive thread's next few loops (it waits at most 1 ms each)
    time.sleep(hub_thread_waits)
    assert [valve.time for valve in valves] == stopped

"""Paced mode: drift-free pacing with an injected clock, and thread safety of the valve."""

from __future__ import annotations

import threading
import time

import pytest

from prm9tool.device.emulator import EmulatedValve
from prm9tool.device.emulator.pacing import Pacer

CYCLE = 200e-6


class FakeClock:
    def __init__(self) -> None:
        self.now = 100.0

    def __call__(self) -> float:
        return self.now


def run_pacer(pacer: Pacer, clock: FakeClock, wall_steps: list[float]) -> int:
    """Advance the fake wall clock step by step, running what the pacer says is due."""
    total = 0
    for step in wall_steps:
        clock.now += step
        while (due := pacer.due()) > 0:
            pacer.done(due)
            total += due
    return total


def test_no_drift_with_irregular_wake_ups():
    clock = FakeClock()
    pacer = Pacer(CYCLE, clock=clock, min_batch=10, max_batch=50)
    steps = [0.0013, 0.0021, 0.0007, 0.0049, 0.0102, 0.0003] * 2000
    total = run_pacer(pacer, clock, steps)
    elapsed = sum(steps)
    assert elapsed / CYCLE - 10 <= total <= elapsed / CYCLE
    assert pacer.lag_s() < 10 * CYCLE


def test_catches_up_after_a_stall_in_bounded_batches():
    clock = FakeClock()
    pacer = Pacer(CYCLE, clock=clock, min_batch=10, max_batch=50)
    run_pacer(pacer, clock, [0.002] * 10)
    clock.now += 1.0  # the process was stalled for a second
    batches = []
    while (due := pacer.due()) > 0:
        batches.append(due)
        pacer.done(due)
    assert max(batches) == 50
    assert sum(batches) >= 1.0 / CYCLE - 10
    assert pacer.lag_s() < 10 * CYCLE
    assert pacer.dropped_cycles == 0


def test_a_very_long_stall_is_dropped_not_replayed():
    clock = FakeClock()
    pacer = Pacer(CYCLE, clock=clock, max_lag_s=5.0)
    clock.now += 60.0
    assert pacer.due() == pacer.max_batch
    assert pacer.dropped_cycles == pytest.approx((60.0 - 5.0) / CYCLE, abs=1)
    assert pacer.lag_s() == pytest.approx(5.0, abs=CYCLE)


def test_waits_until_a_batch_is_due():
    clock = FakeClock()
    pacer = Pacer(CYCLE, clock=clock, min_batch=10)
    assert pacer.due() == 0
    assert pacer.wait_s() == pytest.approx(10 * CYCLE)
    clock.now += 4 * CYCLE
    assert pacer.wait_s() == pytest.approx(6 * CYCLE)
    clock.now += 6 * CYCLE
    assert pacer.due() == 10
    assert pacer.wait_s() == 0.0


def test_reset_starts_a_new_time_base():
    clock = FakeClock()
    pacer = Pacer(CYCLE, clock=clock)
    clock.now += 1.0
    pacer.reset()
    assert pacer.due() == 0
    assert pacer.lag_s() == 0.0


def test_paced_thread_and_a_reader_thread_share_the_valve_safely():
    valve = EmulatedValve("PRM9-06.3Z11/30-24E04S02-CA", switches=(0, 2))
    valve.set_input("setpoint", 5.0)
    errors: list[BaseException] = []
    reads = 0
    stop = threading.Event()

    def reader() -> None:
        nonlocal reads
        try:
            while not stop.is_set():
                assert -16384 <= valve.read(0x6301, 1) <= 16384
                valve.read_bytes(0x6041, 0)
                valve.status()
                valve.signal("current_a")
                reads += 1
        except BaseException as exc:  # report any failure to the main thread
            errors.append(exc)

    valve.start()
    threads = [threading.Thread(target=reader) for _ in range(2)]
    for thread in threads:
        thread.start()
    sampled = []
    while valve.time < 0.3 and not errors:
        with valve.lock:  # the lock freezes the loop: a consistent snapshot
            sampled.append((valve.time, valve.read(0x6310, 1)))
        valve.write(0x6332, 1, 100)
    stop.set()
    for thread in threads:
        thread.join()
    valve.stop()
    assert errors == []
    assert reads > 10
    assert not valve.running
    assert [t for t, _ in sampled] == sorted(t for t, _ in sampled)
    frozen = valve.time
    assert valve.time == frozen  # stopped: time stands still


def test_start_and_stop_are_idempotent():
    valve = EmulatedValve("PRM9-06.3Z11/30-24E02S02")
    valve.start()
    valve.start()
    assert valve.running
    valve.stop()
    valve.stop()
    assert not valve.running


def test_listener_may_stop_the_paced_loop():
    valve = EmulatedValve("PRM9-06.3Z11/30-24E02S02")
    done = threading.Event()

    def listener(now: float) -> None:
        if now >= 0.01 and not done.is_set():
            done.set()
            valve.stop()

    valve.add_cycle_listener(listener)
    valve.start()
    assert done.wait(timeout=30)
    assert not valve.running


@pytest.mark.slow
def test_paced_mode_keeps_real_time_within_1_percent_over_10_s():
    # E04 -CA in analog mode with everything that costs time on: process loop (mode 4) with a
    # moving load, sensor linearization, dither, a three-channel capture at full rate.
    valve = EmulatedValve("PRM9-06.3Z11/30-24E04S02-CA", switches=(0, 2))
    valve.write(0x2008, 0, 1)  # sensor linearization on
    valve.set_input("setpoint", 5.0)
    valve.capture_start(["process_actual", "position_actual", "current_a"])
    wall_start = time.monotonic()
    valve.start()
    time.sleep(10.0)
    valve.stop()
    wall = time.monotonic() - wall_start
    simulated = valve.time
    assert valve.pacer.dropped_cycles == 0
    assert abs(simulated - wall) / wall < 0.01, (simulated, wall)
    assert valve.capture_read().shape == (round(simulated / CYCLE), 3)  # every cycle recorded
    assert valve.signal("process_actual") == pytest.approx(16384 / 2, abs=0.02 * 16384)

"""The SYNC and RPDO-deadline watches of a valve paced in real time judge reception times.

A healthy bus must not fault the valve when its simulation falls behind the wall clock (a
busy PC; here forced by a 1 ms task that stalls the loop, with the valve's lock held, as a
descheduled thread does) and then catches up in a burst. Every assertion compares with what
the bus really carried: the SYNC gaps the master's own send time stamps show.
"""

from __future__ import annotations

import itertools
import threading
import time

import can
import pytest
from support.canopen_rig import E02, Rig, make_rig
from support.waiting import wait_for

from prm9tool.device.emulator.canopen_watch import SYNC_TIMEOUT_FACTOR
from prm9tool.device.records import DeviceState

PERIOD_S = 0.025  # 0x1006 = 25 000 us (the 10 ms bus, with room for a loaded sender)
STALL_S = 0.100  # the loop stands still for four SYNC periods, then catches up
LIMIT_S = SYNC_TIMEOUT_FACTOR * PERIOD_S


@pytest.fixture
def rig(request: pytest.FixtureRequest):
    rig = make_rig(request.node.name, E02)
    yield rig
    rig.valve.stop()
    rig.close()


def _commission(rig: Rig, period_us: int = round(PERIOD_S * 1e6)) -> None:
    rig.exchange(
        f"60A 23 06 10 00 {period_us & 0xFF:02X} {period_us >> 8 & 0xFF:02X} "
        f"{period_us >> 16 & 0xFF:02X} 00",
        "58A 60 06 10 00 00 00 00 00",
    )
    rig.exchange("60A 2B 17 10 00 00 00 00 00", "58A 60 17 10 00 00 00 00 00")  # no heartbeat
    rig.exchange("60A 23 00 18 01 8A 01 00 80", "58A 60 00 18 01 00 00 00 00")  # no TPDO1
    rig.exchange("60A 23 01 18 01 8A 02 00 80", "58A 60 01 18 01 00 00 00 00")  # no TPDO2
    rig.send("000 01 0A")
    rig.wait_for_nmt_state("operational")
    for word in ("08", "09", "0B", "0F"):
        rig.exchange(f"60A 2B 40 60 00 {word} 00 00 00", "58A 60 40 60 00 00 00 00 00")
    assert rig.valve.device_state is DeviceState.DEVICE_MODE_ACTIVE


class _SyncSender:
    """A PLC's SYNC every ``period_s`` in a thread; keeps the send time stamps."""

    def __init__(self, bus: can.BusABC, period_s: float) -> None:
        self.bus, self.period_s = bus, period_s
        self.sent: list[float] = []
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._run, daemon=True)

    def __enter__(self) -> _SyncSender:
        self._thread.start()
        return self

    def __exit__(self, *_: object) -> None:
        self._stop.set()
        self._thread.join()

    def _run(self) -> None:
        start = time.monotonic()
        n = 0
        while not self._stop.is_set():
            n += 1
            self._stop.wait(max(0.0, start + n * self.period_s - time.monotonic()))
            message = can.Message(arbitration_id=0x080, data=b"", is_extended_id=False)
            before = time.time()  # the virtual bus stamps the frame when it sends it: later
            self.bus.send(message)
            self.sent.append(before)

    def max_gap_s(self) -> float:
        return max(b - a for a, b in itertools.pairwise(self.sent))


def _stalls(rig: Rig, count: int, every_s: float) -> threading.Event:
    """Make the paced loop stand still for STALL_S (lock held) ``count`` times."""
    done = threading.Event()
    state = {"next": rig.valve.time + every_s, "left": count}

    def stall(sim_time: float) -> None:
        if state["left"] and sim_time >= state["next"]:
            state["left"] -= 1
            state["next"] = sim_time + every_s
            time.sleep(STALL_S)
            if not state["left"]:
                done.set()

    rig.valve.add_cycle_listener(stall)
    return done


def _emcy(frames: list[str]) -> list[str]:
    return [f for f in frames if f.startswith("08A")]


def test_a_loop_that_falls_behind_does_not_miss_a_healthy_sync(rig: Rig):
    _commission(rig)
    rig.drain()
    rig.valve.start()
    with _SyncSender(rig.master, PERIOD_S) as plc:
        time.sleep(0.3)  # the watch is armed by the first SYNC
        done = _stalls(rig, count=5, every_s=0.3)
        assert done.wait(30.0), "the paced loop never stalled"
        wait_for(lambda: rig.valve.pacer.lag_s() < 0.02, 30.0)  # caught up again
        time.sleep(0.1)
        frames = rig.drain()  # while the SYNC still runs: stopping it is a real loss
        state = rig.valve.device_state
    if plc.max_gap_s() > LIMIT_S:  # the PC held up the PLC thread itself: a real gap
        pytest.skip(f"the SYNC sender itself was {plc.max_gap_s() * 1e3:.1f} ms late")
    assert _emcy(frames) == [], f"largest SYNC gap sent {plc.max_gap_s() * 1e3:.1f} ms"
    assert state is DeviceState.DEVICE_MODE_ACTIVE


def test_a_sync_that_stops_is_missed_in_real_time(rig: Rig):
    _commission(rig)
    rig.drain()
    rig.valve.start()
    with _SyncSender(rig.master, PERIOD_S) as plc:
        time.sleep(0.2)
    wait_for(lambda: rig.valve.status().error_code == 0x8100, 5.0)
    emcy = next(m for m in iter(lambda: rig.master.recv(1.0), None) if m.arbitration_id == 0x08A)
    assert bytes(emcy.data).hex(" ") == "00 81 11 00 00 00 00 00"
    # never before the limit: a loaded PC may hold the sender up earlier, a real gap then
    last_before = max(t for t in plc.sent if t < emcy.timestamp)
    assert emcy.timestamp - last_before >= LIMIT_S


def test_an_rpdo_deadline_is_judged_at_reception_while_the_loop_stalls(rig: Rig):
    rig.exchange("60A 2B 00 14 05 32 00 00 00", "58A 60 00 14 05 00 00 00 00")  # 50 ms
    _commission(rig, period_us=0)
    rig.drain()
    rig.valve.start()
    stop = threading.Event()
    sent: list[float] = []

    def plc() -> None:
        while not stop.wait(0.010):
            message = can.Message(arbitration_id=0x20A, data=bytes(8), is_extended_id=False)
            message.data[0] = 0x0F
            rig.master.send(message)
            sent.append(message.timestamp or time.time())

    thread = threading.Thread(target=plc, daemon=True)
    thread.start()
    try:
        time.sleep(0.1)
        done = _stalls(rig, count=4, every_s=0.3)
        assert done.wait(30.0)
        wait_for(lambda: rig.valve.pacer.lag_s() < 0.02, 30.0)
        frames = rig.drain()  # while the RPDOs still come
    finally:
        stop.set()
        thread.join()
    gap = max(b - a for a, b in itertools.pairwise(sent))
    if gap > 0.050:
        pytest.skip(f"the RPDO sender itself was {gap * 1e3:.1f} ms late")
    assert _emcy(frames) == []
    wait_for(lambda: rig.valve.status().error_code == 0x8100, 5.0)  # it stopped: missed

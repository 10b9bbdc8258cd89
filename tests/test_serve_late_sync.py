"""A served valve that gets to a SYNC more than LATE_SYNC_MS and two SYNC intervals after it
arrived (the PC fell behind the bus: frames queued in the socket) counts it but sends no TPDO, and the serve log
says so once a second for every valve. A TPDO that late carries the state of a later moment,
which a real valve never sends; answering every queued SYNC also kept an overloaded serving
process behind for good (at 16 valves on a loaded 2-core PC, TPDO1s 0.7 s after their SYNC:
benchmarks/bench_plc_rig.py --serve-lag, docs/PERFORMANCE.md)."""

from __future__ import annotations

import struct
import time
from types import SimpleNamespace
from typing import Any

import pytest

from prm9tool.cli import serve
from prm9tool.device.emulator import EmulatedValve
from prm9tool.device.emulator.canopen_pdo import mapping
from prm9tool.device.emulator.canopen_watch import LATE_SYNC_MS

E02 = "PRM9-06.3Z11/30-24E02S02-CA"
NODE = 10  # the node-ID switch as delivered
TPDO1 = 0x180 + NODE


class Recorder:
    """A python-can bus as far as the CANopen slave sends on it."""

    def __init__(self) -> None:
        self.frames: list[tuple[int, bytes]] = []

    def send(self, msg: Any, timeout: float | None = None) -> None:
        self.frames.append((msg.arbitration_id, bytes(msg.data)))


def _sdo_write(index: int, sub: int, value: int, size: int) -> bytes:
    command = {1: 0x2F, 2: 0x2B, 4: 0x23}[size]
    return struct.pack("<BHB", command, index, sub) + value.to_bytes(4, "little")


@pytest.fixture
def served():
    valve = EmulatedValve(E02, 7001)
    bus = Recorder()
    slave = valve.connect_can(bus, receive=False)  # type: ignore[arg-type]
    valve.advance(2.0)  # booted: pre-operational
    for request in (_sdo_write(0x1800, 2, 1, 1), _sdo_write(0x1400, 2, 1, 1)):
        slave.receive_data(0x600 + NODE, request, 0.0)  # TPDO1 and RPDO1 every SYNC
    slave.receive_data(0x000, bytes((1, NODE)), 0.0)  # NMT start
    valve.start()  # in real time: the watches judge reception time stamps
    try:
        yield valve, slave, bus
    finally:
        valve.stop()


def _tpdos(bus: Recorder) -> int:
    return sum(can_id == TPDO1 for can_id, _ in bus.frames)


def test_a_sync_got_to_too_late_is_counted_not_answered(served):
    _valve, slave, bus = served
    late_s = 5 * LATE_SYNC_MS / 1000
    slave.receive_data(0x080, b"", time.time())
    assert _tpdos(bus) == 1  # on time: answered
    slave.receive_data(0x080, b"", time.time() - late_s)
    assert _tpdos(bus) == 1  # too late: no TPDO
    count, worst_ms = slave.take_unanswered_syncs()
    assert count == 1
    assert worst_ms == pytest.approx(5 * LATE_SYNC_MS, abs=LATE_SYNC_MS)
    assert slave.take_unanswered_syncs() == (0, 0.0)  # told once
    slave.receive_data(0x080, b"", time.time())
    assert _tpdos(bus) == 2  # the next SYNC on time is answered again


def test_a_late_sync_still_counts_for_every_nth_and_applies_a_synchronous_rpdo(served):
    valve, slave, bus = served
    slave.receive_data(0x600 + NODE, _sdo_write(0x1800, 2, 2, 1), 0.0)  # every 2nd SYNC
    late_s = 5 * LATE_SYNC_MS / 1000
    answered = []
    for late in (False, True, False, False):
        before = _tpdos(bus)
        slave.receive_data(0x080, b"", time.time() - (late_s if late else 0.0))
        answered.append(_tpdos(bus) - before)
    assert answered == [0, 0, 0, 1]  # the late one was the 2nd: counted, so the 4th sends
    index, sub, _bits = mapping(valve, 0x1600)[1]  # RPDO1's setpoint entry
    slave.receive_data(0x200 + NODE, b"\x00\x00" + (1234).to_bytes(2, "little"), time.time())
    slave.receive_data(0x080, b"", time.time() - late_s)  # synchronous: takes effect now
    assert valve.read(index, sub) == 1234


def test_at_a_slow_sync_a_steady_delay_of_more_than_10_ms_is_still_answered(served):
    """At a 50 ms SYNC a PC 15 ms behind keeps up (no SYNC waits for the one before): only
    a SYNC over two periods late goes unanswered. The SYNCs' time stamps are 50 ms apart
    whatever the delay, as the kernel's are."""
    _valve, slave, bus = served
    period_s = 0.050  # the margin of a busy PC: 85 ms before a 15 ms delay counts
    first = time.time() + 0.01
    answered = []
    for k, behind_s in enumerate((0.0, 0.015, 0.015, 0.015, 3 * period_s)):
        arrived = first + k * period_s
        time.sleep(max(0.0, arrived + behind_s - time.time()))  # a busy PC: later, not sooner
        before = _tpdos(bus)
        slave.receive_data(0x080, b"", arrived)
        answered.append(_tpdos(bus) - before)
    assert answered[-1] == 0  # three periods late: not answered
    assert answered[:-1] == [1, 1, 1, 1]  # 15 ms late at a 50 ms SYNC: answered
    assert slave.take_unanswered_syncs()[0] == 1


def test_a_valve_stepped_in_simulated_time_answers_every_sync():
    valve = EmulatedValve(E02, 7002)
    bus = Recorder()
    slave = valve.connect_can(bus, receive=False)  # type: ignore[arg-type]
    valve.advance(2.0)
    slave.receive_data(0x600 + NODE, _sdo_write(0x1800, 2, 1, 1), 0.0)
    slave.receive_data(0x000, bytes((1, NODE)), 0.0)
    slave.receive_data(0x080, b"", time.time() - 1.0)  # no wall clock to be late against
    assert _tpdos(bus) == 1
    assert slave.take_unanswered_syncs() == (0, 0.0)


def test_the_serve_log_names_every_valve_that_left_syncs_unanswered(capsys):
    counts = {"serial 7001 node 1": (812, 720.4), "serial 7002 node 2": (0, 0.0)}
    counts["serial 7003 node 3"] = (640, 31.0)
    served = [
        SimpleNamespace(label=label, slave=SimpleNamespace(take_unanswered_syncs=lambda c=c: c))
        for label, c in counts.items()
    ]
    due = [0.0]
    serve._report_unanswered(served, due)  # type: ignore[arg-type]
    line = capsys.readouterr().out
    assert line.startswith("prm9tool: SYNCs answered with no TPDO in the last 1 s")
    assert f"more than {LATE_SYNC_MS:g} ms and two SYNC periods after they arrived" in line
    assert "(at most 720 ms)" in line
    assert "serial 7001 node 1 812x, serial 7003 node 3 640x." in line
    assert "node 2" not in line
    assert "serve fewer valves per process or a slower SYNC" in line
    serve._report_unanswered(served, due)  # within the second: nothing more
    assert capsys.readouterr().out == ""

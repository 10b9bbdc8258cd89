"""The compiled kernel passes the CANopen slave's quiet 1 ms tasks itself (issue 30).

The slave's cycle listener says for how many 1 ms tasks it has nothing to do (no heartbeat, no
poll of the PDO parameters, no TPDO event timer and, in simulated time, no watch deadline due:
``CanopenSlave._quiet_ticks``); the kernel passes those instead of handing every millisecond to
Python. Two valves get the same seeded random steps — SYNC, RPDO1, SDO writes (heartbeat, event
timers, SYNC period), USB writes, NMT commands, time in uneven steps, faults, power cycles: one
with the listener's quiet check, one with every 1 ms task in Python (the check hidden, as before).
Every frame and the simulated millisecond it was sent at must be the same, and the object
dictionary and device state after every step.
"""

from __future__ import annotations

import random
import struct
from typing import Any

import pytest
from support.valve_steps import run_step, sdo_download

from prm9tool.device.emulator import EmulatedValve, Fault
from prm9tool.device.emulator.kernels import compiled_unavailable

pytestmark = pytest.mark.skipif(
    compiled_unavailable() is not None, reason=f"compiled kernel: {compiled_unavailable()}"
)

E02 = "PRM9-06.3Z11/30-24E02S02-CA"
NODE = 10
STEPS = 2500


class TimedRecorder:
    """A python-can bus as far as the slave sends on it: each frame with the valve's time."""

    def __init__(self) -> None:
        self.valve: EmulatedValve | None = None
        self.frames: list[tuple[int, int, bytes]] = []

    def send(self, msg: Any, timeout: float | None = None) -> None:
        assert self.valve is not None
        self.frames.append((self.valve.tick_ms, msg.arbitration_id, bytes(msg.data)))

    def recv(self, timeout: float | None = None) -> None:
        return None


def _valve(quiet: bool) -> tuple[EmulatedValve, TimedRecorder, Any]:
    valve = EmulatedValve(E02, NODE)
    bus = TimedRecorder()
    bus.valve = valve
    slave = valve.connect_can(bus, receive=False)  # type: ignore[arg-type]
    if not quiet:
        valve.firmware.cycle_quiet = {}  # every 1 ms task in Python, as before
    return valve, bus, slave


def _steps(seed: int) -> list[tuple[str, Any]]:
    rng = random.Random(seed)
    steps: list[tuple[str, Any]] = [("advance", 2.0)]
    for index, sub, value, size in (
        (0x1017, 0, 7, 2),  # heartbeat every 7 ms
        (0x1801, 5, 13, 2),  # TPDO2 (type 255) every 13 ms
        (0x1400, 5, 25, 2),  # RPDO1 deadline 25 ms
        (0x1006, 0, 4000, 4),  # SYNC every 4 ms
        (0x1800, 2, 1, 1),
    ):
        steps.append(("frame", (0x600 + NODE, sdo_download(index, sub, value, size))))
    steps.append(("frame", (0, bytes((1, NODE)))))
    for word in (8, 9, 11, 15):
        steps.append(("frame", (0x600 + NODE, sdo_download(0x6040, 0, word, 2))))
    for _ in range(STEPS):
        kind = rng.random()
        if kind < 0.25:
            steps.append(("frame", (0x80, b"")))
        elif kind < 0.45:
            setpoint = rng.randint(-16384, 16384)
            steps.append(("frame", (0x200 + NODE, struct.pack("<Hh", 0x0F, setpoint))))
        elif kind < 0.75:
            steps.append(("advance", rng.choice((0.0002, 0.001, 0.003, 0.004, 0.009, 0.031))))
        elif kind < 0.80:
            index, sub, size, values = rng.choice(
                (
                    (0x1017, 0, 2, (0, 1, 7, 50)),
                    (0x1801, 5, 2, (0, 13, 100)),
                    (0x1801, 2, 1, (1, 254, 255)),
                    (0x1400, 5, 2, (0, 3, 25)),
                    (0x1006, 0, 4, (0, 1000, 4000)),
                )
            )
            steps.append(
                ("frame", (0x600 + NODE, sdo_download(index, sub, rng.choice(values), size)))
            )
        elif kind < 0.84:
            index, sub, values = rng.choice(  # read by the slave's 10 ms poll
                ((0x1017, 0, (0, 3, 11)), (0x1801, 5, (0, 9, 40)), (0x1800, 2, (1, 2, 3)))
            )
            steps.append(("usb", (index, sub, rng.choice(values))))
        elif kind < 0.88:
            steps.append(("frame", (0, bytes((rng.choice((1, 1, 2, 0x80, 0x81, 0x82)), NODE)))))
        elif kind < 0.91:
            steps.append(("frame", (0x600 + NODE, bytes((0x40, 0x18, 0x10, 0x01, 0, 0, 0, 0)))))
        elif kind < 0.93:
            steps.append((rng.choice(("inject", "clear")), rng.choice(list(Fault))))
        elif kind < 0.995:
            steps.append(("advance", 0.25))
        else:
            steps.append(("restart", None))
    return steps


def _state(valve: EmulatedValve) -> tuple[Any, ...]:
    fw = valve.firmware
    return (sorted(fw.od.values.items()), fw.sm.state, fw.faults.code(), fw.time, fw.ticks)


@pytest.mark.parametrize("seed", [1, 2])
def test_passing_quiet_1_ms_tasks_sends_the_same_frames_at_the_same_time(seed: int) -> None:
    quiet, python = _valve(quiet=True), _valve(quiet=False)
    for number, step in enumerate(_steps(seed)):
        for valve, _, slave in (quiet, python):
            run_step(valve, slave, step)
        assert quiet[1].frames == python[1].frames, f"step {number}: {step}"
        assert _state(quiet[0]) == _state(python[0]), f"step {number}: {step}"
    sent = {can_id for _, can_id, _ in quiet[1].frames}
    assert {0x700 + NODE, 0x180 + NODE, 0x280 + NODE} <= sent  # heartbeat, TPDO1 and TPDO2 ran
    assert 0x80 + NODE in sent  # an EMCY (a deadline missed, a fault)


def test_an_operational_valve_leaves_few_1_ms_tasks_to_python(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """OPERATIONAL with a heartbeat of 1 s and both TPDOs on SYNC: of 1 000 tasks only the
    heartbeat's runs in Python (all 1 000 before); a USB write of a PDO parameter brings back
    the 10 ms poll that takes it, once."""
    valve, bus, slave = _valve(quiet=True)
    valve.advance(2.0)
    for word in (8, 9, 11, 15):
        slave.receive_data(0x600 + NODE, sdo_download(0x6040, 0, word, 2), 0.0)
    slave.receive_data(0x600 + NODE, sdo_download(0x1801, 2, 1, 1), 0.0)  # TPDO2 on SYNC too
    slave.receive_data(0, bytes((1, NODE)), 0.0)
    fw = valve.firmware
    python_tick = fw.tick
    calls = []
    monkeypatch.setattr(fw, "tick", lambda: (python_tick(), calls.append(fw.ticks)))
    ticks, frames = fw.ticks, len(bus.frames)
    valve.advance(1.0)
    assert fw.ticks - ticks == 1000
    assert 1 <= len(calls) <= 3
    assert [can_id for _, can_id, _ in bus.frames[frames:]] == [0x700 + NODE]  # its heartbeat
    calls.clear()
    valve.write(0x1801, 2, 255)  # TPDO2 on its event timer, over USB: taken at the next poll
    valve.advance(0.0106)
    assert calls[0] % 10 == 0
    assert slave._tpdos[1].trans_type == 255

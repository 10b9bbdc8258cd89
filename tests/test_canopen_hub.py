"""Several emulated valves on one SharedBus (one receive thread): each frame reaches the valves
it is for, and a SYNC that stops is still seen by every valve once the bus goes quiet (how
long the thread may wait is asked of the valves at most every millisecond, not per frame)."""

from __future__ import annotations

import time

import can
import pytest

from prm9tool.catalogue import CATALOGUE
from prm9tool.device.emulator import EmulatedValve
from prm9tool.device.emulator.canopen_hub import SharedBus

E02 = "PRM9-06.3Z11/30-24E02S02-CA"
NODES = (10, 15, 20)  # node-ID switch positions 2, 3, 4
BAUD_SWITCH = int(CATALOGUE["SWBAUD"].default)  # as delivered
CYCLE_US = 100_000  # 0x1006: SYNC missing after 150 ms (a busy PC holds the test up)


@pytest.fixture
def rig():
    channel = f"prm9tool-hub-{time.monotonic_ns()}"
    served, master = can.Bus(interface="virtual", channel=channel), None
    hub = SharedBus(served)
    valves = [
        EmulatedValve(E02, 7100 + k, switches=(BAUD_SWITCH, 2 + k)) for k in range(len(NODES))
    ]
    try:
        for valve in valves:
            valve.start()
            hub.attach(valve.connect_can(served, receive=False))
        master = can.Bus(interface="virtual", channel=channel)
        yield master
    finally:
        hub.stop()
        for valve in valves:
            valve.stop()
        served.shutdown()
        if master is not None:
            master.shutdown()


def _frames(bus: can.BusABC, until, seconds: float) -> list[can.Message]:
    """Frames until ``until(frames)`` holds (or ``seconds`` passed: the test then fails)."""
    frames: list[can.Message] = []
    deadline = time.monotonic() + seconds
    while not until(frames) and time.monotonic() < deadline:
        msg = bus.recv(max(0.0, min(0.05, deadline - time.monotonic())))
        if msg is not None:
            frames.append(msg)
    return frames


def _sdo(bus: can.BusABC, node: int, request: str) -> None:
    bus.send(can.Message(arbitration_id=0x600 + node, data=bytes.fromhex(request),
                         is_extended_id=False))  # fmt: skip
    got = _frames(bus, lambda f: any(m.arbitration_id == 0x580 + node for m in f), 10)
    answer = next(m for m in got if m.arbitration_id == 0x580 + node)
    assert answer.data[0] == 0x60, bytes(answer.data).hex()


def test_a_sync_that_stops_is_reported_by_every_valve_on_the_shared_bus(rig):
    booted = _frames(rig, lambda f: {m.arbitration_id for m in f} >= {0x700 + n for n in NODES}, 30)
    assert {m.arbitration_id for m in booted} >= {0x700 + n for n in NODES}
    for node in NODES:
        _sdo(rig, node, "2B17100000000000")  # no heartbeat
        _sdo(rig, node, f"23061000{CYCLE_US.to_bytes(4, 'little').hex()}")
        _sdo(
            rig, node, f"23001801{(0x180 + node).to_bytes(4, 'little').hex()}"
        )  # TPDO1 on 0x180 + node
        _sdo(rig, node, "2F00180201000000")  # every SYNC
    rig.send(can.Message(arbitration_id=0, data=b"\x01\x00", is_extended_id=False))
    sync = can.Message(arbitration_id=0x80, data=b"", is_extended_id=False)
    seen: list[can.Message] = []
    for _ in range(20):  # SYNC every 5 ms: each valve answers on its own COB-ID
        rig.send(sync)
        seen += _frames(rig, lambda f: False, 0.005)
    tpdo = {m.arbitration_id for m in seen}
    assert not [m for m in seen if 0x80 < m.arbitration_id < 0x100]  # no EMCY while it runs
    assert tpdo >= {0x180 + n for n in NODES}
    emcy = _frames(rig, lambda f: {m.arbitration_id for m in f} >= {0x80 + n for n in NODES}, 10)
    codes = {m.arbitration_id - 0x80: bytes(m.data[:2]) for m in emcy if m.arbitration_id < 0x100}
    assert codes == dict.fromkeys(NODES, b"\x00\x81")  # EMCY 8100 from each: SYNC missing

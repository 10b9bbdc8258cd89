"""Golden traces for the trace decoder: a ``canopen``-package PLC commissions two emulated valves
on a private virtual bus while prm9tool's recorder writes every frame with python-can's
``can.Logger`` (prm9tool.trace.recorder). The valves run on simulated time, so the sequence is
the same on a busy machine; only the time stamps are the wall clock's.

The sequence (docs/trace.md's worked example): boot-up of nodes 10 (E02) and 15 (E04); the PLC
reads their vendor IDs (expedited), node 10's firmware version (segmented) and an object node
15 does not have (abort); sets control mode 4 on node 15, TPDO1 of node 10 synchronous,
TPDO1 of node 15 every 10 ms, heartbeats of 100 ms; NMT start; the enable sequence 08h → 09h → 0Bh → 0Fh on both; 1 kHz SYNC
with RPDO1 setpoints to both; then an RPDO1 deadline of 20 ms on node 10 and node 10's
setpoints stop: the valve reports EMCY 8100h and leaves DEVICE_MODE_ACTIVE.
"""

from __future__ import annotations

import contextlib
import struct
from dataclasses import dataclass
from pathlib import Path

import can
import canopen

from prm9tool.device.canlink.bus import CanOptions
from prm9tool.device.emulator import EmulatedValve
from prm9tool.device.emulator.canopen_slave import CanopenSlave
from prm9tool.trace.recorder import Recorder
from support.canopen_rig import E02, E04, unique_channel
from support.waiting import wait_for

NODES = (10, 15)
SWITCHES = {10: (6, 2), 15: (6, 3)}  # 500 kbit/s, node 10 / node 15
TYPE_KEYS = {10: E02, 15: E04}
SYNC_PERIOD_S = 0.001
RUN_SYNCS = 300
DEADLINE_MS = 20
FAULT_SYNCS = 100


@dataclass
class Plant:
    """The two valves and the PLC on one virtual channel, counting every frame on the bus."""

    channel: str
    valves: dict[int, EmulatedValve]
    slaves: list[CanopenSlave]
    buses: list[can.BusABC]
    plc: canopen.Network
    frames: list[int]  # [frames the PLC received + frames it sent]

    def advance(self, seconds: float) -> None:
        """Both valves run ``seconds`` of simulated time."""
        for valve in self.valves.values():
            valve.advance(seconds)

    def send(self, cob: int, data: bytes) -> None:
        """A frame from the PLC."""
        self.plc.send_message(cob, data)

    def taken(self) -> None:
        """Wait until the valves have taken every frame sent so far from their bus (so that
        a valve's simulated time does not run ahead of its RPDOs)."""
        wait_for(lambda: all(bus.queue.empty() for bus in self.buses))  # type: ignore[attr-defined]

    def close(self) -> None:
        """Stop the valves and the PLC."""
        self.plc.disconnect()
        for slave in self.slaves:
            slave.stop()
        for bus in self.buses:
            bus.shutdown()


class _Counter(can.Listener):
    def __init__(self, frames: list[int]) -> None:
        self.frames = frames

    def on_message_received(self, msg: can.Message) -> None:
        self.frames[0] += 1


def make_plant(name: str) -> Plant:
    """Two powered-off valves and a connected PLC on a new virtual channel."""
    channel = unique_channel(name)
    valves, slaves, buses = {}, [], []
    for node in NODES:
        bus = can.Bus(interface="virtual", channel=channel)
        valve = EmulatedValve(TYPE_KEYS[node], serial=3000 + node, switches=SWITCHES[node])
        slaves.append(valve.connect_can(bus))
        valves[node] = valve
        buses.append(bus)
    frames = [0]
    plc = canopen.Network()
    plc.listeners.append(_Counter(frames))
    plc.connect(interface="virtual", channel=channel)
    send = plc.bus.send

    def counted(msg: can.Message, timeout: float | None = None) -> None:
        send(msg, timeout)
        frames[0] += 1

    plc.bus.send = counted  # every frame the PLC sends (canopen sends through bus.send)
    for node in NODES:
        plc.add_node(canopen.RemoteNode(node, canopen.ObjectDictionary()))
    return Plant(channel, valves, slaves, buses, plc, frames)


def record_commissioning(path: Path, name: str) -> Recorder:
    """Record the whole sequence into ``path``; the recorder (its counts) when done."""
    plant = make_plant(name)
    recorder = Recorder(path, CanOptions("virtual", plant.channel)).start()
    try:
        _commission(plant)
        wait_for(lambda: recorder.frames >= plant.frames[0], timeout_s=30)
    finally:
        recorder.stop()
        plant.close()
    return recorder


def _sdo_write(plant: Plant, node: int, index: int, sub: int, data: bytes) -> None:
    plant.plc[node].sdo.download(index, sub, data)


def _sdo_read(plant: Plant, node: int, index: int, sub: int) -> bytes:
    return plant.plc[node].sdo.upload(index, sub)


def _commission(plant: Plant) -> None:
    plant.advance(2.0)  # power-up: boot-ups
    for node in NODES:
        _sdo_read(plant, node, 0x1018, 1)
    _sdo_read(plant, 10, 0x100A, 0)  # firmware version: a segmented upload
    with contextlib.suppress(canopen.SdoAbortedError):
        _sdo_read(plant, 15, 0x1234, 0)
    _sdo_write(plant, 15, 0x6043, 0, struct.pack("<b", 4))
    _sdo_write(plant, 10, 0x1800, 2, b"\x01")  # TPDO1 at every SYNC
    _sdo_write(plant, 15, 0x1800, 5, struct.pack("<H", 10))  # TPDO1 every 10 ms
    for node in NODES:
        _sdo_write(plant, node, 0x1017, 0, struct.pack("<H", 100))
    plant.send(0x000, bytes([0x01, 0x00]))  # NMT start, all nodes
    wait_for(lambda: all(v.status().nmt_state == "operational" for v in plant.valves.values()))
    for word in (0x08, 0x09, 0x0B, 0x0F):
        for node in NODES:
            _sdo_write(plant, node, 0x6040, 0, struct.pack("<H", word))
        plant.advance(0.11)
    _sdo_write(plant, 10, 0x1400, 5, struct.pack("<H", DEADLINE_MS))
    for k in range(RUN_SYNCS):
        _cycle(plant, setpoint=int(8000 * k / RUN_SYNCS), to=NODES)
    for _ in range(FAULT_SYNCS):
        _cycle(plant, setpoint=8000, to=(15,))  # node 10's setpoints stop


def _cycle(plant: Plant, setpoint: int, to: tuple[int, ...]) -> None:
    """One SYNC period: SYNC, then RPDO1 (control word 0Fh, setpoint) to the nodes ``to``."""
    plant.send(0x080, b"")
    for node in to:
        plant.send(0x200 + node, struct.pack("<Hh", 0x0F, setpoint))
    plant.taken()
    plant.advance(SYNC_PERIOD_S)

"""Emulated -CA valves at node-ID switch 1 (LSS, manual table 7-17) on a private virtual CAN
channel, the tool's shared master on it, and a recorder seeing every frame."""

from __future__ import annotations

import itertools
from dataclasses import dataclass, field

import can

from prm9tool.device.canlink.bus import CanNetwork, CanOptions, acquire, release
from prm9tool.device.emulator import EmulatedValve
from prm9tool.device.emulator.canopen_slave import CanopenSlave
from support.canopen_rig import unique_channel

E04 = "PRM9-06.3Z11/30-24E04S02-CA"
LSS_SWITCHES = (6, 1)  # interface switch 500 kbit/s, node-ID switch 1 (LSS)
_names = itertools.count()


@dataclass
class LssRig:
    """The valves, their slaves, the tool's master and a recorder on one virtual channel."""

    options: CanOptions
    shared: CanNetwork
    recorder: can.BusABC
    valves: list[EmulatedValve] = field(default_factory=list)
    slaves: list[CanopenSlave] = field(default_factory=list)
    buses: list[can.BusABC] = field(default_factory=list)

    def add(self, serial: int, switches: tuple[int, int] = LSS_SWITCHES) -> EmulatedValve:
        """One more valve on the bus, running in real time."""
        valve = EmulatedValve(E04, serial, switches=switches)
        bus = can.Bus(interface="virtual", channel=self.options.channel)
        self.slaves.append(valve.connect_can(bus))
        self.valves.append(valve)
        self.buses.append(bus)
        valve.start()
        return valve

    def frames(self) -> list[str]:
        """Every frame since the last call, as ``COB data`` in hex (``7E5 04 01 00 …``)."""
        out = []
        while (msg := self.recorder.recv(0)) is not None:
            out.append(" ".join([f"{msg.arbitration_id:03X}", *(f"{b:02X}" for b in msg.data)]))
        return out

    def close(self) -> None:
        """Stop the valves, release the master, close the buses."""
        for valve, slave in zip(self.valves, self.slaves, strict=True):
            valve.stop()
            slave.stop()
        for bus in self.buses:
            bus.shutdown()
        release(self.shared)
        self.recorder.shutdown()


def make_lss_rig(name: str) -> LssRig:
    """An empty bus with the tool's master and a recorder; :meth:`LssRig.add` valves."""
    channel = unique_channel(f"lss-{name}-{next(_names)}")
    options = CanOptions("virtual", channel)
    recorder = can.Bus(interface="virtual", channel=channel)
    return LssRig(options, acquire(options), recorder)

"""Test rig: an emulated -CA valve on a private python-can ``virtual`` channel, seen by a master.

Frames the slave sends in reaction to a frame (SDO answers, NMT side effects) arrive from the
Notifier thread, so :meth:`Rig.expect` waits for them with a timeout; frames driven by
simulated time (heartbeat, PDO timers, EMCY) are sent during :meth:`EmulatedValve.advance`
and are already queued when it returns.
"""

from __future__ import annotations

import itertools
import time
from dataclasses import dataclass, field

import can
import canopen

from prm9tool.device.emulator import EmulatedValve
from prm9tool.device.emulator.canopen_slave import CanopenSlave

E02 = "PRM9-06.3Z11/30-24E02S02-CA"
E04 = "PRM9-06.3Z11/30-24E04S02-CA"
BOOT_S = 2.0  # the valve's power-up timeline (~1.8 s) plus margin
TIMEOUT_S = 5.0  # generous: the machine is shared; a healthy answer takes microseconds
_counter = itertools.count()


def foreign_node(channel: str, node_id: int = 5, vendor: int | None = None) -> canopen.Network:
    """A CANopen node that is not a PRM9 on the virtual bus ``channel``: device type 0x191,
    error register, the vendor ID ``vendor`` if given. Disconnect the network when done."""
    network = canopen.Network()
    network.connect(interface="virtual", channel=channel)
    od = canopen.ObjectDictionary()
    for name, index, value in (("device type", 0x1000, 0x191), ("error register", 0x1001, 0)):
        var = canopen.objectdictionary.ODVariable(name, index, 0)
        var.data_type, var.default = canopen.objectdictionary.UNSIGNED32, value
        od.add_object(var)
    if vendor is not None:
        identity = canopen.objectdictionary.ODRecord("identity", 0x1018)
        member = canopen.objectdictionary.ODVariable("vendor", 0x1018, 1)
        member.data_type, member.default = canopen.objectdictionary.UNSIGNED32, vendor
        identity.add_member(member)
        od.add_object(identity)
    network.add_node(canopen.LocalNode(node_id, od))
    return network


def unique_channel(name: str) -> str:
    """A virtual-bus channel no other test uses."""
    return f"prm9-{name}-{next(_counter)}-{time.monotonic_ns()}"


def frame(text: str) -> tuple[int, bytes]:
    """``"60A 40 18 10 04 00 00 00 00"`` -> ``(0x60A, b"...")`` (the manual's notation)."""
    head, *data = text.split()
    return int(head, 16), bytes.fromhex("".join(data))


def show(can_id: int, data: bytes) -> str:
    """The inverse of :func:`frame`, upper case like the manual."""
    return f"{can_id:03X} {data.hex(' ').upper()}".strip()


@dataclass
class Rig:
    """A valve, its slave and a master bus on the same virtual channel."""

    valve: EmulatedValve
    slave: CanopenSlave
    master: can.BusABC
    slave_bus: can.BusABC
    skipped: list[str] = field(default_factory=list)  # frames barrier() passed over
    log: list[str] = field(default_factory=list)  # every frame sent and received, in order

    def send(self, text: str, fd: bool = False) -> None:
        """Send one frame written as ``"60A 2B 17 10 00 E8 03 00 00"`` (``fd``: as CAN FD)."""
        can_id, data = frame(text)
        self.log.append(show(can_id, data))
        message = can.Message(arbitration_id=can_id, data=data, is_extended_id=False, is_fd=fd)
        self.master.send(message)

    def receive(self, timeout: float = TIMEOUT_S) -> str | None:
        """The next frame on the bus as text, or None after ``timeout``."""
        if self.skipped:
            text = self.skipped.pop(0)
        else:
            msg = self.master.recv(timeout)
            if msg is None:
                return None
            text = show(msg.arbitration_id, bytes(msg.data))
        self.log.append(text)
        return text

    def expect(self, text: str) -> None:
        """The next frame must be exactly ``text``."""
        got, want = self.receive(), show(*frame(text))
        assert got == want, f"received {got!r}, expected {want!r}"

    def exchange(self, request: str, response: str) -> None:
        """Send ``request``; the next frame must be exactly ``response``."""
        self.send(request)
        self.expect(response)

    def drain(self, settle_s: float = 0.05) -> list[str]:
        """Every frame queued now (waiting ``settle_s`` for stragglers of the Notifier)."""
        frames = []
        while (text := self.receive(settle_s)) is not None:
            frames.append(text)
        return frames

    def sdo_read(self, index: int, subindex: int) -> bytes:
        """Expedited SDO upload; returns the data bytes (asserts an expedited answer)."""
        self.send(
            f"{0x600 + self.slave.node_id:03X} 40 {index & 0xFF:02X} {index >> 8:02X} "
            f"{subindex:02X} 00 00 00 00"
        )
        answer = self.receive()
        assert answer is not None
        data = bytes.fromhex(answer[4:])
        assert data[0] & 0xE3 == 0x43, answer
        return data[4 : 8 - ((data[0] >> 2) & 3)]

    def barrier(self) -> None:
        """Wait until the slave has processed every frame sent so far (frames are handled in
        order, so the answer to one more SDO request proves it). The answer is consumed; other
        frames received meanwhile are kept for :meth:`receive`."""
        node = self.slave.node_id
        self.send(f"{0x600 + node:03X} 40 00 10 00 00 00 00 00")
        others = []
        for _ in range(1000):
            msg = self.master.recv(TIMEOUT_S)
            assert msg is not None, "no SDO answer"
            text = show(msg.arbitration_id, bytes(msg.data))
            if text.startswith(f"{0x580 + node:03X} 43 00 10 00"):
                self.skipped += others
                return
            others.append(text)
        raise AssertionError("SDO answer not found")

    def wait_for_nmt_state(self, state: str) -> None:
        """Wait (real time) until the Notifier has applied an NMT command without an answer."""
        deadline = time.monotonic() + TIMEOUT_S
        while self.valve.status().nmt_state != state:
            assert time.monotonic() < deadline, f"NMT state {self.valve.status().nmt_state}"
            time.sleep(0.001)

    def close(self) -> None:
        """Stop the slave and close both bus ends."""
        self.slave.stop()
        self.slave_bus.shutdown()
        self.master.shutdown()


def make_rig(name: str, type_key: str = E02, boot: bool = True, **valve_args: object) -> Rig:
    """A rig with a freshly powered valve; ``boot`` runs the power-up and eats the boot-up."""
    channel = unique_channel(name)
    master = can.Bus(interface="virtual", channel=channel)
    slave_bus = can.Bus(interface="virtual", channel=channel)
    valve = EmulatedValve(type_key, **valve_args)  # type: ignore[arg-type]
    rig = Rig(valve, valve.connect_can(slave_bus), master, slave_bus)
    if boot:
        valve.advance(BOOT_S)
        assert rig.receive() == f"{0x700 + rig.slave.node_id:03X} 00"
    return rig

"""A misbehaving CANopen node on raw python-can frames (not the emulator), for the master's
robustness tests (issue 29).

:class:`BadNode` is an SDO server that identifies as a PRM9 (0x1000 = 0x198, 0x1018/1 = 0xE6,
a serial, a firmware text, a type key in 0x2041, control mode 0x6043 = 2) and then
misbehaves in one chosen way (:class:`Fault`). :class:`BadLssSlave` is an LSS slave
(CiA 305) that can acknowledge every request, add stray frames, or answer "inquire node ID"
with random bytes. Both run a receive thread on their own python-can bus: the ``virtual``
interface in-process, or ``udp_multicast`` in another process (tests/support/bad_node_driver.py).
:func:`serving_node` is the in-process set-up the tests share: a BadNode on a bus of its own
on a virtual channel, stopped and its bus shut down afterwards.
"""

from __future__ import annotations

import random
import struct
import threading
import time
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from enum import Enum
from typing import Any

import can

PRM9_DEVICE_TYPE, ARGO_HYTOS = 0x198, 0xE6
TYPE_KEY = "PRM9-06.3Z11/30-24E02S02-CA"
FIRMWARE = "V1.02.0017 build 2026"


class Fault(Enum):
    """How the node misbehaves."""

    NONE = "none"  # a well-behaved node
    ANSWERS_1000_ONLY = "answers-1000-only"  # answers 0x1000, then nothing
    ENDLESS_NO_SIZE = "endless-no-size"  # segmented uploads never end, no size declared
    ENDLESS_HUGE = "endless-huge"  # segmented uploads never end, 0xFFFFFFFF declared
    SHORT = "short"  # segmented uploads end halfway through the size they declared
    LONG = "long"  # segmented uploads send more than the size they declared
    NO_TOGGLE = "no-toggle"  # segmented uploads never alternate the toggle bit
    OTHER_OBJECT = "other-object"  # answers for the next sub-index
    SHORT_FRAMES = "short-frames"  # answers with 3 data bytes
    ABORTS = "aborts"  # aborts every other request after 0x1000 with a random CiA 301 code
    REFUSES_STORE = "refuses-store"  # 0x1010/1 "save": abort 0x08000020 (cannot store)
    CLAMPS = "clamps"  # keeps every written number at half of what was written
    RESETS = "resets"  # at its first write: silent for 1 s, boot-up, its first objects again
    LATE = "late"  # every answer after 0x1000 comes ``delay_s`` late (set it above the timeout)


IDENTITY = frozenset({0x1000, 0x1001, 0x1008, 0x100A, 0x1018, 0x2041, 0x6043})


def prm9_objects(
    serial: int = 777001, control_mode: int = 2, parameters: bool = False
) -> dict[tuple[int, int], bytes]:
    """The identity objects of a PRM9 -CA with 0x2041 (this project's type-key object);
    ``parameters``: also every catalogue object of its variant at its factory value, and
    0x1010/1 (store) — enough for a ``--batch`` upload."""
    objects = _parameters(node_id=11) if parameters else {}
    return objects | {
        (0x1000, 0): PRM9_DEVICE_TYPE.to_bytes(4, "little"),
        (0x1001, 0): b"\0",
        (0x1008, 0): b"PRM9",
        (0x100A, 0): FIRMWARE.encode(),
        (0x1018, 0): b"\x04",
        (0x1018, 1): ARGO_HYTOS.to_bytes(4, "little"),
        (0x1018, 2): (9).to_bytes(4, "little"),
        (0x1018, 3): (0x10000).to_bytes(4, "little"),
        (0x1018, 4): serial.to_bytes(4, "little"),
        (0x2041, 0): TYPE_KEY.encode(),
        (0x6043, 0): control_mode.to_bytes(1, "little", signed=True),
    }


def _parameters(node_id: int) -> dict[tuple[int, int], bytes]:
    from prm9tool.catalogue import CATALOGUE
    from prm9tool.catalogue.typekey import TypeKey

    variant = TypeKey.parse(TYPE_KEY).variant
    objects = {
        p.key: p.dtype.encode(p.default_for(variant, node_id))
        for p in CATALOGUE.for_variant(variant)
    }
    objects[(0x1010, 1)] = (1).to_bytes(4, "little")  # "save" supported on command (CiA 301)
    return objects


@dataclass
class BadNode:
    """An SDO server at ``node_id`` on ``bus`` with ``fault``; start with :meth:`start`."""

    bus: can.BusABC
    node_id: int
    fault: Fault = Fault.NONE
    objects: dict[tuple[int, int], bytes] = field(default_factory=prm9_objects)
    delay_s: float = 0.0  # each answer this late (a second node at one ID answers later)
    # the objects (by index) the fault spares; IDENTITY: it identifies as a PRM9, then fails
    sound: frozenset[int] = frozenset({0x1000})
    segments_sent: int = 0
    requests: int = 0
    aborts: list[bytes] = field(default_factory=list)  # abort frames the client sent
    writes: list[tuple[int, int]] = field(default_factory=list)  # objects a download began
    stored: dict[tuple[int, int], bytes] | None = None  # what the last store kept (None: none)
    _stop: threading.Event = field(default_factory=threading.Event)
    _thread: threading.Thread | None = None
    _upload: bytes = b""
    _pos: int = 0
    _toggle: int = 0
    _random: random.Random = field(default_factory=lambda: random.Random(301))
    _initial: dict[tuple[int, int], bytes] = field(default_factory=dict)
    _sound_upload: bool = False

    def start(self) -> BadNode:
        """Serve in a thread until :meth:`stop`."""
        self._initial = dict(self.objects)
        self._thread = threading.Thread(target=self._serve, daemon=True)
        self._thread.start()
        return self

    def stop(self) -> None:
        """End the thread (the bus stays open: the caller owns it)."""
        self._stop.set()
        if self._thread is not None:
            self._thread.join(5)

    def _serve(self) -> None:
        while not self._stop.is_set():
            msg = self.bus.recv(0.05)
            if msg is None or msg.arbitration_id != 0x600 + self.node_id:
                continue
            answer = self.answer(bytes(msg.data))
            if answer is not None:
                if self.delay_s and self.fault is not Fault.LATE:
                    time.sleep(self.delay_s)
                self.bus.send(
                    can.Message(
                        arbitration_id=0x580 + self.node_id, data=answer, is_extended_id=False
                    )
                )

    # --- the SDO server ------------------------------------------------------------------
    def answer(self, request: bytes) -> bytes | None:
        """The answer to one request frame (None: no answer)."""
        command = request[0]
        if command == 0x80:
            self.aborts.append(request)
            return None
        self.requests += 1
        index, subindex = struct.unpack_from("<HB", request, 1)
        if self.fault is Fault.RESETS and command & 0xE0 == 0x20 and not self.writes:
            self._reset()
            return None
        sound = index in self.sound or (command & 0xE0 == 0x60 and self._sound_upload)
        if self.fault is Fault.ANSWERS_1000_ONLY and not (sound and command & 0xE0 in (0x40, 0x60)):
            return None
        if self.fault is Fault.ABORTS and not sound and self.requests % 2:
            code = self._random.choice((0x06010000, 0x08000000, 0x06060000, 0x05040001))
            return struct.pack("<BHBI", 0x80, index, subindex, code)
        if self.fault is Fault.LATE and not sound:
            time.sleep(self.delay_s)
        fault, self.fault = self.fault, (Fault.NONE if sound else self.fault)
        try:
            frame = self._answer(command, index, subindex, request)
        finally:
            self.fault = fault
        if frame is not None and self.fault is Fault.SHORT_FRAMES and not sound:
            return frame[:3]
        return frame

    def _reset(self) -> None:
        """A power dip: silent while it boots, then a boot-up and the objects it had."""
        self.writes.append((-1, -1))  # the reset, in the order of the writes
        time.sleep(1.0)
        self.objects = dict(self._initial)
        boot_up = can.Message(arbitration_id=0x700 + self.node_id, data=b"\0", is_extended_id=False)
        self.bus.send(boot_up)

    def _answer(self, command: int, index: int, subindex: int, request: bytes) -> bytes | None:
        if command == 0x40:
            return self._initiate_upload(index, subindex)
        if command & 0xE0 == 0x60:
            return self._segment(command)
        if command & 0xE0 == 0x20:
            data = request[4 : 8 - ((command >> 2) & 3)] if command & 0x02 else b""
            self.writes.append((index, subindex))
            if (index, subindex) == (0x1010, 1):
                if self.fault is Fault.REFUSES_STORE:
                    return struct.pack("<BHBI", 0x80, index, subindex, 0x08000020)
                self.stored = dict(self.objects)
                return struct.pack("<BHB4x", 0x60, index, subindex)
            if self.fault is Fault.CLAMPS and data and (index, subindex) in self.objects:
                data = (int.from_bytes(data, "little") // 2).to_bytes(len(data), "little")
            self.objects[(index, subindex)] = data
            return struct.pack("<BHB4x", 0x60, index, subindex)
        return None

    def _initiate_upload(self, index: int, subindex: int) -> bytes:
        value = self.objects.get((index, subindex))
        if value is None:
            return struct.pack("<BHBI", 0x80, index, subindex, 0x06020000)
        if self.fault is Fault.OTHER_OBJECT:
            subindex += 1
        if len(value) <= 4:
            command = 0x43 | ((4 - len(value)) << 2)
            return struct.pack("<BHB", command, index, subindex) + value.ljust(4, b"\0")
        self._upload, self._pos, self._toggle = value, 0, 0
        self._sound_upload = self.fault is Fault.NONE
        if self.fault is Fault.ENDLESS_NO_SIZE:
            return struct.pack("<BHB4x", 0x40, index, subindex)
        size = 0xFFFFFFFF if self.fault is Fault.ENDLESS_HUGE else len(value)
        return struct.pack("<BHBI", 0x41, index, subindex, size)

    def _segment(self, command: int) -> bytes:
        self.segments_sent += 1
        toggle = 0 if self.fault is Fault.NO_TOGGLE else command & 0x10
        if self.fault in (Fault.ENDLESS_NO_SIZE, Fault.ENDLESS_HUGE):
            return bytes([toggle]) + b"x" * 7  # 7 bytes, never the last
        value = self._upload
        if self.fault is Fault.SHORT:
            value = value[: len(value) // 2]
        if self.fault is Fault.LONG:
            value = value + b"-longer-than-declared"
        chunk = value[self._pos : self._pos + 7]
        self._pos += len(chunk)
        last = self._pos >= len(value)
        return bytes([toggle | ((7 - len(chunk)) << 1) | last]) + chunk.ljust(7, b"\0")


@contextmanager
def serving_node(
    channel: str, node_id: int, fault: Fault = Fault.NONE, **kwargs: Any
) -> Iterator[BadNode]:
    """A started :class:`BadNode` at ``node_id`` with ``fault`` (``kwargs``: its other fields)
    on a bus of its own on the in-process ``virtual`` interface's ``channel``; stopped, and its
    bus shut down, at the end of the ``with``."""
    bus = can.Bus(interface="virtual", channel=channel, receive_own_messages=False)
    node: BadNode | None = None
    try:
        node = BadNode(bus, node_id, fault, **kwargs).start()
        yield node
    finally:
        if node is not None:
            node.stop()
        bus.shutdown()


@dataclass
class Flood:
    """Frames of one kind sent back to back on ``bus`` from a thread (a heartbeat or EMCY
    storm, a flood of high-priority frames) until :meth:`stop`; ``sent`` counts them."""

    bus: can.BusABC
    can_id: int
    data: bytes
    other: bytes | None = None  # sent in turn with ``data`` (heartbeats of two nodes)
    period_s: float = 0.0  # 0: back to back
    sent: int = 0
    _stop: threading.Event = field(default_factory=threading.Event)
    _thread: threading.Thread | None = None

    def start(self) -> Flood:
        """Flood in a thread."""
        self._thread = threading.Thread(target=self._flood, daemon=True)
        self._thread.start()
        return self

    def stop(self) -> None:
        """End the flood."""
        self._stop.set()
        if self._thread is not None:
            self._thread.join(5)

    def _flood(self) -> None:
        payloads = [self.data] if self.other is None else [self.data, self.other]
        messages = [
            can.Message(arbitration_id=self.can_id, data=data, is_extended_id=False)
            for data in payloads
        ]
        while not self._stop.is_set():
            self.bus.send(messages[self.sent % len(messages)])
            self.sent += 1
            if self.period_s:
                self._stop.wait(self.period_s)
            elif self.sent % 50 == 0:
                time.sleep(0.001)  # the in-process virtual bus: let the other threads run


class LssFault(Enum):
    """How the LSS slave misbehaves."""

    NONE = "none"
    ACKNOWLEDGES_ALL = "acknowledges-all"  # answers every request with its answer specifier
    STRAY_FRAMES = "stray-frames"  # takes no part; sends other specifiers at each Fastscan step
    RANDOM_INQUIRE = "random-inquire"  # answers "inquire node ID" with random bytes


@dataclass
class BadLssSlave:
    """An LSS slave without a node ID (CiA 305), ``address``: vendor, product, revision,
    serial; with ``fault``."""

    bus: can.BusABC
    address: tuple[int, int, int, int]
    fault: LssFault = LssFault.NONE
    delay_s: float = 0.0  # each answer this long after its request (a slow device)
    requests: int = 0
    configured: bool = False  # Fastscan or the selective switch chose it
    _selective: list[int] = field(default_factory=list)
    _position: int = 0
    _stop: threading.Event = field(default_factory=threading.Event)
    _thread: threading.Thread | None = None
    _random: random.Random = field(default_factory=lambda: random.Random(29))

    def start(self) -> BadLssSlave:
        """Serve in a thread until :meth:`stop`."""
        self._thread = threading.Thread(target=self._serve, daemon=True)
        self._thread.start()
        return self

    def stop(self) -> None:
        """End the thread."""
        self._stop.set()
        if self._thread is not None:
            self._thread.join(5)

    def _serve(self) -> None:
        while not self._stop.is_set():
            msg = self.bus.recv(0.05)
            if msg is None or msg.arbitration_id != 0x7E5:
                continue
            self.requests += 1
            answers = [
                can.Message(arbitration_id=0x7E4, data=a, is_extended_id=False)
                for a in self.answers(bytes(msg.data))
            ]
            if self.delay_s and answers:  # each late by itself, not behind the one before
                threading.Timer(
                    self.delay_s, lambda out=answers: [self.bus.send(m) for m in out]
                ).start()
                continue
            for message in answers:
                self.bus.send(message)

    def answers(self, request: bytes) -> list[bytes]:
        """The frames this slave sends for one request."""
        cs = request[0]
        if self.fault is LssFault.ACKNOWLEDGES_ALL:
            reply = {0x51: 0x4F, 0x4C: 0x50, 0x43: 0x44}.get(cs, cs)
            return [] if cs in (0x04, 0x40, 0x41, 0x42) else [bytes([reply]).ljust(8, b"\0")]
        if self.fault is LssFault.STRAY_FRAMES:
            strays = (0x50, 0x44, 0x5E) if cs == 0x51 else ()
            return [bytes([stray, 1, 2, 3]).ljust(8, b"\0") for stray in strays]
        out = []
        answer = self._proper(cs, request)
        if answer is not None:
            out.append(answer.ljust(8, b"\0"))
        return out

    def _proper(self, cs: int, request: bytes) -> bytes | None:
        if cs == 0x04:  # switch state global
            self.configured = request[1] == 1 and self.configured
            self._selective.clear()
            return None
        if cs == 0x4C:  # identify non-configured remote slave
            return bytes([0x50])
        if cs == 0x51:
            return self._fastscan(request)
        if 0x40 <= cs <= 0x43:
            self._selective = [
                *self._selective[: cs - 0x40],
                struct.unpack_from("<I", request, 1)[0],
            ]
            if cs == 0x43 and tuple(self._selective) == self.address:
                self.configured = True
                return bytes([0x44])
            return None
        if not self.configured:
            return None
        if cs == 0x5E:
            if self.fault is LssFault.RANDOM_INQUIRE:
                return bytes(self._random.randrange(256) for _ in range(8))
            return bytes([0x5E, 0xFF])
        if cs in (0x11, 0x13, 0x17):
            return bytes([cs, 0])
        return None

    def _fastscan(self, request: bytes) -> bytes | None:
        number, bit, sub, following = struct.unpack_from("<IBBB", request, 1)
        if self.configured:
            return None
        if bit == 0x80:
            self._position = 0
            return bytes([0x4F])
        if sub != self._position or bit > 31:
            return None
        mask = ~((1 << bit) - 1) & 0xFFFFFFFF
        if (self.address[sub] & mask) != (number & mask):
            return None
        if bit == 0:
            self._position = following
            if following < sub:  # the last part confirmed: it is chosen (CiA 305)
                self.configured = True
        return bytes([0x4F])

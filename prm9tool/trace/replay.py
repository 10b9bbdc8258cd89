"""Replaying one side of a trace: the master's frames (NMT, SYNC, TIME, RPDOs, SDO requests, LSS
requests) put back on a bus with their timing, so that a recorded machine sequence drives an
emulated valve (or a twin) on a desk; what the nodes answer is recorded and compared with the
trace's own answers: the SDO responses (in order), the EMCY codes, the device states the status
words showed and the boot-ups. The bus is the shared master of the CAN options (frames sent
through it are seen by a recorder beside). No Qt."""

from __future__ import annotations

import threading
import time
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

from prm9tool.device.canlink.bus import CanOptions, acquire, release
from prm9tool.trace.decoder import Decoder
from prm9tool.trace.events import Event, Kind, Trace
from prm9tool.trace.frames import read_frames

if TYPE_CHECKING:
    import can

SETTLE_S = 0.5  # answers are waited for this long after the last frame sent
ANSWER_S = 1.0  # an SDO request answered in the trace: its answer is waited for this long


@dataclass(frozen=True)
class Difference:
    """A node's answers in the replay that differ from the trace's."""

    node: int
    what: str  # "SDO", "EMCY", "states", "boot-ups"
    recorded: tuple[str, ...]
    replayed: tuple[str, ...]

    def to_dict(self) -> dict[str, object]:
        """JSON-ready."""
        return {
            "node": self.node, "what": self.what,
            "recorded": list(self.recorded), "replayed": list(self.replayed),
        }  # fmt: skip


@dataclass
class ReplayResult:
    """What was sent, what came back, and how it differs from the trace."""

    sent: int
    recorded: Trace
    replayed: Trace
    differences: list[Difference] = field(default_factory=list)
    late_s: float = 0.0  # the latest a frame left after its time (a busy PC)


def master_frames(
    path: str | Path, only_node: int | None = None
) -> tuple[Trace, list[_Frame], int]:
    """The decoded trace, the frames of its master side (``only_node``: only those a node
    receives: NMT to it or to all, SYNC, TIME, its RPDOs and SDO requests) and the number of
    the first of them in the trace."""
    frames = list(read_frames(path))
    decoded = Decoder(str(path)).feed_all(frames)
    rpdo = {
        n
        for e in decoded.events
        if e.kind is Kind.PDO and e.text.startswith("RPDO")
        for n in e.frames
    }
    rpdo_node = {
        n: e.node
        for e in decoded.events
        if e.kind is Kind.PDO and e.text.startswith("RPDO")
        for n in e.frames
    }
    answered = _answered_requests(frames)
    chosen, first = [], len(frames)
    for number, msg in enumerate(frames):
        if msg.is_error_frame or msg.is_extended_id:
            continue
        cob = msg.arbitration_id
        node = _target(cob, bytes(msg.data), rpdo_node.get(number))
        master = cob in (0x000, 0x080, 0x100, 0x7E5) or 0x601 <= cob <= 0x67F or number in rpdo
        if master and (only_node is None or node in (None, 0, only_node)):
            chosen.append(_Frame(msg, number in answered))
            first = min(first, number)
    return decoded, chosen, first


@dataclass(frozen=True)
class _Frame:
    msg: can.Message
    answered: bool  # an SDO request the node answered in the trace (the replay waits for it)


def _answered_requests(frames: list[can.Message]) -> set[int]:
    """The SDO requests that got a response before the next request to the same node."""
    pending: dict[int, int] = {}
    answered = set()
    for number, msg in enumerate(frames):
        cob = msg.arbitration_id
        if 0x601 <= cob <= 0x67F:
            pending[cob - 0x600] = number
        elif 0x581 <= cob <= 0x5FF and (cob - 0x580) in pending:
            answered.add(pending.pop(cob - 0x580))
    return answered


def _target(cob: int, data: bytes, rpdo_node: int | None) -> int | None:
    if cob == 0x000:
        return data[1] if len(data) > 1 else None
    if 0x601 <= cob <= 0x67F:
        return cob - 0x600
    return rpdo_node


def replay(
    path: str | Path,
    options: CanOptions,
    speed: float = 1.0,
    only_node: int | None = None,
    settle_s: float = SETTLE_S,
    stop: threading.Event | None = None,
    progress: Callable[[int, int], None] | None = None,
) -> ReplayResult:
    """Send the master side of the trace ``path`` on the bus ``options`` with its timing
    (``speed`` 2: twice as fast), record the answers and compare them with the trace's."""
    recorded, frames, first = master_frames(path, only_node)
    shared = acquire(options)
    captured: list[can.Message] = []
    listener = _Capture(captured)
    shared.add_listener(listener)
    late = 0.0
    try:
        start_t = frames[0].msg.timestamp if frames else 0.0
        started = time.perf_counter()
        for k, frame in enumerate(frames):
            msg = frame.msg
            due = started + (msg.timestamp - start_t) / speed
            wait = due - time.perf_counter()
            if wait > 0:
                time.sleep(wait)
            else:
                late = max(late, -wait)
            if stop is not None and stop.is_set():
                break
            if frame.answered:
                listener.expect(msg.arbitration_id - 0x600 + 0x580)
            shared.network.send_message(msg.arbitration_id, bytes(msg.data))
            if frame.answered:
                listener.wait(ANSWER_S)  # as the PLC did: the next request after the answer
            if progress is not None:
                progress(k + 1, len(frames))
        time.sleep(settle_s)
    finally:
        shared.remove_listener(listener)
        release(shared)
    replayed = Decoder("replay").feed_all(captured)
    nodes = {only_node} if only_node is not None else set(recorded.nodes)
    differences = compare(_since(recorded, first), replayed, nodes)
    return ReplayResult(len(frames), recorded, replayed, differences, late)


class _Capture:
    """Keeps every frame; :meth:`wait` waits for the answer :meth:`expect` named."""

    def __init__(self, into: list[can.Message]) -> None:
        self._into = into
        self._expected: int | None = None
        self._arrived = threading.Event()

    def expect(self, cob: int) -> None:
        self._expected = cob
        self._arrived.clear()

    def wait(self, timeout_s: float) -> bool:
        return self._arrived.wait(timeout_s)

    def on_message_received(self, msg: can.Message) -> None:
        self._into.append(msg)
        if msg.arbitration_id == self._expected and msg.is_rx:
            self._arrived.set()

    def __call__(self, msg: can.Message) -> None:
        self.on_message_received(msg)

    def on_error(self, exc: Exception) -> None:
        """Nothing to do."""

    def stop(self) -> None:
        """Nothing to release."""


def _since(trace: Trace, first: int) -> Trace:
    """The trace's events from frame ``first`` on (what the master side could cause)."""
    events = [e for e in trace.events if e.frames and e.frames[0] >= first]
    return Trace(trace.path, trace.frames, events, [], trace.sync, trace.nodes, trace.start)


def compare(recorded: Trace, replayed: Trace, nodes: Iterable[int]) -> list[Difference]:
    """Where the replayed answers of ``nodes`` differ from the recorded ones."""
    found = []
    for node in sorted(nodes):
        for what, pick in _ASPECTS.items():
            old, new = pick(recorded.events, node), pick(replayed.events, node)
            if old != new:
                found.append(Difference(node, what, old, new))
    return found


def _sdo(events: list[Event], node: int) -> tuple[str, ...]:
    return tuple(e.text for e in events if e.node == node and e.kind is Kind.SDO)


def _emcy(events: list[Event], node: int) -> tuple[str, ...]:
    return tuple(e.text.split(":")[0] for e in events if e.node == node and e.kind is Kind.EMCY)


def _states(events: list[Event], node: int) -> tuple[str, ...]:
    """The device states in the order the status words showed them (repeats folded)."""
    states: list[str] = []
    for e in events:
        if e.node == node and e.kind is Kind.STATE and e.text.startswith("device state"):
            state = e.text.split(" (")[0].split(" ")[-1]
            if not states or states[-1] != state:
                states.append(state)
    return tuple(states)


def _boot_ups(events: list[Event], node: int) -> tuple[str, ...]:
    return tuple(e.text for e in events if e.node == node and e.text == "boot-up")


_ASPECTS: dict[str, Callable[[list[Event], int], tuple[str, ...]]] = {
    "SDO": _sdo,
    "EMCY": _emcy,
    "states": _states,
    "boot-ups": _boot_ups,
}

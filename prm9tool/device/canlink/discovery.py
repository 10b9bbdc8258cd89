"""Finding PRM9 valves on a CAN bus (a bounded scan of node IDs 1–127 plus listening).

The scan sends one SDO read of 0x1000 to every node ID (``canopen``'s NodeScanner) and
listens for answers, boot-ups, heartbeats and EMCY for ``window_s``; every node heard is then
identified: a PRM9 has 0x1000 = 0x198 and 0x1018/1 = 0xE6 (manual §7.6), named by 0x1008
device name, 0x100A firmware and 0x1018/4 serial. Any other node is listed as not a PRM9.

Each node is identified on its own: a node that stops answering, answers garbage or holds
values no PRM9 has is listed with what is wrong (``problem``) and never stops the scan. Two
nodes at one node ID are found by their answers: two answers to the scan's request, or an
answer that comes when none was asked for (an identification waits for it: ten times the
first answer's delay, at least :data:`SETTLE_MIN_S`); and, during the scan, by two boot-ups
closer than one node can boot or heartbeats alternating between two NMT states.
"""

from __future__ import annotations

import time
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass

from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.catalogue.variant import Config
from prm9tool.device.canlink.bus import TWIN_BOOT_S, CanNetwork
from prm9tool.device.canlink.sdo import (
    ARGO_HYTOS_VENDOR,
    MISSING,
    PRM9_DEVICE_TYPE,
    SdoChannel,
)
from prm9tool.device.canlink.typekeys import Derived
from prm9tool.errors import Prm9Error, SdoAbortError

SCAN_WINDOW_S = 0.3
IDENTIFY_TIMEOUT_S = 0.3
SETTLE_MIN_S = 0.05  # a second node at the same ID answers 0–12 ms after the first (measured)
PCODE = CATALOGUE["PCODE"].key  # 0x2041, the type key: this project's decision (not in the manual)
CONTROL_MODE = CATALOGUE["CTRLMODE"].key  # 0x6043; 4 = process control: E04 only (table 7-16)
CONTROL_MODES = frozenset(code for code, _ in CATALOGUE["CTRLMODE"].choices)  # table 7-16
TWO_NODES = "two nodes answer at this ID"
SCAN_REQUEST = bytes([0x40, 0x00, 0x10, 0x00])  # NodeScanner: upload 0x1000/0


class NotIdentifiedError(Prm9Error):
    """A value the node answered is none a PRM9 can hold (it is not identified)."""


@dataclass(frozen=True)
class NodeInfo:
    """One node found on the bus."""

    node_id: int
    device_type: int | None
    vendor: int | None
    name: str = ""
    firmware: str = ""
    serial: int = 0
    type_key: str | None = None  # 0x2041 where the valve has it
    derived: Derived | None = None
    problem: str = ""  # why it is not usable (not a PRM9, no answer, not identified)
    detail: str = ""  # the error when it did not answer or identify itself (English)
    duplicate: bool = False  # two nodes answer at this node ID

    @property
    def usable(self) -> bool:
        """A PRM9 that identified itself completely: prm9tool may open it."""
        return self.is_prm9 and not self.problem

    @property
    def is_prm9(self) -> bool:
        """0x1000 = 0x198 and 0x1018/1 = 0xE6."""
        return self.device_type == PRM9_DEVICE_TYPE and self.vendor == ARGO_HYTOS_VENDOR

    @property
    def device_id(self) -> str:
        """``can:NODE``."""
        return f"can:{self.node_id}"


def scan(shared: CanNetwork, window_s: float = SCAN_WINDOW_S, limit: int = 127) -> list[NodeInfo]:
    """Every node that answered or announced itself, identified, by node ID."""
    network = shared.network
    before = {n: (s.alternations, s.twin_boot_ups) for n, s in list(shared.seen.items())}
    with _answers_counted(shared, limit) as answers:
        network.scanner.reset()
        network.scanner.search(limit)
        time.sleep(window_s)
    heard = set(network.scanner.nodes) | {
        n for n, seen in shared.seen.items() if seen.heartbeat_at is not None
    }
    found = []
    for node_id in sorted(n for n in heard if 0 < n <= limit):
        info = identify_node(shared, node_id)
        evidence = _twin_evidence(shared, node_id, answers.get(node_id, 0), before)
        if evidence and not info.duplicate:
            info = _two_nodes(info, evidence)
        found.append(info)
    return found


def _twin_evidence(
    shared: CanNetwork, node_id: int, answers: int, before: dict[int, tuple[int, int]]
) -> str:
    """Why two nodes seem to share ``node_id`` from what the scan heard ("" none)."""
    if answers > 1:
        return f"{answers} answers to one read of 0x1000"
    seen = shared.node_seen(node_id)
    alternations, twins = before.get(node_id, (0, 0))
    if seen.twin_boot_ups > twins:
        return f"two boot-ups less than {TWIN_BOOT_S:g} s apart"
    if seen.alternations - alternations >= 2:
        return "its heartbeats alternate between two NMT states"
    return ""


@contextmanager
def _answers_counted(shared: CanNetwork, limit: int) -> Iterator[dict[int, int]]:
    """How many answers each node ID gives to the scan's read of 0x1000."""
    counts: dict[int, int] = {}

    def counter(node_id: int):  # type: ignore[no-untyped-def]
        def on_answer(_can_id: int, data: bytearray, _timestamp: float) -> None:
            if bytes(data[1:4]) == SCAN_REQUEST[1:4]:
                counts[node_id] = counts.get(node_id, 0) + 1

        return on_answer

    network = shared.network
    callbacks = {0x580 + n: counter(n) for n in range(1, limit + 1)}
    for cob_id, callback in callbacks.items():
        network.subscribe(cob_id, callback)
    try:
        yield counts
    finally:
        for cob_id, callback in callbacks.items():
            network.unsubscribe(cob_id, callback)


def _two_nodes(info: NodeInfo, evidence: str) -> NodeInfo:
    problem = (
        f"{TWO_NODES} ({evidence}): prm9tool cannot tell their answers apart and writes to "
        "neither; give one of them another node ID"
    )
    return NodeInfo(
        info.node_id,
        info.device_type,
        info.vendor,
        problem=problem,
        detail=problem,
        duplicate=True,
    )


def identify_node(
    shared: CanNetwork, node_id: int, timeout_s: float = IDENTIFY_TIMEOUT_S
) -> NodeInfo:
    """Who node ``node_id`` is (problem set when it is not a PRM9, does not answer, answers
    what no PRM9 holds, or shares its node ID). ``timeout_s``: per SDO answer — short while
    scanning a bus, the session's own when opening a node the user chose. Never raises for
    what the node does."""
    with sdo_channel(shared, node_id, timeout_s) as sdo:
        sdo.take_strays()  # answers to a scan before: not this identification's
        strays, timeouts = sdo.strays, sdo.timeouts
        info = _identify(sdo, node_id)
        if sdo.timeouts != timeouts:
            return info  # a late answer may follow: no evidence of a second node
        _settle(sdo)
        sdo.take_strays()
        extra = sdo.strays - strays  # those within the transfers and those after them
        if extra and not info.duplicate:
            return _two_nodes(info, f"{extra} answers nobody asked for")
        return info


def _identify(sdo: SdoChannel, node_id: int) -> NodeInfo:
    try:
        device_type = sdo.read_u32(0x1000, 0)
    except Prm9Error as exc:
        return NodeInfo(
            node_id,
            None,
            None,
            problem=f"does not answer as CANopen node: {exc}",
            detail=str(exc),
        )
    _settle(sdo)
    if sdo.take_strays():
        return _two_nodes(NodeInfo(node_id, device_type, None), "two answers to one request")
    try:
        vendor: int | None = sdo.read_u32(0x1018, 1)
    except SdoAbortError as exc:
        if exc.code not in MISSING:  # refused for another reason: it may be a PRM9
            return NodeInfo(
                node_id,
                device_type,
                None,
                problem=f"answers 0x1000 only: not identified ({exc})",
                detail=str(exc),
            )
        vendor = None  # no identity object: certainly not a PRM9
    except Prm9Error as exc:
        return NodeInfo(
            node_id,
            device_type,
            None,
            problem=f"answers 0x1000 only: not identified ({exc})",
            detail=str(exc),
        )
    if not NodeInfo(node_id, device_type, vendor).is_prm9:
        shown = "none" if vendor is None else f"0x{vendor:X}"
        return NodeInfo(
            node_id,
            device_type,
            vendor,
            problem=f"not a PRM9 (device type 0x{device_type:X}, vendor {shown})",
        )
    try:
        return _checked(
            NodeInfo(
                node_id,
                device_type,
                vendor,
                sdo.read_text(0x1008),
                sdo.read_text(0x100A),
                sdo.read_u32(0x1018, 4),
                optional_text(sdo, *PCODE),
                derive(sdo),
            )
        )
    except Prm9Error as exc:
        return NodeInfo(
            node_id,
            device_type,
            vendor,
            problem=f"not identified: {exc}",
            detail=str(exc),
        )


def _settle(sdo: SdoChannel) -> None:
    """Wait for a second node's answer to the last request (ten times the first's delay)."""
    time.sleep(max(10 * sdo.transfer.stats.latency_s, SETTLE_MIN_S))


def _checked(info: NodeInfo) -> NodeInfo:
    """``info`` as read, or NotIdentifiedError when its values are none a PRM9 holds."""
    if info.serial == 0:
        raise NotIdentifiedError("serial number 0x1018/4 = 0 is no serial number")
    if info.type_key is not None:
        try:
            key = TypeKey.parse(info.type_key)
        except Prm9Error as exc:
            raise NotIdentifiedError(
                f"type key 0x2041 = {info.type_key!r} is no PRM9 type key ({exc})"
            ) from None
        problem = info.derived.problem(key) if info.derived is not None else None
        if problem:
            raise NotIdentifiedError(f"type key 0x2041: {problem}")
    return info


def optional_text(sdo: SdoChannel, index: int, subindex: int) -> str | None:
    """A string object, or None when the valve does not have it."""
    try:
        return sdo.read_text(index, subindex) or None
    except SdoAbortError as exc:
        if exc.code in MISSING:
            return None
        raise


def derive(sdo: SdoChannel) -> Derived:
    """What the object dictionary tells about the type key: control mode 0x6043 = 4 exists
    on E04 valves only; anything else leaves E02/E04 open (0x2005–0x2100 are on every valve,
    manual table 7-14, so their presence tells nothing)."""
    try:
        data = sdo.upload(*CONTROL_MODE)
    except SdoAbortError as exc:
        if exc.code in MISSING:
            return Derived(None)
        raise
    if not 1 <= len(data) <= 4:
        raise NotIdentifiedError(f"0x6043 answered {len(data)} bytes for an INTEGER8")
    mode = int.from_bytes(data, "little", signed=True)
    if mode not in CONTROL_MODES:
        raise NotIdentifiedError(
            f"0x6043 = {mode} is no control mode of a PRM9 (manual table 7-16)"
        )
    return Derived(Config.E04 if mode == 4 else None)


@contextmanager
def sdo_channel(shared: CanNetwork, node_id: int, timeout_s: float) -> Iterator[SdoChannel]:
    """An SDO channel to ``node_id`` (the session's own node when one is open)."""
    import canopen

    network = shared.network
    with shared.lock:
        existing = network.nodes.get(node_id)
        node = (
            existing
            if existing is not None
            else canopen.RemoteNode(node_id, canopen.ObjectDictionary())
        )
        if existing is None:
            network.add_node(node)
    try:
        yield SdoChannel(node, timeout_s, shared)  # type: ignore[arg-type]
    finally:
        if existing is None:
            with shared.lock:
                if network.nodes.get(node_id) is node:
                    del network[node_id]

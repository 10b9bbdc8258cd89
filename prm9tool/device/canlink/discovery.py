"""Finding PRM9 valves on a CAN bus (a bounded scan of node IDs 1–127 plus listening).

The scan sends one SDO read of 0x1000 to every node ID (``canopen``'s NodeScanner) and
listens for answers, boot-ups, heartbeats and EMCY for ``window_s``; every node heard is then
identified: a PRM9 has 0x1000 = 0x198 and 0x1018/1 = 0xE6 (manual §7.6), named by 0x1008
device name, 0x100A firmware and 0x1018/4 serial. Any other node is listed as not a PRM9.
"""

from __future__ import annotations

import time
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass

from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.variant import Config
from prm9tool.device.canlink.bus import CanNetwork
from prm9tool.device.canlink.sdo import (
    ARGO_HYTOS_VENDOR,
    MISSING,
    PRM9_DEVICE_TYPE,
    SdoChannel,
)
from prm9tool.device.canlink.typekeys import Derived
from prm9tool.errors import CommunicationError, SdoAbortError

SCAN_WINDOW_S = 0.3
IDENTIFY_TIMEOUT_S = 0.3
PCODE = CATALOGUE["PCODE"].key  # 0x2041, the type key: this project's decision (not in the manual)
CONTROL_MODE = CATALOGUE["CTRLMODE"].key  # 0x6043; 4 = process control: E04 only (table 7-16)


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
    problem: str = ""  # why it is not usable (not a PRM9, no answer)

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
    network.scanner.reset()
    network.scanner.search(limit)
    time.sleep(window_s)
    heard = set(network.scanner.nodes) | {
        n for n, seen in shared.seen.items() if seen.heartbeat_at is not None
    }
    return [identify_node(shared, node_id) for node_id in sorted(heard) if 0 < node_id <= limit]


def identify_node(
    shared: CanNetwork, node_id: int, timeout_s: float = IDENTIFY_TIMEOUT_S
) -> NodeInfo:
    """Who node ``node_id`` is (problem set when it is not a PRM9 or does not answer).
    ``timeout_s``: per SDO answer — short while scanning a bus, the session's own when
    opening a node the user chose."""
    with sdo_channel(shared, node_id, timeout_s) as sdo:
        try:
            device_type = sdo.read_u32(0x1000, 0)
        except (CommunicationError, SdoAbortError) as exc:
            return NodeInfo(node_id, None, None, problem=f"does not answer as CANopen node: {exc}")
        try:
            vendor: int | None = sdo.read_u32(0x1018, 1)
        except SdoAbortError:
            vendor = None  # no identity object: certainly not a PRM9
        info = NodeInfo(node_id, device_type, vendor)
        if not info.is_prm9:
            shown = "none" if vendor is None else f"0x{vendor:X}"
            return NodeInfo(
                node_id,
                device_type,
                vendor,
                problem=f"not a PRM9 (device type 0x{device_type:X}, vendor {shown})",
            )
        try:
            return NodeInfo(
                node_id,
                device_type,
                vendor,
                sdo.read_text(0x1008),
                sdo.read_text(0x100A),
                sdo.read_u32(0x1018, 4),
                optional_text(sdo, *PCODE),
                derive(sdo),
            )
        except (CommunicationError, SdoAbortError) as exc:
            return NodeInfo(node_id, device_type, vendor, problem=f"identification failed: {exc}")


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
        mode = int.from_bytes(sdo.upload(*CONTROL_MODE)[:1], "little", signed=True)
    except SdoAbortError as exc:
        if exc.code in MISSING:
            return Derived(None)
        raise
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

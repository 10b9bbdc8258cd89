"""Commissioning on top of the LSS master (prm9tool.device.canlink.lss): whether a node ID is
free, whether a device answers at its new one, and renumbering a configured valve whose
node-ID switch is at 1 (LSS; manual table 7-17) — configure and store by LSS, then NMT reset
communication, at which the pending node ID becomes active (CiA 305)."""

from __future__ import annotations

import time
from typing import TYPE_CHECKING

from prm9tool.catalogue.commissioning import NmtCommand
from prm9tool.device.canlink.lss import LssAddress, LssFailedError, LssMasterLink
from prm9tool.errors import Prm9Error

if TYPE_CHECKING:
    from prm9tool.device.canlink.bus import CanNetwork


def answers_at(shared: CanNetwork, node_id: int, serial: int, timeout_s: float) -> bool:
    """The device with ``serial`` answers SDO at ``node_id`` within ``timeout_s`` (its boot
    after the LSS release included)."""
    from prm9tool.device.canlink.discovery import identify_node

    deadline = time.monotonic() + timeout_s
    while time.monotonic() < deadline:
        if identify_node(shared, node_id).serial == serial:
            return True
        time.sleep(0.05)
    return False


def check_free(shared: CanNetwork, node_id: int) -> None:
    """LssFailedError ``taken`` when a device answers SDO at ``node_id`` (nothing is changed)."""
    from prm9tool.device.canlink.discovery import identify_node

    info = identify_node(shared, node_id)
    if info.device_type is None:
        return
    what = f"serial {info.serial}" if info.serial else info.problem or "a device"
    raise LssFailedError(
        f"node ID {node_id} is taken: {what} answers there. Choose a free node ID; nothing "
        "was changed",
        "taken",
    )


def first_free(taken: set[int], count: int = 1) -> list[int]:
    """The first ``count`` node IDs 1…127 not in ``taken``."""
    return [n for n in range(1, 128) if n not in taken][:count]


def renumber(shared: CanNetwork, node_id: int, new_node_id: int, timeout_s: float) -> int:
    """Give the configured valve at ``node_id`` the node ID ``new_node_id`` by LSS (its node-ID
    switch at 1), stored, and make it take it now (NMT reset communication, CiA 305); returns
    its serial once it answers there. LssFailedError when it cannot be done: the ID is taken,
    the valve does not answer LSS (switch not at 1), a service is refused, it goes silent."""
    import canopen

    from prm9tool.device.canlink.discovery import sdo_channel

    check_free(shared, new_node_id)
    try:
        with sdo_channel(shared, node_id, 0.5) as sdo:
            parts = [sdo.read_u32(0x1018, sub) for sub in (1, 2, 3, 4)]
    except Prm9Error as exc:
        raise LssFailedError(f"node {node_id} does not tell its identity: {exc}", "lost") from exc
    address = LssAddress(*parts)
    try:
        LssMasterLink(shared).assign(address, new_node_id)
    except LssFailedError as exc:
        if exc.kind != "unanswered":
            raise
        raise LssFailedError(
            f"node {node_id} (serial {address.serial}) does not answer LSS: its node-ID switch "
            "is not at 1 (LSS, manual table 7-17). Change its node ID with NODEID (switch at 0) "
            "or by the switch; nothing was changed",
            "refused",
        ) from None
    nmt = canopen.nmt.NmtMaster(node_id)
    nmt.network = shared.network
    nmt.send_command(NmtCommand.RESET_COMMUNICATION)  # the pending node ID becomes active
    if not answers_at(shared, new_node_id, address.serial, timeout_s):
        raise LssFailedError(
            f"serial {address.serial}: node {new_node_id} was stored, but the valve does not "
            f"answer as can:{new_node_id} within {timeout_s:g} s: search the bus",
            "lost",
        )
    return address.serial

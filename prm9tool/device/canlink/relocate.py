"""Finding the valve again after a restart that moves it (node ID or bit rate, manual §7.3.1).

Node ID and bit rate take effect at power-up, so an NMT reset node may bring the valve back at
another address: with the node-ID switch at 0 (table 7-17) its stored NODEID and BITRATE
(0x2030/1, 0x2030/2, this project's objects) decide; at 1 (LSS) the node ID an LSS master
stored (it stays where it is) and the bus's bit rate;
at 2…F the switches, read at power-up. Before the reset :func:`predict` reads the switch
positions and those objects (the working values, which the store made the stored ones) and
works out where the valve will answer (``catalogue.canopen_switches.effective``, the rule the
emulated firmware runs).

After the reset the session (``CanopenSession.restart``) waits for the boot-up at the old and
the predicted node ID. When the bit rate changes it moves the tool's bus first — where it can:
python-can sets the bit rate when it opens most adapters, but not a SocketCAN interface (the
system sets it: ``ip link``), and not while other connections of this program share the bus.
Where it cannot, or where nothing can be predicted (a valve without this project's objects, the
switches turned by hand) and the valve does not come back, :class:`ValveMovedError` says
exactly where the valve is, or how to find it.
"""

from __future__ import annotations

import time
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Protocol

from prm9tool.catalogue.canopen_switches import effective, format_bitrate
from prm9tool.device.session import NotAvailableError
from prm9tool.errors import CommunicationError, DeviceTimeoutError
from prm9tool.messages import QT_TRANSLATE_NOOP

if TYPE_CHECKING:
    from prm9tool.device.canlink.bus import CanNetwork, CanOptions
    from prm9tool.device.canlink.sdo import SdoChannel

LSS_POSITION = 1  # node-ID switch: LSS and automatic bit rate (table 7-17)
SETTINGS = ("SWBAUD", "SWNODE", "NODEID", "BITRATE", "CANTERM")  # effective()'s arguments
FIXED_BITRATE = frozenset({"socketcan"})  # the system sets the bit rate, not python-can


class ValveMovedError(CommunicationError):
    """The valve restarted where this session cannot follow it (the message says where)."""

    summary = QT_TRANSLATE_NOOP(
        "Errors", "The valve restarted at another address or bit rate: go online with it there."
    )


@dataclass(frozen=True)
class Whereabouts:
    """Where a valve answers after its next power-up."""

    can_enabled: bool
    node_id: int | None
    bitrate: int | None  # bit/s; None: automatic bit-rate detection (LSS)
    switches_decide: bool  # node-ID switch at 2…F

    def describe(self) -> str:
        """``node 15, 250 kbit/s``."""
        rate = format_bitrate(self.bitrate // 1000) if self.bitrate else "the bus's bit rate"
        return f"node {self.node_id}, {rate}"


class _Settled(Protocol):
    """What :func:`predict` reads of a CANopen session (``CanopenSession``, which calls it:
    typed by what it needs, relocate stays below the session)."""

    node_id: int

    def read_many(self, mnemonics: Sequence[str]) -> Mapping[str, int | str]: ...


def predict(session: _Settled) -> Whereabouts | None:
    """Where the valve will answer after a restart (None: its objects do not tell)."""
    try:
        values = session.read_many(list(SETTINGS))
    except NotAvailableError:
        return None
    if any(m not in values for m in SETTINGS):
        return None
    raw = [int(values[m]) for m in SETTINGS]
    after = effective(*raw)
    if after.can_enabled and raw[1] == LSS_POSITION:
        # LSS: the node ID an LSS master stored, which the valve runs at now (CiA 305); the
        # bus's bit rate. NODEID/BITRATE do not apply: it stays where it is.
        return Whereabouts(True, session.node_id, None, True)
    rate = after.bitrate_kbit * 1000 if after.bitrate_kbit else None
    return Whereabouts(after.can_enabled, after.node_id, rate, raw[1] >= 2)


def bitrate_moves(options: CanOptions, after: Whereabouts | None) -> bool:
    """True when the valve comes back at a bit rate other than the bus's (as far as known)."""
    return (
        after is not None
        and after.bitrate is not None
        and options.bitrate is not None
        and after.bitrate != options.bitrate
    )


def why_not_follow(options: CanOptions, users: int) -> str:
    """Why the tool cannot move its bus to another bit rate ("" when it can)."""
    if options.interface in FIXED_BITRATE:
        return f"prm9tool cannot change the bit rate of a {options.interface} interface"
    if users > 1:
        return "other connections of prm9tool use this bus at its bit rate"
    return ""


def moved_error(options: CanOptions, after: Whereabouts, reason: str) -> ValveMovedError:
    """What to do to reach a valve that restarted at ``after`` on a bus the tool cannot move."""
    assert after.bitrate is not None
    kbit = format_bitrate(after.bitrate // 1000)
    how = ""
    if options.interface == "socketcan":
        ch = options.channel
        how = (
            f" (sudo ip link set {ch} down && sudo ip link set {ch} up type can bitrate "
            f"{after.bitrate})"
        )
    return ValveMovedError(
        f"the valve restarted at {after.describe()} and {reason}: set the adapter to {kbit}{how}, "
        f"then go online with can:{after.node_id} (Communication → CAN bus, bit rate {kbit})"
    )


def lost_error(node_id: int, after: Whereabouts | None, timeout_s: float) -> ValveMovedError:
    """No boot-up where the valve was expected; what the user can do."""
    if after is not None and not after.can_enabled:
        return ValveMovedError(
            f"node {node_id}: the valve restarted with CANopen switched off (interface switch at "
            "0 or 1, manual table 7-17): set the switch to the bit rate and power the valve up "
            "again, or reach it over USB"
        )
    if after is None:
        where = (
            "its objects do not tell its node ID and bit rate after a restart: if they were "
            "changed, search the bus (Communication → CAN bus) at the bit rate the interface "
            "switch sets (table 7-17)"
        )
    elif after.switches_decide:
        where = (
            f"the rotary switches decide ({after.describe()}): if they were turned, search the "
            "bus (Communication → CAN bus) at the bit rate the interface switch now sets"
        )
    else:
        where = (
            f"it was expected at {after.describe()}; if the change was not stored it is still at "
            f"node {node_id}: search the bus (Communication → CAN bus)"
        )
    return ValveMovedError(
        f"node {node_id}: no boot-up within {timeout_s:g} s after the reset; {where}"
    )


def await_boot_up(
    shared: CanNetwork, boot_ups: dict[int, int], after: Whereabouts | None, timeout_s: float
) -> int:
    """The node of ``boot_ups`` (node → boot-ups counted before the reset) that booted again;
    ValveMovedError when none did in time (the first node is the one reset)."""
    deadline = time.monotonic() + timeout_s
    while True:
        for node, count in boot_ups.items():
            if shared.node_seen(node).boot_ups != count:
                return node
        if time.monotonic() > deadline:
            raise lost_error(next(iter(boot_ups)), after, timeout_s)
        time.sleep(0.02)


def await_answer(sdo: SdoChannel, old: int, after: Whereabouts, timeout_s: float) -> None:
    """Ask ``sdo``'s node until it answers (its boot-up went out before the bus moved)."""
    deadline = time.monotonic() + timeout_s
    while True:
        try:
            sdo.upload(0x1000, 0, 0.1)
            return
        except DeviceTimeoutError:
            if time.monotonic() > deadline:
                raise lost_error(old, after, timeout_s) from None

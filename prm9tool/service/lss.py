"""LSS commissioning once, for every front door: Fastscan, node-ID assignment (stored),
renumbering a configured valve, the bus's bit rate found by listening and changed by LSS.

Valves whose node-ID switch is at position 1 leave their node ID to the bus (manual table
7-17); CiA 305 gives it. The command line (``--lss-scan``, ``--lss-assign``,
``--find-bitrate``: ``cli/lss.py``), the CAN bus window (``online/lss_commissioning.py`` runs
these off the GUI thread) and scripts (:func:`prm9tool.api.lss_scan`, ``lss_assign``,
``find_bitrate``) call the functions here, so each refusal has the same words at every door.
The protocol is the device layer's LSS master (``device/canlink/lss.py``). Blocking; no Qt.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Mapping, Sequence
from contextlib import contextmanager
from dataclasses import dataclass
from typing import TYPE_CHECKING

from prm9tool.device.canlink.bus import CanOptions
from prm9tool.device.canlink.lss import LssAddress, LssFailedError

if TYPE_CHECKING:
    from prm9tool.device.canlink.bitrate import RateHeard
    from prm9tool.device.canlink.bus import CanNetwork
    from prm9tool.device.canlink.lss import LssMasterLink

__all__ = [
    "ANSWER_TIMEOUT_S",
    "Assigned",
    "FoundRate",
    "LssDevice",
    "LssFailedError",
    "RateChanged",
    "Renumbered",
    "assign",
    "change_rate",
    "find_bitrate",
    "nothing_found",
    "plan_problem",
    "renumber",
    "scan",
]

Bus = CanOptions | Mapping[str, object]
SWITCH_DELAY_MS = 200  # decision: CiA 305 activate bit timing's switch delay
ANSWER_TIMEOUT_S = 10.0  # release -> boot-up at the new node ID (as after NMT reset node)


@dataclass(frozen=True)
class LssDevice:
    """A device without a node ID as Fastscan found it (its identity object 0x1018)."""

    vendor: int
    product: int
    revision: int
    serial: int
    is_prm9: bool

    def to_dict(self) -> dict[str, object]:
        """What ``--lss-scan --json`` prints for it."""
        return {
            "serial": self.serial,
            "vendor": self.vendor,
            "product": self.product,
            "revision": self.revision,
            "prm9": self.is_prm9,
        }

    def describe(self) -> str:
        """One line of ``--lss-scan``."""
        return (
            f"serial {self.serial}\t{'PRM9' if self.is_prm9 else 'not a PRM9'}\t"
            f"vendor 0x{self.vendor:X}\tproduct 0x{self.product:X}\t"
            f"revision 0x{self.revision:X}"
        )


@dataclass(frozen=True)
class Assigned:
    """A device that answers at the node ID it was given (stored)."""

    device: LssDevice
    node_id: int

    @property
    def device_id(self) -> str:
        """``can:NODE``."""
        return f"can:{self.node_id}"

    def to_dict(self) -> dict[str, object]:
        """The serial, the node ID and the device ID to open it with."""
        return {"serial": self.device.serial, "node_id": self.node_id, "device": self.device_id}


@dataclass(frozen=True)
class FoundRate:
    """The bus's bit rate found by listening, and the nodes heard at it."""

    bitrate: int
    nodes: tuple[int, ...]


@dataclass(frozen=True)
class Renumbered:
    """A configured valve that answers at the node ID LSS gave it (stored)."""

    serial: int
    old_node_id: int
    node_id: int

    @property
    def device_id(self) -> str:
        """``can:NODE``."""
        return f"can:{self.node_id}"


@dataclass(frozen=True)
class RateChanged:
    """The LSS devices of a bus switched to ``bitrate`` (stored)."""

    bitrate: int
    devices: int


def options(bus: Bus) -> CanOptions:
    """The bus as options: given as such, or as the GUI remembers it (a mapping)."""
    return bus if isinstance(bus, CanOptions) else CanOptions.from_mapping(bus)


@contextmanager
def _bus(bus: Bus) -> Iterator[CanNetwork]:
    from prm9tool.device.canlink.bus import acquire, release

    shared = acquire(options(bus))  # the master shared with any session on that bus
    try:
        yield shared
    finally:
        release(shared)


def nothing_found(bus: Bus) -> str:
    """What an empty Fastscan means and what to check."""
    return (
        f"no device without a node ID answered on {options(bus)}: every device on the bus has "
        "a node ID (--list-devices lists them), or none is at node-ID switch 1, or the bus runs "
        "at another bit rate than the adapter (--find-bitrate)"
    )


def scan(bus: Bus) -> list[LssDevice]:
    """Every device without a node ID on ``bus`` (LSS Fastscan)."""
    from prm9tool.device.canlink.lss import LssMasterLink

    with _bus(bus) as shared:
        found = LssMasterLink(shared).scan()
    return [_device(a) for a in found]


def plan_problem(plan: Sequence[tuple[int, int]]) -> str | None:
    """What is wrong with ``(serial, node ID)`` pairs before the bus is asked (None: fine)."""
    for serial, node in plan:
        if not 1 <= node <= 127:
            return f"--lss-assign {serial}={node}: CANopen node IDs are 1…127"
    serials, nodes = [s for s, _ in plan], [n for _, n in plan]
    twice = next((s for s in serials if serials.count(s) > 1), None)
    if twice is not None:
        return f"--lss-assign: serial {twice} is given twice"
    both = next((n for n in nodes if nodes.count(n) > 1), None)
    if both is not None:
        return f"--lss-assign: node ID {both} is given to two valves"
    return None


def assign(
    bus: Bus,
    plan: Sequence[tuple[LssDevice | int, int]],
    done: Callable[[Assigned], None] | None = None,
) -> list[Assigned]:
    """Give each device of ``plan`` (a Fastscan's device or its serial) its node ID and store
    it, one after the other; returns once each answers there (``done`` hears each).

    Before anything is sent: LssFailedError ``taken`` when a device answers at one of the node
    IDs (with the first free ones), ``none`` when no device without a node ID has a serial.
    A device that does not answer at its new node ID: ``lost``; a failure after some got
    theirs names them ("given before")."""
    from prm9tool.device.canlink.lss import LssMasterLink
    from prm9tool.device.canlink.lss_nodes import answers_at

    given: list[Assigned] = []
    with _bus(bus) as shared:
        for _device_or_serial, node_id in plan:
            _check_free(shared, node_id)
        link = LssMasterLink(shared)
        devices = _resolve(link, [d for d, _ in plan])
        for device, (_, node_id) in zip(devices, plan, strict=True):
            try:
                address = LssAddress(device.vendor, device.product, device.revision, device.serial)
                link.assign(address, node_id)
                if not answers_at(shared, node_id, device.serial, ANSWER_TIMEOUT_S):
                    raise LssFailedError(
                        f"serial {device.serial}: node {node_id} was stored, but the valve does "
                        f"not answer as can:{node_id} within {ANSWER_TIMEOUT_S:g} s: search the "
                        f"bus (--list-devices {_bus_args(options(bus))})",
                        "lost",
                    )
            except LssFailedError as exc:
                before = ", ".join(f"serial {a.device.serial} → {a.device_id}" for a in given)
                if before:
                    raise LssFailedError(f"{exc} (given before: {before})", exc.kind) from exc
                raise
            given.append(Assigned(device, node_id))
            if done is not None:
                done(given[-1])
    return given


def _check_free(shared: CanNetwork, node_id: int) -> None:
    from prm9tool.device.canlink.discovery import scan as scan_nodes
    from prm9tool.device.canlink.lss_nodes import check_free, first_free

    try:
        check_free(shared, node_id)
    except LssFailedError as exc:
        taken = {info.node_id for info in scan_nodes(shared)} | {node_id}
        free = ", ".join(map(str, first_free(taken, 3)))
        raise LssFailedError(f"{exc} (free: {free}, …)", exc.kind) from exc


def _resolve(link: LssMasterLink, wanted: Sequence[LssDevice | int]) -> list[LssDevice]:
    """The devices of ``wanted``; serials are looked up by Fastscan."""
    if all(isinstance(w, LssDevice) for w in wanted):
        return [w for w in wanted if isinstance(w, LssDevice)]
    found = {a.serial: _device(a) for a in link.scan()}
    missing = [w for w in wanted if isinstance(w, int) and w not in found]
    if missing:
        listed = ", ".join(str(s) for s in sorted(found)) or "none"
        raise LssFailedError(
            f"no device without a node ID has serial {missing[0]} (devices without a node ID: "
            f"{listed}); nothing was changed",
            "none",
        )
    return [w if isinstance(w, LssDevice) else found[w] for w in wanted]


def renumber(bus: Bus, node_id: int, new_node_id: int) -> Renumbered:
    """The valve at ``node_id`` (switch 1) gets ``new_node_id`` by LSS."""
    from prm9tool.device.canlink.lss_nodes import renumber as lss_renumber

    with _bus(bus) as shared:
        serial = lss_renumber(shared, node_id, new_node_id, ANSWER_TIMEOUT_S)
    return Renumbered(serial, node_id, new_node_id)


def change_rate(bus: Bus, bitrate: int) -> RateChanged:
    """Every LSS device of ``bus`` goes to ``bitrate`` by LSS; the tool's bus at the old rate
    is released, so the next search opens the adapter at the new one."""
    from prm9tool.catalogue.canopen_switches import lss_bit_timing
    from prm9tool.device.canlink.lss import LssMasterLink

    index = lss_bit_timing(bitrate // 1000)
    if index is None:
        raise LssFailedError(f"a PRM9 does not run at {bitrate} bit/s", "refused")
    with _bus(bus) as shared:
        devices = LssMasterLink(shared).change_bus_bit_timing(index, SWITCH_DELAY_MS)
    return RateChanged(bitrate, devices)


def find_bitrate(bus: Bus, progress: Callable[[RateHeard], None] | None = None) -> FoundRate:
    """Listen-only at each rate a PRM9 supports (never transmits); ``progress`` hears each
    rate as it is listened at. BitrateNotFoundError, NoListenOnlyError say why not."""
    from dataclasses import replace

    from prm9tool.device.canlink import bitrate as rates

    rate, heard = rates.find_bitrate(
        replace(options(bus), bitrate=None), rates.LISTEN_S, progress=progress
    )
    nodes = next(h.nodes for h in heard if h.bitrate == rate)
    return FoundRate(rate, tuple(sorted(nodes)))


def _device(address: LssAddress) -> LssDevice:
    a = address
    return LssDevice(a.vendor, a.product, a.revision, a.serial, a.is_prm9)


def _bus_args(opts: CanOptions) -> str:
    return f"--can-interface {opts.interface} --can-channel {opts.channel}"

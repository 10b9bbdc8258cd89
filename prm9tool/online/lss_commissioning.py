"""LSS commissioning for the CAN bus dialog: Fastscan, node-ID assignment and finding the bit
rate (listen-only), off the GUI thread.

:class:`LssCommissioning` runs one LSS job at a time (``prm9tool.device.canlink.lss``) in a
thread of its own on the bus the dialog names (the master shared with the live network view
and any session on that bus) and delivers the outcome on the GUI thread through a queued
signal. The dialog sees plain :class:`LssDevice` records, never the device layer. QtCore only.
"""

from __future__ import annotations

import contextlib
import logging
import threading
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

from PySide6.QtCore import QObject, Signal

from prm9tool.errors import Prm9Error
from prm9tool.translate import error_text

log = logging.getLogger(__name__)
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


@dataclass(frozen=True)
class Assigned:
    """A device that answers at the node ID it was given (stored)."""

    device: LssDevice
    node_id: int

    @property
    def device_id(self) -> str:
        """``can:NODE``."""
        return f"can:{self.node_id}"


@dataclass(frozen=True)
class FoundRate:
    """The bus's bit rate found by listening, and the nodes heard at it."""

    bitrate: int
    nodes: tuple[int, ...]


def assign_all_on_bus(
    bus: Mapping[str, object], plan: list[tuple[LssDevice, int]]
) -> list[Assigned]:
    """Every device of ``plan`` gets its node ID, one after the other (blocking); on a failure
    the error names the valves that got theirs already."""
    from prm9tool.device.canlink.lss import LssFailedError

    done: list[Assigned] = []
    for device, node_id in plan:
        try:
            done.append(assign_on_bus(bus, device, node_id))
        except LssFailedError as exc:
            given = ", ".join(f"serial {a.device.serial} → {a.device_id}" for a in done)
            if given:
                raise LssFailedError(f"{exc} (given before: {given})", exc.kind) from exc
            raise
    return done


def find_bitrate_on_bus(bus: Mapping[str, object]) -> FoundRate:
    """Listen-only at each rate a PRM9 supports (blocking; never transmits)."""
    from prm9tool.device.canlink.bitrate import find_bitrate

    rate, heard = find_bitrate(_options({**bus, "bitrate": None}))
    nodes = next(h.nodes for h in heard if h.bitrate == rate)
    return FoundRate(rate, tuple(sorted(nodes)))


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


def renumber_on_bus(bus: Mapping[str, object], node_id: int, new_node_id: int) -> Renumbered:
    """The valve at ``node_id`` (switch 1) gets ``new_node_id`` by LSS (blocking)."""
    from prm9tool.device.canlink.bus import acquire, release
    from prm9tool.device.canlink.lss_nodes import renumber

    shared = acquire(_options(bus))
    try:
        serial = renumber(shared, node_id, new_node_id, ANSWER_TIMEOUT_S)
    finally:
        release(shared)
    return Renumbered(serial, node_id, new_node_id)


@dataclass(frozen=True)
class RateChanged:
    """The LSS devices of a bus switched to ``bitrate`` (stored)."""

    bitrate: int
    devices: int


def change_rate_on_bus(bus: Mapping[str, object], bitrate: int) -> RateChanged:
    """Every LSS device of ``bus`` goes to ``bitrate`` by LSS (blocking); the tool's bus at
    the old rate is released, so the next search opens the adapter at the new one."""
    from prm9tool.catalogue.canopen_switches import lss_bit_timing
    from prm9tool.device.canlink.bus import acquire, release
    from prm9tool.device.canlink.lss import LssFailedError, LssMasterLink

    index = lss_bit_timing(bitrate // 1000)
    if index is None:
        raise LssFailedError(f"a PRM9 does not run at {bitrate} bit/s", "refused")
    shared = acquire(_options(bus))
    try:
        devices = LssMasterLink(shared).change_bus_bit_timing(index, SWITCH_DELAY_MS)
    finally:
        release(shared)
    return RateChanged(bitrate, devices)


def _options(bus: Mapping[str, object]) -> Any:
    from prm9tool.device.canlink.bus import CanOptions

    return CanOptions.from_mapping(bus)


def scan_bus(bus: Mapping[str, object]) -> list[LssDevice]:
    """Every device without a node ID on ``bus`` (blocking; the worker thread's job)."""
    from prm9tool.device.canlink.bus import acquire, release
    from prm9tool.device.canlink.lss import LssMasterLink

    shared = acquire(_options(bus))
    try:
        found = LssMasterLink(shared).scan()
    finally:
        release(shared)
    return [LssDevice(a.vendor, a.product, a.revision, a.serial, a.is_prm9) for a in found]


def assign_on_bus(bus: Mapping[str, object], device: LssDevice, node_id: int) -> Assigned:
    """Give ``device`` ``node_id`` and store it, refusing an ID that answers; returns once the
    device answers there (blocking)."""
    from prm9tool.device.canlink.bus import acquire, release
    from prm9tool.device.canlink.lss import LssAddress, LssFailedError, LssMasterLink
    from prm9tool.device.canlink.lss_nodes import answers_at, check_free

    shared = acquire(_options(bus))
    try:
        check_free(shared, node_id)
        address = LssAddress(device.vendor, device.product, device.revision, device.serial)
        LssMasterLink(shared).assign(address, node_id)
        if not answers_at(shared, node_id, device.serial, ANSWER_TIMEOUT_S):
            raise LssFailedError(
                f"serial {device.serial}: node {node_id} was stored, but the valve does not "
                f"answer as can:{node_id} within {ANSWER_TIMEOUT_S:g} s: search the bus",
                "lost",
            )
    finally:
        release(shared)
    return Assigned(device, node_id)


class LssCommissioning(QObject):
    """One LSS job at a time off the GUI thread; outcomes on the GUI thread."""

    scanned = Signal(list)  # [LssDevice]
    bitrate_found = Signal(object)  # FoundRate
    renumbered = Signal(object)  # Renumbered
    assigned_all = Signal(list)  # [Assigned]
    rate_changed = Signal(object)  # RateChanged
    assigned = Signal(object)  # Assigned
    failed = Signal(str, str)  # the job ("scan", "assign", "bitrate"), why (program language)
    _deliver = Signal(str, object, object)

    def __init__(
        self,
        scan: Callable[[Mapping[str, object]], list[LssDevice]] = scan_bus,
        assign: Callable[[Mapping[str, object], LssDevice, int], Assigned] = assign_on_bus,
        find: Callable[[Mapping[str, object]], FoundRate] = find_bitrate_on_bus,
        renumber: Callable[[Mapping[str, object], int, int], Renumbered] = renumber_on_bus,
        assign_all: Callable[
            [Mapping[str, object], list[tuple[LssDevice, int]]], list[Assigned]
        ] = assign_all_on_bus,
        change_rate: Callable[[Mapping[str, object], int], RateChanged] = change_rate_on_bus,
        parent: QObject | None = None,
    ) -> None:
        super().__init__(parent)
        self._scan, self._assign, self._find = scan, assign, find
        self._renumber, self._assign_all = renumber, assign_all
        self._change_rate = change_rate
        self._thread: threading.Thread | None = None
        self._deliver.connect(self._on_delivered)  # queued: emitted from the job's thread

    @property
    def busy(self) -> bool:
        """True while a job runs."""
        return self._thread is not None

    def scan(self, bus: Mapping[str, object]) -> None:
        """Fastscan ``bus``: :attr:`scanned` or :attr:`failed` follows."""
        self._start("scan", self.scanned, lambda: self._scan(dict(bus)))

    def assign(self, bus: Mapping[str, object], device: LssDevice, node_id: int) -> None:
        """Give ``device`` ``node_id``: :attr:`assigned` or :attr:`failed` follows."""
        self._start("assign", self.assigned, lambda: self._assign(dict(bus), device, node_id))

    def assign_all(self, bus: Mapping[str, object], plan: list[tuple[LssDevice, int]]) -> None:
        """Give each device of ``plan`` its node ID: :attr:`assigned_all` or :attr:`failed`."""
        self._start("assign", self.assigned_all, lambda: self._assign_all(dict(bus), list(plan)))

    def renumber(self, bus: Mapping[str, object], node_id: int, new_node_id: int) -> None:
        """Move the valve at ``node_id`` to ``new_node_id`` by LSS: :attr:`renumbered` or
        :attr:`failed` follows."""
        self._start(
            "renumber", self.renumbered, lambda: self._renumber(dict(bus), node_id, new_node_id)
        )

    def change_rate(self, bus: Mapping[str, object], bitrate: int) -> None:
        """Every LSS device of ``bus`` to ``bitrate``: :attr:`rate_changed` or :attr:`failed`."""
        self._start("rate", self.rate_changed, lambda: self._change_rate(dict(bus), bitrate))

    def find_bitrate(self, bus: Mapping[str, object]) -> None:
        """Listen for the bus's bit rate: :attr:`bitrate_found` or :attr:`failed` follows."""
        self._start("bitrate", self.bitrate_found, lambda: self._find(dict(bus)))

    def _start(self, name: str, done: Any, job: Callable[[], object]) -> None:
        if self._thread is not None:
            return
        self._thread = threading.Thread(
            target=self._run, args=(name, done, job), name="lss-commissioning", daemon=True
        )
        self._thread.start()

    def _run(self, name: str, done: Any, job: Callable[[], object]) -> None:
        try:
            result: object = job()
        except Prm9Error as exc:
            result = exc
        except Exception as exc:  # a bug must not pass silently, nor hang the dialog
            log.exception("LSS job")
            result = exc
        with contextlib.suppress(RuntimeError):  # deleted meanwhile
            self._deliver.emit(name, done, result)

    def _on_delivered(self, name: str, done: Any, result: object) -> None:
        self._thread = None
        if isinstance(result, Exception):
            self.failed.emit(name, error_text(result))
        else:
            done.emit(result)

"""LSS commissioning for the CAN bus dialog: Fastscan, node-ID assignment and finding the bit
rate (listen-only), off the GUI thread.

:class:`LssCommissioning` runs one LSS job at a time — the valve service's
(``prm9tool.service.lss``, the same operations as ``--lss-scan``/``--lss-assign`` and the API's
``lss_scan``/``lss_assign``) — in a thread of its own on the bus the dialog names (the master
shared with the live network view and any session on that bus) and delivers the outcome on the
GUI thread through a queued signal. The dialog sees plain :class:`LssDevice` records, never the
device layer. QtCore only.
"""

from __future__ import annotations

import contextlib
import logging
import threading
from collections.abc import Callable, Mapping
from typing import Any

from PySide6.QtCore import QObject, Signal

from prm9tool.errors import Prm9Error
from prm9tool.service import lss
from prm9tool.service.lss import Assigned, FoundRate, LssDevice, RateChanged, Renumbered
from prm9tool.translate import error_text

__all__ = ["Assigned", "FoundRate", "LssCommissioning", "LssDevice", "RateChanged", "Renumbered"]

log = logging.getLogger(__name__)


def scan_bus(bus: Mapping[str, object]) -> list[LssDevice]:
    """Every device without a node ID on ``bus`` (the worker thread's job)."""
    return lss.scan(bus)


def assign_on_bus(bus: Mapping[str, object], device: LssDevice, node_id: int) -> Assigned:
    """Give ``device`` ``node_id`` and store it (the service's one assignment)."""
    return lss.assign(bus, [(device, node_id)])[0]


def assign_all_on_bus(
    bus: Mapping[str, object], plan: list[tuple[LssDevice, int]]
) -> list[Assigned]:
    """Every device of ``plan`` gets its node ID, one after the other."""
    return lss.assign(bus, list(plan))


def find_bitrate_on_bus(bus: Mapping[str, object]) -> FoundRate:
    """Listen-only at each rate a PRM9 supports (never transmits)."""
    return lss.find_bitrate(bus)


def renumber_on_bus(bus: Mapping[str, object], node_id: int, new_node_id: int) -> Renumbered:
    """The valve at ``node_id`` (switch 1) gets ``new_node_id`` by LSS."""
    return lss.renumber(bus, node_id, new_node_id)


def change_rate_on_bus(bus: Mapping[str, object], bitrate: int) -> RateChanged:
    """Every LSS device of ``bus`` goes to ``bitrate`` by LSS."""
    return lss.change_rate(bus, bitrate)


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

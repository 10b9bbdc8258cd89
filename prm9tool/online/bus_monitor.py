"""The live network view's feed: the nodes of a CAN bus as they tell about themselves, delivered
to the GUI thread a few times a second while a view shows them.

:class:`BusMonitor` opens the bus (``prm9tool.device.canlink.watch.BusWatch``) in a thread of
its own — opening an adapter may block — and emits :attr:`BusMonitor.nodes_heard` every
:data:`PERIOD_S` with one ``NodeHeard`` per node (NMT state, heartbeat age, last EMCY, booted,
silent), so the ages tick while nothing arrives. Nothing is sent on the bus. QtCore only.
"""

from __future__ import annotations

import contextlib
import logging
import threading
from collections.abc import Callable, Mapping, Sequence
from typing import TYPE_CHECKING, Protocol

from PySide6.QtCore import QObject, Signal

from prm9tool.errors import Prm9Error
from prm9tool.translate import error_text

if TYPE_CHECKING:
    from prm9tool.device.canlink.watch import BusWatch

log = logging.getLogger(__name__)
PERIOD_S = 0.25


def open_watch(bus: Mapping[str, object]) -> BusWatch:
    """A ``BusWatch`` on the bus ``bus`` (``interface``, ``channel``, ``bitrate``)."""
    from prm9tool.device.canlink.bus import CanOptions
    from prm9tool.device.canlink.watch import BusWatch

    return BusWatch(CanOptions.from_mapping(bus))


class HeardNode(Protocol):
    """What a view shows of one node (``prm9tool.device.canlink.watch.NodeHeard``; read-only)."""

    @property
    def node_id(self) -> int:
        """The node ID (1 … 127)."""
        ...

    @property
    def nmt_state(self) -> str | None:
        """The NMT state its heartbeat tells (None: no heartbeat heard)."""
        ...

    @property
    def heartbeat_age_s(self) -> float | None:
        """Seconds since its last heartbeat (None: none heard)."""
        ...

    @property
    def last_emcy(self) -> str:
        """Its last emergency message ("" none heard)."""
        ...

    @property
    def boot_up_age_s(self) -> float | None:
        """Seconds since its last boot-up frame (None: none heard)."""
        ...

    @property
    def silent(self) -> bool:
        """True when its heartbeats stopped coming (several periods missed)."""
        ...

    @property
    def device_id(self) -> str:
        """``can:NODE``."""
        ...


class NodeWatch(Protocol):
    """An open bus the monitor asks for its nodes (``BusWatch``; a fake in a test)."""

    def nodes(self) -> Sequence[HeardNode]:
        """Every node heard so far, by node ID."""
        ...

    def close(self) -> None:
        """Let the bus go."""
        ...


Watcher = Callable[[Mapping[str, object]], NodeWatch]  # bus dict -> the bus, open


class BusMonitor(QObject):
    """Feeds a network view while it is open (see the module docstring)."""

    nodes_heard = Signal(list)  # [HeardNode], by node ID
    failed = Signal(str)  # the bus could not be opened (the reason, in the program language)
    _deliver = Signal(object)

    def __init__(self, watcher: Watcher = open_watch, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self._watcher = watcher
        self._stop: threading.Event | None = None
        self._thread: threading.Thread | None = None
        self._deliver.connect(self._on_delivered)  # queued: emitted from the watch thread

    @property
    def running(self) -> bool:
        """True while a bus is watched."""
        return self._thread is not None

    def start(self, bus: Mapping[str, object]) -> None:
        """Watch ``bus`` (the one watched before is let go)."""
        self.stop()
        stop = threading.Event()
        self._stop = stop
        self._thread = threading.Thread(
            target=self._run, args=(dict(bus), stop), name="can-bus-monitor", daemon=True
        )
        self._thread.start()

    def stop(self) -> None:
        """Stop watching; the bus is let go in the watch thread (no wait on the GUI thread)."""
        if self._stop is not None:
            self._stop.set()
        self._stop, self._thread = None, None

    def _run(self, bus: dict[str, object], stop: threading.Event) -> None:
        try:
            watch = self._watcher(bus)
        except Prm9Error as exc:
            self._post(exc)
            return
        try:
            while not stop.is_set():
                self._post(watch.nodes())
                stop.wait(PERIOD_S)
        except Exception:  # a bug must not pass silently, nor kill the view
            log.exception("watching the CAN bus")
        finally:
            watch.close()

    def _post(self, payload: object) -> None:
        with contextlib.suppress(RuntimeError):  # the monitor was deleted meanwhile
            self._deliver.emit(payload)

    def _on_delivered(self, payload: object) -> None:
        if self._thread is None:
            return  # stopped meanwhile: a late delivery
        if isinstance(payload, Exception):
            self.failed.emit(error_text(payload))
            self.stop()
        else:
            self.nodes_heard.emit(payload)

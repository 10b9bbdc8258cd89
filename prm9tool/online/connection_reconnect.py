"""The connection's side of finding a lost valve again: runs the :class:`Reconnector` loop
(service/reconnect.py) for a :class:`~prm9tool.online.connection.ValveConnection`, reopens the
valve it finds in the connection's worker and checks the serial number the valve tells.

Everything here runs on the GUI thread except the loop (its own thread) and the reopening (the
worker); their results come back through the connection's ``_post``. A result of a loop that
was stopped meanwhile (the user went online or offline himself) is dropped.
"""

from __future__ import annotations

import logging
from collections.abc import Callable, Mapping, Sequence
from typing import TYPE_CHECKING, Any, Protocol

from prm9tool.online.connection_worker import Job
from prm9tool.service.reconnect import MAX_PAUSE_S, LostValve, Reconnector

if TYPE_CHECKING:
    from PySide6.QtCore import SignalInstance

    from prm9tool.online.connection_worker import ConnectionWorker


log = logging.getLogger("prm9tool.online.connection")


class ReconnectHost(Protocol):
    """What the loop needs of its connection (``ValveConnection`` fits it:
    online/conformance.py)."""

    @property
    def _lister(self) -> Callable[..., Sequence[Any]]: ...
    @property
    def _worker(self) -> ConnectionWorker: ...

    @property
    def is_online(self) -> bool: ...
    @property
    def is_busy(self) -> bool: ...
    @property
    def reconnecting(self) -> SignalInstance: ...
    @property
    def reconnect_ended(self) -> SignalInstance: ...
    @property
    def other_valve(self) -> SignalInstance: ...

    def _post(self, action: Callable[[], None]) -> None: ...
    def _submit(self, job: Job) -> None: ...
    def _set_busy(self, delta: int) -> None: ...
    def _on_reopened(self, info: object) -> None: ...


class ReconnectLink:
    """The loop of one connection: :meth:`prepare` when the link broke (before the connection
    reports it offline, so that its views know it is looked for), :meth:`go` after."""

    def __init__(self, connection: ReconnectHost) -> None:
        self._conn = connection
        self.looking: Reconnector | None = None

    def stop(self) -> None:
        """Stop looking (``reconnect_ended`` follows if it was looking)."""
        looking, self.looking = self.looking, None
        if looking is not None:
            looking.stop.set()
            self._conn.reconnect_ended.emit()

    def prepare(
        self, lost: LostValve, since: float | None = None, pause_first: bool = False
    ) -> None:
        """A loop for ``lost`` (not started yet); ``since``: when it was lost."""
        self.stop()
        conn, lister = self._conn, self._conn._lister

        def listing(emulators: Sequence[str], can: Mapping[str, object] | None) -> list[Any]:
            return list(lister(emulators) if can is None else lister(emulators, can))

        def current(action: Callable[[], None]) -> Callable[[], None]:
            return lambda: action() if self.looking is looking else None

        def other(entry: Any) -> None:
            conn._post(current(lambda: self._found_other(entry.serial, entry.device_id)))

        looking = Reconnector(
            lost,
            listing,
            lambda s: conn._post(current(lambda: conn.reconnecting.emit(s))),
            lambda entry: conn._post(current(lambda: self._reopen(entry))),
            other,
            since=since,
            first_pause_s=MAX_PAUSE_S if pause_first else 0.0,
        )
        self.looking = looking

    def go(self) -> None:
        """Start the prepared loop (``reconnecting`` says since when it looks)."""
        if self.looking is not None:
            self._conn.reconnecting.emit(self.looking.elapsed())
            self.looking.start()

    def _found_other(self, serial: int, device_id: str) -> None:
        looking = self.looking
        self.stop()
        if looking is not None:
            self._conn.other_valve.emit(looking.lost.serial, serial, device_id)

    def _reopen(self, entry: object) -> None:
        """Open the valve found again (worker); a failure keeps looking."""
        conn, looking = self._conn, self.looking
        if looking is None or conn.is_online or conn.is_busy:
            return
        worker = conn._worker
        worker.start()
        conn._set_busy(+1)

        def run(_session: object) -> object:
            try:
                info = worker.open(entry)
            except Exception as exc:  # not (yet) openable: it may be still starting up
                log.info("reopening the lost valve failed: %s", exc)
                worker.close()
                return exc
            if getattr(info, "serial", 0) != looking.lost.serial:
                worker.close()  # another valve answered: nothing is read or written
            return info

        def done(info: object) -> None:
            conn._set_busy(-1)
            if self.looking is not looking:  # the user decided meanwhile
                if not isinstance(info, Exception):
                    conn._submit(Job("offline", lambda _s: worker.close(), None, False,
                                     needs_session=False))  # fmt: skip
                return
            if isinstance(info, Exception):  # look again, after a pause
                self.looking = None
                self.prepare(looking.lost, looking.since, pause_first=True)
                self.go()
                return
            serial = getattr(info, "serial", 0)
            if serial != looking.lost.serial:  # the serial check: the worker closed it
                self._found_other(serial, getattr(info, "device_id", ""))
                return
            self.looking = None
            conn._on_reopened(info)

        conn._submit(Job("reconnect", run, done, False, needs_session=False))

"""The upload, once for every door: type check, rules, backup, the link's upload, history.

The GUI's worker (``ValveConnection.upload``), ``--batch`` (``cli/batch_upload.py``) and a
script's :meth:`Valve.upload <prm9tool.api.valve.Valve.upload>` call :func:`upload`; the link's
own transaction (write, read back and compare, store; CANopen's verify by restart) is
``ValveSession.upload`` in the device layer. No Qt.
"""

from __future__ import annotations

import threading
from collections.abc import Callable, Mapping
from pathlib import Path
from typing import TYPE_CHECKING

from prm9tool.catalogue.typekey import TypeKey
from prm9tool.device.upload_outcome import type_problem
from prm9tool.errors import FileFormatError, Prm9Error, TypeKeyError
from prm9tool.service.values import check_rules

if TYPE_CHECKING:
    from prm9tool.device.records import Progress, UploadResult, Value
    from prm9tool.device.session import ValveSession
    from prm9tool.service.history import HistoryHook

__all__ = ["BackupError", "check_type", "upload"]


class BackupError(Prm9Error):
    """The backup before the first upload could not be written: nothing was uploaded."""


def check_type(wanted: TypeKey, valve: TypeKey, force: bool, option: str) -> None:
    """TypeKeyError when a set for ``wanted`` must not go into a ``valve`` valve: another
    variant never, another type key of the same variant only with ``force`` (``option`` is
    how this door spells it: ``--force-type``, ``force_type=True``)."""
    problem = type_problem(wanted, valve, force, option)
    if problem is not None:
        raise TypeKeyError(problem)


def upload(
    session: ValveSession,
    values: Mapping[str, Value],
    *,
    history: HistoryHook | None = None,
    backup: bool = True,
    rules: bool = True,
    verify_by_restart: bool = False,
    progress: Progress | None = None,
    cancel: threading.Event | None = None,
    purpose: str = "",
    on_backup: Callable[[Path | None], None] | None = None,
) -> UploadResult:
    """Write ``values`` (raw), read every one back and compare, then store: transactional.

    ``rules``: first check the rules between parameters with the valve's caps (a set the
    valve would refuse to store: ValueRangeError, nothing sent). ``backup``: first save the
    valve's parameters as its backup file unless it has one (BackupError when it cannot be
    written, nothing uploaded); ``on_backup`` then gets the new file (None: the valve had
    one), before the first value is written. ``verify_by_restart``: after
    the store, restart the valve and read every value back (the hydraulics are off: the
    caller confirmed it; a link without the step ignores it). ``history``: the backup and the
    upload are recorded (a broken link too). A refused or differing value returns a result
    with ``stored`` False; a broken link raises the CommunicationError naming the step.
    """
    values = dict(values)
    if rules:
        check_rules(session, values)
    if backup:
        from prm9tool.files.backup import ensure_backup  # *.prm writing, only when needed

        if history is not None:  # the database opens (importing older backup files) before
            history.problem()  # this backup is written: it is recorded once, at every door
        try:
            path = ensure_backup(session, progress, cancel)
        except FileFormatError as exc:
            raise BackupError(
                f"the backup could not be written, nothing was uploaded: {exc}"
            ) from exc
        if path is not None and history is not None:
            history.backup(session, path)
        if on_backup is not None:
            on_backup(path)
    if verify_by_restart:
        session.verify_by_restart = True
    if history is None:
        return session.upload(values, progress, cancel)
    return history.upload(session, values, progress, cancel, purpose)

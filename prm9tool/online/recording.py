"""The GUI's history hook: what the connection's worker thread records, and how.

Runs in the worker thread beside the valve I/O, so a slow database never freezes the window.
Recording never raises: a record the database cannot take waits in the local queue (see
:mod:`prm9tool.history.recorder`), and a problem is handed to ``report`` (the connection shows
it). Whether an upload may start while the database is away is decided before the upload,
by the user (``ValveConnection.check_history``). QtCore-free.
"""

from __future__ import annotations

import threading
from collections.abc import Callable, Mapping
from pathlib import Path
from typing import TYPE_CHECKING

from prm9tool.catalogue import CATALOGUE
from prm9tool.errors import CommunicationError, FileFormatError, HistoryError
from prm9tool.history.recorder import Details, Recorder, make_entry

if TYPE_CHECKING:
    from prm9tool.characterize.run import Characterization
    from prm9tool.device.records import UploadResult
    from prm9tool.device.session import ValveSession

Raw = int | str
Progress = Callable[[int, int, str], None]


class HistoryHook:
    """Records the operations of one connection into the history: the GUI's, and a script's
    :class:`~prm9tool.api.valve.Valve` (``context``: details every record carries, e.g. the
    command that ran it; they win over an operation's own)."""

    def __init__(
        self, recorder: Recorder, report: Callable[[str], None], context: Details | None = None
    ) -> None:
        self.recorder, self._report = recorder, report
        self._context: Details = context or {}

    def problem(self) -> HistoryError | None:
        """Why the database cannot take records now (None: it can)."""
        return self.recorder.problem()

    def add(
        self,
        session: ValveSession,
        operation: str,
        outcome: str,
        parameters: Mapping[str, Raw] | None,
        details: Details | None = None,
        failed_step: str | None = None,
    ) -> None:
        """Record one operation on the session's valve; ``details``: a :class:`Details`
        (what the GUI's own jobs pass through ``ValveConnection.record`` is still a mapping)."""
        details = {**(details or {}), **self._context}
        try:
            status = self.recorder.record(
                session.info, operation, outcome, parameters, details, failed_step
            )
        except HistoryError as exc:
            self._report(str(exc))
            return
        if status == "queued":
            self._report(
                f"the history database cannot be reached; the record waits in {self.recorder.queue}"
            )

    def download(self, session: ValveSession, values: Mapping[str, Raw], purpose: str) -> None:
        """Record a download (also the one that compares document and valve)."""
        self.add(session, "download", "ok", values, {"purpose": purpose} if purpose else {})

    def download_later(
        self, session: ValveSession, values: Mapping[str, Raw], purpose: str
    ) -> None:
        """:meth:`download`, made now and written by :meth:`write_later` (or the next use of
        the database), so the values need not wait for the database to open."""
        details: Details = {**({"purpose": purpose} if purpose else {}), **self._context}
        entry = make_entry(session.info, "download", "ok", values, details)
        self.recorder.add_later(entry)

    def write_later(self) -> None:
        """Write what :meth:`download_later` took (a problem goes to ``report``)."""
        try:
            status = self.recorder.write_later()
        except HistoryError as exc:
            self._report(str(exc))
            return
        if status == "queued":
            self._report(
                f"the history database cannot be reached; the record waits in {self.recorder.queue}"
            )

    def backup(self, session: ValveSession, path: Path) -> None:
        """Record the backup file taken before the first upload."""
        from prm9tool.files.prmfile import read_file

        try:
            values: Mapping[str, Raw] | None = read_file(path).values
        except FileFormatError:
            values = None
        self.add(session, "backup", "ok", values, {"file": str(path)})

    def characterization(self, session: ValveSession, result: Characterization) -> None:
        """Record an end-of-line test run on the session's valve (as ``--characterize``'s)."""
        outcome, details = characterization_details(result)
        self.add(session, "characterization", outcome, result.parameters, details)

    def upload(
        self,
        session: ValveSession,
        values: Mapping[str, Raw],
        progress: Progress | None,
        cancel: threading.Event | None,
        purpose: str = "",
    ) -> UploadResult:
        """``session.upload`` with its outcome recorded (a broken link too, then re-raised).

        A partial upload (the compare view's chosen values) is followed by a download, so the
        record holds the valve's whole parameter set after it.
        """
        try:
            result = session.upload(values, progress, cancel)
        except CommunicationError as exc:
            failed: Details = {"written": getattr(exc, "written", 0), "error": str(exc)}
            self.add(
                session, "upload", "communication-error", None, failed, getattr(exc, "step", None)
            )
            raise
        after: Mapping[str, Raw] | None = None
        if result.stored:
            whole = {p.mnemonic for p in CATALOGUE.file_parameters(session.variant)}
            after = values if whole <= set(values) else session.download()
        details: Details = {"written": result.written, "chosen": len(values), "mismatches": {
            m: [str(want), str(got)] for m, (want, got) in result.mismatches.items()}}  # fmt: skip
        if purpose:
            details["purpose"] = purpose
        if result.failure:
            details["error"] = result.failure  # a refused store says why here
        if result.store:
            details["store"] = result.store  # which store happened (CANopen)
        outcome = "ok" if result.stored else "verification-failed"
        self.add(session, "upload", outcome, after, details, result.failed_step)
        return result


def characterization_details(result: Characterization) -> tuple[str, Details]:
    """The outcome (``passed``/``failed``) and details of a ``characterization`` record: the
    profile, when it started, every figure with its verdict (docs/history.md)."""
    details: Details = {
        "profile": result.profile.name,
        "started": result.date,
        "figures": [
            {"name": f.name, "value": f.value, "above": f.above, "unit": f.unit,
             "passed": f.passed}
            for f in result.figures
        ],
    }  # fmt: skip
    return ("passed" if result.passed else "failed"), details


def store_and_read(
    session: ValveSession, history: HistoryHook | None, progress: Progress | None = None
) -> dict[str, Raw]:
    """The valve's working parameters become its stored ones; then they are read back (what
    it holds now) and, with ``history``, recorded as a ``store``. A failing store raises
    before anything is recorded."""
    session.store()
    values = dict(session.download(progress))
    if history is not None:
        history.add(session, "store", "ok", values, {"command": "Valve → Store"})
    return values

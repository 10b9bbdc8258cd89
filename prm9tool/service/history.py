"""The history as one observer of a valve's operations: :class:`HistoryHook`.

The service (:class:`prm9tool.service.valve.ValveService`) attaches one when a valve is opened
(unless the caller turns history off) and every operation records through it, whichever door
started it: the GUI's worker thread, a script's :class:`~prm9tool.api.valve.Valve`, the
command line. In the GUI it runs in the worker thread beside the valve I/O, so a slow
database never freezes the window.
Recording never raises: a record the database cannot take waits in the local queue (see
:mod:`prm9tool.history.recorder`), and a problem is handed to ``report`` (the connection shows
it). Whether an upload may start while the database is away is decided before the upload,
by the user (``ValveConnection.check_history``). No Qt.
"""

from __future__ import annotations

import threading
from collections.abc import Callable, Mapping
from pathlib import Path
from types import SimpleNamespace
from typing import TYPE_CHECKING, Any

from prm9tool.catalogue import CATALOGUE
from prm9tool.errors import CommunicationError, FileFormatError, HistoryError
from prm9tool.history.recorder import Details, Recorder, make_entry

if TYPE_CHECKING:
    from prm9tool.characterize.drift import DriftReport
    from prm9tool.characterize.run import Characterization
    from prm9tool.device.records import UploadResult
    from prm9tool.device.session import ValveSession
    from prm9tool.history.identity import ValveIdentity

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
        self.record(session.info, operation, outcome, parameters, details, failed_step)

    def record(
        self,
        valve: ValveIdentity,
        operation: str,
        outcome: str,
        parameters: Mapping[str, Raw] | None,
        details: Details | Mapping[str, object] | None = None,
        failed_step: str | None = None,
    ) -> str:
        """Record one operation on ``valve`` (its type key, serial, firmware, device ID: a
        session's ``info``, a ``--batch`` report's valve record) — the one place every
        record is written. Returns ``recorded``, ``queued`` (the database is away: the
        record waits in the local queue) or ``not recorded: why``; never raises."""
        merged = {**(details or {}), **self._context}
        try:
            status = self.recorder.record(
                valve, operation, outcome, parameters, merged, failed_step
            )
        except HistoryError as exc:
            self._report(str(exc))
            return f"not recorded: {exc}"
        if status == "queued":
            self._report(
                f"the history database cannot be reached; the record waits in {self.recorder.queue}"
            )
        return status

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
        outcome, details = characterization_details(result, curves=True)
        self.add(session, "characterization", outcome, result.parameters, details)

    def characterization_of(self, result: Characterization) -> None:
        """Record an end-of-line test run on the valve ``result.info`` names (a run on a rig,
        without the session at hand: the tuning window's test report, ``--characterize``):
        outcome ``passed``/``failed``, the parameter set the valve ran with (read at the
        start of the run), every figure with its verdict (:func:`characterization_details`)."""
        info = result.info
        valve = SimpleNamespace(type_key=info.type_key, serial=info.serial, firmware=info.firmware,
                                device_id=info.device_id or info.link)  # fmt: skip
        outcome, details = characterization_details(result, curves=True)
        self.record(valve, "characterization", outcome, result.parameters, details)

    def twin_of(self, result: Characterization, outcome: str, details: Mapping[str, Any]) -> None:
        """Record the twin fitted from ``result`` (issue 31): operation ``twin``, outcome
        ``explained``/``not-explained``, the twin file and fit in ``details``
        (:func:`prm9tool.twin.fitvalve.history_details`), the parameter set of the run."""
        info = result.info
        valve = SimpleNamespace(type_key=info.type_key, serial=info.serial, firmware=info.firmware,
                                device_id=info.device_id or info.link)  # fmt: skip
        self.record(valve, "twin", outcome, result.parameters, details)

    def signature_of(self, report: DriftReport) -> str:
        """Record a field signature compared with the birth certificate (issue 31 item 5):
        operation ``signature``, outcome ``no-drift``/``drifted``, the birth certificate it
        was compared with and every figure's drift in ``details``
        (:func:`prm9tool.characterize.drift.history_details`), the parameter set of the run."""
        from prm9tool.characterize.drift import history_details

        info = report.today.info
        valve = SimpleNamespace(type_key=info.type_key, serial=info.serial, firmware=info.firmware,
                                device_id=info.device_id or info.link)  # fmt: skip
        return self.record(
            valve, "signature", report.verdict, report.today.parameters, history_details(report)
        )

    def records_of(self, serial: int) -> list[dict[str, Any]]:
        """The serial's records, oldest first (HistoryError when the database cannot be
        read: a signature then refuses, as it cannot find the birth certificate)."""
        return self.recorder.store().records(serial)

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
        details = upload_details(result.written, len(values), result.mismatches,
                                 result.failure, result.store)  # fmt: skip
        if purpose:
            details["purpose"] = purpose
        outcome = "ok" if result.stored else "verification-failed"
        self.add(session, "upload", outcome, after, details, result.failed_step)
        return result


def upload_details(
    written: int,
    chosen: int,
    mismatches: Mapping[str, tuple[object, object]],
    error: str | None = None,
    store: str | None = None,
) -> Details:
    """The details of an upload record, the same whichever door uploaded (``upload`` of the
    window and the API, ``batch-upload`` of ``--batch``, which adds its batch context):
    parameters written, values given, mismatches {mnemonic: [wanted, read]}, why it failed
    (a refused store says why here) and which store happened (CANopen)."""
    details: Details = {"written": written, "chosen": chosen, "mismatches": {
        m: [str(want), str(got)] for m, (want, got) in mismatches.items()}}  # fmt: skip
    if error:
        details["error"] = error
    if store:
        details["store"] = store
    return details


def characterization_details(result: Characterization, curves: bool = False) -> tuple[str, Details]:
    """The outcome (``passed``/``failed``) and details of a ``characterization`` record: the
    profile, when it started, the loop and the test settings, every figure with its verdict
    (docs/history.md); ``curves``: also the steps and the Bode, thinned (what a later field
    signature plots its own over: :func:`prm9tool.characterize.birth_certificate.curves`)."""
    from prm9tool.characterize.birth_certificate import curves as thinned
    from prm9tool.characterize.birth_certificate import tests_of

    details: Details = {
        "profile": result.profile.name,
        "started": result.date,
        "loop": result.loop,
        "tests": tests_of(result),
        "figures": [
            {"name": f.name, "value": f.value, "above": f.above, "unit": f.unit,
             "passed": f.passed}
            for f in result.figures
        ],
    }  # fmt: skip
    if curves:
        details["curves"] = thinned(result)
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


def record_characterization(recorder: Recorder, result: Characterization) -> None:
    """One ``characterization`` record of the valve the run names (never raises), through the
    observer: what ``--characterize`` records after its run."""
    import logging

    log = logging.getLogger("prm9tool.history")
    HistoryHook(recorder, lambda problem: log.error("history: %s", problem)).characterization_of(
        result
    )


def record_twin(
    recorder: Recorder, result: Characterization, outcome: str, details: Mapping[str, Any]
) -> None:
    """One ``twin`` record of the valve ``result`` names (never raises): what ``--fit-twin
    --device``/``--emulator`` records after its fit."""
    import logging

    log = logging.getLogger("prm9tool.history")
    HistoryHook(recorder, lambda problem: log.error("history: %s", problem)).twin_of(
        result, outcome, details
    )


def record_signature(recorder: Recorder, report: DriftReport) -> None:
    """One ``signature`` record of the valve the report names (never raises): what
    ``--signature`` records after its run."""
    import logging

    log = logging.getLogger("prm9tool.history")
    HistoryHook(recorder, lambda problem: log.error("history: %s", problem)).signature_of(report)


def signature_with_history(connection: Any, rig: Any, profile: Any = None) -> DriftReport:
    """The field signature on ``rig`` (the GUI's worker: the connection's valve) compared with
    the birth certificate in the connection's history, and recorded there (a ``signature``
    record). With the history off, or offline, it refuses (NoReferenceError) before anything
    moves."""
    from prm9tool.characterize.drift import signature

    hook: HistoryHook | None = getattr(connection, "history", None)
    if not getattr(connection, "is_online", False):
        hook = None
    report = signature(rig, hook.records_of if hook is not None else None, profile)
    if hook is not None:
        hook.signature_of(report)
    return report


def birth_certificate_problem(connection: Any) -> Exception | None:
    """Why :func:`signature_with_history` would refuse on the connection's valve before it
    moves — the history is off, or holds no end-of-line test of this serial (for either loop:
    which one the valve runs is read from it in the worker) — or None. The window asks this
    before its hydraulics and enabling questions, so a refusal asks nothing and enables
    nothing first; offline the worker's own check says why."""
    from prm9tool.characterize.birth_certificate import NO_HISTORY, NoReferenceError, reference_of

    device = getattr(connection, "device", None)
    if device is None or not getattr(connection, "is_online", False):
        return None
    hook: HistoryHook | None = getattr(connection, "history", None)
    if hook is None:
        return NoReferenceError(NO_HISTORY())
    serial, type_key = int(device.serial), str(device.type_key)
    try:
        records = hook.records_of(serial)
    except HistoryError as exc:
        return exc
    problem: Exception | None = None
    for loop in ("position", "process"):
        try:
            reference_of(records, serial, type_key, loop)
            return None
        except NoReferenceError as exc:
            problem = problem or exc
    return problem


def run_with_history(connection: Any, run: Callable[[], Characterization]) -> Characterization:
    """``run()`` (a characterization on the connection's valve, in the GUI's worker) with its
    result recorded into the connection's history (``connection.history``, a
    :class:`HistoryHook`); offline (the simulated valve) or with history off nothing is
    recorded; a run that raises records nothing."""
    result = run()
    hook = getattr(connection, "history", None)
    if hook is not None and getattr(connection, "is_online", False):
        hook.characterization_of(result)
    return result


def open_history(
    url: str | None = None, command: str = "", report: Callable[[str], None] | None = None
) -> HistoryHook:
    """The observer a valve gets when it is opened with history on: records into the
    database ``url`` (default the configured one), every record with ``command`` (what ran
    it) in its details; ``report`` hears a record the database could not take (default:
    the ``prm9tool.history`` logger's warning). The database opens on the first record."""
    import logging

    from prm9tool.history.recorder import Recorder

    if report is None:
        log = logging.getLogger("prm9tool.history")
        report = lambda problem: log.warning("history: %s", problem)  # noqa: E731
    return HistoryHook(Recorder(url), report, {"command": command} if command else None)

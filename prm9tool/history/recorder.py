"""Recording operations on valves: one :class:`Recorder` used by ``--batch`` and the GUI.

The recorder fills in who, where and when (program version, OS user, host name, UTC time) and
appends the record to the database. When the database cannot take it, the record goes to a
local queue file (``history-queue.jsonl`` in the user data dir, one JSON object a line,
appended and flushed to disk) and is moved into the database, in order, the next time it can
be reached. Whether an upload may go ahead while the database is unreachable is decided
*before* the upload (:meth:`Recorder.problem`): the caller refuses or asks the user.
Thread-safe: the batch mode's worker threads share one recorder. No Qt.
"""

from __future__ import annotations

import contextlib
import getpass
import json
import logging
import os
import socket
import threading
from collections.abc import Mapping
from datetime import UTC, datetime
from pathlib import Path
from typing import TYPE_CHECKING, Any, TypedDict

from prm9tool._version import __version__
from prm9tool.errors import HistoryError
from prm9tool.history.chain import Entry
from prm9tool.history.config import database_url, queue_path
from prm9tool.history.identity import ValveIdentity

if TYPE_CHECKING:
    from prm9tool.history.store import HistoryStore

log = logging.getLogger("prm9tool.history")
Raw = int | str

# operations (docs/history.md); "characterization" is reserved for test results (issue 17)
OPERATIONS = (
    "download", "upload", "store", "restore-factory", "online-edits", "batch-upload",
    "backup", "characterization", "restart", "autotune", "frequency-response", "report-saved",
    "twin", "signature",
)  # fmt: skip


class FigureDetails(TypedDict):
    """One figure of a ``characterization`` record: its value and verdict (None: no limit)."""

    name: str
    value: float
    above: bool
    unit: str
    passed: bool | None


class Details(TypedDict, total=False):
    """What a record's ``details`` hold, by the operation that wrote them (docs/history.md).

    Every key is optional: an operation writes the ones that say what it did. The database
    keeps them as JSON; records read back are plain dicts with the same keys.
    """

    command: str  # what ran it: "--diff", "python API", "Valve → Store" …
    purpose: str  # what the GUI's download or upload was for ("compare", "download" …)
    file: str | None  # the *.prm file read or written (backup, batch, --diff)
    written: int  # parameters written (upload)
    verified: bool  # every value read back as written (upload)
    chosen: int  # values the upload was given (a partial upload: fewer than the set)
    mismatches: dict[str, list[str]] | int  # mnemonic -> [wanted, read] (GUI); a count (batch)
    verification: str  # the batch mode's verdict of the read-back
    store: str | None  # which store the link made (CANopen: 0x1010 or the upload's own)
    upload_store: str | None  # restart-verify: how the verified upload had stored the set
    checked: int  # restart-verify: uploaded values compared after the restart
    error: str  # why it failed
    backup: str | None  # the backup file taken before (restore-factory)
    stored: bool  # online edits: whether the values were stored
    profile: str  # characterization: the acceptance profile's name
    started: str  # characterization: when the run started
    figures: list[FigureDetails]  # characterization: every figure with its verdict
    changes: dict[str, list[int | str]]  # online changes: mnemonic -> [from, to] (raw)
    source: str  # online changes: the file or the history record the values came from
    what: str  # tuning accepted: what was accepted
    loop: str  # tuning accepted, autotune, report-saved: the loop
    pdf: str  # report-saved: the PDF file the test report was saved as
    rounds: int | None  # autotune: the rounds it took (None: the critical-gain method)
    method: str  # autotune: "model" or "critical"
    passes: bool  # autotune: the proposal passes the acceptance profile
    applied: bool  # autotune: the proposed gains were written and stored
    meets_targets: bool | None  # autotune: the model's proposal meets the targets
    proposed: dict[str, list[int | None]]  # autotune: mnemonic -> [before, proposed] (raw)
    before: dict[str, float | None]  # autotune: the step with the gains before
    after: dict[str, float | None]  # autotune: the step with the proposed gains
    amplitude_pct: float | None  # frequency-response: the sweep's amplitude
    centre_pct: float | None  # frequency-response: the sweep's centre
    bandwidth_hz: float | None  # frequency-response: −3 dB (None: not found)
    phase_90_hz: float | None  # frequency-response: −90° (None: not found)
    limited_to_hz: float | None  # frequency-response: the sweep's end when the link limited it
    lost_samples: int  # frequency-response: samples the link lost
    tests: dict[str, float]  # characterization: the test settings of its loop
    curves: dict[str, Any]  # characterization: its steps and Bode, thinned (for a signature)
    reference: dict[str, Any]  # signature: the birth certificate it was compared with
    drifted: list[str]  # signature: the figures beyond their drift limit


def now_utc() -> str:
    """The time of a record: ISO 8601 in UTC with microseconds."""
    return datetime.now(UTC).isoformat(timespec="microseconds")


def _user() -> str:
    try:
        return getpass.getuser()
    except (OSError, KeyError, ImportError):
        return "unknown"


def make_entry(
    info: ValveIdentity,
    operation: str,
    outcome: str,
    parameters: Mapping[str, Raw] | None,
    details: Mapping[str, Any] | None = None,
    failed_step: str | None = None,
) -> Entry:
    """A record of ``operation`` on the valve ``info`` describes, made here and now."""
    return Entry(
        serial=int(info.serial),
        type_key=str(info.type_key),
        firmware=str(info.firmware or ""),
        link=str(info.device_id).partition(":")[0] or "file",
        device_id=str(info.device_id),
        operation=operation,
        outcome=outcome,
        recorded_at=now_utc(),
        program_version=__version__,
        os_user=_user(),
        host=socket.gethostname(),
        failed_step=failed_step,
        details=dict(details or {}),
        parameters=None if parameters is None else dict(parameters),
    )


class Recorder:
    """Appends records to the history database, or queues them locally when it is away."""

    def __init__(self, url: str | None = None, queue: Path | None = None) -> None:
        self.url = database_url(url)
        self.queue = queue or queue_path()
        self._store: HistoryStore | None = None
        self._lock = threading.RLock()
        self._later: list[Entry] = []  # add_later(): written before the store is next used

    def store(self, recording: Entry | None = None) -> HistoryStore:
        """The open database (opened and migrated on first use); HistoryError if it cannot.
        ``recording``: the entry the caller appends next; when it records a backup file just
        written, the first opening's import leaves that file to it (one record, not two)."""
        from prm9tool.history.store import HistoryStore  # SQLAlchemy: only when recording

        with self._lock:
            if self._store is None:
                self._store = HistoryStore(self.url)
                self._flush(self._store)
                self._import_backups_once(self._store, _backup_file(recording))
            later, self._later = self._later, []
            for entry in later:  # before anything else reads or writes the store
                self._append_or_queue(self._store, entry)
            return self._store

    def _import_backups_once(self, store: HistoryStore, recorded: Path | None = None) -> None:
        """The backup files of earlier versions become records, once per database and station
        (a marker file remembers it; the import itself never adds a file twice either).
        ``recorded``: a backup file the entry being added records itself, not imported."""
        import hashlib

        from prm9tool.history.importer import import_backups
        from prm9tool.paths import user_data_dir

        backups = user_data_dir() / "backups"
        digest = hashlib.sha256(store.shown_url.encode("utf-8")).hexdigest()[:16]
        marker = user_data_dir() / f"history-imported-{digest}"
        if marker.exists() or not backups.is_dir():
            return
        result = import_backups(store, backups, skip=recorded)
        for path, problem in result.problems:
            log.warning("history: backup %s not imported: %s", path, problem)
        with contextlib.suppress(OSError):
            marker.write_text(f"{store.shown_url}\n{len(result.imported)} imported\n", "utf-8")

    def problem(self) -> HistoryError | None:
        """Why the database cannot take records now (None: it can); flushes the queue."""
        try:
            self.store()
        except HistoryError as exc:
            return exc
        return None

    def record(
        self,
        info: ValveIdentity,
        operation: str,
        outcome: str,
        parameters: Mapping[str, Raw] | None,
        details: Mapping[str, Any] | None = None,
        failed_step: str | None = None,
    ) -> str:
        """Record one operation; returns ``"recorded"`` or ``"queued"``.

        Raises HistoryError only when neither the database nor the local queue took it.
        """
        entry = make_entry(info, operation, outcome, parameters, details, failed_step)
        return self.add(entry)

    def add(self, entry: Entry) -> str:
        """Append a prepared entry (database, else the local queue)."""
        try:
            self.store(entry).append(entry, _marks_backup(entry))
        except HistoryError as exc:
            log.warning("history: %s; the record is kept in %s", exc, self.queue)
            self._enqueue(entry, exc)
            return "queued"
        return "recorded"

    def add_later(self, entry: Entry) -> None:
        """Take a prepared entry now and write it on the next use of the store (or by
        :meth:`write_later`): the caller need not wait for the database to open — the first
        use imports SQLAlchemy and Alembic and checks the migrations (~0.3 s), which delayed
        the GUI's first download (issue 34, item 22). Every read and write of the store comes
        after it, so nobody sees the history without it."""
        with self._lock:
            self._later.append(entry)

    def write_later(self) -> str:
        """Write the entries of :meth:`add_later`; ``"recorded"``, or ``"queued"`` when the
        database cannot be reached (they wait in the local queue then). Raises HistoryError
        only when the local queue could not take them either."""
        try:
            self.store()
        except HistoryError as exc:
            with self._lock:
                later, self._later = self._later, []
                for entry in later:
                    self._enqueue(entry, exc)
            return "queued" if later else "recorded"
        return "recorded"

    def _append_or_queue(self, store: HistoryStore, entry: Entry) -> None:
        try:
            store.append(entry, _marks_backup(entry))
        except HistoryError as exc:
            log.warning("history: %s; the record is kept in %s", exc, self.queue)
            try:
                self._enqueue(entry, exc)
            except HistoryError as lost:
                log.error("history: %s", lost)

    def record_safely(self, info: ValveIdentity, *args: Any, **kwargs: Any) -> str | None:
        """:meth:`record`, but a failure is logged and returned as text instead of raised."""
        try:
            self.record(info, *args, **kwargs)
        except HistoryError as exc:
            log.error("history: %s", exc)
            return str(exc)
        return None

    def close(self) -> None:
        """Close the database connections (what :meth:`add_later` took is written first)."""
        with self._lock:
            if self._later:
                try:
                    self.write_later()
                except HistoryError as exc:
                    log.error("history: %s", exc)
            if self._store is not None:
                self._store.close()
                self._store = None

    # --- the local queue ------------------------------------------------------------------
    def queued(self) -> int:
        """How many records wait in the local queue."""
        try:
            return sum(1 for line in self.queue.read_text("utf-8").splitlines() if line.strip())
        except OSError:
            return 0

    def _enqueue(self, entry: Entry, why: HistoryError) -> None:
        line = json.dumps(entry.to_json(), ensure_ascii=False) + "\n"
        with self._lock:
            try:
                self.queue.parent.mkdir(parents=True, exist_ok=True)
                fd = os.open(self.queue, os.O_WRONLY | os.O_CREAT | os.O_APPEND, 0o644)
                try:
                    os.write(fd, line.encode("utf-8"))
                    os.fsync(fd)
                finally:
                    os.close(fd)
            except OSError as exc:
                raise HistoryError(
                    f"{why}; the record could not be kept in {self.queue} either: "
                    f"{exc.strerror or exc}",
                    why.kind,
                ) from exc

    def _flush(self, store: HistoryStore) -> None:
        """Move queued records into the database, oldest first; what fails stays queued."""
        if not self.queue.exists():
            return
        taken = self.queue.with_name(f"{self.queue.name}.{os.getpid()}.flushing")
        try:
            os.replace(self.queue, taken)  # another process appending starts a new queue
        except OSError:
            return
        lines = [line for line in taken.read_text("utf-8").splitlines() if line.strip()]
        for number, line in enumerate(lines):
            try:
                entry = Entry.from_json(json.loads(line))
                store.append(entry, _marks_backup(entry))
            except HistoryError:
                self._requeue(lines[number:])
                break
        with contextlib.suppress(OSError):
            taken.unlink()

    def _requeue(self, lines: list[str]) -> None:
        with open(self.queue, "a", encoding="utf-8") as queue:
            queue.write("".join(line + "\n" for line in lines))
            queue.flush()
            os.fsync(queue.fileno())


def _backup_file(entry: Entry | None) -> Path | None:
    """The backup file a ``backup`` entry records as it is written (None: none)."""
    if entry is None or entry.operation != "backup":
        return None
    path = entry.details.get("file")
    return Path(path) if path else None


def _marks_backup(entry: Entry) -> Any:
    """A backup file recorded as it is written is never imported again (importer.py)."""
    path = _backup_file(entry)
    if path is None:
        return None
    from prm9tool.history.importer import mark_imported, source_name

    source = source_name(path)
    return lambda conn, record_id: mark_imported(conn, source, record_id)

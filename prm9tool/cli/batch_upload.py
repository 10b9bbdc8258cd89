"""``--batch FILE.prm`` in one valve: the type check, the backup, the upload (or the dry
run) and what goes into the valve's record of the report. Runs in a worker thread per valve."""

from __future__ import annotations

import logging
from collections.abc import Callable, Mapping
from pathlib import Path

from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.cli.batch_history import BatchHistory
from prm9tool.cli.batch_report import ProgressPrinter, Stopwatch, ValveRecord
from prm9tool.device.canlink.storing import KEPT_AS_WRITTEN
from prm9tool.device.factory import CanOptions, DeviceEntry
from prm9tool.device.records import UploadResult
from prm9tool.device.session import ValveSession
from prm9tool.device.upload_outcome import reload_outcome
from prm9tool.errors import CommunicationError, Prm9Error, TypeKeyError
from prm9tool.files.backup import existing_backups
from prm9tool.files.prmfile import PrmContents, check_file
from prm9tool.service.upload import BackupError, check_type, upload

log = logging.getLogger("prm9tool.cli.batch")

Opener = Callable[..., ValveSession]


def summary(record: ValveRecord) -> str:
    """One valve\'s outcome as the last progress line says it."""
    text = f"{record.result} ({record.duration_s:.2f} s)"
    text = f"{text}: {record.error}" if record.error else text
    if record.came_back:
        text += (
            f"; the valve is connected again ({record.came_back}) but was not uploaded "
            "again: run the batch for it once more"
        )
    return text


class UploadJob:
    """Uploads the file into one valve (runs in a worker thread)."""

    def __init__(
        self,
        contents: PrmContents,
        force: bool,
        dry_run: bool,
        printer: ProgressPrinter,
        history: BatchHistory,
        open_valve: Opener,
        can: CanOptions | None = None,
        label_key: str | None = None,
        verify_by_restart: bool = False,
    ) -> None:
        self.contents, self.force, self.dry_run, self.printer = contents, force, dry_run, printer
        self.history = history
        self.can = can
        self.open_valve = open_valve
        self.label_key = label_key  # --type-key
        self.verify_by_restart = verify_by_restart  # --verify-by-restart (CANopen)

    def __call__(self, entry: DeviceEntry) -> ValveRecord:
        clock = Stopwatch()
        record = ValveRecord(
            entry.device_id, entry.kind, entry.serial, entry.type_key, entry.firmware
        )
        try:
            # the file's type key serves a CANopen valve that does not tell its own (0x2041)
            key = str(self.contents.type_key)
            opened = self._open(entry, key)
            with opened as session:
                info = session.info
                record.type_key, record.serial, record.firmware = (
                    info.type_key,
                    info.serial,
                    info.firmware,
                )
                self._run(session, record)
        except CommunicationError as exc:
            record.result, record.error = "communication-error", str(exc)
            _copy_progress(exc, record)
        except TypeKeyError as exc:  # a CANopen valve whose objects contradict the file's key
            record.result, record.error = "type-mismatch", str(exc)
        except Prm9Error as exc:  # a refused read during the backup, an unwritable backup …
            record.result, record.error = "communication-error", str(exc)
        except Exception as exc:  # whatever the valve answered: the run still ends with a report
            log.exception("%s: unexpected error", entry.device_id)
            record.result, record.error = "communication-error", unexpected(exc)
        clock.finish(record)
        self.history.upload(record, self.contents.values)
        return record

    def _open(self, entry: DeviceEntry, key: str) -> ValveSession:
        if self.can is None:
            return self.open_valve(entry)
        return self.open_valve(entry, self.can, key, self.label_key)

    def _run(self, session: ValveSession, record: ValveRecord) -> None:
        who = str(record.serial)
        try:
            check_type(
                self.contents.type_key, TypeKey.parse(session.info.type_key), self.force,
                "--force-type",
            )  # fmt: skip
        except TypeKeyError as exc:
            record.result, record.error = "type-mismatch", str(exc)
            return
        values = self.contents.values
        if self.dry_run:
            current = record.current = session.download()
            record.changes = sum(current.get(m) != v for m, v in values.items())
            record.result = "dry-run"
            return
        self.printer.say(who, f"{record.type_key}, firmware {record.firmware}: backing up")
        record.failed_step = "backup"

        def backed_up(path: Path | None) -> None:  # before the first value is written
            if path is not None:
                self.history.backup(record, path)
            self._note_backup(record, path)

        try:
            # the one upload sequence (prm9tool.service.upload); the batch report says what
            # the valve refused at the store (store-failed), so the rules are the valve's here
            result = upload(
                session, values, rules=False, verify_by_restart=self.verify_by_restart,
                progress=self.printer.callback(who), on_backup=backed_up,
            )  # fmt: skip
        except BackupError as exc:
            raise Prm9Error(str(exc)) from exc
        record.store = result.store
        record.parameters_written, record.failed_step = result.written, result.failed_step
        record.verification = "passed" if result.verified else "failed"
        if result.failed_step == "write":
            record.verification = "not-run"
        record.mismatches = {
            m: {"expected": want, "actual": got} for m, (want, got) in result.mismatches.items()
        }
        record.result = "ok" if result.stored else "verification-failed"
        if result.failed_step == "store":
            record.result = "store-failed"
        record.absent_in_file = absent_in(self.contents)
        record.skipped = sorted({*result.skipped, *record.absent_in_file})
        if result.skipped:
            self.printer.say(
                who,
                "warning: not available over CANopen on this valve, not uploaded: "
                + ", ".join(result.skipped),
            )
        if record.absent_in_file:
            self.printer.say(
                who,
                "warning: marked absent in the file (the valve it was read from lacks them), "
                "not uploaded: " + ", ".join(record.absent_in_file),
            )
        if not result.stored:
            record.error = _failure_text(result, record.backup)
        elif result.store:
            self.printer.say(who, result.store)

    def _note_backup(self, record: ValveRecord, new_backup: Path | None) -> None:
        """The report's backup of the valve: the one just written or its latest."""
        backups = existing_backups(record.serial)
        latest = new_backup or (backups[-1] if backups else None)
        record.backup = str(latest) if latest else None
        record.backup_valid = check_file(latest).valid if latest else None
        if new_backup and not record.backup_valid:
            self.printer.say(
                str(record.serial), f"the valve held an invalid parameter set, kept in {latest}"
            )
        record.failed_step = None


def absent_in(contents: PrmContents) -> list[str]:
    """The parameters of the file's type key that it marks absent (no value: the valve it was
    downloaded from over CANopen lacks them, docs/prm-format.md), in catalogue order."""
    present = contents.values
    return [
        p.mnemonic
        for p in CATALOGUE.file_parameters(contents.type_key.variant)
        if p.mnemonic not in present
    ]


def unexpected(exc: Exception) -> str:
    """The record\'s error for an exception no valve should cause."""
    return (
        f"unexpected error ({type(exc).__name__}: {exc}); the valve may have answered something "
        "this prm9tool cannot handle; details on standard error"
    )


def _copy_progress(exc: CommunicationError, record: ValveRecord) -> None:
    """How far a broken upload got (the attributes ValveSession.upload puts on its error)."""
    record.failed_step = getattr(exc, "step", record.failed_step)
    record.parameters_written = getattr(exc, "written", record.parameters_written)
    if getattr(exc, "verified", False):
        record.verification = "passed"


def _failure_text(result: UploadResult, backup: str | None) -> str:
    """Why a valve's upload was not stored and what it holds now (the record's ``error``)."""
    problem = result.failure or _mismatch_text(result.failed_step, result.mismatches)
    if result.failure and result.mismatches:  # e.g. not kept through the restart: name them
        problem = f"{problem} ({_arrows(result.mismatches)})"
    kept = result.store == KEPT_AS_WRITTEN
    text = f"{problem}; {reload_outcome(result.reload_error, kept, result.restarted)}"
    if result.restarted and not kept and backup:  # nothing was put back: the file can
        text += (
            f"; the backup of its values before the upload is kept in {backup}: upload it "
            f"(--batch {backup}) to put them back"
        )
    return text


def _arrows(mismatches: Mapping[str, tuple[object, object]]) -> str:
    """The first five ``{mnemonic: (uploaded, read back)}`` as ``M: uploaded → read back``
    (the GUI's Verify by restart… lists them so) and how many more."""
    pairs = list(mismatches.items())
    shown = "; ".join(f"{m}: {w} → {g}" for m, (w, g) in pairs[:5])
    return shown + (f" (and {len(pairs) - 5} more)" if len(pairs) > 5 else "")


def _mismatch_text(step: str | None, mismatches: Mapping[str, tuple[object, object]]) -> str:
    shown = "; ".join(f"{m}: wrote {w}, got {g}" for m, (w, g) in list(mismatches.items())[:5])
    more = f" (and {len(mismatches) - 5} more)" if len(mismatches) > 5 else ""
    if step == "write":
        return f"the valve refused a value, nothing was stored: {shown}"
    count = len(mismatches)
    noun = "parameter" if count == 1 else "parameters"
    return f"{count} {noun} read back differently, nothing was stored: {shown}{more}"

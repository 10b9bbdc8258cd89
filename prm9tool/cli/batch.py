"""Headless production mode: ``--list-devices`` and ``--batch`` (no Qt GUI is ever started).

``--batch FILE.prm`` uploads, verifies and stores the file into every selected valve, several
in parallel, with progress on stderr and an optional JSON report; ``--batch --download OUT.prm``
saves one valve's parameters. Usage, exit codes and report schema: docs/batch.md.
"""

from __future__ import annotations

import argparse
import logging
import sys
from collections.abc import Mapping
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from prm9tool.catalogue.typekey import TypeKey
from prm9tool.cli.batch_history import BatchHistory
from prm9tool.cli.batch_report import (
    ProgressPrinter,
    Stopwatch,
    ValveRecord,
    overall,
    write_report,
)
from prm9tool.device.factory import (
    CAN,
    NOT_PRM9,
    CanOptions,
    DeviceEntry,
    can_entries,
    emulator_entries,
    open_session,
    parse_emulator_spec,
    usb_entries,
    usb_unavailable_reason,
)
from prm9tool.device.session import ValveSession, reload_outcome
from prm9tool.errors import (
    CanAdapterError,
    CommunicationError,
    ExitCode,
    FileFormatError,
    Prm9Error,
    TypeKeyError,
)
from prm9tool.files.backup import ensure_backup, existing_backups, write_device_file
from prm9tool.files.prmfile import PrmContents, check_file, read_file

log = logging.getLogger("prm9tool.cli.batch")


class BatchError(Exception):
    """Ends the run before any valve was touched, with ``code`` and a message for stderr."""

    def __init__(self, code: ExitCode, message: str) -> None:
        super().__init__(message)
        self.code = code


def run(args: argparse.Namespace) -> int:
    """Entry point of ``--list-devices`` and ``--batch``; returns the exit code."""
    records: list[ValveRecord] = []
    mode = "list" if args.list_devices else _mode(args)
    try:
        if args.list_devices:
            return _list_devices(args)
        _check_usage(args)
        code = _download(args, records) if args.download else _upload(args, records)
    except BatchError as exc:
        print(f"prm9tool: {exc}", file=sys.stderr)
        code = exc.code
    if args.report and not args.list_devices and _report_refusal(args.report) is None:
        try:
            write_report(args.report, mode, args.batch or args.download, code, records)
        except OSError as exc:
            print(f"prm9tool: cannot write the report {args.report}: {exc}", file=sys.stderr)
            return int(code) if code != ExitCode.OK else ExitCode.USAGE  # keep a valve's outcome
    return int(code)


def _mode(args: argparse.Namespace) -> str:
    if args.download:
        return "download"
    return "dry-run" if args.dry_run else "upload"


def _check_usage(args: argparse.Namespace) -> None:
    if args.download and args.batch:
        raise BatchError(
            ExitCode.USAGE, "use either --batch FILE.prm or --batch --download OUT.prm"
        )
    if not args.download and not args.batch:
        raise BatchError(ExitCode.USAGE, "--batch needs FILE.prm (or --download OUT.prm)")
    if args.download and (args.all or len(args.emulator) > 1):  # --device: checked in select
        raise BatchError(ExitCode.USAGE, "--download saves one valve: select exactly one")
    refusal = _report_refusal(args.report) if args.report else None
    if refusal is not None:
        raise BatchError(ExitCode.USAGE, f"--report {args.report}: {refusal}")
    for spec in args.emulator:
        try:
            parse_emulator_spec(spec)
        except TypeKeyError as exc:
            raise BatchError(ExitCode.USAGE, f"--emulator: {exc}") from exc


def _report_refusal(path: str) -> str | None:
    """Why the report cannot go to ``path`` (checked before any valve is touched), or None.

    A symbolic link is refused: writing through it would replace a file the run was never
    told about (docs/batch.md).
    """
    report = Path(path)
    if not report.parent.is_dir():
        return f"there is no folder {report.parent}"
    if report.is_symlink():
        return "is a symbolic link; give the path of the report itself"
    return None


# --- devices ------------------------------------------------------------------------------------
def _list_devices(args: argparse.Namespace) -> int:
    entries = _usb(required=False) + _emulators(args) + _can(args)
    for entry in entries:
        if entry.kind == NOT_PRM9:
            print(f"{entry.device_id}\tnot a PRM9\t{entry.description}")
            continue
        print(
            f"{entry.device_id}\t{entry.type_key}\tserial {entry.serial}\tfirmware {entry.firmware}"
        )
    if not [e for e in entries if e.kind != NOT_PRM9]:
        reason = usb_unavailable_reason()
        print("prm9tool: no valves found" + (f" ({reason})" if reason else ""), file=sys.stderr)
        return ExitCode.NO_DEVICE
    return ExitCode.OK


def _emulators(args: argparse.Namespace) -> list[DeviceEntry]:
    try:
        return emulator_entries(args.emulator)
    except (TypeKeyError, FileFormatError) as exc:
        raise BatchError(ExitCode.USAGE, f"--emulator: {exc}") from exc
    except Prm9Error as exc:
        raise BatchError(ExitCode.NO_DEVICE, str(exc)) from exc


def can_options(args: argparse.Namespace) -> CanOptions | None:
    """The CAN bus the command line names (None: no CAN option given)."""
    given = (args.can_interface, args.can_channel, args.can_bitrate)
    return CanOptions.from_args(args) if any(v is not None for v in given) else None


def _can(args: argparse.Namespace) -> list[DeviceEntry]:
    """The nodes on the command line's CAN bus (none without CAN options)."""
    options = can_options(args)
    if options is None:
        return []
    try:
        return can_entries(options)
    except CanAdapterError as exc:
        raise BatchError(ExitCode.COMMUNICATION, str(exc)) from exc


def _usb(required: bool) -> list[DeviceEntry]:
    try:
        return usb_entries()
    except CommunicationError as exc:
        if required:
            raise BatchError(ExitCode.NO_DEVICE, str(exc)) from exc
        return []


def select(args: argparse.Namespace) -> list[DeviceEntry]:
    """The valves the options name; BatchError (4 or 2) if that is none or ambiguous."""
    chosen = _emulators(args)
    if can_options(args) is not None:
        return _select_can(args, chosen)
    if args.device or args.all:
        usb = _usb(required=True)
        for wanted in args.device:
            chosen += _match(wanted, usb)
        if args.all:
            chosen += usb
    elif not chosen:
        usb = _usb(required=False)
        if len(usb) > 1:
            raise BatchError(
                ExitCode.USAGE, f"{len(usb)} valves are connected: choose with --device or --all"
            )
        chosen = usb
    if not chosen:
        reason = usb_unavailable_reason()
        raise BatchError(ExitCode.NO_DEVICE, "no valve found" + (f" ({reason})" if reason else ""))
    return _unique(chosen)


def _select_can(args: argparse.Namespace, chosen: list[DeviceEntry]) -> list[DeviceEntry]:
    """The valves on the CAN bus: ``--device can:N`` (checked to be a PRM9) or ``--all``."""
    found = _can(args)
    prm9 = [e for e in found if e.kind == CAN]
    for wanted in args.device:
        matches = [e for e in found if wanted in (e.device_id, str(e.serial)) and e.serial]
        matches += [e for e in found if e.device_id == wanted and e not in matches]
        if not matches:
            known = ", ".join(e.device_id for e in prm9) or "none"
            raise BatchError(
                ExitCode.NO_DEVICE,
                f"no valve {wanted!r} answers on the CAN bus {can_options(args)} (PRM9 found: {known})",
            )
        others = [e for e in matches if e.kind == NOT_PRM9]
        if others:
            raise BatchError(
                ExitCode.NO_DEVICE, f"{others[0].description}; prm9tool does not write to it"
            )
        chosen += matches
    if args.all:
        chosen += prm9
    elif not args.device and not chosen:
        if len(prm9) > 1:
            raise BatchError(
                ExitCode.USAGE, f"{len(prm9)} valves are on the bus: choose with --device or --all"
            )
        chosen = prm9
    if not chosen:
        raise BatchError(ExitCode.NO_DEVICE, f"no PRM9 found on the CAN bus {can_options(args)}")
    return _unique(chosen)


def _unique(entries: list[DeviceEntry]) -> list[DeviceEntry]:
    """Each valve once, in the order first named (``--device 41 --device /dev/hidraw0``)."""
    by_id: dict[str, DeviceEntry] = {}
    for entry in entries:
        by_id.setdefault(entry.device_id, entry)
    return list(by_id.values())


def _match(wanted: str, usb: list[DeviceEntry]) -> list[DeviceEntry]:
    found = [e for e in usb if wanted in (str(e.serial), e.device_id, e.device_id[4:])]
    if not found:
        known = ", ".join(f"{e.serial} ({e.device_id})" for e in usb) or "none"
        raise BatchError(ExitCode.NO_DEVICE, f"no valve {wanted!r} is connected (found: {known})")
    return found


def open_entry(
    entry: DeviceEntry, can: CanOptions | None = None, label_key: str | None = None
) -> ValveSession:
    """Open a session as the headless commands do (``--batch``, ``--diff``); ``label_key``:
    ``--type-key``."""
    return _open(entry) if can is None else _open(entry, can, label_key=label_key)


def _open(
    entry: DeviceEntry,
    can: CanOptions | None = None,
    type_key: str | None = None,
    label_key: str | None = None,
) -> ValveSession:
    """Open one selected valve; ``type_key``: the file's, for a valve that does not tell its
    own; ``label_key``: ``--type-key`` (first, remembered). An emulated valve is stepped on
    the link clock; its link runs at USB speed."""
    return open_session(
        entry,
        paced=False,
        link_paced=True,
        can_link=can,
        type_key=type_key,
        label_key=label_key,
    )


# --- upload -------------------------------------------------------------------------------------
def _read_source(path: str) -> PrmContents:
    try:
        contents = read_file(path)
    except FileFormatError as exc:
        raise BatchError(
            ExitCode.INVALID_FILE, f"{path} is not a valid parameter file:\n{exc}"
        ) from exc
    for warning in contents.warnings:
        print(warning.format(path), file=sys.stderr)
    for name, _ in contents.unknown:
        print(f"{path}: warning: unknown entry {name!r} is not uploaded", file=sys.stderr)
    return contents


def _upload(args: argparse.Namespace, records: list[ValveRecord]) -> ExitCode:
    contents = _read_source(args.batch)
    entries = select(args)
    printer = ProgressPrinter()
    # a dry run changes nothing: it is recorded (or queued) but never refused
    history = (
        BatchHistory.for_download(args) if args.dry_run else BatchHistory.open(args, BatchError)
    )
    job = _UploadJob(contents, args.force_type, args.dry_run, printer, history, can_options(args))
    job.label_key = getattr(args, "type_key", None)
    try:
        with ThreadPoolExecutor(max_workers=len(entries)) as pool:
            records.extend(pool.map(job, entries))
    finally:
        history.close()
    for record in records:
        printer.say(str(record.serial), _summary(record))
    return overall(records)


def _summary(record: ValveRecord) -> str:
    text = f"{record.result} ({record.duration_s:.2f} s)"
    return f"{text}: {record.error}" if record.error else text


class _UploadJob:
    """Uploads the file into one valve (runs in a worker thread)."""

    def __init__(
        self,
        contents: PrmContents,
        force: bool,
        dry_run: bool,
        printer: ProgressPrinter,
        history: BatchHistory,
        can: CanOptions | None = None,
    ) -> None:
        self.contents, self.force, self.dry_run, self.printer = contents, force, dry_run, printer
        self.history = history
        self.can = can
        self.label_key: str | None = None  # --type-key

    def __call__(self, entry: DeviceEntry) -> ValveRecord:
        clock = Stopwatch()
        record = ValveRecord(
            entry.device_id, entry.kind, entry.serial, entry.type_key, entry.firmware
        )
        try:
            # the file's type key serves a CANopen valve that does not tell its own (0x2041)
            key = str(self.contents.type_key)
            opened = (
                _open(entry) if self.can is None else _open(entry, self.can, key, self.label_key)
            )
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
            record.result, record.error = "communication-error", _unexpected(exc)
        clock.finish(record)
        self.history.upload(record, self.contents.values)
        return record

    def _run(self, session: ValveSession, record: ValveRecord) -> None:
        who = str(record.serial)
        mismatch = _type_problem(self.contents.type_key, session, self.force)
        if mismatch:
            record.result, record.error = "type-mismatch", mismatch
            return
        values = self.contents.values
        if self.dry_run:
            current = record.current = session.download()
            record.changes = sum(current.get(m) != v for m, v in values.items())
            record.result = "dry-run"
            return
        self.printer.say(who, f"{record.type_key}, firmware {record.firmware}: backing up")
        record.failed_step = "backup"
        try:
            new_backup = ensure_backup(session, self.printer.callback(who))
        except FileFormatError as exc:
            raise Prm9Error(
                f"the backup could not be written, nothing was uploaded: {exc}"
            ) from exc
        if new_backup is not None:
            self.history.backup(record, new_backup)
        backups = existing_backups(record.serial)
        latest = new_backup or (backups[-1] if backups else None)
        record.backup = str(latest) if latest else None
        record.backup_valid = check_file(latest).valid if latest else None
        if new_backup and not record.backup_valid:
            self.printer.say(who, f"the valve held an invalid parameter set, kept in {latest}")
        record.failed_step = None
        result = session.upload(values, self.printer.callback(who))
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
        if result.skipped:
            record.skipped = list(result.skipped)
            self.printer.say(
                who,
                "warning: not available over CANopen on this valve, not uploaded: "
                + ", ".join(result.skipped),
            )
        if not result.stored:
            problem = result.failure or _mismatch_text(result.failed_step, result.mismatches)
            record.error = f"{problem}; {reload_outcome(result.reload_error)}"


def _unexpected(exc: Exception) -> str:
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


def _mismatch_text(step: str | None, mismatches: Mapping[str, tuple[object, object]]) -> str:
    shown = "; ".join(f"{m}: wrote {w}, got {g}" for m, (w, g) in list(mismatches.items())[:5])
    more = f" (and {len(mismatches) - 5} more)" if len(mismatches) > 5 else ""
    if step == "write":
        return f"the valve refused a value, nothing was stored: {shown}"
    count = len(mismatches)
    noun = "parameter" if count == 1 else "parameters"
    return f"{count} {noun} read back differently, nothing was stored: {shown}{more}"


def _type_problem(file_key: TypeKey, session: ValveSession, force: bool) -> str | None:
    valve_key = TypeKey.parse(session.info.type_key)
    if file_key == valve_key:
        return None
    if file_key.variant != valve_key.variant:
        return (
            f"the file is for {file_key} ({file_key.variant.label}) but the valve is "
            f"{valve_key} ({valve_key.variant.label}): the parameter sets differ, even "
            "--force-type cannot upload it"
        )
    if force:
        return None
    return f"the file is for {file_key} but the valve is {valve_key} (use --force-type to upload anyway)"


# --- download -----------------------------------------------------------------------------------
def _download(args: argparse.Namespace, records: list[ValveRecord]) -> ExitCode:
    entry = select(args)
    if len(entry) != 1:
        raise BatchError(ExitCode.USAGE, "--download saves one valve: select exactly one")
    clock, printer = Stopwatch(), ProgressPrinter()
    record = ValveRecord(
        entry[0].device_id, entry[0].kind, entry[0].serial, entry[0].type_key, entry[0].firmware
    )
    records.append(record)
    try:
        can = can_options(args)
        label = getattr(args, "type_key", None)  # a valve without 0x2041 needs it
        with _open(entry[0]) if can is None else _open(entry[0], can, None, label) as session:
            values = session.download(printer.callback(str(record.serial)))
            info = session.info
    except Exception as exc:  # a Prm9Error, or whatever else the valve's answers caused
        if not isinstance(exc, Prm9Error):
            log.exception("%s: unexpected error", entry[0].device_id)
        record.error = str(exc) if isinstance(exc, Prm9Error) else _unexpected(exc)
        clock.finish(record)
        raise BatchError(ExitCode.COMMUNICATION, f"download failed: {record.error}") from exc
    contents = PrmContents(TypeKey.parse(info.type_key), values, info.serial, info.firmware or None)
    try:
        problems = write_device_file(contents, args.download)
    except FileFormatError as exc:
        record.error = str(exc)
        clock.finish(record)
        raise BatchError(ExitCode.INVALID_FILE, f"cannot save {args.download}:\n{exc}") from exc
    record.result, record.output = "downloaded", args.download
    clock.finish(record)
    history = BatchHistory.for_download(args)  # reading changes nothing: never refused
    history.download(record, values)
    history.close()
    record.parameters_written = 0
    printer.say(str(record.serial), f"saved {len(values)} parameters to {args.download}")
    for problem in problems:  # saved as the valve holds them, marked invalid in the file
        print(
            f"{args.download}: warning: the valve's set is not valid: {problem.message}",
            file=sys.stderr,
        )
    return ExitCode.OK

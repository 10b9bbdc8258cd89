"""Headless production mode: ``--list-devices`` and ``--batch`` (no Qt GUI is ever started).

``--batch FILE.prm`` uploads, verifies and stores the file into every selected valve, several
in parallel, with progress on stderr and an optional JSON report; ``--batch --download OUT.prm``
saves one valve's parameters. Usage, exit codes and report schema: docs/batch.md.
"""

from __future__ import annotations

import argparse
import logging
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from prm9tool.catalogue.typekey import TypeKey
from prm9tool.cli.batch_devices import BatchError, can_options, list_devices, open_valve, select
from prm9tool.cli.batch_history import BatchHistory
from prm9tool.cli.batch_report import (
    ProgressPrinter,
    Stopwatch,
    ValveRecord,
    overall,
    write_report,
)
from prm9tool.cli.batch_upload import UploadJob, summary, unexpected
from prm9tool.device.factory import parse_emulator_spec
from prm9tool.errors import ExitCode, FileFormatError, Prm9Error, TypeKeyError
from prm9tool.files.backup import write_device_file
from prm9tool.files.prmfile import PrmContents, read_file

log = logging.getLogger("prm9tool.cli.batch")


def run(args: argparse.Namespace) -> int:
    """Entry point of ``--list-devices`` and ``--batch``; returns the exit code."""
    records: list[ValveRecord] = []
    mode = "list" if args.list_devices else _mode(args)
    try:
        if args.list_devices:
            return list_devices(args)
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
    job = UploadJob(
        contents,
        args.force_type,
        args.dry_run,
        printer,
        history,
        open_valve,
        can_options(args),
        getattr(args, "type_key", None),
        getattr(args, "verify_by_restart", False),
    )
    try:
        with ThreadPoolExecutor(max_workers=len(entries)) as pool:
            records.extend(pool.map(job, entries))
    finally:
        history.close()
    for record in records:
        printer.say(str(record.serial), summary(record))
    return overall(records)


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
        with (
            open_valve(entry[0])
            if can is None
            else open_valve(entry[0], can, None, label) as session
        ):
            values = session.download(printer.callback(str(record.serial)))
            info = session.info
    except Exception as exc:  # a Prm9Error, or whatever else the valve's answers caused
        if not isinstance(exc, Prm9Error):
            log.exception("%s: unexpected error", entry[0].device_id)
        record.error = str(exc) if isinstance(exc, Prm9Error) else unexpected(exc)
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

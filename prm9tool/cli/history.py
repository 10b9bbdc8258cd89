"""``--history SERIAL``, ``--history-check``, ``--history-export ID``, ``--history-import``;
and the recorder the other commands use (``--history-db URL``). No Qt. docs/history.md."""

from __future__ import annotations

import argparse
import json
import sys
from typing import Any

from prm9tool.cli.json_output import emit_json
from prm9tool.errors import ExitCode, FileFormatError, HistoryError
from prm9tool.history import decoded
from prm9tool.history.chain import other_type
from prm9tool.history.recorder import Recorder


def recorder_for(args: argparse.Namespace) -> Recorder:
    """The recorder of this run (database from ``--history-db``, the environment, the setting)."""
    return Recorder(getattr(args, "history_db", None))


def run(args: argparse.Namespace) -> int:
    """Entry point of the history commands; returns the exit code."""
    recorder = recorder_for(args)
    try:
        if args.history_check:
            return _check(recorder)
        if args.history_export is not None:
            return _export(recorder, args.history_export, args.output)
        if args.history_import:
            return _import(recorder)
        return _list(recorder, args.history, args.json)
    except HistoryError as exc:
        print(f"prm9tool: {exc}", file=sys.stderr)
        return ExitCode.HISTORY
    finally:
        recorder.close()


def _list(recorder: Recorder, serial_text: str, as_json: bool | str | None) -> int:
    if not serial_text.isdigit():
        print(f"prm9tool: --history {serial_text}: a serial number is a number", file=sys.stderr)
        return ExitCode.USAGE
    records = recorder.store().records(int(serial_text))
    if as_json:
        decoded(records)
        text = json.dumps({"serial": int(serial_text), "records": records}, indent=2)
        return emit_json(text, as_json) or ExitCode.OK
    if not records:
        print(f"prm9tool: valve {serial_text} has no records in {recorder.store().shown_url}",
              file=sys.stderr)  # fmt: skip
    for record in records:
        print(summary_line(record))
    other = other_type(records)
    if other:  # a valve's type key never changes: another valve under this serial number
        numbers = ", ".join(str(records[i]["seq"]) for i in other)
        which = f"records {numbers} are" if len(other) > 1 else f"record {numbers} is"
        print(f"prm9tool: valve {serial_text}: {which} of another type key than "
              f"the newest record's ({records[-1]['type_key']}): another valve under the same "
              "serial number", file=sys.stderr)  # fmt: skip
    return ExitCode.OK


def summary_line(record: dict[str, Any]) -> str:
    """``ID  time  operation  outcome  type key  firmware  user@host`` (tab-separated)."""
    failed = f" ({record['failed_step']})" if record["failed_step"] else ""
    return "\t".join(
        [
            str(record["id"]),
            record["recorded_at"],
            record["operation"],
            record["outcome"] + failed,
            record["type_key"],
            record["firmware"],
            f"{record['os_user']}@{record['host']}",
        ]
    )


def _check(recorder: Recorder) -> int:
    store = recorder.store()
    broken = store.check()
    for problem in broken:
        print(f"prm9tool: broken chain: {problem}", file=sys.stderr)
    if broken:
        return ExitCode.VERIFY_FAILED
    print(f"{store.count()} records of {len(store.serials())} valves: every hash chain intact")
    return ExitCode.OK


def _export(recorder: Recorder, record_id: int, output: str | None) -> int:
    from prm9tool.history.export import export_record

    if not output:
        print("prm9tool: --history-export needs -o FILE.prm (or FILE.csv)", file=sys.stderr)
        return ExitCode.USAGE
    record = recorder.store().record(record_id)
    if record is None:
        print(f"prm9tool: there is no history record {record_id}", file=sys.stderr)
        return ExitCode.USAGE
    try:
        export_record(record, output)
    except (FileFormatError, ValueError) as exc:
        print(f"prm9tool: cannot export record {record_id}: {exc}", file=sys.stderr)
        return ExitCode.INVALID_FILE
    print(f"record {record_id} written to {output}")
    return ExitCode.OK


def _import(recorder: Recorder) -> int:
    from prm9tool.history.importer import import_backups

    done = import_backups(recorder.store())
    for path, problem in done.problems:
        print(f"prm9tool: {path}: not imported: {problem}", file=sys.stderr)
    print(f"{len(done.imported)} backup files imported, {done.skipped} imported before")
    return ExitCode.INVALID_FILE if done.problems else ExitCode.OK

"""``--diff A.prm B.prm`` and ``--diff A.prm --device ID``: what differs, one line each.

Prints ``MNEMONIC<TAB>A<TAB>B<TAB>unit`` per differing parameter in display units (a side
whose valve type lacks the parameter shows ``-``), or the same as JSON with ``--json``. A
parameter a side's valve type has but the side does not hold (a valve over CANopen without
this project's object; a file marking it absent) is "not on this valve": listed apart on
standard error, never a difference (issue 20 item 4). Exit 0 when everything both sides have
agrees, 1 when something differs, 3 for an invalid file, 4 when there is no such valve, 6 when
it does not answer. No Qt.
"""

from __future__ import annotations

import argparse
import json
import sys

from prm9tool.cli.json_output import emit_json
from prm9tool.compare.export import as_json, value
from prm9tool.compare.model import NOT_ON_SOURCE_VALVE, Comparison, Row, Side
from prm9tool.errors import CommunicationError, ExitCode, FileFormatError, Prm9Error
from prm9tool.files.prmfile import read_file


class DiffError(Exception):
    """Ends ``--diff`` with ``code`` and a message for stderr."""

    def __init__(self, code: ExitCode, message: str) -> None:
        super().__init__(message)
        self.code = code


def run(args: argparse.Namespace) -> int:
    """Entry point of ``--diff``; returns the exit code."""
    try:
        comparison = build(args)
    except DiffError as exc:
        print(f"prm9tool: {exc}", file=sys.stderr)
        return int(exc.code)
    if args.json:
        failed = emit_json(json.dumps(as_json(comparison), indent=2, ensure_ascii=False), args.json)
        if failed is not None:
            return failed
    else:
        for warning in comparison.warnings():
            print(f"prm9tool: warning: {warning}", file=sys.stderr)
        for row in comparison.rows:
            if row.differs:
                print(line(row))
        for note in not_on_valve_notes(comparison):
            print(f"prm9tool: {note}", file=sys.stderr)
    return ExitCode.OK if comparison.equal else ExitCode.VERIFY_FAILED


def build(args: argparse.Namespace) -> Comparison:
    """The comparison the options name (two files, or a file and a valve)."""
    first = file_side(args.diff[0])
    if len(args.diff) == 2:
        return Comparison((first, file_side(args.diff[1])))
    return Comparison((first, valve_side(args)))


def file_side(path: str) -> Side:
    """A *.prm file as one side; DiffError(3) with every problem when it is invalid."""
    try:
        contents = read_file(path)
    except FileFormatError as exc:
        message = f"{path} is not a valid parameter file:\n{exc}"
        raise DiffError(ExitCode.INVALID_FILE, message) from None
    return Side(path, contents.type_key, contents.values, NOT_ON_SOURCE_VALVE())


def valve_side(args: argparse.Namespace) -> Side:
    """The selected valve's parameters, downloaded (DiffError 4: no such valve, 6: no answer)."""
    from prm9tool.catalogue.typekey import TypeKey
    from prm9tool.cli.batch_devices import BatchError, can_options, open_entry, select

    try:
        entries = select(args)
    except BatchError as exc:
        raise DiffError(exc.code, str(exc)) from exc
    if len(entries) != 1:
        raise DiffError(ExitCode.USAGE, "--diff compares with one valve: select exactly one")
    from prm9tool.service.history import open_history
    from prm9tool.service.valve import service_for

    # a download is an operation on the valve's parameter set: the valve service records it
    warn = lambda problem: print(  # noqa: E731
        f"prm9tool: warning: history: {problem}", file=sys.stderr
    )
    history = open_history(getattr(args, "history_db", None), "--diff", warn)
    try:
        with open_entry(entries[0], can_options(args), args.type_key) as session:
            values = service_for(session, history).download()
            info = session.info
    except (CommunicationError, Prm9Error) as exc:
        raise DiffError(ExitCode.COMMUNICATION, f"reading the valve failed: {exc}") from exc
    finally:
        history.recorder.close()
    key = TypeKey.parse(info.type_key)
    return Side(f"valve {info.serial}", key, values)


def line(row: Row) -> str:
    """``MNEMONIC<TAB>A<TAB>B<TAB>unit`` (``-`` for a side that lacks the parameter)."""
    a, b = (value(row, column) or "-" for column in (0, 1))
    return f"{row.mnemonic}\t{a}\t{b}\t{row.parameter.unit}".rstrip("\t")


def not_on_valve_notes(comparison: Comparison) -> list[str]:
    """Per side, the parameters it does not hold although its valve type has them (not
    compared): ``not on this valve (valve 4711), not compared: POSKP, POSKI``."""
    notes = []
    for column, side in enumerate(comparison.sides):
        names = [row.mnemonic for row in comparison.not_on_valve if row.absent[column]]
        if names:
            notes.append(f"{side.absent} ({side.label}), not compared: {', '.join(names)}")
    return notes

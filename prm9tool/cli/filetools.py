"""Offline file commands: ``--new TYPEKEY -o FILE.prm`` and ``--check FILE.prm``.

Both run without Qt (no QtCore either), so they work on a build server or a production line
without a display. Problems are printed as ``FILE:LINE: message`` on standard output, the
summary and usage errors on standard error.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from prm9tool.catalogue.typekey import TypeKey
from prm9tool.errors import ExitCode, FileFormatError, FileProblem, Prm9Error, TypeKeyError
from prm9tool.files import eds
from prm9tool.files.prmfile import PrmContents, check_file, write_file

STDOUT = "-"  # ``-o -``: standard output, for every command that takes -o


def to_stdout(output: str | None) -> bool:
    """True when ``-o`` names standard output (``-``)."""
    return output == STDOUT


def write_stdout(data: bytes) -> None:
    """A file's bytes to standard output, whatever the console's encoding: a Windows console or
    pipe is cp1252 (or another ANSI code page) and cannot encode e.g. the unit Ω, so the text
    layer would raise UnicodeEncodeError; ``-o - > FILE`` gives the same bytes as ``-o FILE``."""
    sys.stdout.flush()
    buffer = getattr(sys.stdout, "buffer", None)
    if buffer is None:  # a replaced stream with no bytes underneath: text it can take
        encoding = getattr(sys.stdout, "encoding", None) or "utf-8"
        sys.stdout.write(data.decode("utf-8").encode(encoding, "replace").decode(encoding))
        return
    buffer.write(data)
    buffer.flush()


def run(args: argparse.Namespace) -> int:
    """Run ``--new`` or ``--check`` as given in ``args`` (argparse refuses both together);
    returns the exit code."""
    if args.new is not None:
        return new_file(args.new, args.output)
    return check(args.check)


def new_file(type_key_text: str, output: str | None) -> int:
    """Write the factory defaults of a valve type to ``output`` (``-`` = standard output).

    An existing file is never overwritten: exit code 2 and a message instead.
    """
    if not output:
        return _usage("--new needs an output file: -o FILE.prm (or -o - for standard output)")
    try:
        contents = PrmContents.factory(TypeKey.parse(type_key_text))
    except TypeKeyError as exc:
        return _usage(str(exc))
    if to_stdout(output):
        write_stdout(contents.to_text().encode("utf-8"))  # the bytes the file would hold
        return ExitCode.OK
    if Path(output).exists():
        return _usage(f"{output} already exists; --new never overwrites a file")
    try:
        written = write_file(contents, output, backup=False)
    except FileFormatError as exc:
        return _usage(str(exc))
    _print_problems(output, written.warnings)
    count = len(written.values)
    print(f"{output}: factory defaults of {contents.type_key}, {count} parameters", file=sys.stderr)
    return ExitCode.OK


def check(path: str) -> int:
    """Validate a *.prm file: 0 when it can be used (warnings allowed), 3 when not."""
    result = check_file(path)
    _print_problems(path, result.problems)
    errors = len(result.errors)
    warnings = len(result.problems) - errors
    if result.valid:
        print(f"{path}: valid ({_count(warnings, 'warning')})", file=sys.stderr)
        return ExitCode.OK
    counts = f"{_count(errors, 'error')}, {_count(warnings, 'warning')}"
    print(f"{path}: NOT valid ({counts})", file=sys.stderr)
    return ExitCode.INVALID_FILE


def _print_problems(path: str, problems: list[FileProblem]) -> None:
    for problem in problems:
        print(problem.format(path))


def _count(number: int, noun: str) -> str:
    return f"{number} {noun}{'' if number == 1 else 's'}"


def _usage(message: str) -> int:
    print(f"prm9tool: error: {message}", file=sys.stderr)
    return ExitCode.USAGE


def export_eds_command(args: argparse.Namespace) -> int:
    """``prm9tool --export-eds TYPEKEY [-o FILE.eds]`` (standard output without -o or with
    ``-o -``); returns the exit code."""
    from prm9tool.service.export import write_eds

    try:
        text = eds.export_eds(args.export_eds)
    except Prm9Error as exc:
        sys.stderr.write(f"prm9tool: {exc}\n")
        return ExitCode.USAGE
    if not args.output or to_stdout(args.output):
        sys.stdout.write(text)
        return ExitCode.OK
    path = Path(args.output)
    try:
        write_eds(path, args.export_eds)  # the valve service's, as Valve.export_eds()
    except OSError as exc:
        sys.stderr.write(f"prm9tool: cannot write {path}: {exc.strerror or exc}\n")
        return ExitCode.USAGE
    return ExitCode.OK

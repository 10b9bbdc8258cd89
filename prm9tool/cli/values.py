"""``--get MNEMONIC…`` and ``--set MNEMONIC=VALUE… [--store]``: single parameters of one valve
for shell scripts, through the Python API's :class:`~prm9tool.api.valve.Valve` (docs/api.md).

Prints ``MNEMONIC<TAB>value<TAB>unit`` per parameter (display units, as a *.prm file writes
them), or with ``--json`` one object: the valve (``--list-devices --json``'s record), the values
and their units. ``--set`` checks every value against the catalogue before it writes the first
(exit 2, nothing written), writes them in order and reads each back (exit 1 when the valve
refuses one or it reads back differently); ``--store`` then makes them permanent. Exit codes
as ``--batch`` (docs/batch.md). No Qt.
"""

from __future__ import annotations

import argparse
import json
import sys
from typing import Any

from prm9tool.api.params import display
from prm9tool.api.valve import ReadBackError, Valve
from prm9tool.catalogue import Parameter
from prm9tool.cli.batch_devices import BatchError, can_options, open_entry, select
from prm9tool.cli.json_output import emit_json
from prm9tool.device.records import Value
from prm9tool.device.session import ValveSession
from prm9tool.errors import (
    CommunicationError,
    ExitCode,
    Prm9Error,
    SdoAbortError,
    TypeKeyError,
    ValueRangeError,
)
from prm9tool.service.values import ReadOnlyError


def run(args: argparse.Namespace) -> int:
    """Entry point of ``--get``/``--set``; returns the exit code."""
    try:
        wanted = parse_assignments(args.set or [])
    except BatchError as exc:
        print(f"prm9tool: {exc}", file=sys.stderr)
        return int(exc.code)
    session = _one_session(args, "--get/--set work")
    if isinstance(session, int):
        return session
    with Valve(session, history_db=args.history_db, command="--set --store") as valve:
        try:
            return _run(args, valve, wanted)
        except BatchError as exc:
            print(f"prm9tool: {exc}", file=sys.stderr)
            return int(exc.code)


def parse_assignments(items: list[str]) -> list[tuple[str, str]]:
    """``["LIMTA=1800", …]`` → ``[("LIMTA", "1800"), …]``; BatchError(2) for a malformed one."""
    pairs = []
    for item in items:
        name, sep, text = item.partition("=")
        if not sep or not name.strip():
            raise BatchError(ExitCode.USAGE, f"--set {item}: write MNEMONIC=VALUE (LIMTA=1800)")
        pairs.append((name.strip(), text.strip()))
    return pairs


def _run(args: argparse.Namespace, valve: Valve, wanted: list[tuple[str, str]]) -> int:
    raw = _checked(valve, wanted)  # every value before the first is written
    names = [m for m, _ in wanted] + [m for m in args.get or [] if m not in raw]
    for mnemonic in args.get or []:
        _parameter(valve, mnemonic)
    doing, sent = "", []
    try:
        for mnemonic, value in raw.items():
            doing = f"--set {mnemonic}: "
            sent.append(mnemonic)  # a value read back differently was written too
            valve[mnemonic] = display(valve.parameter(mnemonic), value)
        doing = "--store: "
        if args.store and raw:
            valve.store()
        doing = ""
        values = valve.read(*names) if names else {}
    except (ReadBackError, SdoAbortError) as exc:
        raise BatchError(ExitCode.VERIFY_FAILED, _failed(doing, exc, sent)) from exc
    except CommunicationError as exc:
        raise BatchError(ExitCode.COMMUNICATION, _failed(doing, exc, sent)) from exc
    except Prm9Error as exc:  # a parameter the valve lacks on this link
        raise BatchError(ExitCode.VERIFY_FAILED, str(exc)) from exc
    params = {m: valve.parameter(m) for m in values}
    if args.json:
        text = json.dumps(as_json(valve, params, values, bool(args.store and raw)), indent=2)
        return emit_json(text, args.json) or ExitCode.OK
    for mnemonic, shown in values.items():
        print(line(params[mnemonic], shown))
    return ExitCode.OK


def _failed(doing: str, exc: Prm9Error, sent: list[str]) -> str:
    """The words of a ``--set``/``--store``/``--get`` that failed while ``doing``, with what
    it leaves in the valve (``sent``: the values written, or begun)."""
    if not doing:  # the values' final read: whatever was set (and stored) stays
        return str(exc)
    if doing == "--store: " and isinstance(exc, CommunicationError):
        return (
            f"{doing}{exc}; whether the valve stored the values is not known: read them back "
            "(--get) once it answers again"
        )
    return (
        f"{doing}{exc}; nothing was stored; until the valve restarts, it works with what it "
        f"now holds for {', '.join(sent)}"
    )


def _parameter(valve: Valve, mnemonic: str) -> Parameter:
    try:
        return valve.parameter(mnemonic)
    except KeyError as exc:
        raise BatchError(ExitCode.USAGE, str(exc.args[0])) from exc


def _checked(valve: Valve, wanted: list[tuple[str, str]]) -> dict[str, Value]:
    """Every value as the valve service checks it (prm9tool.service.values: the words of the
    API and the window), each alone and then together with what the valve holds."""
    for mnemonic, _text in wanted:
        _parameter(valve, mnemonic)
    try:
        return valve.check(dict(wanted))
    except ReadOnlyError as exc:
        raise BatchError(ExitCode.USAGE, f"--set {exc}") from exc
    except ValueRangeError as exc:
        raise BatchError(ExitCode.USAGE, f"--set: {exc}; nothing was written") from exc
    except SdoAbortError as exc:  # the caps (CURNORM) the check reads from the valve
        raise BatchError(ExitCode.VERIFY_FAILED, f"--set: {exc}; nothing was written") from exc
    except CommunicationError as exc:
        raise BatchError(ExitCode.COMMUNICATION, f"--set: {exc}; nothing was written") from exc


def line(param: Parameter, value: Any) -> str:
    """``MNEMONIC<TAB>value<TAB>unit`` (the value as a *.prm file writes it)."""
    text = param.format_display(param.to_raw(value)) if not param.is_string else str(value)
    return f"{param.mnemonic}\t{text}\t{param.unit}".rstrip("\t")


def as_json(
    valve: Valve, params: dict[str, Parameter], values: dict[str, Any], stored: bool
) -> dict[str, Any]:
    """What ``--get``/``--set --json`` print (docs/api.md)."""
    return {
        "device": valve.info.to_dict(),
        "values": values,
        "units": {m: params[m].unit for m in values},
        "stored": stored,
    }


def export_dcf(args: argparse.Namespace) -> int:
    """Entry point of ``--export-dcf OUT.dcf``: the valve's DCF, as File → Export DCF writes
    it (the valve service's ``export_dcf``); returns the exit code."""
    session = _one_session(args, "--export-dcf works")
    if isinstance(session, int):
        return session
    with Valve(session, record_history=False) as valve:
        try:
            node = valve.export_dcf(args.export_dcf)
        except TypeKeyError as exc:  # a valve without CANopen
            print(f"prm9tool: --export-dcf: {exc}", file=sys.stderr)
            return ExitCode.USAGE
        except OSError as exc:
            print(f"prm9tool: --export-dcf: cannot write {args.export_dcf}: {exc}", file=sys.stderr)
            return ExitCode.USAGE
        except Prm9Error as exc:  # 6 the link, 1 the valve refused a read
            print(f"prm9tool: --export-dcf: {exc}; no DCF was written", file=sys.stderr)
            return (
                ExitCode.COMMUNICATION
                if isinstance(exc, CommunicationError)
                else ExitCode.VERIFY_FAILED
            )
    print(f"DCF saved as {args.export_dcf} (node {node})")
    return ExitCode.OK


def _one_session(args: argparse.Namespace, what: str) -> ValveSession | int:
    """The session of the one valve the options select, or the exit code after saying why
    (``what``: "--get/--set work", the start of the refusal of several valves)."""
    try:
        entries = select(args)
        if len(entries) != 1:
            raise BatchError(ExitCode.USAGE, f"{what} on one valve: select exactly one")
        return open_entry(entries[0], can_options(args), args.type_key)
    except BatchError as exc:
        print(f"prm9tool: {exc}", file=sys.stderr)
        return int(exc.code)
    except CommunicationError as exc:
        print(f"prm9tool: {exc}", file=sys.stderr)
        return ExitCode.COMMUNICATION


__all__ = ["as_json", "export_dcf", "line", "parse_assignments", "run"]

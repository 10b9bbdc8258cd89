"""Command line: one parser for the GUI, the offline file tools and the headless batch mode.

Commands other than the GUI never import Qt's GUI modules, so they run on a production line
without a display. Each command lives in its own module and is imported only when used.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence
from typing import TYPE_CHECKING

from prm9tool.errors import ExitCode

if TYPE_CHECKING:
    from prm9tool.errors import TypeKeyError


EXIT_CODE_TEXT = {
    ExitCode.OK: "done: every valve uploaded and verified (or listed, downloaded, file valid)",
    ExitCode.VERIFY_FAILED: "a valve read back differently, refused a value or the store; "
    "nothing stored",
    ExitCode.USAGE: "usage error (options, several valves and no selection, ...)",
    ExitCode.INVALID_FILE: "invalid *.prm file (or --download cannot write its file)",
    ExitCode.NO_DEVICE: "no valve found, or none with the --device ID",
    ExitCode.TYPE_MISMATCH: "the file's type key does not fit the valve",
    ExitCode.COMMUNICATION: "communication error (valve gone, timeout, backup not written)",
    ExitCode.HISTORY: "the history database cannot be used (nothing uploaded with 'refuse')",
    ExitCode.OUT_OF_LIMITS: "--characterize: a figure is outside the acceptance profile's limits",
}
DIFF_EXIT_TEXT = "--diff: 0 equal, 1 they differ, 3 invalid file, 4 no such valve"
HISTORY_COMMANDS = {
    "--history": "history", "--history-export": "history_export",
    "--history-check": "history_check", "--history-import": "history_import",
}  # fmt: skip
# Options of the headless production mode that mean nothing anywhere else.
BATCH_ONLY = {
    "--download": "download",
    "--report": "report",
    "--dry-run": "dry_run",
    "--force-type": "force_type",
    "--all": "all",
}
FILE_TOOLS = {"--new": "new", "--check": "check", "--export-eds": "export_eds"}
CAN_OPTIONS = {"--can-interface": "can_interface", "--can-channel": "can_channel",
               "--can-bitrate": "can_bitrate"}  # fmt: skip


def add_device_options(parser: argparse.ArgumentParser) -> None:
    """Device selection shared by the GUI and the batch mode (one device factory)."""
    from prm9tool.catalogue.typekey import DEFAULT_EMULATOR_TYPE_KEY  # loaded at start anyway

    group = parser.add_argument_group("device selection")
    group.add_argument(
        "--device",
        action="append",
        default=[],
        metavar="ID",
        help="valve to use (serial number, HID path, usb:PATH, or can:NODE on the CAN bus of "
        "--can-interface); with --batch repeatable",
    )
    group.add_argument(
        "--all",
        action="store_true",
        help="with --batch: use every valve connected over USB (or found on the CAN bus)",
    )
    group.add_argument(
        "--emulator",
        action="append",
        default=[],
        nargs="?",
        const="",
        metavar="TYPEKEY[:SERIAL]",
        help="use an emulated valve of that type (the GUI goes online with it); repeatable; "
        f"without TYPEKEY {DEFAULT_EMULATOR_TYPE_KEY}",
    )
    # no defaults here: None means "not given" (usage_problem) and CanOptions fills it in
    group.add_argument(
        "--can-interface",
        help="python-can interface of the CAN bus (socketcan, pcan, kvaser, ixxat, vector, "
        "slcan, udp_multicast, virtual, ...; default: virtual): valves on it are can:NODE; "
        "an --emulator -CA valve joins it",
    )
    group.add_argument("--can-channel", help="python-can channel (default: prm9tool)")
    group.add_argument(
        "--can-bitrate", type=int, help="CAN bit rate in bit/s (default: from the valve's switches)"
    )
    group.add_argument(
        "--type-key",
        metavar="KEY",
        help="the type key on the label of a CANopen valve that does not tell its own (no "
        "object 0x2041, as real valves): checked against what its objects tell and remembered "
        "for its serial number; with --batch it goes before the file's key",
    )
    serve = parser.add_argument_group("headless emulated valves on a CAN bus (no GUI)")
    serve.add_argument(
        "--serve-emulator",
        action="append",
        default=[],
        metavar="TYPEKEY[:SERIAL]",
        help="run an emulated -CA valve on the CAN bus of --can-interface/--can-channel in real "
        "time until Ctrl+C or SIGTERM; repeatable",
    )
    serve.add_argument(
        "--node-id",
        action="append",
        type=int,
        default=[],
        metavar="N",
        help="with --serve-emulator: node ID 1-127 of the valve named at the same position",
    )


def build_parser() -> argparse.ArgumentParser:
    """The complete argument parser."""
    parser = argparse.ArgumentParser(
        prog="prm9tool",
        description="Parameterize PRM9 proportional valves (GUI, file tools, batch upload).",
        epilog=_epilog(),
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument("file", nargs="?", help="*.prm file to open in the GUI")
    parser.add_argument("--version", action="store_true", help="print the version and exit")
    files = parser.add_argument_group("offline file tools (no GUI)")
    files.add_argument(
        "--new", metavar="TYPEKEY", help="write the factory defaults for TYPEKEY to the -o file"
    )
    files.add_argument("--check", metavar="FILE.prm", help="validate a *.prm file")
    files.add_argument("--export-eds", metavar="TYPEKEY", help="write a CiA 306 EDS for TYPEKEY")
    files.add_argument(
        "-o",
        "--output",
        metavar="FILE",
        help="output file of --new or --export-eds; - is standard output",
    )
    batch = parser.add_argument_group("headless production mode (no GUI)")
    batch.add_argument("--list-devices", action="store_true", help="list valves and exit")
    batch.add_argument(
        "--batch",
        nargs="?",
        const="",
        metavar="FILE.prm",
        help="upload, verify and store FILE.prm into the selected valves",
    )
    batch.add_argument(
        "--download", metavar="OUT.prm", help="with --batch: save a valve's parameters"
    )
    batch.add_argument("--report", metavar="REPORT.json", help="with --batch: JSON report file")
    batch.add_argument(
        "--force-type",
        action="store_true",
        help="with --batch: upload even if the type key does not fit the valve",
    )
    batch.add_argument(
        "--dry-run", action="store_true", help="with --batch: check everything, write nothing"
    )
    eol = parser.add_argument_group("end-of-line test (no GUI; docs/tuning.md)")
    eol.add_argument(
        "--characterize",
        action="store_true",
        help="step responses, Bode and static characteristic of one valve (--report OUT.pdf)",
    )
    eol.add_argument(
        "--profile", metavar="LIMITS.toml", help="with --characterize: acceptance profile"
    )
    add_device_options(parser)
    add_history_options(parser)
    return parser


def add_history_options(parser: argparse.ArgumentParser) -> None:
    """``--diff`` and the history commands (docs/history.md)."""
    group = parser.add_argument_group("compare and history (no GUI)")
    group.add_argument(
        "--diff", nargs="+", metavar="FILE.prm",
        help="compare two *.prm files, or one with the valve of --device/--emulator",
    )  # fmt: skip
    group.add_argument(
        "--json", nargs="?", const=True, metavar="OUT.json",
        help="with --diff, --history: print JSON; with --characterize: the JSON report file",
    )  # fmt: skip
    group.add_argument("--history", metavar="SERIAL", help="list the history of a valve")
    group.add_argument(
        "--history-check", action="store_true", help="verify every valve's hash chain"
    )
    group.add_argument(
        "--history-export", type=int, metavar="ID", help="write record ID to -o FILE.prm/.csv"
    )
    group.add_argument(
        "--history-import", action="store_true", help="import the old backup files once"
    )
    group.add_argument(
        "--history-db", metavar="URL",
        help="history database (default: SQLite in the user data dir; postgresql+psycopg://…)",
    )  # fmt: skip
    group.add_argument(
        "--history-unreachable", choices=("refuse", "queue"),
        help="with --batch, if the history database cannot be reached: refuse to upload "
        "(default) or upload and keep the records in a local queue",
    )  # fmt: skip


def _epilog() -> str:
    codes = "\n".join(f"  {int(code)}  {text}" for code, text in EXIT_CODE_TEXT.items())
    return (
        f"exit codes:\n{codes}\n  {DIFF_EXIT_TEXT}\n\n"
        "headless production mode: README.md, docs/batch.md; USB protocol: docs/usb-protocol.md"
    )


def usage_problem(args: argparse.Namespace) -> str | None:
    """What makes no sense in this combination of options (None: nothing), before anything runs.

    The GUI takes a file, ``--emulator`` and one ``--device``; the batch-only options need
    ``--batch``; ``--list-devices`` takes ``--emulator`` and the CAN options. The CAN options
    name a bus: the one of ``can:NODE`` devices, ``--list-devices``, ``--batch`` and
    ``--serve-emulator``, or the one the GUI's emulated -CA valve joins; a file tool takes
    none (an option that would be ignored is an error, not a surprise).
    """
    if args.type_key is not None:
        problem = _type_key_problem(args)
        if problem is not None:
            return problem
    if args.characterize:
        return _characterize_problem(args)
    if args.profile:
        return "--profile belongs to --characterize"
    if isinstance(args.json, str):
        return "--json OUT.json belongs to --characterize (--diff and --history print JSON)"
    problem = _compare_history_problem(args)
    if problem is not None:
        return problem
    batch_only = [flag for flag, dest in BATCH_ONLY.items() if getattr(args, dest)]
    tools = [flag for flag, dest in FILE_TOOLS.items() if getattr(args, dest) is not None]
    command = _command(args)
    if " and " in command:
        return f"{command} are separate commands: use one at a time"
    if command and tools:
        return f"{command} and {tools[0]} are separate commands: use one at a time"
    can = [flag for flag, dest in CAN_OPTIONS.items() if getattr(args, dest) is not None]
    if can and tools:
        return f"{can[0]} names a CAN bus; {tools[0]} does not use CAN"
    if command == "--serve-emulator":
        return _serve_problem(args, batch_only)
    if args.node_id:
        return "--node-id belongs to --serve-emulator"
    if can and not command and not args.emulator and not _can_devices(args):
        return (
            f"{can[0]} names a CAN bus: use it with --device can:NODE, --list-devices, --batch "
            "or --emulator TYPEKEY"
        )
    if command and args.emulator and can:
        return (
            f"{command} with --emulator uses the emulated valve over USB; to put one on the CAN "
            "bus, run prm9tool --serve-emulator in another process"
        )
    if command == "--list-devices":
        return _list_devices_problem(args, batch_only)
    if command == "--batch":
        return _batch_problem(args)
    if batch_only:
        return f"{batch_only[0]} belongs to the headless production mode: use it with --batch"
    if not tools and len(args.device) > 1:
        return "the GUI goes online with one valve: give --device once (several: --batch)"
    return None


def _command(args: argparse.Namespace) -> str:
    if args.serve_emulator:
        others = [
            flag
            for flag, given in (("--list-devices", args.list_devices), ("--batch", args.batch))
            if given not in (None, False)
        ]
        return "--serve-emulator" if not others else f"--serve-emulator and {others[0]}"
    return "--list-devices" if args.list_devices else "--batch" if args.batch is not None else ""


def _type_key_problem(args: argparse.Namespace) -> str | None:
    from prm9tool.catalogue.typekey import TypeKey
    from prm9tool.errors import TypeKeyError

    on_can = _can_devices(args) or (args.all and args.can_interface is not None)
    if not on_can or args.serve_emulator:
        return (
            "--type-key belongs to a valve on a CAN bus: use it with --device can:NODE (or "
            "--batch --all with the CAN options)"
        )
    try:
        key = TypeKey.parse(args.type_key)
    except TypeKeyError as exc:
        return f"--type-key: {exc}"
    if not key.canopen:
        return f"--type-key {key}: a valve on a CAN bus is a -CA valve"
    return None


def _can_devices(args: argparse.Namespace) -> list[str]:
    return [d for d in args.device if d.startswith("can:")]


def _serve_problem(args: argparse.Namespace, batch_only: list[str]) -> str | None:
    if args.can_interface is None:
        return "--serve-emulator needs --can-interface (and --can-channel) naming the bus"
    extra = batch_only + [
        f for f, v in (("--device", args.device), ("--emulator", args.emulator)) if v
    ]
    if args.file:
        extra.append(f"the file {args.file}")
    if extra:
        return f"--serve-emulator runs emulated valves on a bus and takes no {extra[0]}"
    if len(args.node_id) > len(args.serve_emulator):
        return "give at most one --node-id per --serve-emulator"
    bad = [n for n in args.node_id if not 1 <= n <= 127]
    if bad:
        return f"--node-id {bad[0]}: CANopen node IDs are 1…127"
    return None


def _characterize_problem(args: argparse.Namespace) -> str | None:
    options = {**BATCH_ONLY, **FILE_TOOLS, **HISTORY_COMMANDS, "--diff": "diff"}
    others = [flag for flag, dest in options.items()
              if dest != "report" and getattr(args, dest) not in (None, False)]  # fmt: skip
    if args.batch is not None or args.list_devices:
        others.insert(0, "--batch" if args.batch is not None else "--list-devices")
    if others:
        return f"--characterize and {others[0]} are separate commands: use one at a time"
    if args.file:
        return f"unexpected file {args.file}: --characterize tests a valve"
    if args.json is True:
        return "--characterize writes its JSON report to a file: --json OUT.json"
    return None


def _compare_history_problem(args: argparse.Namespace) -> str | None:
    history = [
        flag for flag, dest in HISTORY_COMMANDS.items() if getattr(args, dest) not in (None, False)
    ]
    commands = history + (["--diff"] if args.diff else [])
    others = [flag for flag, dest in FILE_TOOLS.items() if getattr(args, dest) is not None]
    others += ["--batch"] * (args.batch is not None) + ["--list-devices"] * args.list_devices
    if len(commands) > 1 or (commands and others):
        return f"{commands[0]} and {(commands[1:] + others)[0]} are separate commands: use one at a time"
    if args.json and commands not in (["--diff"], ["--history"]):
        return "--json belongs to --diff and --history"
    if args.history_unreachable and args.batch is None:
        return "--history-unreachable belongs to the headless production mode (--batch)"
    if args.diff:
        return _diff_problem(args)
    if history and (args.device or args.emulator or args.file):
        return f"{history[0]} works on the history database, not on a valve or file"
    return None


def _diff_problem(args: argparse.Namespace) -> str | None:
    valve = bool(args.device or args.emulator)
    if len(args.diff) > 2:
        return "--diff compares two files (or one file and a valve)"
    if len(args.diff) == 2 and valve:
        return "--diff with two files compares them: leave out --device/--emulator"
    if len(args.diff) == 1 and not valve:
        return "--diff with one file compares it with a valve: add --device ID or --emulator"
    if args.all or args.file:
        return "--diff compares with one valve: --all and a file to open do not fit"
    return None


def _list_devices_problem(args: argparse.Namespace, batch_only: list[str]) -> str | None:
    given = {"--batch": args.batch is not None, "--device": args.device, "-o": args.output}
    extra = batch_only + [flag for flag, value in given.items() if value]
    if args.file:
        extra.append(f"the file {args.file}")
    if not extra:
        return None
    return (
        f"--list-devices lists every valve and takes only --emulator and the CAN options, "
        f"not {extra[0]}"
    )


def _batch_problem(args: argparse.Namespace) -> str | None:
    if args.file:
        return f"unexpected file {args.file}: name the file to upload right after --batch"
    if args.output:
        return "-o/--output belongs to --new and --export-eds (--batch --download OUT.prm)"
    return None


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of ``prm9tool`` and ``python -m prm9tool``; returns the exit code."""
    parser = build_parser()
    try:
        args = parser.parse_args(argv)
        problem = usage_problem(args)
        if problem:
            parser.error(problem)
    except SystemExit as exc:
        return int(exc.code or 0)
    if args.version:
        from prm9tool import __version__

        print(f"prm9tool {__version__}")
        return ExitCode.OK
    spools_problem = _load_user_spools()
    if args.new is not None or args.check is not None:
        from prm9tool.cli import filetools as prmcli

        return prmcli.run(args)
    if args.export_eds is not None:
        from prm9tool.cli import filetools as prmcli

        return prmcli.export_eds_command(args)
    if args.serve_emulator:
        from prm9tool.cli.serve import run as run_serve

        return run_serve(args)
    if args.characterize:
        from prm9tool.cli.characterize import run as run_characterize
        from prm9tool.cli.history import recorder_for
        from prm9tool.online.characterization_history import record_characterizations

        recorder = recorder_for(args)  # the end-of-line result goes into the history
        forget = record_characterizations(recorder)
        try:
            return run_characterize(args)
        finally:
            forget()
            recorder.close()
    if args.diff:
        from prm9tool.cli.diff import run as run_diff

        return run_diff(args)
    if any(getattr(args, dest) not in (None, False) for dest in HISTORY_COMMANDS.values()):
        from prm9tool.cli.history import run as run_history

        return run_history(args)
    if args.list_devices or args.batch is not None:
        from prm9tool.cli.batch import run as run_batch

        return run_batch(args)
    from prm9tool.app import run as run_app

    return run_app(args, spools_problem)


def _load_user_spools() -> TypeKeyError | None:
    """Extend the spool catalogue with ``<user data dir>/spools.json`` (type key: manual §8.7.1).

    A broken file is reported on standard error (the GUI shows the returned error as well) and
    left out: type keys with the spools the program ships keep working, and one with a
    missing spool says which spools are known.
    """
    from prm9tool.catalogue.typekey import load_user_spools
    from prm9tool.errors import TypeKeyError
    from prm9tool.paths import user_data_dir

    try:
        load_user_spools(user_data_dir())
    except TypeKeyError as exc:
        print(f"prm9tool: warning: {exc}; using the spools shipped with prm9tool", file=sys.stderr)
        return exc
    return None


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())

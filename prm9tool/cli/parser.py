"""The command line's argument parser: the GUI's file, the offline file tools, the headless
production mode, the end-of-line test, device selection, compare and history (docs/batch.md)."""

from __future__ import annotations

import argparse
from typing import NoReturn

from prm9tool.errors import ExitCode

EXIT_CODE_TEXT = {
    ExitCode.OK: "done: every valve uploaded and verified (or listed, downloaded, file valid)",
    ExitCode.VERIFY_FAILED: "a valve read back differently, refused a value or the store; "
    "nothing stored; --enable: the valve refused to be enabled",
    ExitCode.USAGE: "usage error (options, several valves and no selection, ...)",
    ExitCode.INVALID_FILE: "invalid *.prm file (or --download cannot write its file)",
    ExitCode.NO_DEVICE: "no valve found, or none with the --device ID",
    ExitCode.TYPE_MISMATCH: "the file's type key does not fit the valve",
    ExitCode.COMMUNICATION: "communication error (valve gone, timeout, backup not written)",
    ExitCode.HISTORY: "the history database cannot be used (nothing uploaded with 'refuse'); "
    "--signature: no birth certificate in the history",
    ExitCode.OUT_OF_LIMITS: "--characterize: a figure is outside the acceptance profile's limits; "
    "--autotune: the proposal fails it; --signature: a figure drifted beyond its limit",
}
DIFF_EXIT_TEXT = "--diff: 0 equal, 1 they differ, 3 invalid file, 4 no such valve"

# A refusal's usage: one line, not the 27 lines of the whole usage before its one sentence
SHORT_USAGE = "usage: prm9tool [options] [file] — prm9tool --help lists them"


class Parser(argparse.ArgumentParser):
    """argparse's parser whose refusals print :data:`SHORT_USAGE` and the sentence (exit 2);
    ``--help`` prints the whole usage, as argparse's."""

    def error(self, message: str) -> NoReturn:
        self.exit(ExitCode.USAGE, f"{SHORT_USAGE}\n{self.prog}: error: {message}\n")


def add_device_options(parser: argparse.ArgumentParser) -> None:
    """Device selection shared by the GUI and the batch mode (one device factory)."""
    from prm9tool.catalogue.can_adapters import EVERYWHERE, adapters
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
        f"without TYPEKEY {DEFAULT_EMULATOR_TYPE_KEY}; twin:FILE the twin of a measured valve "
        "(a --fit-twin file: its serial, plant and parameters)",
    )
    # no defaults here: None means "not given" (usage_problem) and CanOptions fills it in
    group.add_argument(
        "--can-interface",
        help="python-can interface of the CAN bus (this system's, each with its usual "
        "--can-channel: "
        + ", ".join(f"{a.interface} {a.channel}" for a in adapters() if a not in EVERYWHERE)
        + "; udp_multicast, virtual, ...; default: virtual): valves on it are can:NODE; an "
        "--emulator -CA valve joins it",
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
    group.add_argument(
        "--od",
        choices=("full", "manual"),
        help="object dictionary of --emulator/--serve-emulator valves over CANopen: full (every "
        "object of the catalogue, store with 0x1010; default) or manual (only the objects the "
        "manual's tables 7-13/7-14/7-16 list; the valve keeps what is written)",
    )
    serve = parser.add_argument_group("headless emulated valves on a CAN bus (no GUI)")
    serve.add_argument(
        "--serve-emulator",
        action="append",
        default=[],
        metavar="TYPEKEY[:SERIAL]",
        help="run an emulated -CA valve on the CAN bus of --can-interface/--can-channel in real "
        "time until Ctrl+C or SIGTERM; repeatable; twin:FILE the twin of a measured valve",
    )
    serve.add_argument(
        "--node-id",
        action="append",
        type=node_id_arg,
        default=[],
        metavar="N",
        help="with --serve-emulator: node ID 1-127 of the valve named at the same position, "
        "or 'lss': node-ID switch at 1, no node ID until an LSS master gives one",
    )
    lss_group = parser.add_argument_group("valves without a node ID: LSS, CiA 305 (no GUI)")
    lss = lss_group.add_mutually_exclusive_group()  # one LSS command at a time (argparse says so)
    lss.add_argument(
        "--lss-scan",
        action="store_true",
        help="list the devices on the CAN bus that have no node ID (Fastscan); --json",
    )
    lss.add_argument(
        "--lss-assign",
        nargs="+",
        metavar="SERIAL=NODE",
        help="give each valve without a node ID its node ID and store it; exit 0 only when "
        "every one then answers at its node ID",
    )
    lss.add_argument(
        "--find-bitrate",
        action="store_true",
        help="find the bit rate of the CAN bus by listening (listen-only adapters: pcan, "
        "kvaser, vector, slcan); never transmits",
    )


def node_id_arg(text: str) -> int | str:
    """``--node-id``: a number, or ``lss`` (node-ID switch at 1)."""
    if text.strip().lower() == "lss":
        return "lss"
    try:
        return int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is neither a node ID 1-127 nor 'lss'") from None


def build_parser() -> argparse.ArgumentParser:
    """The complete argument parser."""
    parser = Parser(
        prog="prm9tool",
        description="Parameterize PRM9 proportional valves (GUI, file tools, batch upload).",
        epilog=_epilog(),
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument("file", nargs="?", help="*.prm file to open in the GUI")
    parser.add_argument("--version", action="store_true", help="print the version and exit")
    files = parser.add_argument_group("offline file tools (no GUI)")
    tool = files.add_mutually_exclusive_group()  # one file tool at a time
    tool.add_argument(
        "--new", metavar="TYPEKEY", help="write the factory defaults for TYPEKEY to the -o file"
    )
    tool.add_argument("--check", metavar="FILE.prm", help="validate a *.prm file")
    tool.add_argument("--export-eds", metavar="TYPEKEY", help="write a CiA 306 EDS for TYPEKEY")
    files.add_argument(
        "-o",
        "--output",
        metavar="FILE",
        help="output file of --new or --export-eds; - is standard output",
    )
    batch = parser.add_argument_group("headless production mode (no GUI)")
    listing = batch.add_mutually_exclusive_group()  # list the valves, or upload into them
    listing.add_argument("--list-devices", action="store_true", help="list valves and exit")
    listing.add_argument(
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
        "--verify-by-restart",
        action="store_true",
        help="with --batch over CANopen: after the store, restart the valve (NMT reset node: "
        "the spool drops — hydraulics off!) and read every value back",
    )
    batch.add_argument(
        "--force-type",
        action="store_true",
        help="with --batch: upload even if the type key does not fit the valve",
    )
    batch.add_argument(
        "--dry-run", action="store_true", help="with --batch: check everything, write nothing"
    )
    eol = parser.add_argument_group(
        "tests and commands of one valve (no GUI; docs/tuning.md, docs/api.md)"
    )
    test = eol.add_mutually_exclusive_group()  # one test or command of a valve at a time
    test.add_argument(
        "--characterize",
        action="store_true",
        help="step responses, Bode and static characteristic of one valve (--report OUT.pdf)",
    )
    eol.add_argument(
        "--profile", metavar="LIMITS.toml", help="with --characterize: acceptance profile"
    )
    eol.add_argument(
        "--enable", action="store_true",
        help="enable the valve as its CANopen master would (NMT start, control word 08h → 09h "
        "→ 0Bh → 0Fh; a -CA valve as delivered waits for that): alone, enable the one valve of "
        "--device/--emulator and exit; with --characterize, --autotune, --fit-twin, "
        "--signature first, before the test; the valve then follows its setpoint: needs "
        "--hydraulics-safe",
    )  # fmt: skip
    test.add_argument(
        "--disable", action="store_true",
        help="control word 0Fh → 0Bh → 09h → 08h: the valve back to INIT, no longer following "
        "its setpoint (the spool returns to its rest position): needs --hydraulics-safe",
    )  # fmt: skip
    test.add_argument(
        "--restart", action="store_true",
        help="restart the valve's electronics, as Valve → Restart valve (the spool returns to "
        "its spring-centred position: hydraulics disconnected!, --hydraulics-safe; a -CA valve "
        "comes back waiting for its master) and print how it came back; recorded; --json "
        "[OUT.json]",
    )  # fmt: skip
    test.add_argument(
        "--restore-factory", action="store_true",
        help="as Valve → Restore factory values: the valve's backup file (if it has none), the "
        "factory values stored, the restart that makes them effective (hydraulics "
        "disconnected!, --hydraulics-safe); recorded; --json [OUT.json]",
    )  # fmt: skip
    eol.add_argument(
        "--hydraulics-safe", action="store_true",
        help="the answer to the window's hydraulics question, for --enable, --disable, "
        "--restart and --restore-factory: the hydraulics are safe for the spool to move "
        "(disconnected, for a restart)",
    )  # fmt: skip
    test.add_argument(
        "--autotune", nargs="?", const="position", choices=("position", "process"),
        metavar="LOOP",
        help="the Tuning window's autotune of the one valve of --device/--emulator (LOOP: "
        "position, or process on E04): gains proposed and checked against --profile, the "
        "valve's own gains back after; --json [OUT.json] or --report OUT.json for the record",
    )  # fmt: skip
    eol.add_argument(
        "--apply", action="store_true",
        help="with --autotune: write the proposed gains and store them (only a proposal that "
        "passes the profile and rests on a trustworthy model)",
    )  # fmt: skip
    test.add_argument(
        "--signature", action="store_true",
        help="the field signature of one valve (≤ 20 s of motion) against its birth "
        "certificate in the history (its end-of-line test): the drift in words, --report "
        "OUT.pdf, --json [OUT.json]; exit 0 no drift, 8 drifted, 7 no birth certificate",
    )  # fmt: skip
    test.add_argument(
        "--fit-twin", metavar="OUT.toml",
        help="fit the valve's twin (plant constants, docs/twin.md) from --from RUN.json, or "
        "characterize the one valve of --device/--emulator (--profile) and fit from that run; "
        "--json [OUT.json] for the fit report",
    )  # fmt: skip
    eol.add_argument(
        "--from", dest="fit_from", metavar="RUN.json",
        help="with --fit-twin: a --characterize JSON report (its CSV files beside it: steps, "
        "sweep, static characteristic)",
    )  # fmt: skip
    values = parser.add_argument_group("single parameters for shell scripts (no GUI; docs/api.md)")
    values.add_argument(
        "--get", nargs="+", metavar="MNEMONIC",
        help="print parameters of the valve of --device/--emulator in display units",
    )  # fmt: skip
    values.add_argument(
        "--set", nargs="+", metavar="MNEMONIC=VALUE",
        help="write parameters (all checked first, each read back); not stored without --store",
    )  # fmt: skip
    values.add_argument(
        "--store", action="store_true", help="with --set: store the working values permanently"
    )
    values.add_argument(
        "--export-dcf", metavar="OUT.dcf",
        help="write the CiA 306 DCF of the valve of --device/--emulator (its working values, "
        "node ID and bit rate), as File → Export DCF does",
    )  # fmt: skip
    add_device_options(parser)
    add_history_options(parser)
    from prm9tool.cli.trace import add_trace_options

    add_trace_options(parser)
    return parser


def add_history_options(parser: argparse.ArgumentParser) -> None:
    """``--diff`` and the history commands (docs/history.md)."""
    group = parser.add_argument_group("compare and history (no GUI)")
    command = group.add_mutually_exclusive_group()  # --diff or one history command
    command.add_argument(
        "--diff", nargs="+", metavar="FILE.prm",
        help="compare two *.prm files, or one with the valve of --device/--emulator",
    )  # fmt: skip
    group.add_argument(
        "--json", nargs="?", const=True, metavar="OUT.json",
        help="with --diff, --history, --get/--set, --list-devices, --decode, --replay, "
        "--autotune, --restart, --restore-factory, --enable, --disable: print JSON (or write "
        "it to OUT.json); with --characterize, --decode, --replay: the JSON report file",
    )  # fmt: skip
    command.add_argument("--history", metavar="SERIAL", help="list the history of a valve")
    command.add_argument(
        "--history-check", action="store_true", help="verify every valve's hash chain"
    )
    command.add_argument(
        "--history-export", type=int, metavar="ID", help="write record ID to -o FILE.prm/.csv"
    )
    command.add_argument(
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

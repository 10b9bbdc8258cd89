"""Which combinations of command-line options make sense: checked before anything runs, so an
option that would be ignored is an error, not a surprise.

Where argparse can say it, the parser does (``cli/parser.py``: mutually exclusive groups for
the LSS commands, the file tools, ``--list-devices`` and ``--batch``, the tests and commands
of a valve — ``--characterize``, ``--autotune``, ``--signature``, ``--fit-twin``,
``--restart``, ``--restore-factory``, ``--disable`` — and ``--diff`` with the history commands,
``choices`` for ``--autotune LOOP``); the checks here are the ones argparse cannot express: an
option that modifies a command (``--store`` of ``--set``, ``--apply`` of ``--autotune``,
``--enable`` of a test or alone), a command with an option or a device of another group, a
number of values argparse's ``nargs`` cannot say (``--diff`` one or two files), a value
judged against another option. tests/test_cli_usage.py shows each one's words."""

from __future__ import annotations

import argparse

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
    "--verify-by-restart": "verify_by_restart",
}
VALUE_COMMANDS = {"--get": "get", "--set": "set", "--store": "store", "--export-dcf": "export_dcf"}
FILE_TOOLS = {"--new": "new", "--check": "check", "--export-eds": "export_eds"}
CAN_OPTIONS = {"--can-interface": "can_interface", "--can-channel": "can_channel",
               "--can-bitrate": "can_bitrate"}  # fmt: skip


def usage_problem(args: argparse.Namespace) -> str | None:
    """What makes no sense in this combination of options (None: nothing), before anything runs.

    The GUI takes a file, ``--emulator`` and one ``--device``; the batch-only options need
    ``--batch``; ``--list-devices`` takes ``--emulator`` and the CAN options. The CAN options
    name a bus: the one of ``can:NODE`` devices, ``--list-devices``, ``--batch`` and
    ``--serve-emulator``, or the one the GUI's emulated -CA valve joins; a file tool takes
    none (an option that would be ignored is an error, not a surprise).
    """
    from prm9tool.cli.trace import trace_command, trace_problem

    problem = trace_problem(args)
    if problem is not None or trace_command(args):
        return problem
    if args.type_key is not None:
        problem = _type_key_problem(args)
        if problem is not None:
            return problem
    from prm9tool.cli.lss import lss_problem

    problem = lss_problem(args)
    if problem is not None or any(
        getattr(args, d) for d in ("lss_scan", "lss_assign", "find_bitrate")
    ):
        return problem
    if args.fit_twin is not None or args.fit_from is not None:
        return _fit_twin_problem(args)
    if args.signature:
        return _signature_problem(args)
    if args.characterize or args.autotune is not None:
        return _characterize_problem(args)
    from prm9tool.cli.valve_commands import command_of

    if command_of(args) is not None:
        return _valve_command_problem(args)
    if args.apply:
        return "--apply belongs to --autotune (it applies the proposed gains)"
    if args.hydraulics_safe:
        return (
            "--hydraulics-safe answers the hydraulics question of --enable, --disable, "
            "--restart or --restore-factory: add one of them, or leave it out"
        )
    if args.get or args.set or args.store or args.export_dcf:
        return _values_problem(args)
    if args.profile:
        return "--profile belongs to --characterize or --autotune"
    if getattr(args, "od", None) and not (args.emulator or args.serve_emulator):
        return "--od chooses the object dictionary of --emulator or --serve-emulator valves"
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


def _fit_twin_problem(args: argparse.Namespace) -> str | None:
    if args.fit_twin is None:
        return "--from RUN.json belongs to --fit-twin OUT.toml"
    if args.fit_from is None:
        if len(args.emulator) + len(args.device) != 1:
            return (
                "--fit-twin OUT.toml needs --from RUN.json (a --characterize JSON report) or "
                "one valve to characterize: --device ID or --emulator KEY"
            )
        others = [
            flag
            for flag, given in (
                ("--batch", args.batch is not None), ("--list-devices", args.list_devices),
                (f"file {args.file}", args.file),
            )
            if given
        ]  # fmt: skip
        if others:
            return f"--fit-twin --device/--emulator takes no {others[0]}"
        if args.hydraulics_safe and not args.enable:
            return "--hydraulics-safe confirms --enable: add --enable, or leave it out"
        return None
    others = [
        flag
        for flag, given in (
            ("--device", args.device), ("--emulator", args.emulator), ("--batch", args.batch is not None),
            ("--list-devices", args.list_devices), ("--profile", args.profile),
            ("--enable", args.enable), (f"file {args.file}", args.file),
        )
        if given
    ]  # fmt: skip
    if others:
        return f"--fit-twin --from RUN.json takes no {others[0]}"
    return None


def _command(args: argparse.Namespace) -> str:
    # --list-devices and --batch: argparse refuses the pair (one exclusive group)
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
    bad = [n for n in args.node_id if n != "lss" and not 1 <= int(n) <= 127]
    if bad:
        return f"--node-id {bad[0]}: CANopen node IDs are 1…127"
    return None


def _characterize_problem(args: argparse.Namespace) -> str | None:
    """--characterize's and --autotune's: tests that move one valve."""
    command = "--characterize" if args.characterize else "--autotune"
    options = {**BATCH_ONLY, **FILE_TOOLS, **HISTORY_COMMANDS, "--diff": "diff", **VALUE_COMMANDS}
    others = [flag for flag, dest in options.items()
              if dest != "report" and getattr(args, dest) not in (None, False)]  # fmt: skip
    if args.batch is not None or args.list_devices:
        others.insert(0, "--batch" if args.batch is not None else "--list-devices")
    if others:
        return f"{command} and {others[0]} are separate commands: use one at a time"
    if args.file:
        return f"unexpected file {args.file}: {command} tests a valve"
    if args.apply and args.characterize:
        return "--apply belongs to --autotune (it applies the proposed gains)"
    if args.json is True and args.characterize:
        return "--characterize writes its JSON report to a file: --json OUT.json"
    if args.hydraulics_safe and not args.enable:
        return "--hydraulics-safe confirms --enable: add --enable, or leave it out"
    return None


def _valve_command_problem(args: argparse.Namespace) -> str | None:
    """``--restart``, ``--restore-factory``, ``--enable``, ``--disable``: one valve, no other
    command, the hydraulics question answered (``--hydraulics-safe``)."""
    from prm9tool.cli.valve_commands import COMMANDS, command_of, confirmation_problem

    flag = command_of(args)
    assert flag is not None
    given = [f for f, dest in COMMANDS.items() if getattr(args, dest)]
    if len(given) > 1:  # --enable is also --characterize's: argparse cannot refuse the pair
        return f"{given[0]} and {given[1]} are separate commands: use one at a time"
    others = {**VALUE_COMMANDS, "--apply": "apply", "--profile": "profile", "--node-id": "node_id"}
    problem = _one_valve_problem(args, flag, others)
    if problem:
        return problem
    if not args.hydraulics_safe:
        return confirmation_problem(flag)
    return None


def _signature_problem(args: argparse.Namespace) -> str | None:
    if len(args.emulator) + len(args.device) != 1:
        return "--signature tests one valve: give one --device or --emulator"
    problem = _characterize_problem(args)
    if problem is not None and "--json OUT.json" not in problem:
        return problem.replace("--characterize", "--signature")
    return None


def _compare_history_problem(args: argparse.Namespace) -> str | None:
    history = [
        flag for flag, dest in HISTORY_COMMANDS.items() if getattr(args, dest) not in (None, False)
    ]
    commands = history + (["--diff"] if args.diff else [])
    others = [flag for flag, dest in FILE_TOOLS.items() if getattr(args, dest) is not None]
    others += ["--batch"] * (args.batch is not None) + ["--list-devices"] * args.list_devices
    if commands and others:  # two of them together: argparse refuses (one exclusive group)
        return f"{commands[0]} and {others[0]} are separate commands: use one at a time"
    if args.json and commands not in (["--diff"], ["--history"]) and not args.list_devices:
        return (
            "--json [OUT.json] belongs to --diff, --history, --get/--set, --list-devices, "
            "--lss-scan, --characterize and --autotune"
        )
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
    given = {"--device": args.device, "-o": args.output}  # --batch: argparse refuses it
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


def _values_problem(args: argparse.Namespace) -> str | None:
    """``--get``/``--set [--store]``: one valve, no other command."""
    if args.store and not args.set:
        return "--store belongs to --set (it stores the values --set writes)"
    if args.export_dcf and (args.get or args.set):
        return f"--export-dcf and {'--set' if args.set else '--get'} are separate commands: use one at a time"
    name = "--set" if args.set else "--get" if args.get else "--export-dcf"
    if args.export_dcf and args.json:
        return "--export-dcf writes the DCF file it names; --json does not belong to it"
    return _one_valve_problem(args, name, {})


def _one_valve_problem(
    args: argparse.Namespace, name: str, also_refused: dict[str, str]
) -> str | None:
    """A command of one valve (``name``): no other command beside it (nor ``also_refused``),
    no file, exactly one valve, and no bus options for an emulated (USB) valve."""
    commands = {**BATCH_ONLY, **FILE_TOOLS, **HISTORY_COMMANDS, "--diff": "diff",
                "--serve-emulator": "serve_emulator", "--list-devices": "list_devices",
                **also_refused}  # fmt: skip
    others = [f for f, dest in commands.items() if getattr(args, dest) not in (None, False, [])]
    others = ["--batch"] * (args.batch is not None) + others
    if others:
        return f"{name} and {others[0]} are separate commands: use one at a time"
    if args.file:
        return f"unexpected file {args.file}: {name} works on a valve"
    if len(args.device) + len(args.emulator) != 1:
        return f"{name} works on one valve: give one --device ID or --emulator TYPEKEY[:SERIAL]"
    can = [f for f, dest in CAN_OPTIONS.items() if getattr(args, dest) is not None]
    if can and args.emulator:
        return (
            f"{name} with --emulator uses the emulated valve over USB; {can[0]} names a bus for "
            "--device can:NODE"
        )
    return None

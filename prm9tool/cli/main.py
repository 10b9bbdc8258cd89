"""Command line: one parser for the GUI, the offline file tools and the headless batch mode.

Commands other than the GUI never import Qt's GUI modules, so they run on a production line
without a display. Each command lives in its own module and is imported only when used.
"""

from __future__ import annotations

import argparse
import importlib
import sys
from collections.abc import Sequence
from typing import TYPE_CHECKING

from prm9tool.cli.parser import build_parser
from prm9tool.cli.usage import HISTORY_COMMANDS, usage_problem
from prm9tool.errors import ExitCode

if TYPE_CHECKING:
    from prm9tool.errors import TypeKeyError


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
        from prm9tool.buildinfo import build_info, qt_version

        print(build_info().line(qt_version()))
        return ExitCode.OK
    if args.od:
        from prm9tool.device.emulated_valves import set_emulator_od

        set_emulator_od(args.od)
    # the CAN libraries' warnings as prm9tool's messages, not their raw log lines
    from prm9tool.device.canlink.liblog import route_library_logs

    undo = route_library_logs(lambda message: print(f"prm9tool: {message}", file=sys.stderr))
    try:
        spools_problem = _load_user_spools()
        command = _headless_command(args)
        from prm9tool.cli.trace import recording

        with recording(args):  # --record beside the command, on its bus
            if command is not None:
                module, function = command
                return int(getattr(importlib.import_module(module), function)(args))
            from prm9tool.app import run as run_app

            return run_app(args, spools_problem)
    finally:
        undo()


def _headless_command(args: argparse.Namespace) -> tuple[str, str] | None:
    """The module and function that run the command ``args`` name (None: the GUI)."""
    from prm9tool.cli.trace import trace_command

    if (command := trace_command(args)) is not None:
        return command
    if args.new is not None or args.check is not None:
        return "prm9tool.cli.filetools", "run"
    if args.export_eds is not None:
        return "prm9tool.cli.filetools", "export_eds_command"
    if args.serve_emulator:
        return "prm9tool.cli.serve", "run"
    if args.lss_scan or args.lss_assign or args.find_bitrate:
        return "prm9tool.cli.lss", "run"
    tests = (args.characterize, args.autotune is not None, args.fit_twin is not None,
             args.signature)  # fmt: skip
    if args.restart or args.restore_factory or args.disable or (args.enable and not any(tests)):
        return "prm9tool.cli.valve_commands", "run"  # --enable alone: enable and exit
    if args.characterize:
        return "prm9tool.cli.main", "_characterize"
    if args.autotune is not None:
        return "prm9tool.cli.autotune", "run"
    if args.fit_twin is not None:
        return "prm9tool.cli.twin", "run"
    if args.signature:
        return "prm9tool.cli.signature", "run"
    if args.diff:
        return "prm9tool.cli.diff", "run"
    if any(getattr(args, dest) not in (None, False) for dest in HISTORY_COMMANDS.values()):
        return "prm9tool.cli.history", "run"
    if args.get or args.set:
        return "prm9tool.cli.values", "run"
    if args.export_dcf:
        return "prm9tool.cli.values", "export_dcf"
    if args.list_devices or args.batch is not None:
        return "prm9tool.cli.batch", "run"
    return None


def _characterize(args: argparse.Namespace) -> int:
    """``--characterize``, its result recorded in the history."""
    from prm9tool.cli.characterize import run as run_characterize
    from prm9tool.cli.history import recorder_for
    from prm9tool.service.history import record_characterization

    recorder = recorder_for(args)  # the end-of-line result goes into the history
    try:
        return run_characterize(args, lambda result: record_characterization(recorder, result))
    finally:
        recorder.close()


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

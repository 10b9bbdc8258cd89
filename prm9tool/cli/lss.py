"""``--lss-scan`` and ``--lss-assign``: valves whose node-ID switch leaves the node ID to the
bus (position 1, manual table 7-17), commissioned by LSS (CiA 305; docs/can-link.md)."""

from __future__ import annotations

import argparse
import json
import sys

from prm9tool.cli.json_output import emit_json
from prm9tool.device.canlink.bus import CanOptions
from prm9tool.errors import CanAdapterError, ExitCode
from prm9tool.service import lss
from prm9tool.service.lss import LssFailedError

LSS_COMMANDS = {"--lss-scan": "lss_scan", "--lss-assign": "lss_assign",
                "--find-bitrate": "find_bitrate"}  # fmt: skip
EXIT_FOR = {"duplicate": ExitCode.USAGE, "taken": ExitCode.USAGE, "refused": ExitCode.VERIFY_FAILED,
            "lost": ExitCode.COMMUNICATION, "none": ExitCode.NO_DEVICE,
            "unanswered": ExitCode.COMMUNICATION}  # fmt: skip


def lss_problem(args: argparse.Namespace) -> str | None:
    """Usage problems of the LSS commands (None: fine, or no LSS command given)."""
    given = [flag for flag, dest in LSS_COMMANDS.items() if getattr(args, dest)]
    if not given:
        return None
    others = {"--batch": args.batch is not None, "--list-devices": args.list_devices,
              "--serve-emulator": args.serve_emulator, "--diff": args.diff,
              "--characterize": args.characterize, "--device": args.device,
              "--emulator": args.emulator, "--all": args.all, "--type-key": args.type_key,
              "--node-id": args.node_id, "--restart": args.restart,
              "--restore-factory": args.restore_factory, "--enable": args.enable,
              "--disable": args.disable}  # fmt: skip
    # two LSS commands together: argparse refuses them (a mutually exclusive group)
    clash = [flag for flag, value in others.items() if value]
    if clash:
        return f"{given[0]} and {clash[0]} are separate commands: use one at a time"
    if args.json is not None and given[0] != "--lss-scan":
        return "--json [OUT.json] belongs to --lss-scan here"
    if args.can_interface is None:
        return f"{given[0]} needs --can-interface (and --can-channel) naming the bus"
    if given[0] == "--lss-assign":
        return _pairs_problem(args.lss_assign)
    if given[0] == "--find-bitrate" and args.can_bitrate is not None:
        return "--find-bitrate listens at every rate a PRM9 supports: leave out --can-bitrate"
    return None


def parse_pairs(pairs: list[str]) -> list[tuple[int, int]]:
    """``SERIAL=NODE`` texts → (serial, node); ValueError with the text at fault."""
    parsed = []
    for text in pairs:
        serial, sep, node = text.partition("=")
        if not sep or not serial.strip().isdigit() or not node.strip().isdigit():
            raise ValueError(f"--lss-assign {text}: give SERIAL=NODE, e.g. 4711=21")
        parsed.append((int(serial), int(node)))
    return parsed


def _pairs_problem(pairs: list[str]) -> str | None:
    try:
        parsed = parse_pairs(pairs)
    except ValueError as exc:
        return str(exc)
    return lss.plan_problem(parsed)


def run(args: argparse.Namespace) -> int:
    """The LSS command ``args`` names; its exit code (the valve service's LSS, as the CAN bus
    window's and the API's)."""
    options = CanOptions.from_args(args)
    if args.find_bitrate:
        return _find_bitrate(options)
    try:
        if args.lss_scan:
            return _scan(options, args.json)
        return _assign(options, parse_pairs(args.lss_assign))
    except CanAdapterError as exc:
        print(f"prm9tool: {exc}", file=sys.stderr)
        return ExitCode.COMMUNICATION
    except LssFailedError as exc:
        print(f"prm9tool: {exc}", file=sys.stderr)
        return EXIT_FOR.get(exc.kind, ExitCode.COMMUNICATION)


def _scan(options: CanOptions, as_json: bool | str | None) -> int:
    """``--json``: print the devices as JSON; ``--json OUT.json``: write them there (as
    ``--characterize --json OUT.json`` writes its report)."""
    found = lss.scan(options)
    if as_json:
        failed = emit_json(json.dumps([d.to_dict() for d in found], indent=1), as_json)
        if failed is not None:
            return failed
    else:
        for device in found:
            print(device.describe())
    if not found:
        print(f"prm9tool: {lss.nothing_found(options)}", file=sys.stderr)
        return ExitCode.NO_DEVICE
    return ExitCode.OK


def nothing_found(options: CanOptions) -> str:
    """What an empty Fastscan means and what to check."""
    return lss.nothing_found(options)


def _assign(options: CanOptions, pairs: list[tuple[int, int]]) -> int:
    def said(done: lss.Assigned) -> None:
        print(f"serial {done.device.serial}: node {done.node_id}, stored; it answers as "
              f"{done.device_id}", flush=True)  # fmt: skip

    lss.assign(options, list(pairs), said)
    return ExitCode.OK


def _find_bitrate(options: CanOptions) -> int:
    """``--find-bitrate``: listen-only at each rate; one line per rate, then the result."""
    from prm9tool.device.canlink import bitrate
    from prm9tool.device.canlink.bitrate import (
        BitrateNotFoundError,
        NoListenOnlyError,
        RateHeard,
        find_bitrate,
    )

    def said(heard: RateHeard) -> None:
        print(f"listening at {heard.describe()}", flush=True)

    try:
        rate, _heard = find_bitrate(options, bitrate.LISTEN_S, progress=said)
    except NoListenOnlyError as exc:
        print(f"prm9tool: {exc}", file=sys.stderr)
        return ExitCode.COMMUNICATION
    except BitrateNotFoundError as exc:
        print(f"prm9tool: {exc}", file=sys.stderr)
        return ExitCode.NO_DEVICE
    except CanAdapterError as exc:
        print(f"prm9tool: {exc}", file=sys.stderr)
        return ExitCode.COMMUNICATION
    print(f"the bus runs at {rate} bit/s: use --can-bitrate {rate}")
    return ExitCode.OK

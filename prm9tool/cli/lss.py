"""``--lss-scan`` and ``--lss-assign``: valves whose node-ID switch leaves the node ID to the
bus (position 1, manual table 7-17), commissioned by LSS (CiA 305; docs/can-link.md)."""

from __future__ import annotations

import argparse
import json
import sys

from prm9tool.cli.json_output import emit_json
from prm9tool.device.canlink.bus import CanNetwork, CanOptions, acquire, release
from prm9tool.device.canlink.lss import LssAddress, LssFailedError, LssMasterLink
from prm9tool.device.canlink.lss_nodes import answers_at, first_free
from prm9tool.errors import CanAdapterError, ExitCode

LSS_COMMANDS = {"--lss-scan": "lss_scan", "--lss-assign": "lss_assign",
                "--find-bitrate": "find_bitrate"}  # fmt: skip
BOOT_TIMEOUT_S = 10.0  # LSS release -> boot-up at the new node ID (as after NMT reset node)
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
              "--node-id": args.node_id}  # fmt: skip
    clash = given[1:] + [flag for flag, value in others.items() if value]
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
    for serial, node in parsed:
        if not 1 <= node <= 127:
            return f"--lss-assign {serial}={node}: CANopen node IDs are 1…127"
    serials, nodes = [s for s, _ in parsed], [n for _, n in parsed]
    twice = next((s for s in serials if serials.count(s) > 1), None)
    if twice is not None:
        return f"--lss-assign: serial {twice} is given twice"
    both = next((n for n in nodes if nodes.count(n) > 1), None)
    if both is not None:
        return f"--lss-assign: node ID {both} is given to two valves"
    return None


def run(args: argparse.Namespace) -> int:
    """The LSS command ``args`` names; its exit code."""
    options = CanOptions.from_args(args)
    if args.find_bitrate:
        return _find_bitrate(options)
    try:
        shared = acquire(options)
    except CanAdapterError as exc:
        print(f"prm9tool: {exc}", file=sys.stderr)
        return ExitCode.COMMUNICATION
    try:
        if args.lss_scan:
            return _scan(shared, options, args.json)
        return _assign(shared, options, parse_pairs(args.lss_assign))
    except LssFailedError as exc:
        print(f"prm9tool: {exc}", file=sys.stderr)
        return EXIT_FOR.get(exc.kind, ExitCode.COMMUNICATION)
    finally:
        release(shared)


def _scan(shared: CanNetwork, options: CanOptions, as_json: bool | str | None) -> int:
    """``--json``: print the devices as JSON; ``--json OUT.json``: write them there (as
    ``--characterize --json OUT.json`` writes its report)."""
    found = LssMasterLink(shared).scan()
    if as_json:
        failed = emit_json(json.dumps([_as_dict(a) for a in found], indent=1), as_json)
        if failed is not None:
            return failed
    for address in found:
        if not as_json:
            print(
                f"serial {address.serial}\t{'PRM9' if address.is_prm9 else 'not a PRM9'}\t"
                f"vendor 0x{address.vendor:X}\tproduct 0x{address.product:X}\t"
                f"revision 0x{address.revision:X}"
            )
    if not found:
        print(f"prm9tool: {nothing_found(options)}", file=sys.stderr)
        return ExitCode.NO_DEVICE
    return ExitCode.OK


def nothing_found(options: CanOptions) -> str:
    """What an empty Fastscan means and what to check."""
    return (
        f"no device without a node ID answered on {options}: every device on the bus has a "
        "node ID (--list-devices lists them), or none is at node-ID switch 1, or the bus runs "
        "at another bit rate than the adapter (--find-bitrate)"
    )


def _as_dict(address: LssAddress) -> dict[str, object]:
    return {
        "serial": address.serial,
        "vendor": address.vendor,
        "product": address.product,
        "revision": address.revision,
        "prm9": address.is_prm9,
    }


def _assign(shared: CanNetwork, options: CanOptions, pairs: list[tuple[int, int]]) -> int:
    from prm9tool.device.canlink.discovery import scan as scan_nodes

    taken = {info.node_id: info for info in scan_nodes(shared)}
    for _serial, node in pairs:
        if node in taken:
            who = taken[node]
            what = f"serial {who.serial}" if who.serial else who.problem or "a device"
            raise LssFailedError(
                f"node ID {node} is taken: {what} answers there. Choose a free node ID; "
                f"nothing was changed (free: {', '.join(map(str, first_free(set(taken), 3)))}, …)",
                "taken",
            )
    link = LssMasterLink(shared)
    found = {address.serial: address for address in link.scan()}
    missing = [serial for serial, _ in pairs if serial not in found]
    if missing:
        listed = ", ".join(str(s) for s in sorted(found)) or "none"
        raise LssFailedError(
            f"no device without a node ID has serial {missing[0]} (devices without a node ID: "
            f"{listed}); nothing was changed",
            "none",
        )
    failed = 0
    for serial, node in pairs:
        link.assign(found[serial], node)
        if answers_at(shared, node, serial, BOOT_TIMEOUT_S):
            print(f"serial {serial}: node {node}, stored; it answers as can:{node}")
        else:
            failed += 1
            print(
                f"prm9tool: serial {serial}: node {node} was stored, but the valve does not "
                f"answer as can:{node} within {BOOT_TIMEOUT_S:g} s: search the bus "
                f"(--list-devices {_bus_args(options)})",
                file=sys.stderr,
            )
    return ExitCode.COMMUNICATION if failed else ExitCode.OK


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


def _bus_args(options: CanOptions) -> str:
    return f"--can-interface {options.interface} --can-channel {options.channel}"

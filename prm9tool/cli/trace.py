"""``--record``, ``--decode`` and ``--replay``: CAN traces on the command line (docs/trace.md).

``--record TRACE`` records the bus of the CAN options alone (until ``--duration`` or Ctrl+C) or
beside another command on the same bus (``--batch``, ``--characterize``, the GUI): the recorder
shares the bus the command opens. ``--decode TRACE`` prints the trace in words (``--json``,
``--csv``), ``--fail-on-incident`` makes an incident exit 1 (CI of PLC code).
"""

from __future__ import annotations

import argparse
import contextlib
import csv
import json
import sys
from collections.abc import Iterator
from pathlib import Path
from typing import TYPE_CHECKING, Any

from prm9tool.errors import ExitCode, Prm9Error

if TYPE_CHECKING:
    from prm9tool.trace.events import Trace

DECODE_ONLY = {"--eds": "eds", "--csv": "csv", "--fail-on-incident": "fail_on_incident"}
REPLAY_ONLY = {"--speed": "speed", "--only-node": "only_node"}
# every option the trace commands take besides their own (the others would be ignored)
_OTHERS = {
    "--device": "device", "--emulator": "emulator", "--batch": "batch", "--list-devices":
    "list_devices", "--characterize": "characterize", "--diff": "diff", "--get": "get",
    "--set": "set", "--serve-emulator": "serve_emulator", "--new": "new", "--check": "check",
    "--export-eds": "export_eds", "--history": "history", "--lss-scan": "lss_scan",
    "--autotune": "autotune", "--restart": "restart", "--restore-factory": "restore_factory",
    "--enable": "enable", "--disable": "disable",
}  # fmt: skip


# commands that use no bus: nothing to record beside them
_OFFLINE = {
    "--new": "new", "--check": "check", "--export-eds": "export_eds", "--diff": "diff",
    "--history": "history", "--history-check": "history_check",
    "--history-export": "history_export", "--history-import": "history_import",
}  # fmt: skip


def add_trace_options(parser: argparse.ArgumentParser) -> None:
    """The trace options (docs/trace.md)."""
    group = parser.add_argument_group("CAN traces: record, decode, replay (docs/trace.md)")
    group.add_argument(
        "--record", metavar="TRACE.asc|.blf|.trc|.log",
        help="record every frame of the CAN bus of the CAN options, alone (until --duration "
        "or Ctrl+C) or beside --batch, --characterize or the GUI on the same bus",
    )  # fmt: skip
    group.add_argument(
        "--duration", type=float, metavar="S", help="with --record alone: stop after S seconds"
    )
    group.add_argument(
        "--decode", metavar="TRACE",
        help="print a trace in words: NMT, SDO, PDO values, states, EMCY, SYNC, LSS, incidents",
    )  # fmt: skip
    group.add_argument(
        "--eds", action="append", default=[], metavar="[NODE=]FILE.eds",
        help="with --decode: the EDS of a node that is no PRM9 valve (without NODE: of every "
        "node the trace shows is none); repeatable",
    )  # fmt: skip
    group.add_argument("--csv", metavar="OUT.csv", help="with --decode: the events as CSV")
    group.add_argument(
        "--replay", metavar="TRACE",
        help="put the master's frames of a trace (NMT, SYNC, RPDOs, SDO requests) back on the "
        "bus of the CAN options with their timing; report the answers that differ (exit 1)",
    )  # fmt: skip
    group.add_argument(
        "--speed", type=float, metavar="X", help="with --replay: X times as fast (default 1)"
    )
    group.add_argument(
        "--only-node", type=int, metavar="N",
        help="with --replay: only the frames node N receives (NMT, SYNC, its RPDOs and SDO)",
    )  # fmt: skip
    group.add_argument(
        "--fail-on-incident", action="store_true",
        help="with --decode: exit 1 when the trace has an incident (CI of PLC code)",
    )  # fmt: skip


def trace_problem(args: argparse.Namespace) -> str | None:
    """What makes no sense among the trace options (None: nothing)."""
    decode_only = [f for f, d in DECODE_ONLY.items() if getattr(args, d, None)]
    if args.decode is None:
        if decode_only:
            return f"{decode_only[0]} belongs to --decode"
    else:
        others = [f for f, d in _OTHERS.items() if getattr(args, d, None) not in (None, False, [])]
        if args.record or args.replay:
            others.insert(0, "--record" if args.record else "--replay")
        if others or args.file:
            what = others[0] if others else f"the file {args.file}"
            return f"--decode reads a trace file and takes no {what}"
        can = [f for f in ("--can-interface", "--can-channel", "--can-bitrate")
               if getattr(args, f[2:].replace("-", "_")) is not None]  # fmt: skip
        if can:
            return f"--decode reads a trace file; {can[0]} names a CAN bus"
        return _eds_problem(args.eds) or _format_problem(args.decode)
    replay_only = [f for f, d in REPLAY_ONLY.items() if getattr(args, d, None) is not None]
    if args.replay is None and replay_only:
        return f"{replay_only[0]} belongs to --replay"
    if args.replay is not None:
        problem = _replay_problem(args)
        if problem is not None:
            return problem
    if args.duration is not None:
        if not args.record:
            return "--duration belongs to --record"
        if args.duration <= 0:
            return f"--duration {args.duration}: give a time in seconds above 0"
    if args.record:
        offline = [
            f for f, d in _OFFLINE.items() if getattr(args, d, None) not in (None, False, [])
        ]
        if offline:
            return (
                f"--record records a CAN bus beside a command that uses one; {offline[0]} does not"
            )
        return _format_problem(args.record)
    return None


def _replay_problem(args: argparse.Namespace) -> str | None:
    others = [f for f, d in _OTHERS.items() if getattr(args, d, None) not in (None, False, [])]
    if others or args.file:
        return (
            f"--replay drives a bus from a trace and takes no {others[0] if others else args.file}"
        )
    if args.speed is not None and args.speed <= 0:
        return f"--speed {args.speed}: give a factor above 0"
    if args.only_node is not None and not 1 <= args.only_node <= 127:
        return f"--only-node {args.only_node}: CANopen node IDs are 1…127"
    if args.record and Path(args.record).resolve() == Path(args.replay).resolve():
        return "--record would overwrite the trace --replay reads"
    return _format_problem(args.replay)


def _format_problem(path: str) -> str | None:
    from prm9tool.trace.frames import FORMATS

    suffix = Path(path).suffix.lower()
    if suffix not in FORMATS:
        return f"{path}: a trace is one of {', '.join(FORMATS)} (python-can's formats)"
    return None


def _eds_problem(given: list[str]) -> str | None:
    for text in given:
        node, sep, _path = text.rpartition("=")
        if sep and not (node.isdigit() and 1 <= int(node) <= 127):
            return f"--eds {text}: NODE=FILE with a node ID 1…127"
    return None


def trace_command(args: argparse.Namespace) -> tuple[str, str] | None:
    """The function that runs a trace command alone (None: none, or --record beside another)."""
    if args.decode is not None:
        return "prm9tool.cli.trace", "decode"
    if args.replay is not None:
        return "prm9tool.cli.trace", "replay"
    if args.record and not _other_command(args):
        return "prm9tool.cli.trace", "wait_recording"
    return None


def _other_command(args: argparse.Namespace) -> bool:
    return any(getattr(args, d, None) not in (None, False, []) for d in _OTHERS.values()) or bool(
        args.file
    )


@contextlib.contextmanager
def recording(args: argparse.Namespace) -> Iterator[None]:
    """Record the bus of the CAN options while the block runs (nothing without ``--record``)."""
    if not args.record:
        yield
        return
    from prm9tool.device.canlink.bus import CanOptions
    from prm9tool.errors import CommunicationError
    from prm9tool.trace.recorder import Recorder

    recorder = Recorder(args.record, CanOptions.from_args(args))
    try:
        recorder.start()
    except Prm9Error as exc:  # the bus or the file: nothing runs without its recording
        print(f"prm9tool: cannot record: {exc}", file=sys.stderr)
        code = (
            ExitCode.COMMUNICATION if isinstance(exc, CommunicationError) else ExitCode.INVALID_FILE
        )
        raise SystemExit(int(code)) from None
    print(f"prm9tool: recording {recorder.options} into {args.record}", file=sys.stderr)
    try:
        yield
    finally:
        recorder.stop()
        print(f"prm9tool: {recorder.written} frames recorded into {args.record}", file=sys.stderr)


def wait_recording(args: argparse.Namespace) -> int:
    """``--record`` alone: the recording runs (see :func:`recording`) until ``--duration``,
    Ctrl+C or SIGTERM; the file is closed with every frame in each case."""
    import signal
    import threading

    done = threading.Event()
    previous = signal.signal(signal.SIGTERM, lambda _signum, _frame: done.set())
    try:
        done.wait(args.duration)
    except KeyboardInterrupt:
        pass
    finally:
        signal.signal(signal.SIGTERM, previous)
    return ExitCode.OK


def decode(args: argparse.Namespace) -> int:
    """``--decode TRACE``: the trace in words (or JSON/CSV); exit 1 with --fail-on-incident and
    an incident, 3 for a file that cannot be read."""
    import prm9tool.trace as trace

    try:
        decoded = trace.read(args.decode, _eds(args.eds))
    except Prm9Error as exc:
        print(f"prm9tool: {exc}", file=sys.stderr)
        return ExitCode.INVALID_FILE
    try:
        _write_outputs(args, decoded)
    except OSError as exc:
        print(f"prm9tool: cannot write {exc.filename}: {exc.strerror}", file=sys.stderr)
        return ExitCode.INVALID_FILE
    if args.fail_on_incident and decoded.incidents:
        return ExitCode.VERIFY_FAILED
    return ExitCode.OK


def replay(args: argparse.Namespace) -> int:
    """``--replay TRACE``: the master side on the bus, the answers compared; exit 1 when they
    differ, 3 for a trace that cannot be read, 6 for a bus that cannot be opened."""
    from prm9tool.device.canlink.bus import CanOptions
    from prm9tool.errors import CommunicationError
    from prm9tool.trace.replay import replay as run_replay

    options = CanOptions.from_args(args)
    try:
        result = run_replay(args.replay, options, args.speed or 1.0, args.only_node)
    except CommunicationError as exc:
        print(f"prm9tool: {exc}", file=sys.stderr)
        return ExitCode.COMMUNICATION
    except Prm9Error as exc:
        print(f"prm9tool: {exc}", file=sys.stderr)
        return ExitCode.INVALID_FILE
    if args.json:
        report = {
            "sent": result.sent, "late_s": result.late_s,
            "differences": [d.to_dict() for d in result.differences],
        }  # fmt: skip
        if isinstance(args.json, str):
            Path(args.json).write_text(json.dumps(report, indent=1), encoding="utf-8")
        else:
            print(json.dumps(report, indent=1))
    else:
        print(
            f"{result.sent} frames sent on {options} (at most {result.late_s * 1000:.1f} ms late)"
        )
        for d in result.differences:
            print(
                f"node {d.node}, {d.what}: recorded {list(d.recorded)}, replayed {list(d.replayed)}"
            )
        print(
            f"{len(result.differences)} differences"
            if result.differences
            else "the answers are the same"
        )
    return ExitCode.VERIFY_FAILED if result.differences else ExitCode.OK


def _eds(given: list[str]) -> dict[int | None, str]:
    result: dict[int | None, str] = {}
    for text in given:
        node, sep, path = text.rpartition("=")
        result[int(node) if sep else None] = path if sep else text
    return result


def _write_outputs(args: argparse.Namespace, decoded: Trace) -> None:
    if args.csv:
        write_csv(decoded, Path(args.csv))
    if isinstance(args.json, str):
        Path(args.json).write_text(json.dumps(decoded.to_dict(), indent=1), encoding="utf-8")
    if args.json is True:
        json.dump(decoded.to_dict(), sys.stdout, indent=1)
        print()
    elif not args.csv and not isinstance(args.json, str):
        print_trace(decoded)


def write_csv(decoded: Trace, path: Path) -> None:
    """The events as CSV: time (s from the first frame), node, kind, text, frames, values."""
    with path.open("w", newline="", encoding="utf-8") as file:
        writer = csv.writer(file)
        writer.writerow(["time_s", "node", "kind", "text", "frames", "values"])
        start = decoded.start
        for e in decoded.events:
            values = ";".join(f"{name}={value}" for name, value in e.values)
            frames = " ".join(map(str, e.frames))
            node = "" if e.node is None else e.node
            writer.writerow([f"{e.time - start:.6f}", node, e.kind.value, e.text, frames, values])


def print_trace(decoded: Trace) -> None:
    """The trace in words on standard output, then its summary."""
    out: Any = sys.stdout
    start = decoded.start
    for e in decoded.events:
        node = f"node {e.node:3d}" if e.node is not None else "        "
        out.write(f"{e.time - start:12.6f}  {node}  {e.kind.value:14}  {e.text}\n")
    print_summary(decoded, start)


def print_summary(decoded: Trace, start: float) -> None:
    """Frames, nodes, events by kind, SYNC period and jitter, incidents."""
    counts = ", ".join(f"{k} {n}" for k, n in sorted(decoded.counts().items()))
    if not decoded.frames:  # a recording of a silent bus: said, not an empty list
        counts = "none (the trace holds no frame)"
    print(f"{chr(10) if decoded.events else ''}{decoded.frames} frames; events: {counts or 'none'}")
    for node, how in sorted(decoded.nodes.items()):
        print(f"node {node}: decoded as {how}")
    sync = decoded.sync
    if sync.mean_period_s is not None and sync.jitter_s is not None:
        print(
            f"SYNC: {sync.count} frames, period {sync.mean_period_s * 1000:.3f} ms (min "
            f"{(sync.min_period_s or 0) * 1000:.3f}, max {(sync.max_period_s or 0) * 1000:.3f}), "
            f"jitter {sync.jitter_s * 1e6:.1f} µs"
        )
    print(f"not understood: {len(decoded.not_understood)} frames")
    print(f"incidents: {len(decoded.incidents)}")
    for incident in decoded.incidents:
        frames = " ".join(map(str, incident.frames))
        print(f"{incident.time - start:12.6f}  {incident.what} (frames {frames})")

"""CAN traces (prm9tool.trace): decoding a large trace, and recording a busy bus.

Decoding: a synthetic trace of a machine with 16 PRM9 valves at 1 kHz SYNC (per period a SYNC,
RPDO1 to every valve, TPDO1 from every valve; heartbeats every second) written by python-can's
``can.Logger`` as candump ``.log`` and BLF; for each file, in a fresh process each, the time and
peak memory (max RSS) of python-can's bare ``can.LogReader`` (the reference: reading alone) and
of ``prm9tool.trace.read`` (reading and decoding).

Recording: the same traffic sent in real time (1 ms periods of 33 frames) on a virtual bus while
prm9tool's recorder writes it (a listener on the shared CANopen master, as beside a session);
frames sent, taken and written (none may be lost), the recorder's longest queue and the time
the file needs after the last frame.

    .venv/bin/python benchmarks/bench_trace.py [--frames 1000000] [--seconds 10] [--quick]

``--quick`` (a smoke run): 20 000 frames, 1 s of recording.
"""

from __future__ import annotations

import argparse
import json
import resource
import struct
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

import can

import prm9tool.trace as trace
from prm9tool.device.canlink.bus import CanOptions, acquire, release

NODES = tuple(range(1, 17))
PERIOD_S = 0.001


def machine_frames(count: int) -> list[can.Message]:
    """``count`` frames of 16 valves at 1 kHz SYNC (time stamps 1 ms apart per period)."""
    frames: list[can.Message] = []
    k = 0
    while len(frames) < count:
        t = 1000.0 + k * PERIOD_S
        frames.append(
            can.Message(timestamp=t, arbitration_id=0x080, data=b"", is_extended_id=False)
        )
        setpoint = int(8000 * ((k % 2000) / 1000 - 1))
        for node in NODES:
            rpdo = struct.pack("<Hh", 0x0F, setpoint)
            frames.append(
                can.Message(
                    timestamp=t + 1e-5 * node,
                    arbitration_id=0x200 + node,
                    data=rpdo,
                    is_extended_id=False,
                )
            )
        for node in NODES:
            tpdo = struct.pack("<Hh", 0x0F, setpoint - 50)
            frames.append(
                can.Message(
                    timestamp=t + 4e-4 + 1e-5 * node,
                    arbitration_id=0x180 + node,
                    data=tpdo,
                    is_extended_id=False,
                )
            )
        if k % 1000 == 0:
            for node in NODES:
                frames.append(
                    can.Message(
                        timestamp=t + 8e-4,
                        arbitration_id=0x700 + node,
                        data=b"\x05",
                        is_extended_id=False,
                    )
                )
        k += 1
    return frames[:count]


def write(path: Path, frames: list[can.Message]) -> None:
    """The frames into ``path`` with python-can's writer."""
    with can.Logger(str(path)) as logger:
        for msg in frames:
            logger.on_message_received(msg)


def measure(what: str, path: str) -> None:
    """In this (fresh) process: time and peak memory of reading or decoding ``path``."""
    started = time.perf_counter()
    if what == "reader":
        count = sum(1 for _ in can.LogReader(path))
        events = 0
    elif what == "window":
        decoded = trace.read(path)
        count, events = decoded.frames, len(decoded.events)
        app, window = trace_window()
        from prm9tool.views.trace.model import pdo_series

        series = pdo_series(decoded)
        started = time.perf_counter()
        show_in_window(app, window, decoded, series)
    else:
        decoded = trace.read(path)
        count, events = decoded.frames, len(decoded.events)
    seconds = time.perf_counter() - started
    rss_mib = peak_rss_mib()
    print(json.dumps({"frames": count, "events": events, "s": seconds, "rss_mib": rss_mib}))


def trace_window() -> tuple[object, object]:
    """The Qt application and an empty trace window (offscreen), built before any timing."""
    import os

    os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
    from PySide6.QtCore import QSettings
    from PySide6.QtWidgets import QApplication

    from prm9tool.online.trace_recording import BusRecording
    from prm9tool.views.trace.window import TraceWindow

    app = QApplication.instance() or QApplication([])
    ini = str(Path(tempfile.gettempdir()) / "bench_trace.ini")
    window = TraceWindow(BusRecording(), dict, QSettings(ini, QSettings.Format.IniFormat))
    window.show()
    app.processEvents()
    return app, window


def show_in_window(app: Any, window: Any, decoded: trace.Trace, series: Any) -> None:
    """The trace window shows the decoded trace (table, filters, incidents, timeline): what
    its GUI thread does (the series are computed in the decoding thread)."""
    window.show_trace(decoded, series)
    app.processEvents()
    window.node.setCurrentIndex(window.node.findData(NODES[0]))  # one node's events
    app.processEvents()


def peak_rss_mib() -> float:
    """This process's peak resident memory (VmHWM: ru_maxrss would include the parent's, which
    a child inherits across exec on Linux)."""
    for line in Path("/proc/self/status").read_text().splitlines():
        if line.startswith("VmHWM:"):
            return int(line.split()[1]) / 1024
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024


def in_process(what: str, path: Path) -> dict[str, float]:
    run = subprocess.run(
        [sys.executable, __file__, "--measure", what, str(path)],
        capture_output=True,
        text=True,
        check=True,
    )
    return json.loads(run.stdout.splitlines()[-1])


def bench_decode(count: int, folder: Path) -> None:
    frames = machine_frames(count)
    for suffix in (".log", ".blf"):
        write(folder / f"machine{suffix}", frames)
    del frames
    for suffix in (".log", ".blf"):
        path = folder / f"machine{suffix}"
        size = path.stat().st_size / 2**20
        reader, decoder = in_process("reader", path), in_process("decode", path)
        shown = in_process("window", path) if suffix == ".log" else None
        print(
            f"{suffix}: {count} frames, {size:.1f} MiB; LogReader alone {reader['s']:.1f} s "
            f"({reader['rss_mib']:.0f} MiB RSS); prm9tool.trace.read {decoder['s']:.1f} s "
            f"({decoder['rss_mib']:.0f} MiB RSS, {decoder['events']:.0f} events), "
            f"{decoder['s'] / reader['s']:.1f}x the reader, {decoder['s'] / count * 1e6:.1f} µs/frame"
        )
        if shown is not None:
            print(
                f"  trace window: the GUI thread shows it (table, incidents, timeline, then a node "
                f"filter) in {shown['s']:.1f} s after decoding, {shown['rss_mib']:.0f} MiB RSS in all"
            )


def bench_record(seconds: float, folder: Path) -> None:
    channel = f"bench-trace-{time.monotonic_ns()}"
    options = CanOptions("virtual", channel)
    shared = acquire(options)  # the session's master: the recorder shares it
    path = folder / "recorded.blf"
    sender = can.Bus(interface="virtual", channel=channel)
    period = machine_frames(33)
    sent = 0
    try:
        with trace.record(path, options) as recorder:
            started = time.perf_counter()
            deadline = started
            while time.perf_counter() - started < seconds:
                for msg in period:
                    sender.send(
                        can.Message(
                            arbitration_id=msg.arbitration_id, data=msg.data, is_extended_id=False
                        )
                    )
                sent += len(period)
                deadline += PERIOD_S
                time.sleep(max(0.0, deadline - time.perf_counter()))
            elapsed = time.perf_counter() - started
            while recorder.frames < sent and time.perf_counter() - started < elapsed + 30:
                time.sleep(0.01)
            drained = time.perf_counter()
        closed = time.perf_counter() - drained
    finally:
        sender.shutdown()
        release(shared)
    rate = sent / elapsed
    print(
        f"recording: {sent} frames sent in {elapsed:.1f} s ({rate:.0f} frames/s, "
        f"{rate / 33:.0f} SYNC periods/s of 33 frames), {recorder.frames} taken, "
        f"{recorder.written} written, lost {sent - recorder.written}; longest queue "
        f"{recorder.most_waiting} frames; file closed {closed * 1000:.0f} ms after the last frame"
    )


def main() -> None:
    """Run the measurements and print the figures."""
    parser = argparse.ArgumentParser()
    parser.add_argument("--frames", type=int, default=1_000_000)
    parser.add_argument("--seconds", type=float, default=10.0)
    parser.add_argument("--quick", action="store_true", help="a smoke run: seconds, not figures")
    parser.add_argument("--measure", nargs=2, metavar=("WHAT", "PATH"), help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.measure:
        measure(*args.measure)
        return
    count, seconds = (20_000, 1.0) if args.quick else (args.frames, args.seconds)
    with tempfile.TemporaryDirectory() as folder:
        bench_decode(count, Path(folder))
        bench_record(seconds, Path(folder))


if __name__ == "__main__":
    main()

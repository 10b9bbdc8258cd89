"""Oscilloscope: 3 channels x 5 kHz from the paced emulator into the scope, offscreen.

Data path under test: paced EmulatedValve -> USB firmware handler -> emulator transport ->
ValveSession stream -> ValveConnection worker thread -> samples_received (queued) ->
ScopeWidget ring buffer -> 30 Hz redraw (clip-to-view, peak downsampling) -> paint.

A frame's cost is the redraw slot (trigger engine + setData + downsampling + read-outs) plus
the paint of the plot that follows it. References measured in the same run, same plot size:
a bare pyqtgraph PlotWidget drawing the same 3 x N points per frame with clip-to-view and peak
downsampling, and the same without downsampling (what a naive live plot does).

    QT_QPA_PLATFORM=offscreen .venv/bin/python benchmarks/bench_scope.py [--seconds 20] [--quick]
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
import tempfile
import time
from collections.abc import Callable

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
os.environ.setdefault("PRM9TOOL_DATA_DIR", tempfile.mkdtemp(prefix="bench_scope_"))

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import QTimer
from PySide6.QtWidgets import QApplication

from prm9tool.model.document import ParameterDocument
from prm9tool.online.connection import ValveConnection
from prm9tool.scope import GeneratorSettings, TriggerMode, Waveform
from prm9tool.views.scope.display import ScopeDisplay
from prm9tool.views.scope.generator import SetpointGenerator
from prm9tool.views.scope.widget import ScopeWidget

TYPE_KEY = "PRM9-06.3Z11/30-24E02S02"
KEYS = ("setpoint_raw", "position_actual", "current_a")
RATE_HZ = 5000
SIZE = (1400, 850)
MIN_RECEIVED = 0.99  # of rate x wall time: less means the stream stalled or dropped blocks
# What is still on its way when the run stops (the link's 10 ms blocks, the worker's hand-over to
# the GUI thread, one 30 Hz frame): not a loss. In a 1 s smoke run it is ~3 % of the stream.
IN_FLIGHT_S = 0.05


class FrameTimer:
    """Times the scope's redraw slot and every plot paint (class-level wrappers).

    A frame is one redraw that drew something plus every paint before the next such redraw
    (pyqtgraph paints the plot, then once more the strip of the third axis).
    """

    def __init__(self) -> None:
        self.redraws: list[tuple[float, float]] = []  # (start, duration)
        self.paints: list[tuple[float, float]] = []
        paint, redraw = pg.GraphicsView.paintEvent, ScopeDisplay.redraw
        timer = self

        def timed_paint(view: pg.GraphicsView, event: object) -> None:
            started = time.perf_counter()
            paint(view, event)
            timer.paints.append((started, time.perf_counter() - started))

        def timed_redraw(display: ScopeDisplay) -> bool:
            started = time.perf_counter()
            drew = redraw(display)
            if drew:
                timer.redraws.append((started, time.perf_counter() - started))
            return drew

        pg.GraphicsView.paintEvent = timed_paint  # type: ignore[method-assign]
        ScopeDisplay.redraw = timed_redraw  # type: ignore[method-assign]

    def frames(self) -> tuple[list[float], list[float], list[float]]:
        """Per frame: total, redraw slot, paints (seconds); the first 5 frames are skipped."""
        starts = [start for start, _ in self.redraws] + [float("inf")]
        total, slot, painted = [], [], []
        for k, (start, duration) in enumerate(self.redraws):
            paint = sum(d for s, d in self.paints if start <= s < starts[k + 1])
            total.append(duration + paint)
            slot.append(duration)
            painted.append(paint)
        return total[5:], slot[5:], painted[5:]


def percentile(values: list[float], share: float) -> float:
    """The ``share`` quantile in milliseconds."""
    return float(np.quantile(np.asarray(values), share)) * 1000.0


def reference(
    app: QApplication, recorded: np.ndarray, points: int, downsample: bool, frames: int = 60
) -> list[float]:
    """Frame times of a bare PlotWidget drawing the recorded data, 3 x ``points`` per frame.

    Each frame shows the next window of what the scope received (the window advances by one
    30 Hz frame's worth of samples), so the reference draws exactly the scope's workload.
    """
    widget = pg.PlotWidget()
    widget.resize(*SIZE)
    widget.show()
    curves = []
    for colour in ("y", "c", "m"):
        curve = widget.plot(pen=pg.mkPen(colour, width=1))
        if downsample:
            curve.setClipToView(True)
            curve.setDownsampling(auto=True, method="peak")
        curves.append(curve)
    step = RATE_HZ // 30
    repeats = -(-(points + frames * step) // max(1, len(recorded)))
    recorded = np.concatenate([recorded] * repeats)  # a short run is replayed in a loop
    times = []
    for frame in range(frames):
        first = frame * step
        t = np.arange(first, first + points) / RATE_HZ
        started = time.perf_counter()
        for c, curve in enumerate(curves):
            curve.setData(t, recorded[first : first + points, c])
        widget.setXRange(t[0], t[-1], padding=0)
        widget.viewport().repaint()
        times.append(time.perf_counter() - started)
        app.processEvents()
    widget.close()
    return times[5:]


def wait_until(app: QApplication, condition: Callable[[], bool], timeout_s: float) -> bool:
    """Process events until ``condition`` holds."""
    deadline = time.monotonic() + timeout_s
    while not condition() and time.monotonic() < deadline:
        app.processEvents()
        time.sleep(0.005)
    return condition()


def online(app: QApplication) -> ValveConnection:
    """A connection to a paced emulated valve."""
    conn = ValveConnection()
    conn.go_online(conn.list_devices([TYPE_KEY])[-1])
    if not wait_until(app, lambda: conn.is_online, 20.0):
        sys.exit("the emulated valve did not come online")
    return conn


def offline(app: QApplication, conn: ValveConnection) -> None:
    """Close the connection and its worker."""
    conn.go_offline()
    wait_until(app, lambda: not conn.is_online, 5.0)
    conn.shutdown()


def run_stream_only(app: QApplication, seconds: float, waveform: str) -> float:
    """CPU share of the same stream and generator with no scope attached (the baseline)."""
    conn = online(app)
    received = [0]
    conn.samples_received.connect(lambda block: received.__setitem__(0, received[0] + len(block)))
    generator = SetpointGenerator(conn)
    conn.start_stream(list(KEYS), RATE_HZ)
    wait_until(app, lambda: received[0] > 0, 5.0)
    if waveform != "off":
        generator.start(GeneratorSettings(Waveform(waveform), 40.0, -20.0, 1.0))
    cpu0, wall0 = time.process_time(), time.monotonic()
    QTimer.singleShot(int(seconds * 1000), app.quit)
    app.exec()
    share = (time.process_time() - cpu0) / (time.monotonic() - wall0)
    generator.stop()
    offline(app, conn)
    return share


def scope_on(conn: object, window_s: float) -> ScopeWidget:
    """The scope at SIZE on ``conn``: KEYS at RATE_HZ, roll mode, a ``window_s`` window."""
    scope = ScopeWidget(conn, ParameterDocument(TYPE_KEY))  # type: ignore[arg-type]
    scope.resize(*SIZE)
    scope.show()
    for key in KEYS:
        scope.preselect(key)
    c = scope.controls
    c.rate.setCurrentIndex(c.rate.findData(RATE_HZ))
    c.time_window.setCurrentIndex(c.time_window.findData(window_s))
    c.mode.setCurrentIndex(c.mode.findData(TriggerMode.ROLL))
    return scope


def run_scope(app: QApplication, seconds: float, window_s: float, waveform: str) -> dict:
    """Stream into the scope for ``seconds``; return the measured figures."""
    conn = online(app)
    scope = scope_on(conn, window_s)
    timer = FrameTimer()
    scope.start()
    wait_until(app, lambda: scope.receiving, 5.0)
    if waveform != "off":
        scope.generator.start(GeneratorSettings(Waveform(waveform), 40.0, -20.0, 1.0))
    cpu0, wall0 = time.process_time(), time.monotonic()
    total0 = scope.capture.buffer.total
    QTimer.singleShot(int(seconds * 1000), app.quit)
    app.exec()
    wall, cpu = time.monotonic() - wall0, time.process_time() - cpu0
    received = scope.capture.buffer.total - total0
    lost = conn.samples_lost  # gaps in the stream's sequence, as the connection reports them
    _, recorded = scope.capture.buffer.latest(scope.capture.buffer.capacity)
    recorded = recorded.copy()
    scope.stop()
    offline(app, conn)
    return {
        "wall": wall,
        "cpu": cpu / wall,
        "received": received,
        "lost": lost,
        "frames": timer.frames(),
        "recorded": recorded,
    }


def main() -> None:
    """Run the benchmark and print its figures."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=20.0)
    parser.add_argument("--window", type=float, default=10.0)
    parser.add_argument("--baseline-seconds", type=float, default=10.0)
    parser.add_argument(
        "--waveform",
        choices=[w.value for w in Waveform] + ["off"],
        default="square",
        help="setpoint generator waveform during the run (default: a 1 s square wave)",
    )
    parser.add_argument("--quick", action="store_true", help="a smoke run: seconds, not figures")
    args = parser.parse_args()
    if args.quick:
        args.seconds, args.window, args.baseline_seconds = 1.0, 0.5, 0.5
    app = QApplication.instance() or QApplication([])
    points = int(args.window * RATE_HZ)
    result = run_scope(app, args.seconds, args.window, args.waveform)
    ref_ds = reference(app, result["recorded"], points, downsample=True)
    ref_raw = reference(app, result["recorded"], points, downsample=False, frames=30)
    baseline = run_stream_only(app, args.baseline_seconds, args.waveform)
    frames, redraw, paint = result["frames"]
    expected = result["wall"] * RATE_HZ
    print(
        f"stream: {len(KEYS)} channels x {RATE_HZ} Hz, {args.window:g} s window, "
        f"{result['wall']:.1f} s, generator: {args.waveform}"
    )
    print(
        f"samples received {result['received']} (expected ~{expected:.0f}), "
        f"samples lost {result['lost']}"
    )
    print(f"frames drawn {len(redraw)} ({len(redraw) / result['wall']:.1f} per s)")
    span = np.ptp(result["recorded"], axis=0)
    print(
        "signal span per channel: "
        + ", ".join(f"{k} {v:.3g}" for k, v in zip(KEYS, span, strict=True))
    )
    print(
        f"process CPU share {100 * result['cpu']:.0f} % of one core with the scope, "
        f"{100 * baseline:.0f} % with the same stream and generator but no scope "
        "(both: paced emulator, USB link, connection worker, GUI thread)"
    )
    print("                                   median ms   p95 ms")
    rows = [
        ("scope frame (redraw slot + paint)", frames),
        ("  redraw slot", redraw),
        ("  paint", paint),
        (f"reference: bare pyqtgraph 3x{points}, clip+peak", ref_ds),
        (f"reference: bare pyqtgraph 3x{points}, no downsampling", ref_raw),
    ]
    for name, values in rows:
        print(f"{name:<52} {percentile(values, 0.5):8.1f} {percentile(values, 0.95):8.1f}")
    ratio = statistics.median(frames) / statistics.median(ref_ds)
    print(f"scope frame / bare clip+peak reference (median): {ratio:.2f}x")
    failures = []
    if result["lost"] != 0:
        failures.append(f"{result['lost']} samples lost (gaps in the session's sequence)")
    least = MIN_RECEIVED * expected - IN_FLIGHT_S * RATE_HZ
    if result["received"] < least:  # gaps are not the only way to lose data
        failures.append(
            f"received {result['received']} samples, under {MIN_RECEIVED:.0%} of the "
            f"{expected:.0f} the stream should have carried (less {IN_FLIGHT_S * 1000:.0f} ms "
            "still in flight)"
        )
    if failures:
        sys.exit("FAIL: " + "; ".join(failures))


if __name__ == "__main__":
    main()

"""What one repaint of the oscilloscope's plot costs, against pyqtgraph's own grid and axes.

    QT_QPA_PLATFORM=offscreen .venv/bin/python benchmarks/bench_scope_paint.py

The scope (1400 x 850, three channels, 10 s window at 5 kHz: 50 000 samples per channel, a noisy
square wave and a noisy current) is repainted with nothing changed ("static": a paused plot, a
cursor moved) and with the time axis moving by one 30 Hz frame per repaint ("roll": a running
recording). Each case is measured as the scope is built (an opaque grid item under all
curves, the y axes cached as pixmaps) and, as the reference in the same run, the same plot
with pyqtgraph's standard set-up: the grid drawn by the axes, 30 % alpha, above the main view,
no caching. The ratio is the figure to compare between machines. Medians of 60 repaints after
10 warm-up repaints, the two set-ups interleaved three times.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

import numpy as np
import shiboken6
from bench_scope import RATE_HZ, SIZE, scope_on
from PySide6.QtWidgets import QApplication, QGraphicsItem

from prm9tool.views.scope.widget import ScopeWidget

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "tests"))
from support.scope_fakes import FakeConnection  # the scope tests' stand-in connection


def filled_scope(window_s: float) -> ScopeWidget:
    """A running scope showing ``window_s`` seconds of three channels."""
    link = FakeConnection()
    scope = scope_on(link, window_s)
    scope.start()
    count = int(window_s * RATE_HZ)
    rng = np.random.default_rng(1)
    square = np.where((np.arange(count) // RATE_HZ) % 2, 8000, -8000)
    noisy = square + rng.normal(0, 300, count)
    current = 600 + rng.normal(0, 20, count)
    block = np.column_stack([square, noisy, current]).astype(np.int64)
    for start in range(0, count, 500):
        link.samples_received.emit(block[start : start + 500])
    scope.display.redraw()  # what the scope's 30 Hz timer does
    return scope


def repaint_ms(scope: ScopeWidget, roll: bool, repaints: int = 60) -> float:
    """Median milliseconds of one repaint of the plot."""
    view = scope.plot.views[0]
    low, high = view.viewRange()[0]
    step = 1.0 / 30.0
    viewport = scope.plot.graphics.viewport()
    times = []
    for k in range(10 + repaints):
        if roll:
            view.setXRange(low + k * step, high + k * step, padding=0)
        started = time.perf_counter()
        viewport.repaint()
        if k >= 10:
            times.append(time.perf_counter() - started)
    return statistics.median(times) * 1000.0


def standard_grid(scope: ScopeWidget, on: bool) -> None:
    """Switch between pyqtgraph's grid and uncached axes (on) and the scope's own set-up."""
    plot = scope.plot
    plot.grid.setVisible(not on)
    plot.item.getAxis("left").setGrid(0.3 if on else False)
    plot.item.getAxis("bottom").setGrid(0.3 if on else False)
    cache = QGraphicsItem.CacheMode
    for axis in plot.axes:
        axis.setCacheMode(cache.NoCache if on else cache.DeviceCoordinateCache)


def main() -> int:
    """Measure and print the table."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--window", type=float, default=10.0)
    parser.add_argument("--quick", action="store_true", help="a smoke run: seconds, not figures")
    args = parser.parse_args()
    rounds, repaints = (1, 5) if args.quick else (3, 60)
    if args.quick:
        args.window = 1.0
    app = QApplication.instance() or QApplication([])
    scope = filled_scope(args.window)
    app.processEvents()
    print(f"scope {SIZE[0]}x{SIZE[1]}, plot {scope.plot.graphics.width()}x"
          f"{scope.plot.graphics.height()}, 3 channels x {int(args.window * RATE_HZ)} samples")  # fmt: skip
    print(f"{'repaint':10s} {'scope':>12s} {'pyqtgraph grid':>15s} {'ratio':>7s}")
    for label, roll in (("static", False), ("roll", True)):
        cached, uncached = [], []
        for _ in range(rounds):  # interleaved, so a slow spell of the machine hits both
            standard_grid(scope, False)
            cached.append(repaint_ms(scope, roll, repaints))
            standard_grid(scope, True)
            uncached.append(repaint_ms(scope, roll, repaints))
        standard_grid(scope, False)
        a, b = statistics.median(cached), statistics.median(uncached)
        print(f"{label:10s} {a:9.2f} ms {b:12.2f} ms {a / b:6.2f}x")
    # Delete the scope while the application still exists: left to interpreter shutdown, the
    # QApplication was sometimes destroyed first and the widget's destructor crashed (CI, -11).
    scope.close()
    shiboken6.delete(scope)
    app.processEvents()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

"""The GUI's cycle-collector pauses: what the GUI thread holds the GIL for, on each timer tick.

The window as ``prm9tool --emulator TYPEKEY`` opens it, online, with the Tuning window open;
each figure is the median of 10 collections on the GUI thread, each after 1 s of the running
program (the timer's period). The valve connection's
worker sends no report while a collection runs, and the valve drops its setpoint override after
0.5 s without one (docs/tuning.md). Reference, in the same run: a full collection of the same
objects, as the timer ran every second before (``gc.collect()``).

Run:  QT_QPA_PLATFORM=offscreen python benchmarks/bench_gui_gc.py [--quick]
"""

from __future__ import annotations

import argparse
import gc
import statistics
import sys
import time
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from PySide6.QtWidgets import QApplication

TYPE_KEY = "PRM9-06.3Z11/30-24E02S02"


def _pause_ms(qapp: QApplication, generation: int, runs: int, tick_s: float) -> float:
    """Median pause of ``gc.collect(generation)`` after ``tick_s`` of the running program."""
    times = []
    for _ in range(runs):
        end = time.monotonic() + tick_s
        while time.monotonic() < end:  # the window and the connection at work, as between ticks
            qapp.processEvents()
            time.sleep(0.005)
        start = time.perf_counter()
        gc.collect(generation)
        times.append(time.perf_counter() - start)
    return statistics.median(times) * 1000.0


def main(argv: list[str] | None = None) -> int:
    """Print the pauses of a young and a full collection, before and after the start-up freeze."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="smoke run: fewer collections")
    options = parser.parse_args(argv)
    runs, tick_s = (2, 0.1) if options.quick else (10, 1.0)

    from prm9tool import app
    from prm9tool.app import start_plan
    from prm9tool.cli.parser import build_parser
    from prm9tool.views.tuning.window import TuningWindow

    args = build_parser().parse_args(["--emulator", TYPE_KEY])
    qapp = app.create_application()
    window = app.create_window(args)
    window.show()
    start_plan.start(window, start_plan.plan_from(args))
    deadline = time.monotonic() + 60.0
    while not window.connection.is_online and time.monotonic() < deadline:
        qapp.processEvents()
        time.sleep(0.01)
    tuning = TuningWindow(window.doc, window.connection)
    tuning.show()
    qapp.processEvents()
    try:
        objects = len(gc.get_objects())
        full = _pause_ms(qapp, 2, runs, tick_s)
        young = _pause_ms(qapp, 1, runs, tick_s)
        app.freeze_start_up_objects()
        frozen = _pause_ms(qapp, 2, runs, tick_s)
        print(f"objects tracked by the collector: {objects}, frozen at start-up: "
              f"{gc.get_freeze_count()}")  # fmt: skip
        print(f"full collection (reference, each second before): {full:8.3f} ms")
        print(f"young generations (each second now):             {young:8.3f} ms  "
              f"({young / full:.4f} of the reference)")  # fmt: skip
        print(f"full collection after the start-up freeze:       {frozen:8.3f} ms  "
              f"({frozen / full:.4f} of the reference)")  # fmt: skip
    finally:
        gc.unfreeze()
        tuning.close()
        window.connection.shutdown()
        window.close()
        qapp.processEvents()
    return 0


if __name__ == "__main__":
    sys.exit(main())

"""Start-up time: process start → main window shown, and → online with an emulated valve.

Reference, measured in the same run: ``python -c "import PySide6.QtWidgets"`` (the floor any
PySide6 program pays). Each figure is the median of several fresh processes, offscreen, with
settings and emulator data in a temporary folder.

Run:  QT_QPA_PLATFORM=offscreen python benchmarks/bench_startup.py [--runs N]
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable, Sequence
from pathlib import Path

TYPE_KEY = "PRM9-06.3Z11/30-24E02S02-CA"

# The child starts prm9tool exactly as ``prm9tool --emulator TYPEKEY`` does and prints the
# wall-clock moments it reaches: window shown, online, parameters read (edits go to the valve).
CHILD = r"""
import os, sys, time
from prm9tool import app
from prm9tool.cli.main import build_parser
from PySide6.QtCore import QTimer

args = build_parser().parse_args(sys.argv[1:])
qapp = app.create_application()
window = app.create_window(args)
window.show()
qapp.processEvents()
print("shown", time.time(), flush=True)

def on_online(online):
    if online:
        print("online", time.time(), flush=True)

def poll():
    if window.sync.active:
        print("ready", time.time(), flush=True)
        window.connection.shutdown()
        os._exit(0)

window.connection.online_changed.connect(on_online)
timer = QTimer()
timer.timeout.connect(poll)
timer.start(5)
app.start(window, app.plan_from(args))
QTimer.singleShot(20000, lambda: os._exit(3))
qapp.exec()
"""


def _environment(folder: str) -> dict[str, str]:
    env = dict(os.environ)
    env.pop("PYTHONDONTWRITEBYTECODE", None)  # an installed program has its bytecode cached
    env.setdefault("QT_QPA_PLATFORM", "offscreen")
    env["XDG_CONFIG_HOME"] = str(Path(folder) / "config")
    env["PRM9TOOL_DATA_DIR"] = str(Path(folder) / "data")
    return env


def reference_once() -> float:
    """Seconds for a fresh ``python -c "import PySide6.QtWidgets"``."""
    start = time.time()
    subprocess.run([sys.executable, "-c", "import PySide6.QtWidgets"], check=True)
    return time.time() - start


def prm9tool_once() -> dict[str, float]:
    """Seconds from process start to each milestone of one start of prm9tool."""
    with tempfile.TemporaryDirectory() as folder:
        start = time.time()
        result = subprocess.run(
            [sys.executable, "-c", CHILD, "--emulator", TYPE_KEY],
            env=_environment(folder),
            capture_output=True,
            text=True,
            timeout=60,
            check=False,
        )
    moments = {}
    for line in result.stdout.splitlines():
        name, _, stamp = line.partition(" ")
        moments[name] = float(stamp) - start
    if "ready" not in moments:
        raise RuntimeError(f"prm9tool did not get online:\n{result.stdout}\n{result.stderr}")
    return moments


def compare_with_pyside(
    description: str | None,
    measure_once: Callable[[], dict[str, float]],
    rows: Sequence[tuple[str, str]],
) -> int:
    """Parse ``--runs``/``--quick``, then print the median of each of ``rows`` (figure name,
    label) measured by ``measure_once`` in fresh processes, against the reference."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--runs", type=int, default=7)
    parser.add_argument("--quick", action="store_true", help="a smoke run: seconds, not figures")
    args = parser.parse_args()
    runs = 1 if args.quick else args.runs
    reference_once()  # warm the file cache for both
    measure_once()
    reference = statistics.median(reference_once() for _ in range(runs))
    samples = [measure_once() for _ in range(runs)]
    print(f"runs per figure: {runs} (median), Python {sys.version.split()[0]}")
    print(f"{'python -c import PySide6.QtWidgets':44s} {reference * 1000:7.0f} ms   1.00 x")
    for name, label in rows:
        value = statistics.median(s[name] for s in samples)
        print(f"{label:44s} {value * 1000:7.0f} ms {value / reference:6.2f} x")
    return 0


def main() -> int:
    """Measure and print the figures."""
    return compare_with_pyside(
        __doc__,
        prm9tool_once,
        (
            ("shown", "prm9tool: main window shown"),
            ("online", "prm9tool --emulator: online"),
            ("ready", "prm9tool --emulator: valve read, edits live"),
        ),
    )


if __name__ == "__main__":
    sys.exit(main())

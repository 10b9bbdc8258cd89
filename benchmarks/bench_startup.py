"""Start-up time: process start → main window shown, and → online with an emulated valve.

Reference, measured in the same run: ``python -c "import PySide6.QtWidgets"`` (the floor any
PySide6 program pays). Each figure is the median of several fresh processes, offscreen, with
settings and emulator data in a temporary folder, with the bytecode cache an installed program
has (also when ``PYTHONDONTWRITEBYTECODE`` is set: compiling every module cost +0.12 s).

Beside the wall time, the CPU time the process has used at each milestone (all its threads;
the reference's: the child's whole run) and its ratio: on a machine loaded by other work the
wall times swing by a factor of two from run to run, the CPU times much less, so they tell a
change from noise.

Run:  QT_QPA_PLATFORM=offscreen python benchmarks/bench_startup.py [--runs N]
"""

from __future__ import annotations

import argparse
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable, Sequence
from pathlib import Path

try:
    import resource  # the children's CPU time; not on Windows
except ImportError:  # pragma: no cover - Windows
    resource = None  # type: ignore[assignment]

TYPE_KEY = "PRM9-06.3Z11/30-24E02S02-CA"

# The child starts prm9tool exactly as ``prm9tool --emulator TYPEKEY`` does and prints the
# wall-clock moments it reaches: window shown, online, parameters read (edits go to the valve).
CHILD = r"""
import os, sys, time
from prm9tool import app
from prm9tool.app import start_plan
from prm9tool.cli.main import build_parser
from PySide6.QtCore import QTimer

args = build_parser().parse_args(sys.argv[1:])
qapp = app.create_application()
window = app.create_window(args)
window.show()
qapp.processEvents()
print("shown", time.time(), time.process_time(), flush=True)

def on_online(online):
    if online:
        print("online", time.time(), time.process_time(), flush=True)

def poll():
    if window.sync.active:
        print("ready", time.time(), time.process_time(), flush=True)
        window.connection.shutdown()
        os._exit(0)

window.connection.online_changed.connect(on_online)
timer = QTimer()
timer.timeout.connect(poll)
timer.start(5)
start_plan.start(window, start_plan.plan_from(args))
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
    return reference_with_cpu()[0]


def reference_with_cpu() -> tuple[float, float]:
    """Wall and CPU seconds of a fresh ``python -c "import PySide6.QtWidgets"``."""
    start = time.time()
    if resource is None:  # Windows: the wall time only
        subprocess.run([sys.executable, "-c", "import PySide6.QtWidgets"], check=True)
        return time.time() - start, math.nan
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run([sys.executable, "-c", "import PySide6.QtWidgets"], check=True)
    wall = time.time() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu


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
        name, _, stamps = line.partition(" ")
        wall, _, cpu = stamps.partition(" ")
        moments[name] = float(wall) - start
        if cpu:
            moments[f"{name} cpu"] = float(cpu)
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
    references = [reference_with_cpu() for _ in range(runs)]
    reference = statistics.median(wall for wall, _cpu in references)
    reference_cpu = statistics.median(cpu for _wall, cpu in references)
    samples = [measure_once() for _ in range(runs)]
    print(f"runs per figure: {runs} (median), Python {sys.version.split()[0]}, "
          f"load average {_load()} at the end")  # fmt: skip
    print(f"{'':44s} {'wall':>7s}    {'ratio':>6s} {'CPU':>7s}    {'ratio':>6s}")
    print(f"{'python -c import PySide6.QtWidgets':44s} {reference * 1000:7.0f} ms   1.00 x"
          f" {reference_cpu * 1000:7.0f} ms   1.00 x")  # fmt: skip
    for name, label in rows:
        value = statistics.median(s[name] for s in samples)
        line = f"{label:44s} {value * 1000:7.0f} ms {value / reference:6.2f} x"
        if all(f"{name} cpu" in s for s in samples) and not math.isnan(reference_cpu):
            cpu = statistics.median(s[f"{name} cpu"] for s in samples)
            line += f" {cpu * 1000:7.0f} ms {cpu / reference_cpu:6.2f} x"
        print(line)
    return 0


def _load() -> str:
    try:
        return f"{os.getloadavg()[0]:.1f}"
    except (AttributeError, OSError):  # Windows
        return "unknown"


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

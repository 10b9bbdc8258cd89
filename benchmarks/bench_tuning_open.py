"""Opening the Tuning window the first time: Tools → Tuning in a program whose main window is up.

The child process imports what the program has imported once its main window is shown
(``prm9tool.views.main_window``), then times ``TuningWindow(doc)`` shown, imports included
(the first opening pays them); then, separately, importing scipy, which the window's analyses
need and now load when a test first runs (in the runner's worker thread). Reference, measured
in the same run: ``python -c "import PySide6.QtWidgets"`` in a fresh process. Median of several
fresh processes, offscreen.

The child runs with ``-P``: the prm9tool it opens is the one on PYTHONPATH (or installed), not
the current folder's, so an older tree can be measured beside this one.

Run:  QT_QPA_PLATFORM=offscreen PYTHONPATH=$PWD python benchmarks/bench_tuning_open.py [--runs N]
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import time

CHILD = r"""
import sys, time
from PySide6.QtWidgets import QApplication
qapp = QApplication([])
import prm9tool.views.main_window  # loaded before Tools -> Tuning can be chosen
from prm9tool.model.document import ParameterDocument
doc = ParameterDocument("PRM9-06.3Z11/30-24E02S02")
start = time.perf_counter()
from prm9tool.views.tuning.window import TuningWindow
window = TuningWindow(doc)
window.show()
qapp.processEvents()
print("open", time.perf_counter() - start, flush=True)
start = time.perf_counter()
import scipy.optimize, scipy.signal
print("scipy", time.perf_counter() - start, flush=True)
"""


def reference_once() -> float:
    """Seconds for a fresh ``python -c "import PySide6.QtWidgets"``."""
    start = time.perf_counter()
    subprocess.run([sys.executable, "-c", "import PySide6.QtWidgets"], check=True)
    return time.perf_counter() - start


def tuning_once() -> dict[str, float]:
    """Seconds to open the Tuning window, and to import scipy after it, in a fresh process."""
    env = dict(os.environ)
    env.setdefault("QT_QPA_PLATFORM", "offscreen")
    result = subprocess.run(
        [sys.executable, "-P", "-c", CHILD], env=env, capture_output=True, text=True, timeout=120
    )
    figures = {}
    for line in result.stdout.splitlines():
        name, _, value = line.partition(" ")
        figures[name] = float(value)
    if "scipy" not in figures:
        raise RuntimeError(f"the Tuning window did not open:\n{result.stdout}\n{result.stderr}")
    return figures


def main() -> int:
    """Measure and print the figures."""
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--runs", type=int, default=7)
    parser.add_argument("--quick", action="store_true", help="a smoke run: seconds, not figures")
    args = parser.parse_args()
    runs = 1 if args.quick else args.runs
    reference_once()  # warm the file cache for both
    tuning_once()
    reference = statistics.median(reference_once() for _ in range(runs))
    samples = [tuning_once() for _ in range(runs)]
    print(f"runs per figure: {runs} (median), Python {sys.version.split()[0]}")
    print(f"{'python -c import PySide6.QtWidgets':44s} {reference * 1000:7.0f} ms   1.00 x")
    for name, label in (
        ("open", "Tuning window opened the first time"),
        ("scipy", "then scipy imported (first test run)"),
    ):
        value = statistics.median(s[name] for s in samples)
        print(f"{label:44s} {value * 1000:7.0f} ms {value / reference:6.2f} x")
    return 0


if __name__ == "__main__":
    sys.exit(main())

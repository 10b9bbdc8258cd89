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

import os
import subprocess
import sys

from bench_startup import compare_with_pyside

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
    return compare_with_pyside(
        __doc__,
        tuning_once,
        (
            ("open", "Tuning window opened the first time"),
            ("scipy", "then scipy imported (first test run)"),
        ),
    )


if __name__ == "__main__":
    sys.exit(main())

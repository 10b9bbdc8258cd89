"""Opening the Tuning window does not import scipy: that import took over a second (2–3 s on
a tester's PC) before the window appeared. The analyses import it when a test first runs, in
the runner's worker thread (benchmarks/bench_tuning_open.py measures both)."""

from __future__ import annotations

import os
import subprocess
import sys

CHILD = r"""
import sys
from PySide6.QtWidgets import QApplication
app = QApplication([])
from prm9tool.model.document import ParameterDocument
from prm9tool.views.tuning.window import TuningWindow
window = TuningWindow(ParameterDocument("PRM9-06.3Z11/30-24E02S02"))
window.show()
app.processEvents()
print("tabs", window.tabs.count())
print("scipy", sorted(name for name in sys.modules if name.split(".")[0] == "scipy")[:3])
"""


def test_opening_the_tuning_window_leaves_scipy_unimported():
    env = dict(os.environ, QT_QPA_PLATFORM="offscreen")
    run = subprocess.run(
        [sys.executable, "-c", CHILD], env=env, capture_output=True, text=True, timeout=120
    )
    assert run.returncode == 0, run.stderr
    lines = dict(line.split(" ", 1) for line in run.stdout.splitlines())
    assert int(lines["tabs"]) >= 4  # the window was built, every page
    assert lines["scipy"] == "[]"


def test_the_analyses_still_work_with_scipy_imported_where_used():
    import numpy as np

    from prm9tool.analysis.flow import velocity
    from prm9tool.analysis.frequency import frequency_response, log_chirp

    fs = 1000.0
    u = log_chirp(2.0, fs, 1.0, 100.0)
    response = frequency_response(u, 0.5 * u, fs, 2.0, 50.0)
    assert np.allclose(np.abs(response.magnitude), 0.5, atol=0.01)
    assert np.allclose(velocity(np.arange(200.0), fs), fs)

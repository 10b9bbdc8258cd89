"""Offscreen screenshot of the oscilloscope holding a captured step response.

Usage (from the repository root)::

    QT_QPA_PLATFORM=offscreen python tools/scope_screenshot.py [OUTPUT.png]

The capture is real: a paced emulated valve streams through the USB emulator transport, the
valve session and the connection into the scope while the setpoint generator steps the valve's
setpoint; a single trigger on the setpoint's rising edge holds the step, the cursors mark the
step and the settling point, and the step-response figures sit next to the plot.
"""

from __future__ import annotations

import os
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
os.environ.setdefault("PRM9TOOL_DATA_DIR", tempfile.mkdtemp(prefix="scope_shot_"))

from PySide6.QtWidgets import QApplication

from prm9tool.model.document import ParameterDocument
from prm9tool.online.connection import ValveConnection
from prm9tool.scope import Edge, TriggerMode, Waveform
from prm9tool.views.scope.widget import ScopeWidget

TYPE_KEY = "PRM9-06.3Z11/30-24E02S02"
OUTPUT = Path("docs/screenshots/scope_step_response.png")


def wait_until(app: QApplication, condition: Callable[[], bool], timeout_s: float) -> bool:
    """Process events until ``condition`` holds."""
    deadline = time.monotonic() + timeout_s
    while not condition() and time.monotonic() < deadline:
        app.processEvents()
        time.sleep(0.005)
    return condition()


def capture(app: QApplication, scope: ScopeWidget) -> None:
    """Record one rising setpoint step with a single trigger."""
    for key in ("setpoint_raw", "position_actual", "current_a"):
        scope.preselect(key)
    c = scope.controls
    c.time_window.setCurrentIndex(c.time_window.findData(0.1))
    c.channel.setCurrentIndex(0)
    c.edge.setCurrentIndex(c.edge.findData(Edge.RISING))
    c.level.setValue(0.0)
    c.pre.setValue(10)
    scope.start()
    wait_until(app, lambda: scope.receiving, 5.0)
    panel = scope.generator_panel
    panel.waveform.setCurrentIndex(panel.waveform.findData(Waveform.SQUARE))
    panel.amplitude.setValue(60.0)
    panel.offset.setValue(-30.0)
    panel.period.setValue(0.4)
    scope.generator.start(panel.settings())  # the confirmation box is the user's part
    wait_until(app, lambda: False, 1.0)  # a few periods: the valve swings steadily
    c.mode.setCurrentIndex(c.mode.findData(TriggerMode.SINGLE))
    if not wait_until(app, lambda: scope.display.engine.done, 10.0):
        sys.exit("no step was captured")


def mark(scope: ScopeWidget) -> None:
    """Cursors on the step and the settling point; figures between them."""
    scope.cursor_panel.show_cursors.setChecked(True)
    figures = scope.display.measure(*scope.plot.x_range()).figures
    settle = figures.settling_time if figures is not None else 0.05
    scope.plot.set_cursor_times(0.0, settle)  # Δt reads the settling time
    scope.display.update_readouts()
    scope.readouts.setCurrentWidget(scope.step_panel)


def main() -> None:
    """Take the screenshot."""
    output = Path(sys.argv[1]) if len(sys.argv) > 1 else OUTPUT
    app = QApplication.instance() or QApplication([])
    conn = ValveConnection()
    conn.go_online(conn.list_devices([TYPE_KEY])[-1])
    if not wait_until(app, lambda: conn.is_online, 20.0):
        sys.exit("the emulated valve did not come online")
    time.sleep(1.5)  # let the valve finish booting before the generator drives it
    scope = ScopeWidget(conn, ParameterDocument(TYPE_KEY))
    scope.resize(1280, 760)
    scope.show()
    capture(app, scope)
    mark(scope)
    for _ in range(20):
        app.processEvents()
        time.sleep(0.01)
    output.parent.mkdir(parents=True, exist_ok=True)
    scope.grab().save(str(output), "PNG")
    print(f"wrote {output}")  # noqa: T201
    scope.close()  # stops the generator: SETPOVRON = 0
    conn.go_offline()
    wait_until(app, lambda: not conn.is_online, 5.0)
    conn.shutdown()


if __name__ == "__main__":
    main()

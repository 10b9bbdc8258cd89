"""The Tuning window's progress bar: how far a test is, from the valve time it has played.

A test plays a known stimulus (its steps, sweep and triangle); the rig counts the valve seconds
it has played (``Rig.played_s``), and the bar shows that share of what the test plans
(``planned_s``). A test whose length is not known beforehand (the autotune's search) shows a
busy bar. The bar polls the runner on the GUI thread; the test runs in its own thread.
"""

from __future__ import annotations

from PySide6.QtCore import QTimer
from PySide6.QtWidgets import QProgressBar

from prm9tool.online.tuning_runner import TuningRunner

POLL_MS = 200


class TestProgress(QProgressBar):
    """A progress bar beside the Stop button, shown while a test runs."""

    def __init__(self) -> None:
        super().__init__()
        self.setObjectName("tuning_progress")
        self.setMinimumWidth(160)
        self.setVisible(False)
        self._runner: TuningRunner | None = None
        self._planned: float | None = None
        self._timer = QTimer(self)
        self._timer.setInterval(POLL_MS)
        self._timer.timeout.connect(self.poll)

    def start(self, runner: TuningRunner, planned_s: float | None) -> None:
        """Follow ``runner``'s test, which plays about ``planned_s`` valve seconds."""
        if not runner.busy:
            return
        self._runner, self._planned = runner, planned_s
        if planned_s:
            self.setRange(0, 100)
            self.setValue(0)
        else:
            self.setRange(0, 0)  # busy: the length is not known
        self.setVisible(True)
        self._timer.start()

    def poll(self) -> None:
        """Show the share of the planned valve time played so far (at most 99 % while running)."""
        runner = self._runner
        if runner is None or not self._planned:
            return
        share = runner.played_s() / self._planned
        self.setValue(min(99, int(share * 100.0)))

    def finish(self) -> None:
        """The test ended (done, stopped or failed): hide the bar."""
        self._timer.stop()
        self._runner = None
        self.setVisible(False)

"""Issue 34 "done means": the E04 process-loop path from commissioning to a passing end-of-line
report, as a service engineer does it at the screen: an E04S02-CA valve as delivered, online,
NMT start and Enable in the Valve status window, Expert level, the Tuning window (it opens on
the process loop), Test report with the built-in profile — PASS, the report naming the loop."""

from __future__ import annotations

import time

from PySide6.QtWidgets import QMessageBox
from support.gui_support import emulated, go_online, main_window

from prm9tool.model.access import Access

E04_CA = "PRM9-06.3Z11/30-24E04S02-CA"
SERIAL = 4391
TIMEOUT = 10_000


def test_an_e04_process_loop_passes_its_end_of_line_report_online(qtbot, tmp_path, monkeypatch):
    with main_window(qtbot, tmp_path, E04_CA) as window:
        go_online(qtbot, window, f"{E04_CA}:{SERIAL}")
        emulated(SERIAL).advance(2.0)  # booted: pre-operational, INIT
        panel = window.show_status_window().commissioning
        qtbot.waitUntil(
            lambda: "waits for a CANopen master" in panel.reason.text(), timeout=TIMEOUT
        )
        panel.buttons["nmt_start"].click()
        panel.buttons["enable"].click()
        qtbot.waitUntil(lambda: "follows its setpoint" in panel.reason.text(), timeout=TIMEOUT)
        window.access.set_level(Access.EXPERT)
        window.show_tuning_window(None)
        tuning = window.tuning_window
        assert tuning.current_loop() == "process"  # control mode 4 as delivered
        monkeypatch.setattr(QMessageBox, "question", lambda *a: QMessageBox.StandardButton.Yes)
        tuning.tabs.setCurrentWidget(tuning.report)
        started = time.monotonic()
        tuning.report.run_button.click()
        assert tuning.runner.busy, tuning.status.text()
        qtbot.waitUntil(lambda: not tuning.runner.busy, timeout=300_000)
        result = tuning.report.last
        assert result is not None, tuning.status.text()
        failed = [(f.name, f.value) for f in result.figures if f.passed is False]
        assert result.passed, failed
        assert result.loop == "process" and tuning.report.result.text() == "Result: PASS"
        assert all(s.record.t[-1] >= 1.4 for s in result.steps)
        print(f"end-of-line report of the process loop online: {time.monotonic() - started:.0f} s")

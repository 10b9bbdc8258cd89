"""Issue 31 item 2 in the Tuning window: the Twin page fits a twin — of the connected valve
(its end-of-line test on the valve, off the GUI thread) or of a characterization's JSON report
— through the implementation of ``--fit-twin``, shows the fit report and the twin set beside
the valve, writes the twin file and records it in the history."""

from __future__ import annotations

import json
import os
from dataclasses import replace
from pathlib import Path

import pytest
from PySide6.QtWidgets import QMessageBox

import prm9tool
from prm9tool.device.emulator.twinfile import read_twin
from prm9tool.model.document import ParameterDocument
from prm9tool.views.tuning.window import TuningWindow

E02 = "PRM9-06.3Z11/30-24E02S02"
SHOTS = os.environ.get("PRM9TOOL_SCREENSHOTS")
SHORT = """name = "short"
[test]
step_amplitudes_pct = [25]
bode_duration_s = 3
bode_f_min_hz = 2
bode_f_max_hz = 100
static_period_s = 4
"""


def _window(qtbot, connection=None) -> TuningWindow:
    w = TuningWindow(ParameterDocument(E02), connection)
    qtbot.addWidget(w)
    w.show()
    w.tabs.setCurrentWidget(w.twin)
    return w


def _rows(table) -> dict[str, list[str]]:
    return {
        table.item(r, 0).text(): [table.item(r, c).text() for c in range(table.columnCount())]
        for r in range(table.rowCount())
    }


def test_offline_the_valve_is_asked_for_and_a_report_is_fitted(qtbot, tmp_path, monkeypatch):
    from prm9tool.analysis.profile import parse_profile
    from prm9tool.characterize.rig import EmulatorRig
    from prm9tool.characterize.run import characterize, report_data, write_csv_files
    from prm9tool.device.emulator import EmulatedValve
    from prm9tool.device.emulator.constants import PLANT
    from prm9tool.views.files import dialogs

    w = _window(qtbot)
    page = w.twin
    assert page.run_button.text() == "Fit twin of the valve"
    page.run_button.click()
    assert "go online with the valve" in page.result.text() and not w.runner.busy
    plant = replace(PLANT, force_n_per_a=24.0)
    valve = EmulatedValve(E02, serial=3127, plant=plant, nv_path=tmp_path / "3127.json")
    run = characterize(EmulatorRig(valve), parse_profile({"test": {
        "step_amplitudes_pct": [25], "bode_duration_s": 3, "bode_f_min_hz": 2,
        "bode_f_max_hz": 100, "static_period_s": 4}}))  # fmt: skip
    report = tmp_path / "run.json"
    report.write_text(json.dumps(report_data(run, write_csv_files(run, tmp_path / "run"))))
    out = tmp_path / "nowhere" / "twin.toml"
    page.out.setText(str(out))
    monkeypatch.setattr(dialogs, "open_file_name", lambda *_a, **_k: (str(report), ""))
    page.from_report.click()  # a folder that does not exist: said, nothing started
    assert "There is no folder" in page.result.text() and not page.reports.busy
    out = tmp_path / "twin.toml"
    page.out.setText(str(out))
    page.from_report.click()
    assert page.reports.busy and not page.from_report.isEnabled()  # off the GUI thread
    qtbot.waitUntil(lambda: page.from_report.isEnabled(), timeout=180000)
    text = page.result.text()
    assert text.startswith(f"Twin written to {out} and recorded in the history."), text
    assert "sweep" in text and "static characteristic" in text  # the whole run fitted
    assert "The twin was characterized over: emulator" in text  # the proof says its link
    constants = _rows(page.constants)
    assert constants["force_n_per_a"][3] == "determined"
    assert float(constants["force_n_per_a"][2]) == pytest.approx(24.0, rel=0.05)
    sides = _rows(page.sides)
    assert "−3 dB frequency" in sides and "hysteresis" in sides
    assert read_twin(out).serial == 3127
    records = prm9tool.history.records(3127)  # the configured history (no connection)
    assert [r["operation"] for r in records] == ["twin"]


@pytest.fixture
def online(qtbot, tmp_path):
    """A connection online with emulated valve 7301, recording into a fresh history."""
    from support.gui_support import online_recording

    with online_recording(qtbot, tmp_path, f"{E02}:7301") as both:
        yield both


def test_online_the_valve_is_characterized_fitted_and_recorded(
    qtbot, online, tmp_path, monkeypatch
):
    connection, recorder = online
    (tmp_path / "short.toml").write_text(SHORT, encoding="utf-8")
    w = _window(qtbot, connection)
    w.report.profile_path.setText(str(tmp_path / "short.toml"))
    out = tmp_path / "7301-twin.toml"
    monkeypatch.setattr(w, "save_file", lambda *_a: out)  # the field empty: asked for
    asked = []
    monkeypatch.setattr(
        QMessageBox, "question", lambda *a: asked.append(a[2]) or QMessageBox.StandardButton.Yes
    )
    w.twin.run_button.click()
    assert "moves the spool" in asked[0] and "twin fitted" in asked[0]
    assert w.runner.busy
    qtbot.waitUntil(lambda: not w.runner.busy, timeout=240000)
    status = w.status.text()
    if "too seldom" in status or "link lost" in status:  # a PC too loaded: said, not hidden
        pytest.skip(f"the test was refused on this loaded PC: {status}")
    page = w.twin
    assert page.result.text().startswith(f"Twin written to {out}"), (status, page.result.text())
    assert _rows(page.constants)["force_n_per_a"][3] == "determined"
    assert "−3 dB frequency" in _rows(page.sides)
    assert read_twin(out).serial == 7301
    operations = [r["operation"] for r in recorder.store().records(7301)]
    assert operations[-2:] == ["characterization", "twin"]
    if SHOTS:
        w.grab().save(str(Path(SHOTS) / "tuning_twin.png"))


def test_a_report_of_another_serial_does_not_overwrite_the_twin_the_field_names(
    qtbot, tmp_path, monkeypatch
):
    """The field still names the twin of serial 3127 (its suggestion, or a fit before): a
    report of serial 3128 asks where its twin goes, suggesting 3128's name, and a cancel
    writes nothing and keeps the field."""
    from prm9tool.views.files import dialogs

    w = _window(qtbot)
    page = w.twin
    kept = tmp_path / "3127-twin.toml"
    kept.write_text('format = "prm9tool twin"\nversion = 1\nserial = 3127\n', encoding="utf-8")
    page.out.setText(str(kept))
    report = tmp_path / "run.json"
    report.write_text(json.dumps({"valve": {"serial": 3128}}), encoding="utf-8")
    monkeypatch.setattr(dialogs, "open_file_name", lambda *_a, **_k: (str(report), ""))
    asked = []
    monkeypatch.setattr(w, "save_file", lambda *a: asked.append(a[2]))  # cancelled
    page.from_report.click()
    assert asked == ["3128-twin.toml"]
    assert not page.reports.busy and page.out.text() == str(kept)
    assert kept.read_text(encoding="utf-8").endswith("serial = 3127\n")


def test_a_figure_not_measured_is_a_dash_without_a_unit(qtbot, tmp_path):
    """The 5 % step of a valve that never settles within ±2 %: "—", not "— s"."""
    import math
    from types import SimpleNamespace

    from prm9tool.service.twin import ProvenTwin
    from prm9tool.twin.proof import Side

    w = _window(qtbot)
    fit = SimpleNamespace(explained=True, start_rms_pct=1.0, rms_pct=0.5, parts_rms_pct={},
                          constants=[])  # fmt: skip
    sides = [
        Side("step_5_settling_s", "step 5 %: settling time", "s", math.nan, math.nan),
        Side("step_25_settling_s", "step 25 %: settling time", "s", 0.0244, 0.0158),
        Side("step_25_overshoot_pct", "step 25 %: overshoot", "%", 2.0, 1.5),
    ]
    w.twin.show_result(ProvenTwin(SimpleNamespace(fit=fit, path=tmp_path / "t.toml"), sides))
    rows = list(_rows(w.twin.sides).values())
    assert rows[0][1:] == ["—", "—", "—"]
    assert rows[1][1:] == ["0.0244 s", "0.0158 s", "×0.648 (twin/valve)"]  # each row its kind
    assert rows[2][3] == "−0.5 pp (twin − valve)"
    assert w.twin.sides.horizontalHeaderItem(3).text() == "Twin compared with valve"

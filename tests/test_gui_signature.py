"""Issue 31 item 5 in the Tuning window: "Compare with birth certificate" runs the field
signature on the connected valve off the GUI thread, shows the drift and saves the PDF;
without a birth certificate it says how to make one; offline it asks for the valve."""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest
from PySide6.QtWidgets import QMessageBox

from prm9tool.model.document import ParameterDocument
from prm9tool.views.tuning.window import TuningWindow

E02 = "PRM9-06.3Z11/30-24E02S02"
SHOTS = os.environ.get("PRM9TOOL_SCREENSHOTS")


@pytest.fixture
def online(qtbot, tmp_path):
    """A connection online with emulated valve 7201, recording into a fresh history."""
    from support.gui_support import online_recording

    with online_recording(qtbot, tmp_path, f"{E02}:7201") as both:
        yield both


def _window(qtbot, connection=None) -> TuningWindow:
    w = TuningWindow(ParameterDocument(E02), connection)
    qtbot.addWidget(w)
    w.show()
    return w


def test_offline_the_comparison_asks_for_the_valve(qtbot):
    w = _window(qtbot)
    w.tabs.setCurrentWidget(w.signature)
    assert w.signature.run_button.text() == "Compare with birth certificate"
    w.signature.run_button.click()
    assert "go online with the valve first" in w.signature.result.text()
    assert not w.runner.busy


def test_without_a_birth_certificate_the_window_says_how_to_make_one(qtbot, online, monkeypatch):
    """Refused before the hydraulics and enabling questions: asking "Start the test?" and
    enabling the valve only to say then that there is nothing to compare with (seen at a real
    screen) asked for a confirmation that led nowhere and left the valve enabled."""
    connection, _recorder = online
    w = _window(qtbot, connection)
    asked = []
    monkeypatch.setattr(
        QMessageBox, "question", lambda *a: asked.append(a[2]) or QMessageBox.StandardButton.Yes
    )
    w.signature.run_button.click()
    message = w.signature.result.text()  # it stays on the page, a sentence
    assert message.startswith("Not compared: the history holds no")
    assert "no end-of-line test of serial 7201" in message
    assert "Run the end-of-line test" in message
    assert asked == [] and not w.runner.busy  # nothing asked, nothing started
    assert not w.signature.save_button.isEnabled()


def test_the_comparison_runs_on_the_valve_shows_the_drift_and_saves_the_pdf(
    qtbot, online, monkeypatch, tmp_path
):
    from prm9tool.analysis.profile import DEFAULT
    from prm9tool.characterize.rig import EmulatorRig
    from prm9tool.characterize.run import characterize
    from prm9tool.device import emulated_valves
    from prm9tool.service.history import record_characterization

    connection, recorder = online
    # its birth certificate: the end-of-line test of the same valve (stepped here)
    valve = emulated_valves.emulated_valve(E02, 7201)
    record_characterization(recorder, characterize(EmulatorRig(valve), DEFAULT))
    w = _window(qtbot, connection)
    w.tabs.setCurrentWidget(w.signature)
    asked = []
    monkeypatch.setattr(
        QMessageBox, "question", lambda *a: asked.append(a[2]) or QMessageBox.StandardButton.Yes
    )
    w.signature.result.setText("Not compared: an earlier refusal")
    w.signature.run_button.click()
    assert "moves the spool" in asked[0] and "at most 20\u00a0s" in asked[0]  # one line (i18n)
    assert w.runner.busy  # off the GUI thread: the window is still there to Stop it
    assert w.signature.result.text() == ""  # the earlier refusal is not this run's answer
    qtbot.waitUntil(lambda: not w.runner.busy, timeout=180000)
    page = w.signature
    status = w.status.text()
    if "too seldom" in status or "link lost" in status:  # a PC too loaded: said, not hidden
        pytest.skip(f"the test was refused on this loaded PC: {status}")
    text = page.result.text()
    assert text.startswith("No figure drifted beyond its limit since the end-of-line test on"), text
    rows = {page.table.item(r, 0).text(): r for r in range(page.table.rowCount())}
    assert "−3 dB frequency" in rows and "hysteresis" in rows
    assert page.table.item(rows["−3 dB frequency"], 4).text() == "± 15 %"
    assert page.plot.plots  # today's step and Bode over the birth certificate's
    assert any("birth certificate" in s.label for p in page.plot.plots for s in p.series)
    if SHOTS:
        w.grab().save(str(Path(SHOTS) / "tuning_signature.png"))
    monkeypatch.setattr(w, "save_file", lambda *_a: tmp_path / "drift.pdf")
    page.save_button.click()
    assert (tmp_path / "drift.pdf").read_bytes().startswith(b"%PDF")
    operations = [r["operation"] for r in recorder.store().records(7201)]
    assert operations[-1] == "signature"


def test_the_drift_table_speaks_the_program_language(qapp):
    """Numbers with the language's decimal comma, the unit after it: a Czech "p. b." kept its
    points (it read "p, b," when the whole cell was localized)."""
    from prm9tool import i18n
    from prm9tool.analysis.profile import DriftLimit
    from prm9tool.characterize.drift import DriftItem
    from prm9tool.views.tuning.signature_report import change_text, limit_text, verdict_text

    hysteresis = DriftItem("static_hysteresis_pct", "hysteresis", "%", 1.1, 0.3,
                           DriftLimit(absolute=0.5), True)  # fmt: skip
    phase = DriftItem("bode_phase90_hz", "−90° frequency", "Hz", 24.1, 29.7,
                      DriftLimit(relative=15.0), True)  # fmt: skip
    rise = DriftItem("step_90_rise_s", "rise", "s", 0.01, 0.008, DriftLimit(absolute=0.002), True)
    shown = {}
    for language in ("en", "de", "cs"):
        i18n.set_language(language)
        shown[language] = (change_text(hysteresis), limit_text(hysteresis), change_text(phase),
                           limit_text(phase), limit_text(rise), verdict_text(True))  # fmt: skip
    i18n.set_language("en")
    assert shown["en"] == ("+0.8 pp", "± 0.5 pp", "−19 %", "± 15 %", "± 2 ms", "DRIFTED")
    assert shown["de"] == ("+0,8 Pp", "± 0,5 Pp", "−19 %", "± 15 %", "± 2 ms", "DRIFT")
    assert shown["cs"] == ("+0,8 p. b.", "± 0,5 p. b.", "−19 %", "± 15 %", "± 2 ms", "DRIFT")
    # a change that rounds to nothing has no minus sign (the gain read "−0.000" on screen)
    from prm9tool.characterize import drift

    gain = DriftItem("static_gain", "gain", "", 0.99995, 1.0, DriftLimit(absolute=0.03), False)
    still = DriftItem("bode_bandwidth_hz", "−3 dB", "Hz", 29.9, 30.0, DriftLimit(relative=15.0),
                      False)  # fmt: skip
    assert (change_text(gain), drift.change_text(gain)) == ("+0.000", "+0.000")
    assert (change_text(still), drift.change_text(still)) == ("+0 %", "+0 %")


def test_a_characterization_record_shows_its_figures_not_its_curves(qtbot):
    """The curves a record keeps for a later signature are some thousand numbers: the
    record's details dialog names them and shows the rest."""
    from prm9tool.views.history.details import RecordDetailsDialog

    details = {"profile": "default", "figures": [], "curves": {"steps": [{"t": [0.0] * 160}]}}
    record = {
        "seq": 1,
        "serial": 7201,
        "operation": "characterization",
        "details": json.dumps(details),
    }  # as the store gives it: JSON text
    dialog = RecordDetailsDialog(record, "Test report", False)
    qtbot.addWidget(dialog)
    text = dialog.text.toPlainText()
    assert '"curves": "…"' in text and '"profile": "default"' in text and "0.0" not in text

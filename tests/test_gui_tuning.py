"""The Tuning window offline (on an emulated copy of the document's valve) and its entries."""

from __future__ import annotations

import os
import re
from pathlib import Path

import numpy as np
import pytest
from pypdf import PdfReader
from PySide6.QtWidgets import QMessageBox
from support.waiting import AUTOTUNE_WORK, work_timeout_s

from prm9tool.model.access import Access, AccessModel
from prm9tool.model.document import ParameterDocument
from prm9tool.model.undo import DocumentUndo
from prm9tool.views.diagram.dialogs import create_block_dialog
from prm9tool.views.diagram.dialogs.base import BlockContext
from prm9tool.views.tuning.window import TuningWindow

E02 = "PRM9-06.3Z11/30-24E02S02"
E04 = "PRM9-06.3Z11/30-24E04S02"
SHOTS = os.environ.get("PRM9TOOL_SCREENSHOTS")


@pytest.fixture
def window(qtbot):
    doc = ParameterDocument(E02)
    doc.set_values({"POSKP": 4}, "detuned")  # Kp/10
    undo = DocumentUndo(doc, doc)
    w = TuningWindow(doc)
    qtbot.addWidget(w)
    w.undo = undo
    w.show()
    yield w
    w.close()


def finish(qtbot, w: TuningWindow, timeout_s: float = 30.0) -> None:
    qtbot.waitUntil(lambda: not w.runner.busy, timeout=round(timeout_s * 1000))


def shot(w: TuningWindow, name: str) -> None:
    if SHOTS:
        w.grab().save(str(Path(SHOTS) / f"tuning_{name}.png"))


def use_profile(window: TuningWindow, tmp_path: Path, text: str) -> None:
    path = tmp_path / "profile.toml"
    path.write_text(text)
    window.report.profile_path.setText(str(path))


def test_model_autotune_proposes_and_accepts_as_one_undo_step(qtbot, window, tmp_path):
    """Issue 25 item 4: the proposal is checked against the acceptance profile (its steps both
    ways and its static test) before it is offered; this one passes."""
    use_profile(window, tmp_path, "[test]\nstep_amplitudes_pct = [25, 90]\nstatic_period_s = 4\n")
    assert "Offline" in window.mode.text()
    wait_s = work_timeout_s(AUTOTUNE_WORK)
    window.autotune.run_button.click()
    assert window.progress.isVisible()  # a test with Stop and a progress bar
    finish(qtbot, window, wait_s)
    assert not window.progress.isVisible()
    page = window.autotune
    text = page.result.text()
    assert "POSKP: 0.04 → " in text
    assert "passes the acceptance profile" in text
    assert "Step 0 → 50 %, window −20 … 120 ms — before:" in text
    assert page.accept_button.isEnabled() and not page.override.isVisible()
    names = [page.table.item(r, 0).text() for r in range(page.table.rowCount())]
    assert "step 0 → −90 %: overshoot" in names and "hysteresis" in names, names
    assert all(page.table.item(r, 4).text() != "FAIL" for r in range(page.table.rowCount()))
    assert [p.title for p in page.plot.plots[1:]] == [
        "Acceptance steps of 25 %",
        "Acceptance steps of 90 %",
    ]
    proposal = dict(page.proposal)
    assert proposal["POSKP"] != 4
    shot(window, "autotune")
    steps = window.undo.stack.count()
    page.accept_button.click()
    assert {k: window.doc.value(k) for k in proposal} == proposal
    assert window.undo.stack.count() == steps + 1
    window.undo.stack.undo()
    assert window.doc.value("POSKP") == 4


def test_a_proposal_that_fails_the_profile_says_so_and_needs_accept_anyway(qtbot, window, tmp_path):
    """A profile stricter than friction allows: a 5 % step overshoots 1 % with any gains. The
    autotune tries stricter targets, then shows the best proposal in red with what it fails;
    Accept needs the explicit override."""
    use_profile(
        window,
        tmp_path,
        "[test]\nstatic_period_s = 4\n[limits]\nstep_overshoot_pct = { max = 1 }\n",
    )
    wait_s = work_timeout_s(AUTOTUNE_WORK)
    window.autotune.run_button.click()
    finish(qtbot, window, wait_s)
    page = window.autotune
    text = page.result.text()
    assert "fails the acceptance profile" in text and "step 0 → 5 %: overshoot" in text
    assert "Tried before and failed the profile" in text
    assert not page.accept_button.isEnabled() and page.override.isVisible()
    assert "FAIL" in [page.table.item(r, 4).text() for r in range(page.table.rowCount())]
    names = [page.table.item(r, 0).text() for r in range(page.table.rowCount())]
    settling = page.table.item(names.index("step 0 → 5 %: settling time (±2 %)"), 2)
    assert settling.text() == "not reached"  # what it saw instead: in the tooltip
    assert settling.toolTip().startswith("did not settle within ±2 % of the step: oscillation")
    shot(window, "autotune_fails_profile")
    page.override.setChecked(True)
    assert page.accept_button.isEnabled()


def test_critical_gain_method_shows_kkr_and_tkr(qtbot, window):
    window.autotune.method.setCurrentIndex(1)
    window.autotune.run_button.click()
    finish(qtbot, window)
    text = window.autotune.result.text()
    kkr = float(text.split("Kkr = ")[1].split(",")[0])
    assert 6.3 <= kkr <= 7.3  # the direct sweep of test_characterize finds 6.85
    assert window.autotune.proposal["POSKP"] == round(kkr * 50)  # K = 0.5·Kkr, raw ×0.01
    # the proposal simulated on the emulator's firmware beside the measured before/after
    assert "simulated on the emulator's firmware (as the controller dialog): overshoot" in text
    # the rule's starting values ring: the profile check says so (Accept needs the override)
    assert "fails the acceptance profile" in text and not window.autotune.accept_button.isEnabled()
    labels = [s.label for s in window.autotune.plot.plots[0].series]
    assert labels == ["before (measured)", "proposed (measured)", "proposed (simulated)"]
    simulated = window.autotune.plot.plots[0].series[2]
    measured = window.autotune.plot.plots[0].series[1]
    # the copy holds the document's parameters: it answers like the measured valve
    assert max(simulated.y) == pytest.approx(max(measured.y), abs=3.0)


def test_bode_and_static_characteristic_with_linearization(qtbot, window):
    window.tabs.setCurrentWidget(window.bode)
    window.bode.duration.setValue(2.0)
    window.bode.f_min.setValue(2.0)
    window.bode.f_max.setValue(100.0)
    window.bode.run_button.click()
    finish(qtbot, window)
    assert "−3 dB: " in window.bode.result.text()
    shot(window, "bode")
    window.tabs.setCurrentWidget(window.static)
    window.static.period.setValue(4.0)
    window.static.run_button.click()
    finish(qtbot, window)
    assert "linearity error" in window.static.result.text()
    shot(window, "static")
    window.static.apply_button.click()
    assert window.doc.value("SETPLINON") == -1
    assert window.doc.value("SETPLINXA") == -16384


def test_report_page_runs_a_profile_and_saves_pdf(qtbot, window, tmp_path, monkeypatch):
    profile = tmp_path / "p.toml"
    profile.write_text("[test]\nbode_duration_s = 2\nbode_f_min_hz = 2\nstatic_period_s = 4\n")
    window.tabs.setCurrentWidget(window.report)
    window.report.profile_path.setText(str(profile))
    window.report.run_button.click()
    finish(qtbot, window)
    assert window.report.table.rowCount() == 15
    shot(window, "report")
    monkeypatch.setattr(window, "save_file", lambda *_a: tmp_path / "r.pdf")
    window.report.save_button.click()
    text = " ".join(PdfReader(tmp_path / "r.pdf").pages[0].extract_text().split())
    assert "PRM9 test report" in text and E02 in text
    assert (tmp_path / "r-static.csv").exists()
    # what limited the run (here a busy PC's sweep) is on the page too, not only in the PDF
    verdict_line = window.report.result.text()
    assert verdict_line in ("Result: PASS", "Result: FAIL")  # nothing limited this run
    from dataclasses import replace

    from prm9tool.characterize.procedures import SWEEP_UPDATED
    from prm9tool.messages import Number

    busy = SWEEP_UPDATED(Number("19.8"), Number("37"), 4)
    window.report.show_result(replace(window.report.last, skipped=[busy]))
    assert window.report.result.text().splitlines() == [
        verdict_line,
        "Limited by the link: sweep usable up to 19.8 Hz: the PC held the valve's setpoint for "
        "37 ms there (at least 4 updates per period are needed; the PC was busy)",
    ]


def test_a_bad_profile_is_reported_and_nothing_runs(qtbot, window, tmp_path):
    (tmp_path / "bad.toml").write_text("[limits]\nnonsense = { max = 1 }\n")
    window.report.profile_path.setText(str(tmp_path / "bad.toml"))
    window.report.run_button.click()
    assert "has no figure 'nonsense'" in window.report.result.text()
    assert not window.runner.busy


def test_the_profile_refusal_goes_when_the_field_is_cleared_or_a_good_profile_chosen(
    qtbot, window, tmp_path
):
    report = window.report
    window.tabs.setCurrentWidget(report)
    report.profile_path.setText(str(tmp_path / "missing.toml"))
    report.run_button.click()
    assert "cannot read the profile" in report.result.text()
    shot(window, "profile_error")
    report.profile_path.clear()
    assert report.result.text() == ""
    shot(window, "profile_cleared")
    report.profile_path.setText(str(tmp_path / "missing.toml"))
    report.run_button.click()
    assert "cannot read the profile" in report.result.text()
    use_profile(window, tmp_path, "[test]\nstep_amplitudes_pct = [25]\n")  # as Browse… does
    assert report.result.text() == ""
    assert not window.runner.busy  # choosing a profile runs nothing


def test_the_profile_refusal_leads_in_the_program_language(qtbot, window, tmp_path):
    """In German the refusal was the analysis layer's English sentence alone."""
    from prm9tool import i18n

    report = window.report
    window.tabs.setCurrentWidget(report)
    report.profile_path.setText(str(tmp_path / "missing.toml"))
    i18n.set_language("de")
    try:
        report.run_button.click()
        shown = report.result.text()
    finally:
        i18n.set_language("en")
    assert shown.startswith("Das Abnahmeprofil kann nicht verwendet werden.")
    assert "missing.toml" in shown  # the file named, as the analysis layer says it
    assert not window.runner.busy


def test_stop_ends_the_test_and_says_so(qtbot, window):
    window.tabs.setCurrentWidget(window.static)
    window.static.period.setValue(60.0)
    window.static.run_button.click()
    window.stop_button.click()
    finish(qtbot, window)
    assert "Stopped" in window.status.text()
    assert not window.static.apply_button.isEnabled()


def test_online_a_test_asks_first_and_does_nothing_when_declined(qtbot, monkeypatch):
    class Online:
        is_online = True
        device = None

        def __init__(self):
            self.streaming_keys: list[str] = []
            from PySide6.QtCore import QObject, Signal

            class Signals(QObject):
                online_changed = Signal(bool)
                operation_finished = Signal(str, object)
                failed = Signal(str)
                lost = Signal(str)
                reconnected = Signal(object)  # as ValveConnection's (ValveRunner follows it)

            self.signals = Signals()
            for name in ("online_changed", "operation_finished", "failed", "lost", "reconnected"):
                setattr(self, name, getattr(self.signals, name))
            self.jobs = []

        def run_job(self, name, work):
            self.jobs.append(name)

    connection = Online()
    w = TuningWindow(ParameterDocument(E02), connection)
    qtbot.addWidget(w)
    asked = []
    monkeypatch.setattr(
        QMessageBox, "question", lambda *a: asked.append(a[2]) or QMessageBox.StandardButton.No
    )
    w.autotune.run_button.click()
    assert "moves the spool" in asked[0] and "50\u00a0%" in asked[0]  # one line: issue 34
    assert connection.jobs == []
    monkeypatch.setattr(QMessageBox, "question", lambda *a: QMessageBox.StandardButton.Yes)
    w.autotune.run_button.click()
    assert connection.jobs == ["tuning:autotune"]


def test_a_test_on_the_valve_says_that_it_stops_the_running_setpoint_generator(qtbot, monkeypatch):
    """Issue 25 item 7: the autotune stopped a running generator without a word."""
    from PySide6.QtCore import QObject, Signal

    class Signals(QObject):
        online_changed = Signal(bool)
        operation_finished = Signal(str, object)
        failed = Signal(str)
        lost = Signal(str)
        reconnected = Signal(object)  # as ValveConnection's (ValveRunner follows it)

    class Online:
        is_online = True
        device = None

        def __init__(self):
            self.streaming_keys: list[str] = []
            self.signals = Signals()
            for name in ("online_changed", "operation_finished", "failed", "lost", "reconnected"):
                setattr(self, name, getattr(self.signals, name))
            self.jobs: list[str] = []
            self.generator_running = True

        def run_job(self, name, work):
            self.jobs.append(name)

        def stop_generator(self):
            self.generator_running = False

    connection = Online()
    w = TuningWindow(ParameterDocument(E02), connection)
    qtbot.addWidget(w)
    asked = []
    monkeypatch.setattr(
        QMessageBox, "question", lambda *a: asked.append(a[2]) or QMessageBox.StandardButton.Yes
    )
    w.autotune.run_button.click()
    assert "setpoint generator is running: the test stops it" in asked[0]
    assert not connection.generator_running and connection.jobs == ["tuning:autotune"]
    assert w.status.text().startswith("The oscilloscope's setpoint generator was stopped")


def test_the_end_of_line_test_shows_its_progress_and_stops(qtbot, window):
    """Issue 25 item 7: the 31 s end-of-line run had no progress bar."""
    window.tabs.setCurrentWidget(window.report)
    window.report.run_button.click()
    bar = window.progress
    assert bar.isVisible() and bar.maximum() == 100
    qtbot.waitUntil(lambda: bar.value() >= 20, timeout=30000)  # the steps and the sweep played
    assert bar.value() <= 99
    window.stop_button.click()
    finish(qtbot, window)
    assert not bar.isVisible()
    assert window.status.text().startswith("Stopped: stopped by the user")
    assert window.report.table.rowCount() == 0  # nothing half-measured is shown


def test_the_position_controller_dialog_opens_the_tuning_window(qtbot):
    doc = ParameterDocument(E02)
    opened = []
    ctx = BlockContext(doc, AccessModel(Access.EXPERT), None, None, opened.append)
    dialog = create_block_dialog("position_controller", ctx, "position")
    qtbot.addWidget(dialog)
    dialog.tuning_button.click()
    assert opened == ["position"]


def test_online_the_autotune_runs_on_the_connected_valve_and_leaves_it_as_it_was(
    qtbot, monkeypatch, tmp_path
):
    from support.gui_support import emulator_connection

    from prm9tool.catalogue import CATALOGUE
    from prm9tool.device import emulated_valves, factory

    connection = emulator_connection()  # unpaced: the link's reports step the valve
    try:
        entry = factory.list_devices([f"{E02}:5101"])[-1]
        with qtbot.waitSignal(connection.online_changed, timeout=10000):
            connection.go_online(entry)
        w = TuningWindow(ParameterDocument(E02), connection)
        qtbot.addWidget(w)
        assert "Online" in w.mode.text()
        monkeypatch.setattr(QMessageBox, "question", lambda *a: QMessageBox.StandardButton.Yes)
        profile = tmp_path / "short.toml"  # real time: a short acceptance check
        profile.write_text("[test]\nstep_amplitudes_pct = [25]\nstatic_period_s = 0.5\n")
        w.report.profile_path.setText(str(profile))
        w.autotune.run_button.click()
        finish(qtbot, w, 120.0)  # real time: the tests, and a parameter exchange between them
        assert "POSKP: 0.4 → " in w.autotune.result.text(), w.status.text()
        valve = emulated_valves.emulated_valve(E02, 5101)
        for mnemonic, raw in {"POSKP": 40, "THRESETP": 819, "SETPOVRON": 0}.items():
            param = CATALOGUE[mnemonic]
            assert valve.read(param.index, param.subindex) == raw
    finally:
        connection.shutdown()
        emulated_valves.forget_emulated_valves()


def test_static_proposes_offsets_with_the_linearization_as_one_undo_step(qtbot):
    from test_characterize_deadband import DEAD_ZONE

    doc = ParameterDocument(E02)
    doc.set_values(DEAD_ZONE, "a dead zone of ±25 % in the linearization")
    w = TuningWindow(doc)
    qtbot.addWidget(w)
    w.undo = DocumentUndo(doc, doc)
    w.tabs.setCurrentWidget(w.static)
    w.static.period.setValue(4.0)
    w.static.run_button.click()
    finish(qtbot, w)
    text = w.static.result.text()
    assert "Dead band behind the gain/offset stage -2" in text and "OFFSETPOS 25." in text, text
    proposal = w.static.proposal
    assert proposal["OFFSETPOS"] == pytest.approx(4096, rel=0.03)
    assert proposal["SETPLINON"] == -1
    labels = [s.label for s in w.static.plot.plots[0].series]
    assert "with the proposed offsets and linearization (preview)" in labels
    preview = w.static.plot.plots[0].series[-1]
    inner = np.abs(preview.x) < 20
    assert np.abs(preview.y[inner] - preview.x[inner]).max() < 3.0  # no dead band left
    shot(w, "static_offsets")
    steps = w.undo.stack.count()
    w.static.apply_button.click()
    assert w.undo.stack.count() == steps + 1
    assert doc.value("OFFSETPOS") == proposal["OFFSETPOS"]
    w.undo.stack.undo()
    assert doc.value("OFFSETPOS") == 0 and doc.value("SETPLINYF") == 0


def test_e04_flow_page_measures_and_applies_the_offsets(qtbot):
    doc = ParameterDocument(E04)
    w = TuningWindow(doc)
    qtbot.addWidget(w)
    w.undo = DocumentUndo(doc, doc)
    assert w.tabs.tabText(3) == "Flow characteristic (E04)"
    w.tabs.setCurrentWidget(w.flow)
    w.flow.run_button.click()
    finish(qtbot, w)
    text = w.flow.result.text()
    assert "Flow gain 4.0" in text or "Flow gain 3.9" in text, text
    shot(w, "flow")
    # the emulated plant has no overlap: nothing worth compensating
    assert all(v < 50 for v in w.flow.proposal.values())
    assert TuningWindow(ParameterDocument(E02)).flow is None


def test_proposed_gains_use_the_decimal_separator_of_the_language(qapp):
    from prm9tool import i18n
    from prm9tool.views.tuning.host import gain_text

    i18n.set_language("cs")
    try:
        shown = gain_text("POSKP", 42), gain_text("POSKD", 42)
    finally:
        i18n.set_language("en")
    assert shown == ("0,42", "0,42 ms")


def test_report_figures_use_the_decimal_separator_of_the_language(qapp):
    """In German the test report showed ``5.75 %`` and ``0.95 … 1.05``."""
    from prm9tool import i18n
    from prm9tool.analysis.profile import Limit
    from prm9tool.characterize.run import Figure
    from prm9tool.views.tuning.report import limit_text, value_text

    gain = Figure("gain", "gain", 1.14, "", Limit(0.95, 1.05))
    rise = Figure("rise", "rise time", 0.0162, "s", Limit(None, 0.03))
    i18n.set_language("de")
    try:
        shown = value_text(gain), limit_text(gain), value_text(rise), limit_text(rise)
    finally:
        i18n.set_language("en")
    assert shown == ("1,14", "0,95 … 1,05", "16,2 ms", "≤ 30 ms")
    assert (value_text(gain), limit_text(gain)) == ("1.14", "0.95 … 1.05")


def test_an_untrustworthy_fit_proposes_no_gains_without_an_explicit_override(
    qtbot, window, monkeypatch, tmp_path
):
    """A fit error above the threshold (docs/tuning.md) disables Accept until the user insists."""
    from dataclasses import replace

    import prm9tool.characterize.acceptance as acceptance
    from prm9tool.characterize.autotune import model_tune

    def badly_fitted(*args, **kwargs):
        result = model_tune(*args, **kwargs)
        return replace(result, model=replace(result.model, fit_error=45.0))

    monkeypatch.setattr(acceptance, "model_tune", badly_fitted)
    use_profile(window, tmp_path, "[test]\nstep_amplitudes_pct = [25, 90]\nstatic_period_s = 4\n")
    page = window.autotune
    page.run_button.click()
    finish(qtbot, window)
    assert "fit error 45 %, at most 20 %" in page.result.text()
    assert "not trustworthy" in page.result.text()
    assert not page.accept_button.isEnabled()
    assert page.override.isVisible()
    shot(window, "autotune_untrusted")
    page.override.setChecked(True)
    assert page.accept_button.isEnabled()
    page.accept_button.click()
    assert window.doc.value("POSKP") == page.proposal["POSKP"]


def test_the_legend_goes_to_the_corner_the_curves_leave_free(qapp):
    """A step response fills the top right (where the legend used to be): the legend moves."""
    from PySide6.QtCore import QRectF

    from prm9tool.views.tuning.plot import legend_box

    area = QRectF(0, 0, 400, 200)
    t = np.linspace(0, 400, 401)
    step = np.where(t < 40, 200.0, 10.0)  # pixels: rises at once, then along the top
    box = legend_box(area, (120, 50), np.column_stack([t, step]))
    assert (box.left(), box.top()) == (280, 150)  # bottom right: nothing drawn there
    assert legend_box(area, (120, 50), np.zeros((0, 2))).topRight() == area.topRight()


def test_steps_both_ways_leave_room_for_the_legend_above_their_curves(qapp):
    """Acceptance steps of ±25 % fill the top and the bottom of the plot, so every corner
    covered a curve (the legend hid the +25 % step on screen): the plot's range now leaves
    room above the data, and the second direction's lines (same colours) add no entries."""
    from PySide6.QtCore import QRectF
    from PySide6.QtGui import QColor, QImage, QPainter

    from prm9tool.views.tuning.plot import COLOURS, Plot, Series, paint_plot

    t = np.linspace(-20, 150, 400)
    series = []
    for k, target in enumerate((25.0, -25.0)):
        response = np.where(t < 5, 0.0, target * (1 - np.exp(-np.clip(t - 5, 0, None) / 4)))
        named = k == 0
        series += [
            Series(t, response * 0.98, "before" if named else "", "#888888", True),
            Series(t, response, "proposed" if named else "", COLOURS[1]),
        ]
    image = QImage(340, 260, QImage.Format.Format_RGB32)
    image.fill(QColor("white"))
    painter = QPainter(image)
    painted = paint_plot(painter, QRectF(0, 0, 340, 260), Plot("±25 %", "ms", "%", series))
    painter.end()
    box = painted.legend
    assert box is not None
    assert box.height() < 3.5 * painter.fontMetrics().height()  # two entries, not four
    for s in series:
        xy = painted.pixels(s)
        inside = (
            (xy[:, 0] >= box.left())
            & (xy[:, 0] <= box.right())
            & (xy[:, 1] >= box.top())
            & (xy[:, 1] <= box.bottom())
        )
        assert not inside.any(), f"the legend hides {inside.sum()} points of a curve"
    assert painted.y_range[1] > 25 * 1.2  # the room is above the data


def test_a_marker_label_is_drawn_whole_inside_the_plot(qtbot):
    """Issue 25 item 9: the "−3 dB" label of the Bode plot lost its top to the plot's clip."""
    import numpy as np
    from PySide6.QtGui import QFont, QFontMetrics

    from prm9tool.views.tuning.plot import Plot, Series, plot_image

    def image(label):
        x = np.geomspace(1, 100, 50)
        series = [Series(x, -x / 10, "magnitude")]
        return plot_image(Plot("t", "f", "dB", series, logx=True, vlines=[(20.0, label)]))

    with_label, without = image("−3 dB: 27.0 Hz"), image("")
    a = np.frombuffer(with_label.constBits(), np.uint32).reshape(with_label.height(), -1)
    b = np.frombuffer(without.constBits(), np.uint32).reshape(without.height(), -1)
    rows = np.nonzero((a != b).any(axis=1))[0]
    font = QFont()
    font.setPixelSize(20)  # plot_image's font at 1200 × 560
    digits = QFontMetrics(font).tightBoundingRect("3").height()
    assert rows.max() - rows.min() + 1 >= digits  # the whole height of the text


def test_an_open_tuning_window_follows_the_program_language(qtbot, window):
    """The main window keeps its Tuning window: after View → Language → Deutsch it showed
    "Tuning and characterization", "Loop:" and "Run autotune" in English for good."""
    from prm9tool import i18n

    window.status.setText("Stopped: a result the user still reads")
    i18n.set_language("de")
    try:
        shown = (window.windowTitle(), window._loop_label.text(), window.tabs.tabText(0),
                 window.autotune.run_button.text(), window.status.text())  # fmt: skip
    finally:
        i18n.set_language("en")
    assert shown[:4] == ("Einstellung und Charakterisierung", "Regelkreis:", "Autotune",
                         "Autotune starten")  # fmt: skip
    assert shown[4] == "Stopped: a result the user still reads"  # not replaced by "Bereit."
    assert window.windowTitle() == "Tuning and characterization"


def test_at_basic_level_accepting_gains_is_refused_as_in_the_controller_dialogs(qtbot):
    """The Tuning window (open at Basic level from the oscilloscope) accepted an autotune's
    POSKP…POST1 into the document, and online into the valve, at Basic level, where the
    diagram and the list lock the controllers."""
    doc, access = ParameterDocument(E02), AccessModel()
    w = TuningWindow(doc, access=access)
    qtbot.addWidget(w)
    kp = doc.value("POSKP")
    w.accept_values({"POSKP": kp + 10, "POSKI": 500}, "Autotune")
    assert doc.value("POSKP") == kp and not doc.modified
    assert w.status.text() == (
        "Not accepted: POSKP can only be changed at Expert access level. (View → Access level)"
    )
    access.set_level(Access.EXPERT)
    w.accept_values({"POSKP": kp + 10}, "Autotune")
    assert doc.value("POSKP") == kp + 10 and w.status.text() == "Accepted: Autotune"


def test_a_figure_and_its_unit_stay_on_one_line_in_the_status(qtbot, window):
    """Issue 34 (a new user): "about 53 s in all" wrapped between "53" and "s"."""
    window.autotune.run_button.click()
    shown = window.status.text()
    window.runner.stop()
    finish(qtbot, window)
    assert re.search(r"about \d+\u00a0s in all", shown), shown
    assert not re.search(r"\d (s|ms|Hz|%)(\W|$)", shown), shown

"""Valve → History (issue 34 items 4 and 14): records of another valve type under the same
serial are marked, a test report names its failing figures and its PDF, autotune runs,
frequency responses and restarts are recorded, and a double-click opens a record's details,
its PDF or the comparison."""

from __future__ import annotations

import json
import math

import pytest
from PySide6.QtCore import Qt, QUrl
from PySide6.QtGui import QDesktopServices
from PySide6.QtWidgets import QDialog
from support.gui_support import E02, go_online
from support.history_support import E04, Valve, factory_values

from prm9tool.history.recorder import Recorder
from prm9tool.views.history.details import RecordDetailsDialog
from prm9tool.views.history.table import MEANING, OPERATION, OUTCOME, TYPE_KEY
from prm9tool.views.history.window import HistoryWindow

TIMEOUT = 10_000
E02_CA = "PRM9-06.3Z11/30-24E02S02-CA"


@pytest.fixture
def recorder(tmp_path):
    return Recorder(f"sqlite:///{tmp_path / 'h.sqlite3'}", tmp_path / "queue.jsonl")


def _window(qtbot, recorder, serial, type_key=None) -> HistoryWindow:
    window = HistoryWindow(recorder, serial, lambda *_a: None, lambda *_a: True, None, type_key)
    qtbot.addWidget(window)
    qtbot.waitUntil(lambda: "record" in window.state.text(), timeout=TIMEOUT)
    return window


def _select(window: HistoryWindow, *rows: int) -> None:
    selection = window.table.selectionModel()
    selection.clearSelection()
    for row in rows:
        selection.select(
            window.model.index(row, 0),
            selection.SelectionFlag.Select | selection.SelectionFlag.Rows,
        )


def test_the_operation_and_outcome_are_in_the_program_language(qtbot, recorder):
    """The German History read "characterization", "passed", "no-drift" and
    "verification-failed (verify)"; English shows the recorded words, as --history does."""
    from prm9tool import i18n

    valve = Valve(1001, E02_CA)
    recorder.record(valve, "characterization", "passed", None)
    recorder.record(valve, "signature", "no-drift", None)
    recorder.record(valve, "upload", "verification-failed", None, failed_step="verify")
    recorder.record(valve, "upload", "a-new-outcome", None)
    model = _window(qtbot, recorder, 1001).model
    english = [model.data(model.index(row, OUTCOME)) for row in range(4)]
    assert english == ["passed", "no-drift", "verification-failed (verify)", "a-new-outcome"]
    i18n.set_language("de")
    try:
        german = [model.data(model.index(row, OUTCOME)) for row in range(4)]
        operations = [model.data(model.index(row, OPERATION)) for row in range(3)]
    finally:
        i18n.set_language("en")
    assert operations == ["Endprüfung", "Vergleich mit Geburtsurkunde", "Hochladen"]
    assert model.data(model.index(0, OPERATION)) == "characterization"
    assert german == [
        "bestanden",
        "keine Drift",
        "Prüfung fehlgeschlagen (Prüfen)",
        "a-new-outcome",
    ]


def test_an_open_window_follows_a_language_switch_in_every_column_and_title(qtbot, recorder):
    """The model builds its words once per language: a switch with the window open rebuilds
    them (the Operation column, What was done and the titles), the selection stays."""
    from prm9tool import i18n

    recorder.record(Valve(1001, E02_CA), "download", "ok", None, {"purpose": "compare"})
    window = _window(qtbot, recorder, 1001)
    window.show()
    _select(window, 0)
    model = window.model

    def shown() -> tuple[object, object, object]:
        return (
            model.data(model.index(0, OPERATION)),
            model.data(model.index(0, MEANING)),
            model.headerData(OPERATION, Qt.Orientation.Horizontal, Qt.ItemDataRole.DisplayRole),
        )

    assert shown() == ("download", "Read from the valve: going online", "Operation")
    try:
        with qtbot.waitSignals([model.headerDataChanged, model.dataChanged], timeout=TIMEOUT):
            i18n.set_language("de")
        german = shown()
        own = (window.windowTitle(), window.buttons["compare"].text(), window.state.text())
        i18n.set_language("cs")
        czech = shown()
    finally:
        i18n.set_language("en")
    assert german == ("Herunterladen", "Aus dem Ventil gelesen: beim Online-Gehen", "Vorgang")
    # the window's own words too: title, buttons and the state line
    assert own[:2] == ("Verlauf", "Die zwei gewählten Einträge vergleichen")
    assert own[2].startswith("1 Eintrag in ")
    assert window.windowTitle() == "History"
    assert czech == (
        "stažení z ventilu",
        "Načteno z ventilu: při přechodu do režimu online",
        "Operace",
    )
    assert shown() == ("download", "Read from the valve: going online", "Operation")
    assert window.selected() == model.records  # the switch did not reset the model


def test_records_of_another_valve_type_under_the_same_serial_are_marked(qtbot, recorder):
    """Item 4: every emulated type started at serial 1001, so History for 1001 held the E02
    of one run and the E04 of the next in one chain, without a warning."""
    recorder.record(Valve(1001, E02_CA), "download", "ok", factory_values(E02_CA))
    recorder.record(Valve(1001, E02_CA), "upload", "ok", factory_values(E02_CA))
    recorder.record(Valve(1001, E04), "download", "ok", factory_values(E04))
    window = _window(qtbot, recorder, 1001, E04)  # online with the E04
    model = window.model
    cells = [model.data(model.index(row, TYPE_KEY)) for row in range(3)]
    assert cells == [f"⚠ {E02_CA}", f"⚠ {E02_CA}", E04]
    assert "records of another valve type than " + E04 in window.state.text()
    assert model.data(model.index(0, 2), 3) == model.other_type_text()  # the tooltip says why
    offline = _window(qtbot, recorder, 1001)  # offline: the newest record's type
    assert offline.model.other_type == {0, 1}
    one_type = _window(qtbot, recorder, 1001, E02_CA)
    assert one_type.model.other_type == {2}


def _report_details(pdf: str | None = None) -> dict:
    figures = [
        {"name": "step_90_overshoot_pct", "value": 5.46, "above": False, "unit": "%",
         "passed": True},
        {"name": "step_90_rise_s", "value": math.nan, "above": False, "unit": "s",
         "passed": False},
        {"name": "bode_bandwidth_hz", "value": 11.9, "above": False, "unit": "Hz", "passed": False},
    ]  # fmt: skip
    details = {"profile": "default", "started": "2026-12-01T20:00:00", "figures": figures}
    return details | ({"pdf": pdf, "loop": "process"} if pdf else {})


def test_a_test_report_names_its_failing_figures_and_its_pdf(qtbot, recorder, tmp_path):
    """Item 14: a test report entry said only "Test report / failed"."""
    pdf = tmp_path / "4711-report.pdf"
    pdf.write_bytes(b"%PDF-1.4\n")
    valve = Valve(4711)
    recorder.record(valve, "characterization", "failed", factory_values(), _report_details())
    recorder.record(valve, "report-saved", "failed", None, _report_details(str(pdf)))
    window = _window(qtbot, recorder, 4711, E04)
    run, saved = (window.model.meaning(r) for r in window.model.records)
    failed = "failed: step 90 %: rise time (10–90 %) not reached; −3 dB frequency 11.9 Hz"
    assert run == f"Test report: profile default, {failed}"
    assert saved == f"Test report saved: process loop, profile default, {failed}, PDF {pdf}"
    opened: list[QUrl] = []
    qtbot_open = lambda url: opened.append(url) or True  # noqa: E731
    import unittest.mock as mock

    with mock.patch.object(QDesktopServices, "openUrl", staticmethod(qtbot_open)):
        dialog = window.open_record(window.model.index(1, 0))  # double-click
        assert isinstance(dialog, RecordDetailsDialog)
        qtbot.addWidget(dialog)
        assert dialog.isVisible() and dialog.pdf_button.isVisible()
        assert dialog.failing == failed.removeprefix("failed: ").split("; ")
        assert dialog.open_pdf() and opened == [QUrl.fromLocalFile(str(pdf))]
    pdf.unlink()  # moved away since: said so, nothing opened
    assert not dialog.open_pdf() and "The PDF cannot be opened" in dialog.status.text()


def test_a_double_click_opens_the_details_and_from_there_the_comparison(qtbot, recorder):
    valve = Valve(4712)
    recorder.record(valve, "download", "ok", factory_values())
    recorder.record(valve, "upload", "ok", factory_values() | {"LIMTA": 1500})
    window = _window(qtbot, recorder, 4712, E04)
    window.table.doubleClicked.emit(window.model.index(1, 3))
    (dialog,) = [d for d in window.findChildren(RecordDetailsDialog) if d.isVisible()]
    assert dialog.labels["Type key"].text() == E04
    assert not dialog.pdf_button.isVisible()  # a download names no PDF (it offered one)
    assert json.loads(dialog.text.toPlainText()) == json.loads(window.model.records[1]["details"])
    dialog.compare_button.click()  # with the record before
    compare = [d for d in window.findChildren(QDialog) if type(d).__name__ == "CompareDialog"]
    assert [r.mnemonic for r in compare[-1].comparison.changed] == ["LIMTA"]
    first = window.open_record(window.model.index(0, 0))
    qtbot.addWidget(first)
    assert not first.compare_button.isEnabled()  # nothing before the first record
    _select(window, 0, 1)
    both = window.open_record(window.model.index(1, 0))  # two selected: their comparison
    assert type(both).__name__ == "CompareDialog"


def test_restarts_and_frequency_responses_on_the_valve_are_recorded(qtbot, window, monkeypatch):
    """Item 14: autotune runs, frequency responses and restarts were not recorded."""
    from PySide6.QtWidgets import QMessageBox

    from prm9tool.views.online_dialogs import RestartDialog
    from prm9tool.views.tuning.window import TuningWindow

    window.connection.set_recorder(Recorder())
    go_online(qtbot, window, f"{E02}:4740")
    qtbot.waitUntil(lambda: window.sync.active, timeout=TIMEOUT)
    monkeypatch.setattr(RestartDialog, "exec", lambda self: QDialog.DialogCode.Accepted)
    with qtbot.waitSignal(window.connection.operation_finished, timeout=TIMEOUT,
                          check_params_cb=lambda name, _r: name == "after_restart"):  # fmt: skip
        window.commands["restart"].trigger()
    qtbot.waitUntil(lambda: window.sync.active, timeout=TIMEOUT)
    tuning = TuningWindow(window.doc, window.connection)
    qtbot.addWidget(tuning)
    monkeypatch.setattr(QMessageBox, "question", lambda *a: QMessageBox.StandardButton.Yes)
    tuning.bode.duration.setValue(1.0)
    tuning.bode.f_min.setValue(5.0)
    tuning.bode.f_max.setValue(50.0)
    tuning.bode.run_button.click()
    qtbot.waitUntil(lambda: not tuning.runner.busy, timeout=60_000)
    assert "−3 dB: " in tuning.bode.result.text(), tuning.status.text()
    store = window.connection.history.recorder.store()
    qtbot.waitUntil(  # recorded by the connection's worker, after the result is shown
        lambda: "frequency-response" in [r["operation"] for r in store.records(4740)],
        timeout=TIMEOUT,
    )
    history = window.compare.show_history()
    qtbot.addWidget(history)
    qtbot.waitUntil(lambda: history.model.rowCount() > 0, timeout=TIMEOUT)
    operations = [r["operation"] for r in history.model.records]
    assert "restart" in operations
    run = history.model.records[operations.index("frequency-response")]
    assert history.model.meaning(run).startswith("Frequency response measured: −3 dB: ")
    restart = history.model.records[operations.index("restart")]
    assert history.model.meaning(restart) == "Restarted (Valve → Restart valve)"


@pytest.mark.parametrize(
    "details",
    [
        {"figures": 3},
        {"figures": [1, "x", {"name": 5, "value": "high", "passed": False}]},
        {"figures": [{"name": "step", "value": True, "passed": False}]},
        {"bandwidth_hz": "fast", "phase_90_hz": [1], "proposed": {"POSKP": 5}, "loop": 1},
    ],
)
def test_a_record_with_odd_details_is_shown_not_a_crash(qapp, details):
    """An exception in a Qt model's data() ends the program: a record written by another
    version (or by hand) must still be shown."""
    from prm9tool.views.history.table import HistoryTableModel

    model = HistoryTableModel()
    for operation in ("characterization", "report-saved", "autotune", "frequency-response"):
        text = model.meaning({"operation": operation, "details": json.dumps(details)})
        assert isinstance(text, str) and text


def test_every_operation_the_history_records_has_a_label(qtbot, recorder):
    """A ``twin`` record (issue 31) reads as words in the window, as every other operation."""
    from prm9tool.history.recorder import OPERATIONS

    labels = _window(qtbot, recorder, 1).model._operations()
    assert [op for op in OPERATIONS if op not in labels] == []
    assert labels["twin"] == "Twin fitted (--fit-twin)"


@pytest.mark.parametrize("lang", ["de", "cs"])
def test_every_column_title_is_whole_in_german_and_czech(qtbot, recorder, lang):
    """German at a real screen: the last title read "tzer, Station, Verbin" (the stretched last
    column got only the room left); each column is now as wide as its title and cells."""
    from prm9tool import i18n

    values = factory_values(E02_CA)
    recorder.record(Valve(1001, E02_CA), "download", "ok", values, {"purpose": "compare"})
    i18n.set_language(lang)
    try:
        window = HistoryWindow(recorder, 1001, lambda *_a: None, lambda *_a: True, None, None)
        qtbot.addWidget(window)
        window.show()
        qtbot.waitUntil(lambda: window.model.rowCount() == 1, timeout=TIMEOUT)
        qtbot.wait(10)  # the header follows in the event loop
        header = window.table.horizontalHeader()
        metrics = header.fontMetrics()
        for column in range(window.model.columnCount()):
            title = str(window.model.headerData(column, header.orientation()))
            assert header.sectionSize(column) >= metrics.horizontalAdvance(title), title
    finally:
        i18n.set_language("en")


def test_a_serial_that_is_no_number_clears_the_last_valve_s_records(qtbot, recorder):
    """Enter on "abc" after valve 1001's records showed them on under "Type a valve's serial
    number." as if they were abc's (seen under Xvfb)."""
    recorder.record(Valve(1001, E02_CA), "download", "ok", None, {"purpose": "compare"})
    window = _window(qtbot, recorder, 1001)
    assert window.model.rowCount() == 1
    window.serial.setText("abc")
    qtbot.keyClick(window.serial, Qt.Key.Key_Return)
    assert window.state.text() == "Type a valve's serial number."
    assert window.model.rowCount() == 0
    assert not window.buttons["export"].isEnabled()

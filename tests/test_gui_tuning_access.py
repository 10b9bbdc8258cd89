"""Issue 34 item 10 (and the autotune's targets of item 2): accepting tuned gains at Basic
level threw the test away — after switching to Expert, Accept stayed disabled and "Accept
anyway" was gone, so the 60–100 s test had to run again. The access level is now checked before
a test whose result would be locked (asked), a valve holding a fault is refused before it
starts, and a finished result stays acceptable across the access-level change."""

from __future__ import annotations

from types import SimpleNamespace

import pytest
from PySide6.QtWidgets import QMessageBox

from prm9tool.model.access import Access, AccessModel
from prm9tool.model.document import ParameterDocument
from prm9tool.views import prompts
from prm9tool.views.tuning.window import TuningWindow

E02 = "PRM9-06.3Z11/30-24E02S02"
E04 = "PRM9-06.3Z11/30-24E04S02"


@pytest.fixture
def basic(qtbot):
    access = AccessModel(Access.BASIC)
    w = TuningWindow(ParameterDocument(E04), access=access)
    qtbot.addWidget(w)
    w.access_model = access
    w.loop.setCurrentIndex(w.loop.findData("process"))
    yield w
    w.close()


def test_the_autotune_at_basic_asks_first_and_does_not_start_when_declined(basic, monkeypatch):
    asked: list[str] = []
    monkeypatch.setattr(prompts, "ask", lambda *a, **k: asked.append(a[3]) or prompts.Button.No)
    basic.autotune.run_button.click()
    assert not basic.runner.busy  # nothing ran: no minute wasted
    assert len(asked) == 1 and "PRCKP can only be changed at Expert access level" in asked[0]
    assert "its result is kept" in asked[0]
    asked.clear()
    basic.access_model.set_level(Access.EXPERT)
    monkeypatch.setattr(basic.runner, "run", lambda *a: None)  # (the test itself: elsewhere)
    basic.autotune.run_button.click()
    assert asked == []  # at Expert nothing to ask


def test_a_proposal_refused_at_basic_is_accepted_after_switching_to_expert(basic):
    page = basic.autotune
    page.proposal = {"PRCKP": 321}
    page.accept_button.setEnabled(True)  # as a finished autotune leaves it
    page.accept_button.click()
    assert "Not accepted: PRCKP can only be changed at Expert" in basic.status.text()
    assert page.accept_button.isEnabled()  # was disabled: the test had to run again
    assert basic.doc.value("PRCKP") != 321
    basic.access_model.set_level(Access.EXPERT)
    page.accept_button.click()
    assert basic.doc.value("PRCKP") == 321
    assert not page.accept_button.isEnabled()


def test_a_valve_holding_a_fault_is_refused_before_the_test_starts(basic, monkeypatch):
    started: list[str] = []
    runner = SimpleNamespace(busy=False, run=lambda *a: started.append("run"))  # on a valve
    monkeypatch.setattr(basic, "runner", runner)
    monkeypatch.setattr(QMessageBox, "question", lambda *a: QMessageBox.StandardButton.Yes)
    basic._status = SimpleNamespace(
        device_state="FAULT_HOLD", nmt_state="operational", active_errors=(0x8611,),
        booting=False, error_code=0x8611, error_text="following error",
    )  # fmt: skip
    basic.access_model.set_level(Access.EXPERT)
    basic.report.run_button.click()
    assert started == []
    assert basic.status.text().startswith("Not started: the valve does not follow its setpoint")
    assert "FAULT_HOLD" in basic.status.text()


def test_the_settling_target_follows_the_loop(basic):
    page = basic.autotune
    assert page.settling.value() == 500.0 and page.amplitude.value() == 20.0  # was 40 ms
    basic.loop.setCurrentIndex(basic.loop.findData("position"))
    assert page.settling.value() == 40.0 and page.amplitude.value() == 50.0
    page.settling.setValue(60.0)  # the user's choice stays
    basic.loop.setCurrentIndex(basic.loop.findData("process"))
    assert page.settling.value() == 60.0 and page.amplitude.value() == 20.0


# --- issue 34 item 11: the Tuning window's state -------------------------------------------------
def test_the_status_line_follows_the_language_and_a_recovered_valve(basic):
    from PySide6.QtCore import QEvent

    from prm9tool import i18n

    try:
        i18n.set_language("de")
        basic.changeEvent(QEvent(QEvent.Type.LanguageChange))
        basic.stop()  # a line other than "Ready." (as "Fertig." after a test)
        german = basic.status.text()
        assert german == basic.tr("Stopping…") != "Stopping…"
        i18n.set_language("cs")
        basic.changeEvent(QEvent(QEvent.Type.LanguageChange))
        assert basic.status.text() != german  # stayed German in the Czech UI
        assert basic.status.text() == basic.tr("Stopping…")
    finally:
        i18n.set_language("en")
    fault = SimpleNamespace(
        device_state="FAULT_HOLD", nmt_state="operational", active_errors=(0x8611,),
        booting=False, error_code=0x8611, error_text="following error", warning=False,
    )  # fmt: skip
    well = SimpleNamespace(
        device_state="DEVICE_MODE_ACTIVE", nmt_state="operational", active_errors=(),
        booting=False, error_code=0, error_text="", warning=False,
    )  # fmt: skip
    basic._on_status_changed(fault)
    basic._on_failed("report", "the valve reported error 0x8611 (FAULT_HOLD)")
    assert "FAULT_HOLD" in basic.status.text()
    basic._on_status_changed(well)  # restarted, or the fault reset
    assert basic.status.text() == "Ready."  # not the stale "FAULT_HOLD"


def test_an_e04_in_control_mode_4_opens_on_the_process_loop(qtbot):
    w = TuningWindow(ParameterDocument(E04))
    qtbot.addWidget(w)
    assert w.current_loop() == "process"
    assert w.autotune.settling.value() == 500.0


def test_reopened_from_the_scope_the_window_keeps_its_loop_and_takes_ctrl_i(qtbot, tmp_path):
    from support.gui_support import main_window

    with main_window(qtbot, tmp_path, E04) as window:
        window.show_tuning_window("process")
        tuning = window.tuning_window
        tuning.autotune.amplitude.setValue(30.0)
        tuning.close()
        window._build_view("scope").tuning_requested.emit()  # "Tuning and characterization…"
        assert window.tuning_window is tuning
        assert tuning.current_loop() == "process"  # was reset to Position, the rest kept
        assert tuning.autotune.amplitude.value() == 30.0
        status = window.commands["valve_status"]
        assert status in tuning.actions()  # Ctrl+I while the Tuning window has focus
        assert status.shortcut().toString() == "Ctrl+I"


def test_a_test_on_the_valve_puts_the_status_it_reads_on_the_main_status_bar(qtbot, monkeypatch):
    """While a test holds the link the connection polls no status: the status bar went on
    saying "waiting for a CANopen master" on a valve enabled just before the test."""
    from support.gui_support import emulator_connection

    from prm9tool.characterize.procedures import bode_test
    from prm9tool.device import emulated_valves, factory

    connection = emulator_connection()
    try:
        entry = factory.list_devices([f"{E02}:5102"])[-1]
        with qtbot.waitSignal(connection.online_changed, timeout=10000):
            connection.go_online(entry)
        w = TuningWindow(ParameterDocument(E02), connection)
        qtbot.addWidget(w)
        monkeypatch.setattr(QMessageBox, "question", lambda *a: QMessageBox.StandardButton.Yes)
        during: list[str] = []
        connection.status_changed.connect(
            lambda s: during.append(str(s.device_state)) if w.runner.busy else None
        )
        w.start("bode", "a sweep", lambda rig: bode_test(rig, 5.0, 0.0, 5.0, 50.0, 0.2))
        qtbot.waitUntil(lambda: not w.runner.busy, timeout=60000)
        assert "Stopped" not in w.status.text(), w.status.text()
        assert "DEVICE_MODE_ACTIVE" in during  # read by the test, shown while it runs
    finally:
        connection.shutdown()
        emulated_valves.forget_emulated_valves()

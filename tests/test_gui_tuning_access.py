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

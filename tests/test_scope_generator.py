"""Setpoint generator safety: confirmation, override on/off, stop on Stop, close and link loss."""

from __future__ import annotations

import pytest
from support.scope_fakes import FakeConnection

from prm9tool.model.document import ParameterDocument
from prm9tool.scope import GeneratorSettings, Waveform
from prm9tool.views import prompts
from prm9tool.views.scope.widget import ScopeWidget

YES, NO = prompts.Button.Yes, prompts.Button.No


@pytest.fixture
def conn():
    return FakeConnection()


@pytest.fixture
def scope(qtbot, conn):
    widget = ScopeWidget(conn, ParameterDocument("PRM9-06.3Z11/30-24E02S02"))
    qtbot.addWidget(widget)
    return widget


@pytest.fixture
def answer(monkeypatch):
    """What the user answers in the confirmation box (records that it was asked)."""
    asked: list[str] = []
    reply = {"button": YES}

    def ask(_parent, _icon, _title, text, *_args):
        asked.append(text)
        return reply["button"]

    monkeypatch.setattr(prompts, "ask", ask)
    reply["asked"] = asked
    return reply


def _start(scope: ScopeWidget, waveform=Waveform.SQUARE, amplitude=30.0, offset=10.0):
    panel = scope.generator_panel
    panel.waveform.setCurrentIndex(panel.waveform.findData(waveform))
    panel.amplitude.setValue(amplitude)
    panel.offset.setValue(offset)
    panel.period.setValue(0.2)
    panel.button.click()


def test_generator_asks_first_then_switches_the_override_on(scope, conn, answer, qtbot):
    _start(scope)
    assert answer["asked"] and "valve will move" in answer["asked"][0]
    assert conn.writes[:2] == [("SETPOVR", 1638), ("SETPOVRON", 1)]  # 10 % of ±16384
    assert scope.generator.running and scope.generator_panel.button.isChecked()
    assert conn.generators == [GeneratorSettings(Waveform.SQUARE, 30.0, 10.0, 0.2)]
    # the waveform runs off the GUI thread: tests/test_setpoint_driver.py


def test_declining_the_confirmation_writes_nothing(scope, conn, answer):
    answer["button"] = NO
    _start(scope)
    assert conn.writes == []
    assert not scope.generator.running
    assert not scope.generator_panel.button.isChecked()


def test_stop_button_switches_the_override_off(scope, conn, answer):
    _start(scope)
    scope.generator_panel.button.click()
    assert conn.writes[-1] == ("SETPOVRON", 0)
    assert not scope.generator.running
    assert scope.generator_panel.button.text() == "Start generator"


def test_scope_stop_and_close_stop_the_generator(scope, conn, answer):
    _start(scope)
    scope.stop()
    assert conn.writes[-1] == ("SETPOVRON", 0) and not scope.generator.running
    _start(scope)
    scope.close()
    assert conn.writes[-1] == ("SETPOVRON", 0) and not scope.generator.running


def test_link_loss_stops_the_generator_without_writing(scope, conn, answer, qtbot):
    _start(scope)
    count = len(conn.writes)
    conn.drop_link()  # FakeConnection.write raises if anything is written offline
    assert not scope.generator.running
    assert not scope.generator_panel.isEnabled()
    assert "generator has stopped" in scope.status.text()
    qtbot.wait(100)
    assert len(conn.writes) == count


def test_going_offline_stops_the_generator(scope, conn, answer):
    _start(scope)
    conn.is_online = False
    conn.online_changed.emit(False)
    assert not scope.generator.running


def test_a_waveform_outside_the_setpoint_range_is_refused_with_its_reason(
    scope, conn, answer, monkeypatch
):
    shown: list[str] = []
    monkeypatch.setattr(prompts, "inform", lambda _p, _i, _t, text, *_a: shown.append(text))
    _start(scope, Waveform.SINE, amplitude=60.0, offset=50.0)
    assert shown == [
        "The waveform reaches -10 … 110 %; the setpoint must stay within -100 … 100 %."
    ]
    assert conn.writes == [] and answer["asked"] == []


def test_a_refused_setpoint_write_stops_the_generator_with_the_reason(scope, conn, answer, qtbot):
    conn.refuse.add("SETPOVR")
    _start(scope)
    qtbot.waitUntil(lambda: not scope.generator.running, timeout=2000)
    assert conn.writes[-1] == ("SETPOVRON", 0)
    assert not scope.generator_panel.button.isChecked()
    assert "refused a value of the setpoint generator" in scope.status.text()
    assert "access denied" in scope.status.text()


def test_a_refused_switch_off_is_repeated_at_the_next_connection(scope, conn, answer, qtbot):
    _start(scope)
    conn.refuse.add("SETPOVRON")
    scope.generator_panel.button.click()
    qtbot.wait(20)  # the refusal arrives from the worker
    conn.refuse.clear()
    conn.drop_link()
    conn.go_online()
    assert conn.writes[-1] == ("SETPOVRON", 0)


def test_after_a_lost_link_the_next_connection_switches_the_override_off(scope, conn, answer):
    _start(scope)
    conn.drop_link()
    conn.go_online()
    assert conn.writes[-1] == ("SETPOVRON", 0)
    assert not scope.generator.running
    count = len(conn.writes)
    conn.drop_link()
    conn.go_online()
    assert len(conn.writes) == count  # switched off already: nothing more to write


def test_generator_messages_follow_the_language(scope, conn, answer, monkeypatch):
    from prm9tool import i18n

    shown: list[str] = []
    monkeypatch.setattr(prompts, "inform", lambda _p, _i, _t, text, *_a: shown.append(text))
    i18n.set_language("de")
    try:
        _start(scope, Waveform.SINE, amplitude=60.0, offset=50.0)
        conn.is_online = False
        with pytest.raises(RuntimeError, match="verbundenes Ventil"):
            scope.generator.start(GeneratorSettings())
    finally:
        i18n.set_language("en")
    assert shown == [
        "Die Kurvenform erreicht -10 … 110 %; der Sollwert muss zwischen -100 … 100 % bleiben."
    ]


def test_the_measured_demand_becomes_the_reference_of_the_step_figures(scope, conn, answer):
    scope.preselect("position_actual")
    _start(scope)
    assert scope.channels.selected() == ["demand", "position_actual"]
    assert scope.step_panel.reference_slot() == 0 and scope.step_panel.response_slot() == 1
    scope.stop()
    scope.channels.set_selected(["position_actual", "current_a", "demand"])
    _start(scope)
    assert scope.step_panel.reference_slot() == 2  # already recorded: it is the reference


def test_a_long_operation_stops_the_generator_before_it_runs_and_says_so(scope, conn, answer):
    _start(scope)
    conn.is_busy = True
    conn.busy_changed.emit(True)  # e.g. a tuning test: emitted before its job is queued
    assert conn.writes[-1] == ("SETPOVRON", 0)
    assert not scope.generator.running
    assert scope.generator_panel.button.text() == "Start generator"
    assert "another operation" in scope.status.text()


def test_the_generator_does_not_start_while_the_valve_is_busy(scope, conn, answer):
    conn.is_busy = True
    _start(scope)
    assert conn.writes == [] and conn.generators == []
    assert not scope.generator.running and not scope.generator_panel.button.isChecked()
    assert "busy" in scope.status.text()

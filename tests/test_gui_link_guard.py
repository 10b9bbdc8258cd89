"""A node-ID or bit-rate change online over CAN is warned about: where the valve answers after
its next restart, or that the rotary switches decide."""

from __future__ import annotations

import pytest
from support.can_link_rig import make_link_rig
from support.gui_support import record_prompts, settings_in

from prm9tool.device import factory
from prm9tool.model.access import AccessModel
from prm9tool.model.document import ParameterDocument
from prm9tool.model.undo import DocumentUndo
from prm9tool.online.connection import ValveConnection


@pytest.fixture
def window(qtbot, tmp_path, monkeypatch):
    from prm9tool.views.main_window import MainWindow

    monkeypatch.setenv("PRM9TOOL_DATA_DIR", str(tmp_path / "data"))
    rig = make_link_rig("guard", tmp_path)
    connection = ValveConnection(opener=lambda e: factory.open_session(e, can_link=rig.options))
    doc = ParameterDocument(str(rig.valve.type_key))
    win = MainWindow(doc, DocumentUndo(doc), AccessModel(), connection, settings_in(tmp_path))
    qtbot.addWidget(win)
    with qtbot.waitSignal(connection.online_changed, timeout=10_000):
        connection.go_online("can:10")
    qtbot.waitUntil(lambda: not connection.is_busy, timeout=10_000)
    yield win, rig
    connection.shutdown()
    rig.close()


def test_a_node_id_change_says_where_the_valve_answers_after_a_restart(qtbot, window, monkeypatch):
    win, _rig = window
    answers = record_prompts(monkeypatch)
    win.doc._live["SWNODE"] = 0
    win.doc.set_value("NODEID", 20)
    assert answers.informed, "no warning"
    assert "answers at node 20, 500 kbit/s" in answers.informed[-1]
    assert "Communication → CAN bus" in answers.informed[-1]


def test_with_the_node_switch_deciding_the_change_does_not_move_it(qtbot, window, monkeypatch):
    win, _rig = window
    answers = record_prompts(monkeypatch)
    win.doc._live["SWNODE"] = 2
    win.doc.set_value("NODEID", 20)
    assert "the switches decide node ID and bit rate" in answers.informed[-1]
    assert "stays at node 10" in answers.informed[-1]


def test_with_the_node_switch_at_lss_the_change_does_not_move_it(qtbot, window, monkeypatch):
    win, _rig = window
    answers = record_prompts(monkeypatch)
    win.doc._live["SWNODE"] = 1
    win.doc.set_value("NODEID", 20)
    assert answers.informed[-1].endswith(
        "The node-ID switch is at position 1 (LSS): an LSS master sets node ID and bit rate "
        "(manual table 7-17; Communication → CAN bus). NODEID and BITRATE apply at position 0 "
        "only, so this change does not move the valve."
    )


def test_other_changes_are_not_warned_about(qtbot, window, monkeypatch):
    win, _rig = window
    answers = record_prompts(monkeypatch)
    win.doc.set_value("LIMTA", 1500)
    assert answers.informed == []

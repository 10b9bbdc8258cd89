"""At Basic access level, sending a document whose Expert-level values differ from the valve's
asks first (issue 15, item 19)."""

from __future__ import annotations

from gui_support import E02, go_online, valve_value
from PySide6.QtWidgets import QDialog

from prm9tool.catalogue import Access
from prm9tool.views import prompts
from prm9tool.views.online_dialogs import DiffChoice, OnlineDiffDialog

TIMEOUT = 10_000


def _send_the_document(monkeypatch):
    def run(dialog):
        dialog.choice = DiffChoice.SEND_DOCUMENT
        return QDialog.DialogCode.Accepted

    monkeypatch.setattr(OnlineDiffDialog, "exec", run)


def _document_with_expert_changes(window):
    window.doc.set_value("POSKP", 90)  # as a file opened at Basic level may hold
    window.doc.set_value("MONDELAY", 500)
    window.doc.set_value("DTAMP", 1000)  # a Basic-level value


def test_a_basic_user_sending_expert_values_is_asked_and_no_keeps_the_valve(
    qtbot, window, answers, monkeypatch
):
    assert window.access.level is Access.BASIC
    _document_with_expert_changes(window)
    _send_the_document(monkeypatch)
    answers.answers = [prompts.Button.No]
    go_online(qtbot, window, f"{E02}:4301")
    qtbot.waitUntil(lambda: not window.connection.is_online, timeout=TIMEOUT)
    assert answers.asked[-1] == (
        "Expert values at Basic level: The document changes 2 Expert-level values of the "
        "valve (POSKP, MONDELAY), which the Basic access level cannot edit (controllers, "
        "linearizations, monitoring). Send them anyway?"
    )
    assert window.doc.value("POSKP") == 90 and window.doc.modified  # nothing lost either


def test_a_basic_user_who_confirms_sends_the_expert_values(qtbot, window, answers, monkeypatch):
    _document_with_expert_changes(window)
    _send_the_document(monkeypatch)
    answers.answers = [prompts.Button.Yes]
    go_online(qtbot, window, f"{E02}:4302")
    qtbot.waitUntil(lambda: window.sync.active, timeout=TIMEOUT)
    assert "Expert values at Basic level" in answers.asked[0]
    assert valve_value(qtbot, window, "POSKP") == 90
    assert valve_value(qtbot, window, "DTAMP") == 1000


def test_an_expert_user_is_not_asked(qtbot, window, answers, monkeypatch):
    window.access.set_level(Access.EXPERT)
    _document_with_expert_changes(window)
    _send_the_document(monkeypatch)
    go_online(qtbot, window, f"{E02}:4303")
    qtbot.waitUntil(lambda: window.sync.active, timeout=TIMEOUT)
    assert not any("Expert values" in text for text in answers.asked)
    assert valve_value(qtbot, window, "POSKP") == 90


def test_the_upload_command_at_basic_level_asks_too(qtbot, window, answers):
    go_online(qtbot, window, f"{E02}:4304")
    qtbot.waitUntil(lambda: window.sync.active, timeout=TIMEOUT)
    with window.sync.suspended():  # an expert value the valve does not have
        window.doc.set_value("POSKI", 5000)
    answers.answers = [prompts.Button.No]
    window.commands["upload"].trigger()
    assert "(POSKI)" in answers.asked[-1]
    assert window.valve.progress_dialog is None  # nothing was sent
    assert "Nothing was sent to the valve" in window.status.currentMessage()

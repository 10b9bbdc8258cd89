"""At Basic access level, sending a document whose Expert-level values differ from the valve's
asks first (issue 15, item 19)."""

from __future__ import annotations

from PySide6.QtWidgets import QDialog
from support.gui_support import E02, go_online, valve_value

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


def _file_with(tmp_path, **values):
    from prm9tool.catalogue.typekey import TypeKey
    from prm9tool.files.prmfile import PrmContents, write_file

    contents = PrmContents.factory(TypeKey.parse(E02))
    contents.values.update(values)
    write_file(contents, tmp_path / "other.prm")
    return tmp_path / "other.prm"


def _take_from_the_file(monkeypatch, mnemonics):
    from PySide6.QtCore import Qt

    from prm9tool.views.compare.view import FIRST_VALUE, CompareDialog

    def run(dialog):
        model = dialog.model
        for row, shown in enumerate(model.rows):
            if shown.mnemonic in mnemonics:
                index = model.index(row, FIRST_VALUE + 1)  # the file's value ticked
                model.setData(index, Qt.CheckState.Checked.value, Qt.ItemDataRole.CheckStateRole)
        dialog.apply_buttons[0].click()
        return dialog.result()

    monkeypatch.setattr(CompareDialog, "exec", run)


def test_online_at_basic_level_values_taken_from_a_file_ask_before_expert_ones_go(
    qtbot, window, answers, monkeypatch, tmp_path
):
    """File → Compare with file… online at Basic level took POSKP from the file and sent it to
    the valve at once, without the question an upload asks."""
    go_online(qtbot, window, f"{E02}:4305")
    qtbot.waitUntil(lambda: window.sync.active, timeout=TIMEOUT)
    path = _file_with(tmp_path, POSKP=90, DTAMP=1000)
    _take_from_the_file(monkeypatch, {"POSKP", "DTAMP"})
    answers.answers = [prompts.Button.No]
    window.compare.compare_with_file(path)
    assert "Expert values at Basic level" in answers.asked[-1] and "(POSKP)" in answers.asked[-1]
    assert window.doc.value("POSKP") != 90 and window.doc.value("DTAMP") != 1000
    assert valve_value(qtbot, window, "POSKP") != 90  # nothing went to the valve
    assert "Nothing was sent to the valve" in window.status.currentMessage()
    answers.answers = [prompts.Button.Yes]
    window.compare.compare_with_file(path)
    assert window.doc.value("POSKP") == 90
    qtbot.waitUntil(lambda: valve_value(qtbot, window, "POSKP") == 90, timeout=TIMEOUT)


def test_online_at_basic_level_a_history_record_asks_before_expert_values_go(
    qtbot, window, answers
):
    go_online(qtbot, window, f"{E02}:4306")
    qtbot.waitUntil(lambda: window.sync.active, timeout=TIMEOUT)
    record = {**window.doc.values, "POSKP": 91}
    answers.answers = [prompts.Button.No, prompts.Button.No]
    window.compare.restore_into_document(None, {"POSKP": 91})
    assert window.compare.restore_to_valve(4306, record)  # online: handled (declined)
    assert ["(POSKP)" in text for text in answers.asked[-2:]] == [True, True]
    assert window.doc.value("POSKP") != 91 and valve_value(qtbot, window, "POSKP") != 91
    assert window.valve.progress_dialog is None

"""The main window online with an emulated valve: diff prompt, edits to the valve, upload,
download, restart, factory values, the status window, and a valve that disappears."""

from __future__ import annotations

import json
import threading

import pytest
from PySide6.QtWidgets import QDialog, QLabel, QPushButton
from support.gui_support import (
    E02,
    E02_CA,
    E04_CA,
    emulated,
    go_online,
    main_window,
    session_of,
    valve_value,
)

from prm9tool.device.usb.transport.emulator import LinkFaults
from prm9tool.files import backup
from prm9tool.views import prompts
from prm9tool.views.online_dialogs import DiffChoice, OnlineDiffDialog, RestartDialog

TIMEOUT = 10_000


def _settled(qtbot, window):
    """Wait until the going-online comparison is over and edits go to the valve."""
    qtbot.waitUntil(lambda: window.sync.active, timeout=TIMEOUT)


def _choose(monkeypatch, choice, shown=None):
    def run(dialog):
        if shown is not None:
            shown.append(dialog)
        dialog.choice = choice
        return QDialog.DialogCode.Accepted

    monkeypatch.setattr(OnlineDiffDialog, "exec", run)


def test_a_new_document_simply_takes_the_valve(qtbot, window, monkeypatch):
    shown = []
    _choose(monkeypatch, DiffChoice.CANCEL, shown)
    go_online(qtbot, window, f"{E04_CA}:4101")
    _settled(qtbot, window)
    assert shown == []  # nothing to lose: no prompt
    assert str(window.doc.type_key) == E04_CA and window.doc.source_serial == 4101
    assert not window.doc.modified and not window.undo.stack.canUndo()
    bar = window.status
    assert bar.mode_label.text() == "Mode: ONLINE" and bar.firmware_label.text().startswith("FW: ")
    # a -CA valve as delivered: no error, but it waits for its CANopen master (issue 14)
    waiting = "Status: waiting for a CANopen master"
    emulated(4101).advance(2.0)  # booted (the unpaced valve's clock moves with the link)
    qtbot.waitUntil(lambda: bar.status_label.text() == waiting, timeout=TIMEOUT)
    for name in ("upload", "download", "restart", "offline", "view_scope"):
        assert window.commands[name].isEnabled(), name
    assert not window.commands["online"].isEnabled()
    assert not window.commands["valve_selection"].isEnabled()


def test_differences_prompt_take_the_valve_values(qtbot, window, monkeypatch):
    window.doc.set_value("LIMTA", 1500)
    shown = []
    _choose(monkeypatch, DiffChoice.TAKE_VALVE, shown)
    go_online(qtbot, window)
    _settled(qtbot, window)
    dialog = shown[0]
    rows = [dialog.table.item(r, 0).text() for r in range(dialog.table.rowCount())]
    assert rows == ["LIMTA"]
    assert (
        dialog.table.item(0, 2).text() == "1500 mA" and dialog.table.item(0, 3).text() == "2400 mA"
    )
    assert window.doc.value("LIMTA") == 2400
    window.undo.stack.undo()  # taking the valve's values is one undo step …
    assert window.doc.value("LIMTA") == 1500
    assert valve_value(qtbot, window, "LIMTA") == 1500  # … and online, undo reaches the valve


def test_differences_prompt_send_the_document(qtbot, window, monkeypatch):
    window.doc.set_value("DTAMP", 1000)
    _choose(monkeypatch, DiffChoice.SEND_DOCUMENT)
    go_online(qtbot, window, f"{E02}:4102")
    _settled(qtbot, window)
    assert valve_value(qtbot, window, "DTAMP") == 1000
    assert len(backup.existing_backups(4102)) == 1  # the valve's own values were saved first
    assert "written, verified and stored" in window.status.currentMessage()


def test_differences_prompt_cancel_stays_offline(qtbot, window, monkeypatch):
    window.doc.set_value("DTAMP", 1000)
    _choose(monkeypatch, DiffChoice.CANCEL)
    go_online(qtbot, window)
    qtbot.waitUntil(lambda: not window.connection.is_online, timeout=TIMEOUT)
    assert window.doc.value("DTAMP") == 1000 and window.doc.modified


@pytest.mark.parametrize(
    ("choice", "mode"), [(DiffChoice.CANCEL, "OFFLINE"), (DiffChoice.TAKE_VALVE, "ONLINE")]
)
def test_a_ca_document_and_a_valve_without_canopen_ask_one_question(
    qtbot, tmp_path, answers, monkeypatch, choice, mode
):
    seen = []

    def decide(dialog):  # what the user sees while the question is open
        seen.append((window.status.mode_label.text(), list(answers.informed)))
        dialog.choice = choice
        return QDialog.DialogCode.Accepted

    monkeypatch.setattr(OnlineDiffDialog, "exec", decide)
    with main_window(qtbot, tmp_path, E02_CA) as window:
        window.doc.set_value("LIMTA", 1500)
        window.show_canopen_window()  # it used to read SWBAUD from the valve: "no such parameter"
        go_online(qtbot, window, f"{E02}:4077")
        qtbot.waitUntil(lambda: bool(seen), timeout=TIMEOUT)
        qtbot.waitUntil(lambda: window.status.mode_label.text() == f"Mode: {mode}", timeout=TIMEOUT)
        qtbot.wait(300)  # a late refusal from the valve would arrive by now
    assert seen == [("Mode: CONNECTING", [])]  # not ONLINE while "Cancel stays offline"
    assert answers.informed == [] and len(answers.asked) == 0


def test_diff_dialog_offers_only_taking_values_of_another_variant(window):
    dialog = OnlineDiffDialog({"LIMTA": 2000}, {"LIMTA": 2400, "PRCKP": 1}, E02, E04_CA, window)
    assert not dialog.send_button.isEnabled()
    assert "another valve variant" in dialog.send_button.toolTip()
    assert dialog.intro.text().splitlines() == [
        "2 values in the document differ from the valve.",
        f"Document type key: {E02} — valve type key: {E04_CA}",
        "The valve is of another variant: only its values can be taken.",
        "Cancel stays offline; the document is not changed and nothing is written.",
    ]
    dialog.take_button.click()
    assert dialog.choice is DiffChoice.TAKE_VALVE


def test_table_edits_go_to_the_valve_and_downloads_come_back(qtbot, window):
    go_online(qtbot, window)
    _settled(qtbot, window)
    dialog = window.parameter_view.make_edit_dialog("LIMTB")
    dialog.set_text("1900")
    dialog._buttons.accepted.emit()
    assert window.doc.value("LIMTB") == 1900
    assert valve_value(qtbot, window, "LIMTB") == 1900
    window.connection.write("DYNFREQ", 120)  # the valve changes behind the document's back
    with qtbot.waitSignal(window.connection.operation_finished, timeout=TIMEOUT):
        window.commands["download"].trigger()
    assert window.doc.value("DYNFREQ") == 120
    window.undo.stack.undo()
    assert window.doc.value("DYNFREQ") == 80


def test_live_values_refresh_in_the_table(qtbot, window):
    go_online(qtbot, window)
    model = window.parameter_view.model
    index = model.index(model.row_of("PWR"), 2)
    qtbot.waitUntil(lambda: model.data(index) != "—", timeout=TIMEOUT)
    assert 19 < float(model.data(index)) < 29
    with qtbot.waitSignal(window.connection.online_changed, timeout=TIMEOUT):
        window.valve.go_offline()
    assert model.data(index) == "—"  # offline, a live value would be stale
    go_online(qtbot, window)  # the same valve again: its supply has not changed
    error = model.index(model.row_of("ERROR"), 2)
    assert error.isValid()
    qtbot.waitUntil(lambda: model.data(index) != "—", timeout=TIMEOUT)  # was "—" for good
    qtbot.waitUntil(lambda: model.data(error) == "0x0000", timeout=TIMEOUT)


def test_a_refused_online_edit_is_reported_and_kept(qtbot, window, answers):
    go_online(qtbot, window)
    _settled(qtbot, window)
    window.doc.set_values({"LIMTA": 3000}, "beyond CURNORM", validate=False)
    qtbot.waitUntil(lambda: bool(answers.informed), timeout=TIMEOUT)
    assert "LIMTA" in answers.informed[-1] or "0x" in answers.informed[-1]
    assert window.doc.value("LIMTA") == 3000 and window.connection.is_online


def test_valve_that_disappears_goes_offline_and_keeps_the_edits(qtbot, window, answers):
    go_online(qtbot, window)
    _settled(qtbot, window)
    window.doc.set_value("THRESETP", 1638)
    transport = session_of(window).transport
    transport.faults = LinkFaults(die_after=transport.reports_on_link)
    qtbot.waitUntil(lambda: not window.connection.is_online, timeout=TIMEOUT)
    assert "Connection to the valve lost" in answers.informed[-1]
    assert "kept in the document" in answers.informed[-1]
    assert window.status.mode_label.text() == "Mode: OFFLINE"
    assert window.commands["online"].isEnabled() and not window.commands["upload"].isEnabled()
    window.doc.set_value("DTAMP", 2000)  # offline edits go to the document only
    assert window.doc.value("THRESETP") == 1638 and window.doc.value("DTAMP") == 2000


def test_upload_shows_a_progress_dialog_and_stores(qtbot, window):
    go_online(qtbot, window)
    _settled(qtbot, window)
    window.doc.set_value("DTAMP", 1234)
    with qtbot.waitSignal(window.connection.operation_finished, timeout=TIMEOUT) as done:
        window.commands["upload"].trigger()
        assert window.valve.progress_dialog is not None
    assert done.args[0] == "upload" and done.args[1].stored
    assert window.valve.progress_dialog is None
    assert not window.sync.unstored


def test_a_second_identical_upload_says_so(qtbot, window):
    go_online(qtbot, window)
    _settled(qtbot, window)
    window.doc.set_value("DTAMP", 1234)
    messages = []
    window.valve.message_posted.connect(messages.append)
    for _ in range(2):
        with qtbot.waitSignal(window.connection.operation_finished, timeout=TIMEOUT):
            window.commands["upload"].trigger()
    first, second = [m for m in messages if "verified and stored" in m]
    assert "again" not in first and "already held them" in second
    assert window.status.currentMessage() == second


def test_upload_to_a_valve_of_another_variant_names_both_in_the_program_language(
    qtbot, window, answers
):
    go_online(qtbot, window)
    _settled(qtbot, window)
    with window.sync.suspended():
        window.doc.set_type_key("PRM9-06.2Z51/30-24E04S02-CA")
    window.set_language("cs")
    window.valve.upload()
    assert answers.asked[-1] == (
        "Načtení do ventilu: Dokument je pro ventil E04 cívka A -CA, připojený ventil je "
        "E02 dvě cívky. Zvolte odpovídající typ ventilu nebo nejprve stáhněte parametry z ventilu."
    )
    assert window.valve.progress_dialog is None  # nothing was written


def test_cancelling_the_progress_dialog_cancels_the_operation(qtbot, window, answers):
    go_online(qtbot, window)
    _settled(qtbot, window)
    release = threading.Event()
    values = dict(window.doc.values)

    def slow_upload(session):
        release.wait(5)  # the user presses Cancel meanwhile
        return session.upload(values, None, window.connection._worker.cancel)

    window.valve.progress.start("upload", "Uploading")
    window.connection.run_job("upload", slow_upload)
    window.valve.progress_dialog.findChild(QPushButton).click()  # the user presses Cancel
    release.set()
    qtbot.waitUntil(lambda: bool(answers.informed), timeout=TIMEOUT)
    assert "cancelled" in answers.informed[-1] and "nothing was stored" in answers.informed[-1]
    assert window.valve.progress_dialog is None and window.connection.is_online


def test_restart_needs_the_hydraulics_confirmation(qtbot, window, monkeypatch):
    go_online(qtbot, window)
    _settled(qtbot, window)
    dialog = RestartDialog(window)
    assert not dialog.restart_button.isEnabled()
    dialog.confirm.setChecked(True)
    assert dialog.restart_button.isEnabled()
    monkeypatch.setattr(RestartDialog, "exec", lambda self: QDialog.DialogCode.Rejected)
    window.commands["restart"].trigger()
    assert not window.connection.is_busy
    monkeypatch.setattr(RestartDialog, "exec", lambda self: QDialog.DialogCode.Accepted)
    _choose(monkeypatch, DiffChoice.TAKE_VALVE)
    window.doc.set_value("DTAMP", 1111)  # written but not stored: the restart undoes it
    with qtbot.waitSignal(window.connection.operation_finished, timeout=TIMEOUT) as done:
        window.commands["restart"].trigger()
    assert done.args[0] == "after_restart" and done.args[1]["DTAMP"] != 1111
    qtbot.waitUntil(lambda: window.sync.active, timeout=TIMEOUT)
    assert window.doc.value("DTAMP") == done.args[1]["DTAMP"]  # the valve's values taken


def _online_with_limta_2000(qtbot, window, serial: int) -> None:
    """Online with an emulated E02 valve whose LIMTA the document changed to 2000 mA."""
    go_online(qtbot, window, f"{E02}:{serial}")
    _settled(qtbot, window)
    window.doc.set_value("LIMTA", 2000)
    assert valve_value(qtbot, window, "LIMTA") == 2000


def test_restore_factory_values_online_needs_the_hydraulics_confirmation(
    qtbot, window, answers, monkeypatch
):
    _online_with_limta_2000(qtbot, window, 4105)
    shown = []

    def cancel(dialog):
        shown.append(dialog)
        return QDialog.DialogCode.Rejected

    monkeypatch.setattr(RestartDialog, "exec", cancel)
    window.commands["restore_factory"].trigger()
    assert shown[0].factory and "hydraulic circuit" in shown[0].findChild(QLabel).text()
    assert not shown[0].restart_button.isEnabled()  # not before the hydraulics are confirmed
    assert answers.asked == []  # no plain Yes/No box instead of the confirmation
    assert not window.connection.is_busy and backup.existing_backups(4105) == []
    assert valve_value(qtbot, window, "LIMTA") == 2000


def test_restore_factory_values_online_backs_the_valve_up_first(
    qtbot, window, answers, monkeypatch
):
    from prm9tool.files import prmfile

    _online_with_limta_2000(qtbot, window, 4106)

    def confirm(dialog):
        dialog.confirm.setChecked(True)
        assert dialog.restart_button.isEnabled()
        return QDialog.DialogCode.Accepted

    monkeypatch.setattr(RestartDialog, "exec", confirm)
    with qtbot.waitSignal(window.connection.operation_finished, timeout=TIMEOUT) as done:
        window.commands["restore_factory"].trigger()
    assert done.args[0] == "restore_factory"
    assert window.doc.value("LIMTA") == 2400 and valve_value(qtbot, window, "LIMTA") == 2400
    [saved] = backup.existing_backups(4106)
    assert prmfile.read_file(saved).values["LIMTA"] == 2000  # the values before the reset
    assert str(saved) in window.status.currentMessage()
    window.undo.stack.undo()  # the reset is one undo step in the document
    assert window.doc.value("LIMTA") == 2000


def test_going_offline_offers_to_store_online_changes(qtbot, window, answers):
    go_online(qtbot, window)
    _settled(qtbot, window)
    window.doc.set_value("DTAMP", 999)
    answers.answers = [prompts.Button.Yes]
    with qtbot.waitSignal(window.connection.online_changed, timeout=TIMEOUT):
        window.commands["offline"].trigger()
    assert "not stored" in answers.asked[-1]
    go_online(qtbot, window, f"{E02}:4001")  # same valve: the stored value survived
    qtbot.waitUntil(lambda: window.sync.active, timeout=TIMEOUT)
    assert valve_value(qtbot, window, "DTAMP") == 999


def test_status_window_follows_the_valve(qtbot, window):
    status = window.show_status_window()
    go_online(qtbot, window, f"{E04_CA}:4103")
    qtbot.waitUntil(lambda: status.fields["state"].text() not in ("", "—"), timeout=TIMEOUT)
    assert status.fields["serial"].text() == "4103"
    assert status.fields["type_key"].text() == E04_CA
    assert status.fields["supply"].text().endswith(" V")
    assert any(led.colour != "off" for led in status.leds)
    qtbot.waitUntil(lambda: "\n" in status._led_states[0].text(), timeout=TIMEOUT)
    colour, pattern = status._led_states[0].text().split("\n")  # colour above pattern
    assert colour in ("white", "green") and pattern in ("power-up", "on")

    def shown_whole(label):
        widest = max(label.fontMetrics().horizontalAdvance(t) for t in label.text().split("\n"))
        return widest <= label.contentsRect().width()

    qtbot.waitUntil(
        lambda: all(shown_whole(label) for label in status._led_states), timeout=TIMEOUT
    )
    session_of(window).transport.valve.inject(__import__(
        "prm9tool.device.emulator.states", fromlist=["Fault"]).Fault.COIL_A_OPEN)  # fmt: skip
    qtbot.waitUntil(lambda: "0x5411" in status.errors.item(0).text(), timeout=TIMEOUT)
    assert "Solenoid A" in status.errors.item(0).text()
    qtbot.waitUntil(lambda: "0x5411" in window.status.status_label.text(), timeout=TIMEOUT)


def test_oscilloscope_opens_online_with_the_measuring_point(qtbot, window):
    go_online(qtbot, window)
    _settled(qtbot, window)
    window.open_scope("demand")
    assert window.current_view() == "scope"
    with qtbot.waitSignal(window.connection.online_changed, timeout=TIMEOUT):
        window.valve.go_offline()
    assert window.current_view() == "parameters"


def test_online_action_uses_the_valve_chosen_in_the_hid_configuration(qtbot, window, monkeypatch):
    from prm9tool.views.hid_dialog import HidConfigurationDialog

    def choose(dialog):
        dialog.add_emulator(f"{E04_CA}:4104")
        qtbot.waitUntil(lambda: not dialog.listing, timeout=TIMEOUT)  # listed off this thread
        dialog.accept()
        return QDialog.DialogCode.Accepted

    monkeypatch.setattr(HidConfigurationDialog, "exec", choose)
    assert window.valve.configure_hid() is not None
    with qtbot.waitSignal(window.connection.online_changed, timeout=TIMEOUT):
        window.commands["online"].trigger()
    assert window.connection.device.serial == 4104


def test_hid_configuration_is_off_while_online_and_says_why(qtbot, window, monkeypatch):
    from prm9tool.views.hid_dialog import HidConfigurationDialog

    opened = []
    monkeypatch.setattr(HidConfigurationDialog, "exec", lambda self: opened.append(self) or 0)
    hid = window.commands["hid_configuration"]
    go_online(qtbot, window)
    assert not hid.isEnabled()
    assert "go offline first" in hid.statusTip() and "go offline first" in hid.toolTip()
    hid.trigger()
    assert opened == []
    with qtbot.waitSignal(window.connection.online_changed, timeout=TIMEOUT):
        window.valve.go_offline()
    assert hid.isEnabled() and hid.statusTip() == "Choose the valve to communicate with"
    hid.trigger()
    assert len(opened) == 1


def test_online_action_with_a_single_valve_needs_no_question(qtbot, window):
    with qtbot.waitSignal(window.connection.online_changed, timeout=TIMEOUT):
        window.commands["online"].trigger()  # the default emulated valve is the only one
    assert window.connection.device.serial == 1001


def test_opening_a_file_online_asks_before_anything_is_written(qtbot, window, tmp_path,
                                                                monkeypatch):  # fmt: skip
    from prm9tool.catalogue.typekey import TypeKey
    from prm9tool.files import prmfile

    go_online(qtbot, window)
    _settled(qtbot, window)
    path = tmp_path / "other.prm"
    contents = prmfile.PrmContents.factory(TypeKey.parse(E02))
    contents.values["LIMTA"] = 1700
    prmfile.write_file(contents, path)
    shown = []
    _choose(monkeypatch, DiffChoice.CANCEL, shown)
    assert window.files.open_path(path)
    qtbot.waitUntil(lambda: bool(shown), timeout=TIMEOUT)
    assert [shown[0].table.item(r, 0).text() for r in range(shown[0].table.rowCount())] == ["LIMTA"]
    qtbot.waitUntil(lambda: not window.connection.is_online, timeout=TIMEOUT)
    assert window.doc.value("LIMTA") == 1700  # the file stays open, offline
    go_online(qtbot, window)  # the valve was not written meanwhile
    qtbot.waitUntil(lambda: len(shown) == 2, timeout=TIMEOUT)
    assert shown[1].table.item(0, 3).text() == "2400 mA"


def test_a_broken_usb_stack_still_offers_the_hid_configuration(qtbot, window, monkeypatch):
    from prm9tool.errors import CommunicationError
    from prm9tool.views.hid_dialog import HidConfigurationDialog

    def broken(_emulators):
        raise CommunicationError("hidapi: libhidapi-hidraw.so.0 not found")

    monkeypatch.setattr(window.connection, "_lister", broken)
    shown = []

    def look(dialog):
        qtbot.waitUntil(lambda: not dialog.listing, timeout=TIMEOUT)
        shown.append(dialog.info.text())
        return QDialog.DialogCode.Rejected

    monkeypatch.setattr(HidConfigurationDialog, "exec", look)
    window.commands["online"].trigger()  # lists off the GUI thread, then asks
    qtbot.waitUntil(lambda: bool(shown), timeout=TIMEOUT)
    assert "Listing the valves failed: The valve could not be reached. (hidapi:" in shown[0]
    assert "Listing the valves failed" in window.statusBar().currentMessage()
    assert not window.connection.is_online


def test_going_online_again_retries_the_can_node_chosen_last_not_the_remembered_emulator(
    qtbot, tmp_path, monkeypatch
):
    """``--device can:10`` while the node was still booting, then F5: the CAN node again."""
    from prm9tool.views.hid_dialog import EMULATORS_KEY, SELECTED_KEY

    with main_window(qtbot, tmp_path) as window:
        window.settings.setValue(EMULATORS_KEY, [f"{E02}:4001"])
        window.settings.setValue(SELECTED_KEY, f"emulator:{E02}:4001")
        tried: list[str] = []
        monkeypatch.setattr(
            window.connection, "go_online", lambda e: tried.append(getattr(e, "device_id", e))
        )
        window.valve.go_online("can:10")  # what app.start does for --device can:10
        window.valve.go_online()  # F5 after that attempt failed
        qtbot.waitUntil(lambda: len(tried) == 2, timeout=5000)
        assert tried == ["can:10", "can:10"]


@pytest.mark.parametrize("answer", [prompts.Button.No, prompts.Button.Yes])
def test_a_document_of_another_valve_is_named_before_going_online(
    qtbot, window, answers, tmp_path, answer
):
    """Issue 25 item 11: a document read from valve 1001 went online with valve 4711 unasked."""
    window.doc.source_serial = 1001
    window.files.save_to(tmp_path / "valve_1001.prm")
    answers.answers = [answer]
    go_online(qtbot, window, f"{E02}:4711")
    if answer == prompts.Button.No:
        qtbot.waitUntil(lambda: not window.connection.is_online, timeout=TIMEOUT)
        assert not window.sync.active
    else:
        _settled(qtbot, window)  # the same values: online as usual
    (question,) = answers.asked
    assert question.startswith("Another valve: The document was read from valve 1001; you are "
                               "online with valve 4711")  # fmt: skip


def test_the_same_valve_goes_online_without_a_question(qtbot, window, answers, tmp_path):
    window.doc.source_serial = 4712
    window.files.save_to(tmp_path / "valve_4712.prm")
    go_online(qtbot, window, f"{E02}:4712")
    _settled(qtbot, window)
    assert answers.asked == []


def test_valve_store_keeps_the_online_edits_and_the_history_records_them(qtbot, window, answers):
    """Issue 25 item 12: there was no Store command; the user uploaded all 43 parameters to
    store two online edits."""
    from prm9tool.history.recorder import Recorder

    window.connection.set_recorder(Recorder())
    go_online(qtbot, window, f"{E02}:4720")
    _settled(qtbot, window)
    window.doc.set_value("DTAMP", 999)
    qtbot.waitUntil(lambda: valve_value(qtbot, window, "DTAMP") == 999, timeout=TIMEOUT)
    assert window.commands["store"].isEnabled()
    with qtbot.waitSignal(window.connection.operation_finished, timeout=TIMEOUT,
                          check_params_cb=lambda name, _r: name == "store") as done:  # fmt: skip
        window.commands["store"].trigger()
    assert done.args[1]["DTAMP"] == 999  # read back after the store
    assert "The valve stored its parameters at " in window.status.currentMessage()
    emulated(4720).reload()  # working values <- stored ones: the edit was stored
    assert valve_value(qtbot, window, "DTAMP") == 999
    records = Recorder().store().records(4720)
    assert records[-1]["operation"] == "store" and records[-1]["outcome"] == "ok"
    full = Recorder().store().record(records[-1]["id"])
    assert json.loads(full["parameters"])["DTAMP"] == 999
    with qtbot.waitSignal(window.connection.online_changed, timeout=TIMEOUT):
        window.commands["offline"].trigger()
    assert answers.asked == []  # stored: nothing left to ask about


def test_taking_the_values_of_another_valve_type_never_overwrites_the_file(
    qtbot, window, monkeypatch, tmp_path
):
    """Issue 34 item 3: an E02 file, online with an E04 -CA valve, "Take the valve's values",
    Ctrl+S: the E02 file was overwritten with the E04 type key, unasked."""
    from PySide6.QtWidgets import QFileDialog

    path = tmp_path / "e02.prm"
    window.files.save_to(path)
    before = path.read_bytes()
    _choose(monkeypatch, DiffChoice.TAKE_VALVE)
    go_online(qtbot, window, f"{E04_CA}:4120")
    _settled(qtbot, window)
    assert str(window.doc.type_key) == E04_CA
    assert window.doc.path is None and window.doc.modified  # a new, unsaved document
    assert window.windowTitle() == "untitled[*] – prm9tool"
    assert "the document is a new, unsaved one (e02.prm stays as it is)" in (
        window.status.currentMessage()
    )
    asked: list[str] = []
    monkeypatch.setattr(
        QFileDialog, "getSaveFileName", lambda _p, _t, where, _f: (asked.append(where), ("", ""))[1]
    )
    window.commands["save"].trigger()  # Ctrl+S asks for a name …
    assert len(asked) == 1 and asked[0].startswith(str(tmp_path))
    assert path.read_bytes() == before  # … and the E02 file holds what it held


def test_a_document_confirmed_for_another_valve_is_not_asked_about_again(
    qtbot, window, answers, tmp_path
):
    """Issue 34 item 13: "The document was read from valve 1001; you are online with valve
    4711…" came back at every reconnect after the user had said Yes and both agreed."""
    window.doc.source_serial = 1001
    window.files.save_to(tmp_path / "valve_1001.prm")
    answers.answers = [prompts.Button.Yes]
    go_online(qtbot, window, f"{E02}:4713")
    _settled(qtbot, window)  # the same values: online as usual
    assert len(answers.asked) == 1 and window.doc.source_serial == 4713
    with qtbot.waitSignal(window.connection.online_changed, timeout=TIMEOUT):
        window.commands["offline"].trigger()
    go_online(qtbot, window, f"{E02}:4713")
    _settled(qtbot, window)
    assert len(answers.asked) == 1  # the same valve again: no question


def test_a_second_factory_reset_still_says_it_was_done(qtbot, window, answers, monkeypatch):
    """With the valve's backup kept from before, the reset said nothing at all: the user at the
    screen saw the dialog close and did not know whether the values were restored."""
    _online_with_limta_2000(qtbot, window, 4107)

    def confirm(dialog):
        dialog.confirm.setChecked(True)
        return QDialog.DialogCode.Accepted

    monkeypatch.setattr(RestartDialog, "exec", confirm)
    for _ in range(2):
        window.status.showMessage("")
        with qtbot.waitSignal(window.connection.operation_finished, timeout=TIMEOUT):
            window.commands["restore_factory"].trigger()
        assert "Factory values restored" in window.status.currentMessage()
    assert len(backup.existing_backups(4107)) == 1

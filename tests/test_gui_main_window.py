"""The main window offline: menus and toolbar, enabled actions, access levels, files, undo."""

from __future__ import annotations

import os

import pytest
from PySide6.QtCore import Qt
from support.gui_support import E02, E04_CA, main_window, reject_all_dialogs

from prm9tool.catalogue import Access
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.model.password import DEFAULT_PASSWORD, PasswordStore
from prm9tool.views import main_window as main_window_module
from prm9tool.views import prompts
from prm9tool.views.access_dialog import ChangePasswordDialog, PasswordDialog
from prm9tool.views.valve.selection import ValveSelectionDialog

Accepted = ValveSelectionDialog.DialogCode.Accepted
Rejected = ValveSelectionDialog.DialogCode.Rejected


def _menu_texts(window, name):
    return [a.text() for a in window.commands.menus[name].actions() if not a.isSeparator()]


def test_menus_and_toolbar_are_those_of_the_manual(window):
    titles = [a.text() for a in window.menuBar().actions()]
    assert titles == ["&File", "&View", "V&alve", "&Communication", "&Help"]
    assert {"&Open…", "&Save", "Save &As…", "&Print…", "Co&mpare with file…", "E&xit"} <= set(
        _menu_texts(window, "file")
    )
    assert _menu_texts(window, "valve") == [
        "Valve &selection…",
        "Valve s&tatus…",
        "&Upload to valve",
        "&Download from valve",
        "St&ore in valve",  # issue 25
        "&Compare with valve",  # issue 17
        "&History…",
        "Restore &factory values…",
        "&Restart valve…",
        "&Verify by restart…",  # issue 20 item 2: after an upload, hydraulics off
        "E&mulated valve",  # this program's addition: the emulated valve's inputs and faults
    ]
    assert _menu_texts(window, "communication") == [
        "&HID configuration…",
        "&CAN bus…",
        "CAN &trace…",  # issue 32: record the bus, decode a trace file
        "O&nline mode",
        "O&ffline mode",
    ]
    assert _menu_texts(window, "help") == ["&Help", "Home&page", "&About prm9tool"]
    assert _menu_texts(window, "language") == ["Deutsch", "English", "Čeština"]
    toolbar = [a.objectName() for a in window.commands.toolbar.actions() if not a.isSeparator()]
    assert toolbar == [
        f"action_{name}"
        for name in ("open", "save", "print", "online", "offline", "download", "upload",
                     "restart", "valve_selection", "view_diagram", "view_parameters",
                     "view_scope", "canopen")
    ]  # fmt: skip
    assert all(
        not a.icon().isNull() for a in window.commands.toolbar.actions() if not a.isSeparator()
    )


def test_shortcuts_include_the_standard_ones(window):
    shortcuts = {n: window.commands[n].shortcut().toString() for n in ("open", "save", "undo")}
    assert shortcuts == {"open": "Ctrl+O", "save": "Ctrl+S", "undo": "Ctrl+Z"}
    assert "Ctrl+Y" in [k.toString() for k in window.commands["redo"].shortcuts()]


def test_offline_only_what_makes_sense_is_enabled(window):
    a = window.commands
    for name in ("upload", "download", "restart", "offline", "view_scope"):
        assert not a[name].isEnabled(), name
    for name in ("online", "hid_configuration", "open", "valve_selection", "valve_status",
                 "restore_factory"):  # fmt: skip
        assert a[name].isEnabled(), name
    assert not a["canopen"].isEnabled()  # E02 without -CA
    assert not a["undo"].isEnabled() and not a["redo"].isEnabled()


def test_status_bar_shows_mode_type_key_and_file(window):
    bar = window.status
    assert bar.mode_label.text() == "Mode: OFFLINE"
    assert bar.type_key_label.text() == E02
    assert bar.file_label.text() == "untitled"
    window.doc.set_value("LIMTA", 2000)
    assert bar.file_label.text() == "untitled *"


def test_status_bar_shows_the_access_level(window, monkeypatch):
    assert window.status.level_label.text() == "Level: Basic"
    monkeypatch.setattr(window, "_ask_password", lambda: Accepted)
    window.commands["level_expert"].trigger()
    assert window.status.level_label.text() == "Level: Expert"
    window.commands["level_basic"].trigger()
    assert window.status.level_label.text() == "Level: Basic"


def test_views_switch_and_scope_needs_a_valve(window):
    window.commands["view_parameters"].trigger()
    assert window.current_view() == "parameters"
    window.commands["view_diagram"].trigger()
    assert window.current_view() == "diagram"
    window.open_scope("demand")
    assert window.current_view() == "diagram"
    assert "online mode only" in window.status.currentMessage()


def test_expert_needs_the_password(window, monkeypatch):
    monkeypatch.setattr(window, "_ask_password", lambda: Rejected)
    window.commands["level_expert"].trigger()
    assert window.access.level is Access.BASIC
    assert window.commands["level_basic"].isChecked()
    monkeypatch.setattr(window, "_ask_password", lambda: Accepted)
    window.commands["level_expert"].trigger()
    assert window.access.level is Access.EXPERT
    assert window.commands["change_password"].isEnabled()
    window.commands["level_basic"].trigger()
    assert window.access.level is Access.BASIC
    assert not window.commands["change_password"].isEnabled()


def test_password_dialog_accepts_only_the_right_password(window):
    dialog = PasswordDialog(window.passwords, window)
    dialog.password.setText("guess")
    dialog._on_accepted()
    assert dialog.error_label.text() == "Wrong password." and dialog.result() != Accepted
    dialog.password.setText(DEFAULT_PASSWORD)
    dialog._on_accepted()
    assert dialog.result() == Accepted


def _clipped_texts(dialog):
    from PySide6.QtWidgets import QLabel

    return [
        label.text()
        for label in dialog.findChildren(QLabel)
        if label.isVisible() and label.wordWrap()
        if label.height() < label.heightForWidth(label.width())
    ]


@pytest.mark.parametrize("language", ["en", "de", "cs"])
def test_a_wrong_password_is_explained_in_full(qtbot, window, language):
    from prm9tool import i18n

    i18n.set_language(language)
    try:
        dialog = PasswordDialog(window.passwords, window)
        dialog.show()
        qtbot.waitExposed(dialog)
        assert _clipped_texts(dialog) == []
        dialog.password.setText("guess")
        dialog._on_accepted()
        assert dialog.error_label.isVisible() and _clipped_texts(dialog) == []
        change = ChangePasswordDialog(window.passwords, window)
        change.show()
        change.old.setText("guess")
        change._on_accepted()
        assert change.error_label.isVisible() and _clipped_texts(change) == []
    finally:
        i18n.set_language("en")


def test_password_is_changed_and_stored_only_as_a_salted_hash(window):
    dialog = ChangePasswordDialog(window.passwords, window)
    dialog.old.setText(DEFAULT_PASSWORD)
    dialog.new.setText("valve-42")
    dialog.repeat.setText("valve-41")
    dialog._on_accepted()
    assert dialog.error_label.text() == "The two new passwords differ."
    dialog.repeat.setText("valve-42")
    dialog._on_accepted()
    assert dialog.result() == Accepted
    stored = str(window.settings.value("access/expert_password"))
    assert "valve-42" not in stored and stored.startswith("pbkdf2_sha256$")
    fresh = PasswordStore(window.settings)
    assert fresh.check("valve-42") and not fresh.check(DEFAULT_PASSWORD)


def test_basic_level_hides_and_locks_the_controllers(window, monkeypatch):
    window.show_view("parameters")
    model = window.parameter_view.model
    assert model.row_of("POSKP") < 0
    monkeypatch.setattr(window, "_ask_password", lambda: Accepted)
    window.commands["level_expert"].trigger()
    assert model.row_of("POSKP") >= 0


def test_valve_selection_makes_a_new_document_with_factory_defaults(window, monkeypatch):
    window.doc.set_value("LIMTA", 2000)
    window.doc.mark_saved(None)
    monkeypatch.setattr(ValveSelectionDialog, "exec", _select(E04_CA))
    window.commands["valve_selection"].trigger()
    assert str(window.doc.type_key) == E04_CA
    assert window.doc.value("LIMTA") == 2400 and "PRCKP" in window.doc.values
    assert not window.doc.modified and window.doc.path is None
    assert window.commands["canopen"].isEnabled()
    assert window.status.type_key_label.text() == E04_CA


def _select(key):
    def run(dialog):
        dialog._show_key(TypeKey.parse(key))
        return Accepted

    return run


def test_valve_selection_validates_a_typed_key(window):
    dialog = ValveSelectionDialog(None, window)
    dialog._on_key_edited("PRM9-07.3Z11/30-24E02S02")
    assert "nominal size '07'" in dialog.error_label.text()
    assert not dialog.buttons.button(dialog.buttons.StandardButton.Ok).isEnabled()
    dialog._on_key_edited("prm9-10.3z11/60-24e04s02-ca")
    assert str(dialog.selected_type_key()) == E04_CA
    assert dialog.flow.currentData() == "60" and dialog.canopen.isChecked()


def test_restore_factory_values_offline_resets_the_document(window, answers):
    window.doc.set_value("LIMTA", 2000)
    answers.answers = [prompts.Button.Yes]
    window.commands["restore_factory"].trigger()
    assert window.doc.value("LIMTA") == 2400
    window.commands["undo"].trigger()
    assert window.doc.value("LIMTA") == 2000


def test_help_about_and_homepage(window, answers, monkeypatch):
    window.commands["help"].trigger()
    assert window.help_window.isVisible()
    assert "Expert" in window.help_window.browser.toPlainText()
    window.commands["about"].trigger()
    assert "prm9tool" in answers.asked[-1] and "PySide6" in answers.asked[-1]
    opened = []
    monkeypatch.setattr(main_window_module, "open_homepage", lambda parent: opened.append(parent))
    window.commands["homepage"].trigger()
    assert opened == [window]


def test_home_page_without_a_browser_says_so(window, answers, monkeypatch):
    from PySide6.QtGui import QDesktopServices

    from prm9tool.views.help_dialog import HOMEPAGE

    monkeypatch.setattr(QDesktopServices, "openUrl", lambda _url: False)
    window.commands["homepage"].trigger()
    assert "No web browser" in answers.informed[-1] and HOMEPAGE in answers.informed[-1]


def test_window_geometry_and_view_are_remembered(qtbot, tmp_path, answers):
    with main_window(qtbot, tmp_path) as first:
        first.resize(700, 500)
        first.show_view("parameters")
        first.close()
    with main_window(qtbot, tmp_path) as second:
        assert second.current_view() == "parameters"
        assert (second.width(), second.height()) == (700, 500)


def test_status_window_offline_says_so(window):
    status = window.show_status_window()
    assert status.fields["mode"].text() == "OFFLINE"
    assert status.errors.item(0).text() == "No status: the valve is offline."


def test_hid_dialog_lists_emulated_valves_and_remembers_the_choice(qtbot, window):
    from prm9tool.views.hid_dialog import SELECTED_KEY, HidConfigurationDialog

    dialog = HidConfigurationDialog(window.connection.list_devices_async, window.settings, window)
    assert dialog.listing and "Looking for valves" in dialog.info.text()  # not on this thread
    assert not dialog.buttons.button(dialog.buttons.StandardButton.Ok).isEnabled()
    dialog.add_emulator(f"{E04_CA}:77")
    qtbot.waitUntil(lambda: not dialog.listing)
    assert str(dialog.selected_entry().device_id).endswith(":77")  # the one just added
    cells = [dialog.table.item(r, 1).text() for r in range(dialog.table.rowCount())]
    assert E04_CA in cells
    dialog.accept()
    assert str(window.settings.value(SELECTED_KEY)).endswith(":77")


def test_every_action_can_be_triggered_offline(window, monkeypatch, answers):
    reject_all_dialogs(monkeypatch)
    monkeypatch.setattr(main_window_module, "open_homepage", lambda _parent: True)
    window._connect_actions()
    skipped = {"exit", "online"}  # closing is tested above, going online in test_gui_online
    for name, action in window.commands.actions.items():
        if action.isEnabled() and name not in skipped:
            action.trigger()
    for action in window.commands.language_actions.values():
        action.trigger()
    window.set_language("en")
    assert window.isVisible() and not window.connection.is_online


def test_change_password_action_opens_the_dialog_at_expert_level(window, monkeypatch):
    opened = []
    monkeypatch.setattr(ChangePasswordDialog, "exec", lambda self: opened.append(self) or 0)
    window.commands["change_password"].trigger()
    assert opened == []  # Basic level: nothing to change
    window.access.set_level(Access.EXPERT)
    window.commands["change_password"].trigger()
    assert len(opened) == 1


def test_highlight_follows_a_dark_palette(window, qapp):
    from PySide6.QtGui import QColor, QPalette

    from prm9tool.views.parameters.model import Column as Col

    old = qapp.palette()
    dark = QPalette(old)
    dark.setColor(QPalette.ColorRole.Base, QColor("#202124"))
    dark.setColor(QPalette.ColorRole.Highlight, QColor("#3d7eff"))
    qapp.setPalette(dark)
    try:
        window.doc.set_value("LIMTA", 2000)
        model = window.parameter_view.model
        colour = model.data(
            model.index(model.row_of("LIMTA"), Col.VALUE), Qt.ItemDataRole.BackgroundRole
        )
        assert colour.rgb() == QColor("#3d7eff").rgb() and colour.alpha() < 255
    finally:
        qapp.setPalette(old)


def test_emulated_valve_dialog_builds_type_key_and_serial(window):
    from prm9tool.views.hid_dialog import EmulatorDialog

    dialog = EmulatorDialog(window)
    dialog.selection._on_key_edited(E04_CA)
    dialog.serial.setValue(4711)
    assert dialog.spec() == f"{E04_CA}:4711"


def test_hid_dialog_lists_valves_despite_two_saved_emulators_with_one_serial(qtbot, window):
    """Settings of an earlier version held both; every listing failed ("two emulated valves
    with serial 1001") and left no row to remove. One serial is one valve: the later counts."""
    from prm9tool.views.hid_dialog import EMULATORS_KEY, HidConfigurationDialog, saved_emulators

    e02_ca = "PRM9-06.3Z11/30-24E02S02-CA"
    window.settings.setValue(EMULATORS_KEY, [f"{e02_ca}:1001", f"{E04_CA}:1001", f"{E02}:79"])
    assert saved_emulators(window.settings) == [f"{E04_CA}:1001", f"{E02}:79"]
    dialog = HidConfigurationDialog(window.connection.list_devices_async, window.settings, window)
    qtbot.waitUntil(lambda: not dialog.listing)
    assert "failed" not in dialog.info.text()
    assert [dialog.table.item(r, 2).text() for r in range(dialog.table.rowCount())] == [
        "1001",
        "79",
    ]
    dialog.add_emulator(f"{e02_ca}:79")  # the same serial again: it replaces that valve
    qtbot.waitUntil(lambda: not dialog.listing)
    assert saved_emulators(window.settings) == [f"{E04_CA}:1001", f"{e02_ca}:79"]


def test_a_saved_emulated_valve_that_cannot_be_made_is_listed_with_why_and_can_go(qtbot, window):
    """An E04-CA remembered at 1001 where an E02-CA left its EEPROM image: every listing
    failed, the dialog stayed empty and nothing could be removed."""
    from prm9tool.device import emulated_valves, factory
    from prm9tool.views.hid_dialog import EMULATORS_KEY, HidConfigurationDialog, saved_emulators

    with factory.open_session(f"emulator:{E02}:1001", paced=False) as session:
        session.store()
    emulated_valves.forget_emulated_valves()
    window.settings.setValue(EMULATORS_KEY, [f"{E04_CA}:1001", f"{E02}:80"])
    from prm9tool import app

    def lister(specs, deliver):  # the program's (the fixture's connection lists plainly)
        deliver(app._lister(specs))

    dialog = HidConfigurationDialog(lister, window.settings, window)
    qtbot.waitUntil(lambda: not dialog.listing)
    rows = [
        [dialog.table.item(r, c).text() for c in (2, 4)] for r in range(dialog.table.rowCount())
    ]
    assert rows[0][0] == "80" and rows[1][0] == "1001"
    assert "cannot be used" in rows[1][1] and "image belongs to" in rows[1][1]
    dialog.table.selectRow(1)
    ok = dialog.buttons.button(dialog.buttons.StandardButton.Ok)
    assert not ok.isEnabled() and dialog.remove_button.isEnabled()
    dialog.remove_button.click()
    qtbot.waitUntil(lambda: not dialog.listing)
    assert saved_emulators(window.settings) == [f"{E02}:80"]


def test_hid_dialog_removes_an_emulated_valve(qtbot, window):
    from prm9tool.views.hid_dialog import HidConfigurationDialog, saved_emulators

    dialog = HidConfigurationDialog(window.connection.list_devices_async, window.settings, window)
    dialog.add_emulator(f"{E04_CA}:78")
    qtbot.waitUntil(lambda: not dialog.listing)
    assert dialog.remove_button.isEnabled()
    dialog.remove_button.click()
    qtbot.waitUntil(lambda: not dialog.listing)
    assert f"{E04_CA}:78" not in saved_emulators(window.settings)
    assert E04_CA not in [dialog.table.item(r, 1).text() for r in range(dialog.table.rowCount())]


def test_canopen_window_of_the_toolbar_is_gated_by_the_access_level(qtbot, tmp_path, answers):
    with main_window(qtbot, tmp_path, E04_CA) as window:
        canopen = window.show_canopen_window()
        assert not canopen.terminator.isEnabled()
        assert "Expert" in canopen.terminator.toolTip()
        assert not canopen.apply("CANTERM", 1)
        assert window.doc.value("CANTERM") == 0
        window.access.set_level(Access.EXPERT)
        assert canopen.terminator.isEnabled()


def test_status_bar_shows_lost_stream_samples_only_while_there_are_some(window):
    label = window.status.lost_label
    assert label.isHidden()
    window.connection.samples_lost_changed.emit(1)
    assert not label.isHidden() and label.text() == "1 sample lost"
    window.connection.samples_lost_changed.emit(120)
    assert label.text() == "120 samples lost"
    window.connection.samples_lost_changed.emit(0)
    assert label.isHidden()


@pytest.mark.parametrize(
    ("language", "one", "two"),
    [
        ("en", "1 value in the document differs", "2 values in the document differ"),
        ("de", "1 Wert im Dokument weicht", "2 Werte im Dokument weichen"),
        ("cs", "1 hodnota v dokumentu se liší", "2 hodnoty v dokumentu se liší"),
    ],
)
def test_counts_use_the_plural_forms_of_the_language(window, language, one, two):
    from prm9tool.views.online_dialogs import OnlineDiffDialog

    window.set_language(language)
    valve = {"LIMTA": 2400, "DTAMP": 2458}
    single = OnlineDiffDialog({"LIMTA": 2000, "DTAMP": 2458}, valve, E02, E02, window)
    double = OnlineDiffDialog({"LIMTA": 2000, "DTAMP": 1000}, valve, E02, E02, window)
    assert single.intro.text().startswith(one)
    assert double.intro.text().startswith(two)
    assert "(s)" not in single.intro.text() + double.intro.text()


def _accelerator(text):
    """The letter after a single '&' ('&&' is a literal ampersand), lower case, or None."""
    plain = text.replace("&&", "")
    index = plain.find("&")
    return plain[index + 1].lower() if 0 <= index < len(plain) - 1 else None


def _menus_of(window):
    bar = window.menuBar()
    yield "menu bar", [a.text() for a in bar.actions()]
    for name, menu in window.commands.menus.items():
        yield name, [a.text() for a in menu.actions() if not a.isSeparator()]


@pytest.mark.parametrize("language", ["en", "de", "cs"])
def test_no_two_entries_of_a_menu_share_an_accelerator(window, language):
    window.set_language(language)
    for name, texts in _menus_of(window):
        letters = [_accelerator(text) for text in texts]
        taken = [letter for letter in letters if letter is not None]
        clashes = sorted({letter for letter in taken if taken.count(letter) > 1})
        assert clashes == [], f"{language} {name}: {texts}"
        if name != "language":  # language names stay as they are written
            assert None not in letters, f"{language} {name}: {texts}"


def test_save_as_and_exit_have_windows_shortcuts_too(window):
    keys = {n: [k.toString() for k in window.commands[n].shortcuts()] for n in ("save_as", "exit")}
    assert "Ctrl+Shift+S" in keys["save_as"] and "Ctrl+Q" in keys["exit"]
    assert all(len(set(v)) == len(v) for v in keys.values())  # no key bound twice


def _message_lines(bar) -> list[str]:
    """The lines the message label shows the message in, each checked to fit its width."""
    label = bar.message_label
    lines = label.text().split("\n") if label.text() else []
    width = label.contentsRect().width()
    assert all(label.fontMetrics().horizontalAdvance(line) <= width for line in lines), lines
    return lines


def test_a_long_status_message_is_read_whole_and_the_fields_stay(qtbot, window):
    """Issue 25 item 16: the status bar cut "… stored at 03:37:0" (German and Czech are
    longer); issue 34 item 20: making room for it hid the type key and the file name. The
    message wraps onto a second line instead; every field stays."""
    window.resize(1024, 700)
    bar = window.status
    bar.set_type_key("PRM9-06.3Z11/30-24E02S02-CA")
    message = (
        "43 Parameter geschrieben, überprüft und um 03:37:05 gespeichert; das Ventil arbeitet "
        "jetzt mit ihnen"
    )
    bar.showMessage(message, 8000)
    qtbot.waitUntil(lambda: bar.message_label.height() >= 2 * bar.fontMetrics().height())
    assert all(label.isVisible() for label in bar.labels())  # type key and file name too
    assert bar.type_key_label.text() == "PRM9-06.3Z11/30-24E02S02-CA"
    lines = _message_lines(bar)
    assert len(lines) == 2 and " ".join(lines) == message  # whole, on two lines
    assert bar.message_label.height() >= len(lines) * bar.fontMetrics().height()
    assert bar.toolTip() == message and bar.currentMessage() == message
    snapshot_path = os.environ.get("PRM9TOOL_SCREENSHOTS")
    if snapshot_path:
        window.grab().save(os.path.join(snapshot_path, "status_long_message.png"))
    bar.clearMessage()
    assert bar.currentMessage() == "" and bar.message_label.text() == ""


def test_a_status_message_stays_whole_when_the_fields_grow_after_it(qtbot, window):
    """In Czech, "Online: parametry načteny z ventilu" was cut to "…z ventil" when the firmware
    and the valve's status arrived after the message and widened their fields."""
    window.resize(1024, 700)
    bar = window.status
    message = "Online: parametry načteny z ventilu"
    bar.showMessage(message, 8000)
    bar.set_online(True)
    bar.set_firmware("1.0.0")
    bar.set_type_key("PRM9-06.3Z11/30-24E02S02-CA")
    bar.set_device_status("čeká na CANopen master")
    qtbot.wait(50)  # the layout settles
    assert all(label.isVisible() for label in bar.labels())
    assert " ".join(_message_lines(bar)) == message
    assert bar.message_label.height() >= len(_message_lines(bar)) * bar.fontMetrics().height()


def test_a_longer_message_breaks_at_spaces_only_and_ends_in_an_ellipsis(qtbot, window):
    """Issue 34 (a new user): a long message broke inside the type key at a hyphen and its
    third line hid below the bar, behind the "samples lost" field. It keeps to two lines,
    broken at spaces; what does not fit ends in "…" (the whole is the bar's tip)."""
    window.resize(1024, 700)
    bar = window.status
    bar.set_type_key("PRM9-06.3Z11/30-24E04S02-CA")
    bar.set_samples_lost(1234)
    message = (
        "Backup of the valve's parameters saved: /home/user/.local/share/prm9tool/backups/"
        "4711/PRM9-06.3Z11_30-24E04S02-CA_4711_20261202-031652.prm, the valve "
        "PRM9-06.3Z11/30-24E04S02-CA works with them now and the history has the record"
    )
    bar.showMessage(message)
    qtbot.waitUntil(lambda: bar.lost_label.isVisible())
    qtbot.wait(50)  # the layout settles
    lines = _message_lines(bar)
    assert len(lines) == 2 and lines[-1].endswith("…")
    words = message.split(" ")
    assert all(w in words for w in " ".join(lines).rstrip("…").split(" ")[:-1])  # no broken word
    assert bar.message_label.geometry().right() < bar.lost_label.geometry().left()
    assert bar.toolTip() == message
    snapshot_path = os.environ.get("PRM9TOOL_SCREENSHOTS")
    if snapshot_path:
        window.grab().save(os.path.join(snapshot_path, "status_longer_message.png"))


def test_a_message_goes_after_its_timeout(qtbot, window):
    window.status.showMessage("short", 50)
    with qtbot.waitSignal(window.status.messageChanged, timeout=5000) as changed:
        pass
    assert changed.args == [""] and window.status.currentMessage() == ""


@pytest.mark.parametrize(
    ("language", "on", "off"),
    [("en", "-1: on (9-point curve)", "0: off"), ("de", "-1: ", "0: "), ("cs", "-1: ", "0: ")],
)
def test_the_differ_dialog_shows_a_choice_with_its_meaning_as_the_list(window, language, on, off):
    """Issue 34, item 20: SETPLINON showed as a bare "-1"/"0" where the list shows
    "-1: on (9-point curve)"."""
    from prm9tool.catalogue import CATALOGUE
    from prm9tool.views.online_dialogs import OnlineDiffDialog
    from prm9tool.views.parameters.model import format_value

    window.set_language(language)
    dialog = OnlineDiffDialog({"SETPLINON": -1}, {"SETPLINON": 0}, E02, E02, window)
    document, valve = dialog.table.item(0, 2).text(), dialog.table.item(0, 3).text()
    assert document.startswith(on) and valve.startswith(off)
    window.doc.set_value("SETPLINON", -1)
    assert document == format_value(window.doc, CATALOGUE["SETPLINON"], live=False)


def test_first_window_fits_the_screen(window):
    """A first start on a small screen (here offscreen's) keeps the status bar on the screen."""
    free = window.screen().availableGeometry()
    assert window.width() <= free.width()
    assert window.height() <= free.height()

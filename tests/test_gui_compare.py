"""The compare view and the history window in the main window, online with an emulated valve."""

from __future__ import annotations

import os
from pathlib import Path

from PySide6.QtCore import Qt
from PySide6.QtWidgets import QFileDialog
from support.gui_support import E02, go_online

from prm9tool import i18n
from prm9tool.catalogue import Access
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.compare import Comparison, Side
from prm9tool.files.prmfile import PrmContents, write_file
from prm9tool.history.recorder import Recorder
from prm9tool.views import prompts
from prm9tool.views.compare.view import BOTH, DOCUMENT, FIRST_VALUE, VALVE, CompareDialog
from prm9tool.views.online_dialogs import DiffChoice, OnlineDiffDialog

TIMEOUT = 10_000


def snapshot(widget, name):
    folder = os.environ.get("PRM9TOOL_SCREENSHOTS")
    if folder:
        widget.grab().save(str(Path(folder) / name))


def factory_side(label, **changes):
    contents = PrmContents.factory(TypeKey.parse(E02))
    contents.values.update(changes)
    return Side(label, contents.type_key, contents.values)


def check(dialog, mnemonic, side):
    model = dialog.model
    row = next(i for i, r in enumerate(model.rows) if r.mnemonic == mnemonic)
    index = model.index(row, FIRST_VALUE + side)
    assert model.setData(index, Qt.CheckState.Checked.value, Qt.ItemDataRole.CheckStateRole)


def answer_compare(monkeypatch, choices, target, shown, picture=None):
    def run(dialog):
        shown.append(dialog)
        for mnemonic, side in choices.items():
            check(dialog, mnemonic, side)
        if picture:
            snapshot(dialog, picture)
        assert dialog.apply_buttons[target].isEnabled()
        dialog.apply_buttons[target].click()
        return dialog.result()

    monkeypatch.setattr(CompareDialog, "exec", run)


def test_comparing_two_files_says_nothing_about_a_valve(qtbot):
    """Issue 34, item 15: two files compared reported "0 parameters not on the valve"."""
    i18n.set_language("en")
    first, second = factory_side("a.prm", LIMTA=1500), factory_side("b.prm")
    dialog = CompareDialog(Comparison((first, second)), (0, 1))
    qtbot.addWidget(dialog)
    assert dialog.summary.text().split("\n")[0] == (
        "1 parameter differs, 0 parameters only on one side, 1 shown"
    )


def test_the_view_filters_counts_and_enables_apply_only_with_a_choice(qtbot):
    i18n.set_language("en")  # the English plural forms
    document, valve = factory_side("Document", LIMTA=1500, DTAMP=1000), factory_side("Valve")
    comparison = Comparison((document, valve), Side.factory(valve.type_key, "Factory"))
    dialog = CompareDialog(comparison, (0, 1))
    qtbot.addWidget(dialog)
    assert [r.mnemonic for r in dialog.model.rows] == ["LIMTA", "DTAMP"]
    assert dialog.summary.text().startswith("2 parameters differ, 0 parameters only on one side")
    assert not dialog.apply_buttons[0].isEnabled() and not dialog.apply_buttons[1].isEnabled()
    limta = dialog.model.index(0, FIRST_VALUE)
    assert dialog.model.data(limta) == "1500 mA"
    assert dialog.model.data(dialog.model.index(0, FIRST_VALUE + 2)) == "2400 mA"  # factory
    check(dialog, "LIMTA", 0)
    assert dialog.apply_buttons[1].isEnabled() and not dialog.apply_buttons[0].isEnabled()
    block = next(
        i for i in range(dialog.block.count()) if "LIMTA" in (dialog.block.itemData(i) or [])
    )
    dialog.block.setCurrentIndex(block)
    assert [r.mnemonic for r in dialog.model.rows] == ["LIMTA"]
    dialog.differences_only.setChecked(False)
    assert len(dialog.model.rows) > 1 and "DTAMP" not in {r.mnemonic for r in dialog.model.rows}
    dialog.apply_buttons[1].click()
    assert dialog.applied == (1, {"LIMTA": 1500})


def test_values_are_shown_with_the_decimal_separator_of_the_language(qtbot):
    """In German the compare view showed ``1.5`` where the parameter list shows ``1,5``."""
    document = factory_side("Dokument", GAINSETPOS=24576)  # 1.5
    comparison = Comparison((document, factory_side("Ventil")), Side.factory(document.type_key))
    i18n.set_language("de")
    try:
        dialog = CompareDialog(comparison, (0, 1))
        qtbot.addWidget(dialog)
        row = next(i for i, r in enumerate(dialog.model.rows) if r.mnemonic == "GAINSETPOS")
        shown = [dialog.model.data(dialog.model.index(row, FIRST_VALUE + s)) for s in (0, 1, 2)]
    finally:
        i18n.set_language("en")
    assert shown == ["1,5", "1", "1"]


def test_compare_with_file_takes_the_chosen_values_as_one_undo_step(
    qtbot, window, tmp_path, monkeypatch
):
    contents = PrmContents.factory(TypeKey.parse(E02))
    contents.values.update(LIMTA=1700, DTAMP=900)
    write_file(contents, tmp_path / "other.prm")
    shown = []
    answer_compare(monkeypatch, {"LIMTA": 1}, 0, shown)
    window.compare.compare_with_file(tmp_path / "other.prm")
    assert [r.mnemonic for r in shown[0].model.rows] == ["LIMTA", "DTAMP"]
    assert window.doc.value("LIMTA") == 1700 and window.doc.value("DTAMP") != 900
    window.undo.stack.undo()
    assert window.doc.value("LIMTA") == 2400


def test_an_invalid_file_is_named_and_nothing_changes(window, tmp_path, answers):
    (tmp_path / "bad.prm").write_text("garbage\n", encoding="utf-8")
    window.compare.compare_with_file(tmp_path / "bad.prm")
    assert answers.informed and "bad.prm cannot be compared" in answers.informed[0]
    assert not window.doc.modified


def test_an_invalid_file_to_compare_names_its_first_problem_in_the_box(window, tmp_path, answers):
    """The box said only "kaputt.prm kann nicht verglichen werden.": the reason was in the
    details alone, while File → Open names the first problem."""
    contents = PrmContents.factory(TypeKey.parse(E02))
    write_file(contents, tmp_path / "range.prm")
    text = (tmp_path / "range.prm").read_text(encoding="utf-8")
    (tmp_path / "range.prm").write_text(text.replace("THRESETP = 5", "THRESETP = 500"))
    window.compare.compare_with_file(tmp_path / "range.prm")
    lead = answers.informed[-1].split("\n")[:2]
    assert lead[0].endswith("range.prm cannot be compared.")
    assert lead[1].startswith("range.prm:") and "THRESETP" in lead[1]


def test_going_online_choose_per_parameter_makes_both_sides_agree(qtbot, window, monkeypatch):
    window.doc.set_value("LIMTA", 1500)
    window.doc.set_value("DTAMP", 1000)
    monkeypatch.setattr(
        OnlineDiffDialog, "exec", lambda d: (setattr(d, "choice", DiffChoice.CHOOSE), 1)[1]
    )
    shown = []
    answer_compare(monkeypatch, {"LIMTA": 0}, BOTH, shown, "window_dialog_compare.png")
    # DTAMP keeps the valve's value: every difference starts as "take the valve's"
    with qtbot.waitSignal(window.connection.operation_finished, timeout=TIMEOUT,
                          check_params_cb=lambda name, _r: name == "upload") as done:  # fmt: skip
        go_online(qtbot, window, f"{E02}:4301")
    assert done.args[1].stored and done.args[1].written == 1  # exactly the chosen value
    qtbot.waitUntil(lambda: window.sync.active, timeout=TIMEOUT)
    valve_dtamp = shown[0].comparison.row("DTAMP").values[1]
    assert window.doc.value("DTAMP") == valve_dtamp and window.doc.value("LIMTA") == 1500
    assert window.sync.differences() == {}


def test_history_records_what_the_gui_did_and_the_window_shows_it(qtbot, window, monkeypatch):
    window.connection.set_recorder(Recorder())
    go_online(qtbot, window, f"{E02}:4302")
    qtbot.waitUntil(lambda: window.sync.active, timeout=TIMEOUT)
    window.doc.set_value("DTAMP", 1234)
    with qtbot.waitSignal(window.connection.operation_finished, timeout=TIMEOUT,
                          check_params_cb=lambda name, _r: name == "upload"):  # fmt: skip
        window.commands["upload"].trigger()
    history = window.compare.show_history()
    qtbot.addWidget(history)
    qtbot.waitUntil(lambda: history.model.rowCount() == 3, timeout=TIMEOUT)
    operations = [r["operation"] for r in history.model.records]
    assert operations == ["download", "backup", "upload"]
    assert "3 records in sqlite:///" in history.state.text()
    snapshot(history, "window_dialog_history.png")
    selection = history.table.selectionModel()
    for row in (0, 2):  # read when going online, and the upload (the backup has the edit)
        selection.select(
            history.model.index(row, 0),
            selection.SelectionFlag.Select | selection.SelectionFlag.Rows,
        )
    dialog = history.compare_selected()
    qtbot.addWidget(dialog)
    assert [r.mnemonic for r in dialog.comparison.changed] == ["DTAMP"]
    selection.clearSelection()
    selection.select(
        history.model.index(0, 0), selection.SelectionFlag.Select | selection.SelectionFlag.Rows
    )
    before = window.undo.stack.count()
    window.connection.go_offline()
    qtbot.waitUntil(lambda: not window.connection.is_online, timeout=TIMEOUT)
    history.buttons["document"].click()  # the valve's values when the window went online
    assert window.doc.value("DTAMP") != 1234 and window.undo.stack.count() == before + 1


def test_an_unreachable_history_asks_and_no_uploads_nothing(qtbot, window, answers, tmp_path):
    damaged = tmp_path / "damaged.sqlite3"
    damaged.write_bytes(b"not a database " * 100)
    window.connection.set_recorder(Recorder(f"sqlite:///{damaged}", tmp_path / "q.jsonl"))
    go_online(qtbot, window, f"{E02}:4303")
    qtbot.waitUntil(lambda: window.sync.active, timeout=TIMEOUT)
    window.sync.stop()
    window.doc.set_value("DTAMP", 1111)
    answers.answers = [prompts.Button.No]
    window.commands["upload"].trigger()
    qtbot.waitUntil(lambda: bool(answers.asked), timeout=TIMEOUT)
    assert "History database unavailable" in answers.asked[-1] and "is damaged" in answers.asked[-1]
    assert window.valve.progress_dialog is None
    answers.answers = [prompts.Button.Yes]
    with qtbot.waitSignal(window.connection.operation_finished, timeout=TIMEOUT,
                          check_params_cb=lambda name, _r: name == "upload") as done:  # fmt: skip
        window.commands["upload"].trigger()
    assert done.args[1].stored
    lines = (tmp_path / "q.jsonl").read_text(encoding="utf-8").splitlines()
    assert any('"operation": "upload"' in line for line in lines)


def test_the_refuse_setting_uploads_nothing_without_the_history(qtbot, window, answers, tmp_path):
    from prm9tool.history.config import save_settings

    save_settings(None, "refuse")
    damaged = tmp_path / "damaged.sqlite3"
    damaged.write_bytes(b"not a database " * 100)
    window.connection.set_recorder(Recorder(f"sqlite:///{damaged}", tmp_path / "q.jsonl"))
    go_online(qtbot, window, f"{E02}:4304")
    qtbot.waitUntil(lambda: window.sync.active, timeout=TIMEOUT)
    window.commands["upload"].trigger()
    qtbot.waitUntil(lambda: bool(answers.informed), timeout=TIMEOUT)
    assert answers.asked == [] and "Upload refused" in answers.informed[-1]
    assert window.valve.progress_dialog is None
    queued = (tmp_path / "q.jsonl").read_text(encoding="utf-8")  # the download going online
    assert '"operation": "download"' in queued and '"operation": "upload"' not in queued


def test_a_record_is_restored_into_its_valve_and_exported(qtbot, window, answers, tmp_path):
    window.connection.set_recorder(Recorder())
    go_online(qtbot, window, f"{E02}:4305")
    qtbot.waitUntil(lambda: window.sync.active, timeout=TIMEOUT)
    original = dict(window.doc.values)
    window.doc.set_value("DTAMP", 777)  # online: written to the valve at once
    history = window.compare.show_history()
    qtbot.addWidget(history)
    qtbot.waitUntil(lambda: history.model.rowCount() == 1, timeout=TIMEOUT)
    history.table.selectRow(0)  # the download when going online: the valve's values then
    with qtbot.waitSignal(window.connection.operation_finished, timeout=TIMEOUT,
                          check_params_cb=lambda name, _r: name == "upload") as done:  # fmt: skip
        history.buttons["valve"].click()
    assert done.args[1].stored and done.args[1].written == len(original)
    assert window.doc.value("DTAMP") == original["DTAMP"]  # the document follows the valve
    assert window.sync.differences() == {}
    history.export_selected(str(tmp_path / "record.csv"))
    text = (tmp_path / "record.csv").read_text(encoding="utf-8")
    assert text.splitlines()[1] == "mnemonic,value,unit,description" and "\nDTAMP," in text
    history.table.selectRow(0)
    other = Recorder()
    assert [r["operation"] for r in other.store().records(4305)][-1] == "upload"
    other.close()


def test_the_history_setting_chooses_the_database_for_the_gui_and_the_command_line(
    qtbot, window, tmp_path, monkeypatch
):
    from prm9tool.history.config import database_url, unreachable_policy
    from prm9tool.views.history.settings import HistorySettingsDialog

    def answer(dialog):
        assert dialog.url.text() == ""  # the default: SQLite on this computer
        snapshot(dialog, "window_dialog_history_settings.png")
        dialog.url.setText(str(tmp_path / "line.sqlite3"))
        dialog.policy.setCurrentIndex(dialog.policy.findData("refuse"))
        dialog._save()
        return dialog.result()

    monkeypatch.setattr(HistorySettingsDialog, "exec", answer)
    window.connection.set_recorder(Recorder())
    history = window.compare.show_history()
    qtbot.addWidget(history)
    history.buttons["settings"].click()
    expected = f"sqlite:///{tmp_path / 'line.sqlite3'}"
    assert database_url() == expected and unreachable_policy() == "refuse"
    assert window.connection.history.recorder.url == expected


def test_the_history_window_names_a_damaged_database_and_keeps_working(qtbot, window, tmp_path):
    damaged = tmp_path / "damaged.sqlite3"
    damaged.write_bytes(b"not a database " * 100)
    window.connection.set_recorder(Recorder(f"sqlite:///{damaged}", tmp_path / "q.jsonl"))
    history = window.compare.show_history()
    qtbot.addWidget(history)
    history.serial.setText("4711")
    history.reload()
    qtbot.waitUntil(lambda: "is damaged" in history.state.text(), timeout=TIMEOUT)
    assert history.model.rowCount() == 0 and not history.buttons["compare"].isEnabled()
    assert damaged.read_bytes() == b"not a database " * 100


def test_compare_with_file_opens_in_the_last_folder_used(window, tmp_path, monkeypatch):
    """Issue 25 item 10: Compare with file opened in the home folder."""
    folder, other = tmp_path / "valves", tmp_path / "elsewhere"
    folder.mkdir(), other.mkdir()
    window.files.save_to(folder / "work.prm")
    write_file(PrmContents.factory(TypeKey.parse(E02)), other / "other.prm")
    asked = []

    def choose(_parent, _title, where, _filter):
        asked.append(where)
        return (str(other / "other.prm"), "") if len(asked) == 1 else ("", "")

    monkeypatch.setattr(QFileDialog, "getOpenFileName", choose)
    monkeypatch.setattr(CompareDialog, "exec", lambda _d: 0)
    window.commands["compare_file"].trigger()
    window.commands["compare_file"].trigger()
    assert asked == [str(folder), str(other)]


def test_the_apply_buttons_say_where_the_ticked_values_go(qtbot):
    """Issue 25 item 10: the user did not find how to put values back into the valve."""
    i18n.set_language("en")
    document, valve = factory_side("Document", LIMTA=1500, DTAMP=1000), factory_side("Valve 4711")
    dialog = CompareDialog(Comparison((document, valve)), (0, 1), roles={0: DOCUMENT, 1: VALVE})
    qtbot.addWidget(dialog)
    to_valve, to_document = dialog.apply_buttons[1], dialog.apply_buttons[0]
    assert to_valve.text() == "Write 0 ticked values into the valve"
    assert not to_valve.isEnabled() and "“Document”" in to_valve.toolTip()
    assert "To write values into the valve: tick them in the column “Document”" in (
        dialog.hint.text()
    )
    assert not to_valve.icon().isNull() and not to_document.icon().isNull()
    check(dialog, "LIMTA", 0)
    check(dialog, "DTAMP", 0)
    assert to_valve.isEnabled() and to_valve.text() == "Write 2 ticked values into the valve"
    assert to_document.text() == "Take 0 ticked values into the document"
    to_valve.click()
    assert dialog.applied == (1, {"LIMTA": 1500, "DTAMP": 1000})


def _select_rows(history, rows):
    selection = history.table.selectionModel()
    selection.clearSelection()
    for row in rows:
        selection.select(
            history.model.index(row, 0),
            selection.SelectionFlag.Select | selection.SelectionFlag.Rows,
        )


def test_values_ticked_in_two_history_records_go_into_the_valve_or_the_document(qtbot, window):
    """Issue 25 item 10: the history's compare view only showed the difference."""
    window.connection.set_recorder(Recorder())
    go_online(qtbot, window, f"{E02}:4303")
    qtbot.waitUntil(lambda: window.sync.active, timeout=TIMEOUT)
    original = window.doc.value("DTAMP")
    window.doc.set_value("DTAMP", 1234)
    with qtbot.waitSignal(window.connection.operation_finished, timeout=TIMEOUT,
                          check_params_cb=lambda name, _r: name == "upload"):  # fmt: skip
        window.commands["upload"].trigger()
    history = window.compare.show_history()
    qtbot.addWidget(history)
    qtbot.waitUntil(lambda: history.model.rowCount() == 3, timeout=TIMEOUT)
    _select_rows(history, (0, 2))  # read when going online; the upload
    dialog = history.compare_selected()
    assert "write them into the valve" in dialog.hint.text()
    check(dialog, "DTAMP", 0)
    assert dialog.apply_buttons[VALVE].text() == "Write 1 ticked value into the valve"
    snapshot(dialog, "window_dialog_history_compare.png")
    with qtbot.waitSignal(window.connection.operation_finished, timeout=TIMEOUT,
                          check_params_cb=lambda name, _r: name == "upload") as done:  # fmt: skip
        dialog.apply_buttons[VALVE].click()
    assert done.args[1].stored and done.args[1].written == 1
    assert window.doc.value("DTAMP") == original  # the document follows the valve
    dialog = history.compare_selected()
    check(dialog, "DTAMP", 1)
    before = window.undo.stack.count()
    dialog.apply_buttons[DOCUMENT].click()
    assert window.doc.value("DTAMP") == 1234 and window.undo.stack.count() == before + 1
    assert window.undo.stack.undoText() == "1 value taken from the history"


def _records(serial):
    return Recorder().store().records(serial)


def test_the_history_records_what_the_user_did_online_with_its_meaning(
    qtbot, window, tmp_path, monkeypatch
):
    """Issue 25 item 13: values put back from a compared file and accepted tuning gains went
    into the history only as "online-edits", and only once stored on exit."""
    i18n.set_language("en")
    window.connection.set_recorder(Recorder())
    go_online(qtbot, window, f"{E02}:4304")
    qtbot.waitUntil(lambda: window.sync.active, timeout=TIMEOUT)
    contents = PrmContents.factory(TypeKey.parse(E02))
    contents.values.update(LIMTA=1700)
    write_file(contents, tmp_path / "other.prm")
    answer_compare(monkeypatch, {"LIMTA": 1}, 0, [])
    window.compare.compare_with_file(tmp_path / "other.prm")
    window.show_tuning_window()
    tuning = window.tuning_window
    window.access.set_level(Access.EXPERT)  # the controllers are locked at Basic level
    tuning.accept_values({"POSKP": 55}, "Autotune")
    qtbot.waitUntil(lambda: len(_records(4304)) == 3, timeout=TIMEOUT)
    _download, applied, accepted = _records(4304)
    assert (applied["operation"], accepted["operation"]) == ("compare-apply", "tuning-accepted")
    history = window.compare.show_history()
    qtbot.addWidget(history)
    qtbot.waitUntil(lambda: history.model.rowCount() == 3, timeout=TIMEOUT)
    meanings = [history.model.meaning(r) for r in history.model.records]
    assert meanings[0] == "Read from the valve: going online"
    assert meanings[1] == (
        "Values from a compared file, written online: other.prm; LIMTA 2400 → 1700 mA"
    )
    assert meanings[2].startswith("Tuning accepted, written online: Autotune; POSKP 0.4 → ")
    assert history.model.data(history.model.index(1, 3)) == meanings[1]


def test_an_upload_from_the_compare_view_says_so_in_the_history(qtbot, window, monkeypatch):
    i18n.set_language("en")
    window.connection.set_recorder(Recorder())
    go_online(qtbot, window, f"{E02}:4305")
    qtbot.waitUntil(lambda: window.sync.active, timeout=TIMEOUT)
    with window.sync.suspended():
        window.doc.set_value("DTAMP", 1000)  # the document differs, the valve does not know
    answer_compare(monkeypatch, {"DTAMP": 0}, 1, [])
    with qtbot.waitSignal(window.connection.operation_finished, timeout=TIMEOUT,
                          check_params_cb=lambda name, _r: name == "upload"):  # fmt: skip
        window.compare.compare_with_valve()
    qtbot.waitUntil(lambda: _records(4305)[-1]["operation"] == "upload", timeout=TIMEOUT)
    history = window.compare.show_history()
    qtbot.addWidget(history)
    qtbot.waitUntil(lambda: history.model.rowCount() >= 3, timeout=TIMEOUT)
    assert history.model.meaning(history.model.records[-1]) == (
        "Written, verified and stored: chosen in the compare view"
    )


def test_parameters_not_on_the_valve_are_shown_apart_not_as_differences(qtbot):
    """Issue 20 item 4: a -CA valve without this project's objects (POSKP …) showed each of
    them as a difference ("only on one side"), so the view never said equal."""
    from prm9tool.catalogue import CATALOGUE

    i18n.set_language("en")
    document = factory_side("Document")
    ours = {p.mnemonic for p in CATALOGUE if not p.address_from_manual} & set(document.values)
    valve = Side(
        "Valve 7", document.type_key, {m: v for m, v in document.values.items() if m not in ours}
    )
    dialog = CompareDialog(Comparison((document, valve)), (0, 1))
    qtbot.addWidget(dialog)
    assert ours and dialog.model.rows == []  # differences only: nothing differs
    assert dialog.summary.text().startswith(
        f"0 parameters differ, 0 parameters only on one side, {len(ours)} parameters not on"
        " the valve, not compared"
    )
    dialog.differences_only.setChecked(False)
    model = dialog.model
    row = next(i for i, r in enumerate(model.rows) if r.mnemonic == "POSKP")
    assert model.data(model.index(row, FIRST_VALUE + 1)) == "not on this valve"
    assert "not a difference" in model.data(
        model.index(row, FIRST_VALUE + 1), Qt.ItemDataRole.ToolTipRole
    )
    assert not model.flags(model.index(row, FIRST_VALUE)) & Qt.ItemFlag.ItemIsUserCheckable
    snapshot(dialog, "compare_not_on_valve.png")

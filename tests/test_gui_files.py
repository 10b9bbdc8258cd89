"""The main window's files: new/open/save/recent, drag and drop, unsaved-changes prompts,
undo/redo, print and PDF export."""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import QMimeData, QPointF, Qt, QUrl
from PySide6.QtGui import QDropEvent
from PySide6.QtWidgets import QFileDialog
from support.gui_support import E02, E04_CA

from prm9tool.catalogue.typekey import TypeKey
from prm9tool.files import prmfile
from prm9tool.views import prompts
from prm9tool.views.valve.selection import ValveSelectionDialog

Accepted = ValveSelectionDialog.DialogCode.Accepted


def _select(key):
    def run(dialog):
        dialog._show_key(TypeKey.parse(key))
        return Accepted

    return run


def test_unsaved_changes_prompt_on_new_can_cancel(window, answers, monkeypatch):
    window.doc.set_value("LIMTA", 2000)
    monkeypatch.setattr(ValveSelectionDialog, "exec", _select(E04_CA))
    answers.answers = [prompts.Button.Cancel]
    window.commands["new"].trigger()
    assert "Unsaved changes" in answers.asked[-1]
    assert str(window.doc.type_key) == E02 and window.doc.value("LIMTA") == 2000


def test_the_diagrams_valve_block_is_valve_selection_and_asks_first(
    window, answers, tmp_path, monkeypatch
):
    path = tmp_path / "open.prm"
    window.files.save_to(path)
    window.doc.set_value("LIMTA", 2000)
    monkeypatch.setattr(ValveSelectionDialog, "exec", _select(E04_CA))
    view = window.views["diagram"]
    answers.answers = [prompts.Button.Cancel]
    view.open_block("valve")
    assert "Unsaved changes" in answers.asked[-1]
    assert str(window.doc.type_key) == E02 and window.doc.value("LIMTA") == 2000
    assert window.doc.path == path and window.doc.modified
    answers.answers = [prompts.Button.Discard]
    view.open_block("valve")
    assert str(window.doc.type_key) == E04_CA and window.doc.value("LIMTA") == 2400
    assert window.doc.path is None  # Save cannot overwrite open.prm with another valve type
    assert "ext_sensor" in view.block_ids()
    assert prmfile.read_file(path).type_key == TypeKey.parse(E02)


def test_save_as_then_open_round_trip_and_recent_files(window, tmp_path, monkeypatch):
    assert not window.commands.menus["recent"].isEnabled()  # nothing opened yet
    path = tmp_path / "valve.prm"
    window.doc.set_value("DTAMP", 1000)
    monkeypatch.setattr(QFileDialog, "getSaveFileName", lambda *a, **k: (str(path)[:-4], ""))
    window.commands["save_as"].trigger()
    assert path.exists() and not window.doc.modified
    assert window.status.file_label.text() == "valve.prm"
    assert window.files.recent_files() == [str(path)]
    window.doc.set_value("DTAMP", 2000)
    window.commands["save"].trigger()
    assert prmfile.read_file(path).values["DTAMP"] == 2000
    window.files.new_document(TypeKey.parse(E02))
    monkeypatch.setattr(QFileDialog, "getOpenFileName", lambda *a, **k: (str(path), ""))
    window.commands["open"].trigger()
    assert window.doc.value("DTAMP") == 2000 and window.doc.path == path
    recent = window.commands.menus["recent"]
    assert [a.text() for a in recent.actions()] == ["&1 valve.prm"] and recent.isEnabled()


def test_opening_a_broken_file_reports_the_line_and_changes_nothing(window, tmp_path, answers):
    path = tmp_path / "broken.prm"
    path.write_text("format = prm9tool 1\ntype_key = PRM9-06.3Z11/30-24E02S02\nLIMTA = lots\n")
    window.doc.set_value("LIMTA", 2000)
    window.doc.mark_saved(None)
    assert not window.files.open_path(path)
    assert "broken.prm:3" in answers.asked[-1]
    assert window.doc.value("LIMTA") == 2000 and window.doc.path is None


def _factory_text(replaces: str, line: str) -> str:
    lines = prmfile.PrmContents.factory(TypeKey.parse(E02)).to_text().splitlines()
    return "\n".join(line if text.startswith(replaces) else text for text in lines) + "\n"


def test_a_broken_file_is_reported_in_the_program_language(window, tmp_path, answers):
    path = tmp_path / "broken.prm"
    text = _factory_text("LIMTA =", "LIMTA = lots")
    path.write_text(text, encoding="utf-8")
    lines = [line.split(" =")[0] for line in text.splitlines()]
    limta, checksum = lines.index("LIMTA") + 1, lines.index("checksum") + 1
    window.set_language("de")
    assert not window.files.open_path(path)
    assert answers.asked[-1] == (
        f"„broken.prm“ kann nicht geöffnet werden: broken.prm:{limta}: LIMTA: 'lots' ist keine "
        "Zahl\n1 weiteres Problem in den Details.\n"
        f"{path}:{limta}: LIMTA: 'lots' ist keine Zahl\n"
        f"{path}:{checksum}: Warnung: Prüfsumme stimmt nicht: Die Datei wurde außerhalb von "
        "prm9tool geändert (von Hand bearbeitet?); Speichern aus prm9tool schreibt eine neue "
        "Prüfsumme"
    )
    assert window.doc.path is None


def test_the_warnings_of_an_opened_file_are_shown_in_the_program_language(
    window, tmp_path, answers
):
    path = tmp_path / "edited.prm"
    path.write_text(_factory_text("LIMTA =", "LIMTA = 2000"), encoding="utf-8")
    window.set_language("cs")
    assert window.files.open_path(path)
    assert "edited.prm:" in answers.informed[-1]
    assert (
        ": varování: kontrolní součet nesouhlasí: soubor byl změněn mimo prm9tool"
        in (answers.informed[-1])
    )


def test_unsaved_prompt_on_close_save_keeps_window_on_cancel(window, answers):
    window.doc.set_value("LIMTA", 2000)
    answers.answers = [prompts.Button.Cancel]
    window.close()
    assert window.isVisible()
    answers.answers = [prompts.Button.Discard]
    window.close()
    assert not window.isVisible()


def test_drop_a_prm_file_opens_it(window, tmp_path):
    path = tmp_path / "dropped.prm"
    prmfile.write_file(prmfile.PrmContents.factory(TypeKey.parse(E04_CA)), path)
    mime = QMimeData()
    mime.setUrls([QUrl.fromLocalFile(str(path))])
    event = QDropEvent(
        QPointF(10, 10), Qt.DropAction.CopyAction, mime, Qt.MouseButton.LeftButton,
        Qt.KeyboardModifier.NoModifier,
    )  # fmt: skip
    window.dropEvent(event)
    assert window.doc.path == path and str(window.doc.type_key) == E04_CA


def test_undo_redo_every_edit(window):
    window.doc.set_value("LIMTA", 2000)
    window.doc.set_value("DTAMP", 1000)
    assert window.commands["undo"].isEnabled()
    window.commands["undo"].trigger()
    assert window.doc.value("DTAMP") != 1000 and window.doc.value("LIMTA") == 2000
    window.commands["undo"].trigger()
    assert window.doc.value("LIMTA") == 2400 and not window.doc.modified
    assert window.commands["redo"].isEnabled()
    window.commands["redo"].trigger()
    assert window.doc.value("LIMTA") == 2000


def _pdf_text_and_images(path) -> tuple[list[str], list[tuple[int, int]]]:
    """The words of a PDF and the (width, height) of its images."""
    from pypdf import PdfReader

    reader = PdfReader(path)
    words = " ".join(page.extract_text() for page in reader.pages).split()
    images = []
    for page in reader.pages:
        for ref in page["/Resources"].get("/XObject", {}).values():
            xobject = ref.get_object()
            if xobject.get("/Subtype") == "/Image":
                images.append((int(xobject["/Width"]), int(xobject["/Height"])))
    return words, images


def test_export_pdf_holds_the_parameters_and_the_diagram(window, tmp_path, monkeypatch):
    target = tmp_path / "record"
    window.doc.set_value("LIMTA", 1234)
    monkeypatch.setattr(QFileDialog, "getSaveFileName", lambda *a, **k: (str(target), ""))
    window.commands["export_pdf"].trigger()
    pdf = target.with_suffix(".pdf")
    assert pdf.read_bytes().startswith(b"%PDF")
    words, images = _pdf_text_and_images(pdf)
    for needle in (E02, "LIMTA", "1234", "mA", "DYNFREQ", "Basic", "untitled"):
        assert needle in words
    row = words[words.index("LIMTA") : words.index("LIMTB")]  # mnemonic, description, value, unit
    assert row[-2:] == ["1234", "mA"]
    assert any(width > 1000 and height > 300 for width, height in images)  # the diagram


def test_the_record_holds_the_diagram_picture(window):
    from PySide6.QtGui import QImage, QTextDocument

    from prm9tool.views.record.document import DIAGRAM_URL

    record = window.records.record()
    picture = record.resource(QTextDocument.ResourceType.ImageResource, QUrl(DIAGRAM_URL))
    assert isinstance(picture, QImage) and not picture.isNull()
    assert picture.width() > 1000 and picture.height() > 300
    assert DIAGRAM_URL in record.toHtml()
    colours = {picture.pixel(x, y) for x in range(0, picture.width(), 9) for y in range(0, 300, 9)}
    assert len(colours) > 8  # ink, not a blank page


def test_print_goes_through_the_print_dialog(window, tmp_path, monkeypatch):
    from PySide6.QtPrintSupport import QPrintDialog, QPrinter

    out = tmp_path / "printed.pdf"

    def accept(dialog):
        printer = dialog.printer()
        printer.setOutputFormat(QPrinter.OutputFormat.PdfFormat)
        printer.setOutputFileName(str(out))
        return Accepted

    monkeypatch.setattr(QPrintDialog, "exec", accept)
    window.commands["print"].trigger()
    assert out.exists() and out.stat().st_size > 10_000


def test_pdf_export_error_is_reported(window, answers, tmp_path):
    assert not window.records.export_pdf(tmp_path / "missing" / "dir" / "x.pdf")
    assert "Cannot write" in answers.asked[-1]


def test_last_folder_is_remembered(window, tmp_path, monkeypatch):
    folder = tmp_path / "records"
    folder.mkdir()
    seen = []

    def save_name(_parent, _title, suggestion, _filter):
        seen.append(suggestion)
        return (str(folder / "a.prm"), "")

    monkeypatch.setattr(QFileDialog, "getSaveFileName", save_name)
    window.commands["save_as"].trigger()
    window.files.new_document(TypeKey.parse(E04_CA))
    window.commands["save_as"].trigger()
    assert window.files.last_folder() == str(folder)
    assert seen[-1].startswith(str(folder))


def test_a_vanished_recent_file_is_removed_with_a_message(window, tmp_path, answers):
    path = tmp_path / "gone.prm"
    window.files.save_to(path)
    path.unlink()
    recent = window.commands.menus["recent"]
    recent.actions()[0].trigger()
    assert "no longer exists" in answers.informed[-1]
    assert window.files.recent_files() == [] and not recent.isEnabled()


def test_a_number_for_the_recent_files_in_the_settings_counts_as_none(window, tmp_path):
    from prm9tool.views.files.workflow import RECENT_KEY
    from prm9tool.views.hid_dialog import EMULATORS_KEY, saved_emulators

    window.settings.setValue(RECENT_KEY, 5)  # e.g. a hand-edited settings file
    window.settings.setValue(EMULATORS_KEY, 7)
    assert window.files.recent_files() == []
    assert saved_emulators(window.settings) == []
    path = tmp_path / "after.prm"
    window.files.save_to(path)
    assert window.files.recent_files() == [str(path)]


def test_unsaved_changes_prompt_on_open_can_cancel(window, answers):
    window.doc.set_value("LIMTA", 2000)
    answers.answers = [prompts.Button.Cancel]
    window.commands["open"].trigger()  # a file dialog would fail the test: it must not open
    assert "Unsaved changes" in answers.asked[-1]
    assert window.doc.value("LIMTA") == 2000 and window.doc.modified


def test_a_backup_copy_leaves_the_document_as_it_is(window, answers, tmp_path, monkeypatch):
    """Issue 25 item 8: a backup made with Save As became the working document, and Exit
    offered to save later edits into the backup. Save backup copy keeps the document."""
    work = tmp_path / "work.prm"
    window.files.save_to(work)
    window.doc.set_value("DTAMP", 1000)  # an unsaved change, kept in the copy
    suggested = []

    def save_name(_parent, _title, suggestion, _filter):
        suggested.append(suggestion)
        return str(tmp_path / "copy"), ""

    monkeypatch.setattr(QFileDialog, "getSaveFileName", save_name)
    assert window.commands["save_copy"] in window.commands.menus["file"].actions()
    window.commands["save_copy"].trigger()
    copy = tmp_path / "copy.prm"
    assert prmfile.read_file(copy).values["DTAMP"] == 1000
    assert window.doc.path == work and window.doc.modified  # still the working document
    assert prmfile.read_file(work).values["DTAMP"] != 1000
    assert window.files.recent_files() == [str(work)]  # the copy is not the document
    assert Path(suggested[0]).name.startswith(f"{str(window.doc.type_key).replace('/', '_')}_")
    window.doc.set_value("DTAMP", 2000)
    answers.answers = [prompts.Button.Save]
    window.close()
    assert "“work.prm”" in answers.asked[-1]
    assert prmfile.read_file(work).values["DTAMP"] == 2000
    assert prmfile.read_file(copy).values["DTAMP"] == 1000  # later edits never reach the copy


def test_the_next_backup_copy_is_proposed_in_the_folder_of_the_last(window, tmp_path, monkeypatch):
    folder = tmp_path / "backups"
    folder.mkdir()
    window.files.save_backup_copy(folder / "first.prm")
    seen = []
    monkeypatch.setattr(
        QFileDialog, "getSaveFileName", lambda _p, _t, where, _f: (seen.append(where), ("", ""))[1]
    )
    assert window.files.save_backup_copy() is None  # cancelled: nothing written
    assert Path(seen[0]).parent == folder and Path(seen[0]).suffix == ".prm"
    assert sorted(p.name for p in folder.iterdir()) == ["first.prm"]


def test_a_backup_copy_that_cannot_be_written_says_so_and_loses_nothing(window, answers, tmp_path):
    window.doc.set_value("DTAMP", 1000)
    target = tmp_path / "missing-folder" / "copy.prm"
    assert window.files.save_backup_copy(target) is None
    assert "Cannot save “copy.prm”" in answers.asked[-1]
    assert window.doc.value("DTAMP") == 1000 and window.doc.modified and window.doc.path is None


def test_after_a_download_the_status_bar_points_to_the_backup_copy(qtbot, window):
    """Issue 25 item 8: the backup workflow (Download from valve, then keep a copy) leads to
    Save backup copy, which leaves the document as it is."""
    from support.gui_support import go_online

    go_online(qtbot, window, f"{E02}:4730")
    qtbot.waitUntil(lambda: window.sync.active, timeout=10_000)
    with qtbot.waitSignal(window.connection.operation_finished, timeout=10_000):
        window.commands["download"].trigger()
    assert "File → Save backup copy… keeps a copy" in window.status.currentMessage()


def test_save_asks_for_a_name_when_the_file_is_of_another_valve_type(window, tmp_path, monkeypatch):
    """Issue 34 item 3: whatever made the document another valve type, Save does not write
    that type into the file of the old one."""
    path = tmp_path / "e02.prm"
    window.files.save_to(path)
    before = path.read_bytes()
    asked: list[str] = []
    monkeypatch.setattr(
        QFileDialog, "getSaveFileName", lambda _p, _t, where, _f: (asked.append(where), ("", ""))[1]
    )
    window.doc.set_type_key(E04_CA)
    assert not window.files.save()
    assert len(asked) == 1 and Path(asked[0]).parent == tmp_path and asked[0] != str(path)
    assert path.read_bytes() == before
    window.undo.stack.undo()  # the file's type again: Save writes into it as usual
    window.doc.set_value("LIMTA", 2000)
    assert window.files.save() and len(asked) == 1
    assert prmfile.read_file(path).values["LIMTA"] == 2000

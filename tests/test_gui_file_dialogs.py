"""The file dialogs show the files' dates in the program language (issue 34, item 20: Qt's
dialog wrote them with the system locale, "1 12 2026 21:24" under LANG=C, in every language)."""

from __future__ import annotations

import pytest
from PySide6.QtCore import QDateTime, QLocale, QTimer
from PySide6.QtWidgets import (
    QApplication,
    QFileDialog,
    QFileSystemModel,
    QStyleOptionViewItem,
    QTreeView,
)

from prm9tool import i18n
from prm9tool.views.files import dialogs as file_dialogs


def _date_shown(qtbot, folder, file) -> dict[str, str]:
    """Open the program's file dialog on ``folder``; what its detail view shows as the date of
    ``file`` (and what Qt's own model says)."""
    seen: dict[str, str] = {}

    def look() -> None:
        dialog = QApplication.activeModalWidget()
        assert isinstance(dialog, QFileDialog)
        model = dialog.findChild(QFileSystemModel)
        view = dialog.findChild(QTreeView)
        qtbot.waitUntil(lambda: model.index(str(file)).isValid(), timeout=5000)
        index = model.index(str(file)).siblingAtColumn(file_dialogs.DATE_COLUMN)
        option = QStyleOptionViewItem()
        view.itemDelegateForColumn(file_dialogs.DATE_COLUMN).initStyleOption(option, index)
        seen.update(shown=option.text, model=str(index.data()))
        dialog.reject()

    QTimer.singleShot(0, look)
    file_dialogs.open_file_name(
        None, "Open", str(folder), "*.prm", options=QFileDialog.Option.DontUseNativeDialog
    )
    return seen


@pytest.mark.parametrize("language", ["en", "de", "cs"])
def test_the_file_dialog_shows_dates_in_the_program_language(qtbot, tmp_path, language):
    file = tmp_path / "valve.prm"
    file.write_text("x", encoding="utf-8")
    i18n.set_language(language)
    try:
        seen = _date_shown(qtbot, tmp_path, file)
    finally:
        i18n.set_language("en")
    modified = QDateTime.fromSecsSinceEpoch(int(file.stat().st_mtime))
    expected = QLocale(language).toString(modified, QLocale.FormatType.ShortFormat)
    assert seen["shown"] == expected
    if language != "en":
        assert "." in seen["shown"]  # "01.12.26 21:24", not "1 12 2026 21:24"


def test_no_filter_is_left_on_the_application(qtbot, tmp_path):
    with file_dialogs.dates_in_program_language():
        pass
    dialog = QFileDialog(None, "x", str(tmp_path))
    dialog.setOption(QFileDialog.Option.DontUseNativeDialog)
    qtbot.addWidget(dialog)
    dialog.show()
    view = dialog.findChild(QTreeView)
    assert not isinstance(
        view.itemDelegateForColumn(file_dialogs.DATE_COLUMN), file_dialogs.DateDelegate
    )


def test_a_bare_file_name_is_suggested_in_the_home_folder(monkeypatch, tmp_path):
    """A new user at a real screen: Save the test report and Record… opened in the folder
    prm9tool was started from (the program's own source tree there), not in the home folder
    as Save does; a bare name or none now starts in the home folder, a path is kept."""
    from pathlib import Path

    home = tmp_path / "home"
    monkeypatch.setattr(Path, "home", classmethod(lambda cls: home))
    asked: list[str] = []

    def fake(_parent, _caption, folder="", _filter="", *args, **kwargs):
        asked.append(folder)
        return "", ""

    monkeypatch.setattr(QFileDialog, "getSaveFileName", fake)
    monkeypatch.setattr(QFileDialog, "getOpenFileName", fake)
    file_dialogs.save_file_name(None, "Save the test report", "1001-report.pdf", "PDF (*.pdf)")
    file_dialogs.open_file_name(None, "Open a trace", "", "*.asc")
    file_dialogs.save_file_name(None, "Save", str(tmp_path / "kept.prm"), "*.prm")
    assert asked == [str(home / "1001-report.pdf"), str(home), str(tmp_path / "kept.prm")]


def test_record_suggests_its_trace_in_the_home_folder(monkeypatch, qtbot, tmp_path):
    from pathlib import Path

    from prm9tool.online.trace_recording import BusRecording
    from prm9tool.views.trace.record_controls import RecordControls

    home = tmp_path / "home"
    monkeypatch.setattr(Path, "home", classmethod(lambda cls: home))
    asked: list[str] = []
    monkeypatch.setattr(
        QFileDialog,
        "getSaveFileName",
        lambda _p, _c, folder, *a, **k: asked.append(folder) or ("", ""),
    )
    controls = RecordControls(BusRecording(), dict)
    qtbot.addWidget(controls)
    controls.record.click()
    assert asked == [str(home / "trace.asc")]

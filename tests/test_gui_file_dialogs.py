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

"""Help (issue 25 item 15): a page per topic in every language, linked from the main page,
and F1 in a window opening the page about it."""

from __future__ import annotations

import pytest
from PySide6.QtCore import QFile, QIODevice, Qt
from support.gui_support import E02

from prm9tool import i18n
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.compare import Comparison, Side
from prm9tool.views.compare.view import CompareDialog
from prm9tool.views.help_dialog import TOPICS, help_file, help_window

LANGUAGES = ("en", "de", "cs")


def _page(path: str) -> str:
    file = QFile(path)
    assert file.open(QIODevice.OpenModeFlag.ReadOnly), path
    return bytes(file.readAll().data()).decode("utf-8")


@pytest.mark.parametrize("language", LANGUAGES)
def test_every_topic_has_a_page_in_every_language_linked_from_the_main_page(language):
    main = _page(help_file(language))
    for topic in TOPICS[1:]:
        page = help_file(language, topic)
        assert page.endswith(f"{topic}_{language}.html"), page  # not the English fallback
        assert f'href="{topic}_{language}.html"' in main
        assert f'href="help_{language}.html"' in _page(page)  # and back


def test_the_pages_name_what_the_user_looks_for():
    assert "NMT start" in _page(help_file("en", "can"))
    assert "Write … ticked values into the" in _page(help_file("en", "compare"))
    assert "What was done" in _page(help_file("en", "history"))
    assert "Accept the" in _page(help_file("en", "tuning"))


@pytest.mark.parametrize("language", ["en", "de"])
def test_f1_in_the_compare_view_opens_its_help_page(qtbot, language):
    i18n.set_language(language)
    try:
        side = Side.factory(TypeKey.parse(E02), "A")
        dialog = CompareDialog(Comparison((side, side)), (0, 1))
        qtbot.addWidget(dialog)
        dialog.show()
        with qtbot.waitActive(dialog):
            dialog.activateWindow()
        dialog.table.setFocus()
        qtbot.keyClick(dialog.table, Qt.Key.Key_F1)
        window = help_window(dialog)
        qtbot.addWidget(window)
        assert window.isVisible() and window.topic == "compare"
        assert window.browser.source().toString().endswith(f"compare_{language}.html")
    finally:
        i18n.set_language("en")


def test_the_help_window_belongs_to_the_main_window_not_to_the_dialog(qtbot, window, monkeypatch):
    """A dialog closed (and deleted) must not take the help window it opened with it."""
    from prm9tool.views import help_dialog
    from prm9tool.views.help_dialog import show_help

    monkeypatch.setattr(help_dialog, "_HELP", [])  # not the help window of an earlier test
    side = Side.factory(TypeKey.parse(E02), "A")
    dialog = CompareDialog(Comparison((side, side)), (0, 1), parent=window)
    help_page = show_help(dialog, "compare")
    assert help_page.parentWidget() is window
    dialog.deleteLater()
    qtbot.wait(10)
    assert help_page.isVisible()

"""Valve selection's type-key builder driven through its widgets, as a user drives it.

The older tests set the key with ``_show_key`` or a typed key and so never went through the
combo boxes: ``QComboBox.currentData()`` hands an enum stored as item data back as ``str``,
and the key built from it failed when it was formatted (issue 14, item 1).
"""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt
from support.gui_support import E02, E02_CA, main_window

from prm9tool.catalogue.typekey import TypeKey
from prm9tool.catalogue.variant import Config
from prm9tool.views import prompts
from prm9tool.views.valve.selection import ValveSelectionDialog

Accepted = ValveSelectionDialog.DialogCode.Accepted


@pytest.fixture
def window(qtbot, tmp_path, answers):
    with main_window(qtbot, tmp_path, E02_CA) as win:
        yield win


def test_every_part_changed_in_the_builder_updates_the_type_key(window):
    dialog = ValveSelectionDialog(TypeKey.parse(E02_CA), window)
    dialog.canopen.setChecked(False)
    assert dialog.key_edit.text() == E02
    dialog.config.setCurrentIndex(1)
    assert dialog.key_edit.text() == "PRM9-06.3Z11/30-24E04S02"
    dialog.nominal_size.setCurrentIndex(dialog.nominal_size.findData("10"))
    assert dialog.key_edit.text() == "PRM9-10.3Z11/30-24E04S02"
    assert dialog.selected_type_key().config is Config.E04
    assert dialog.buttons.button(dialog.buttons.StandardButton.Ok).isEnabled()


def test_a_type_key_refuses_a_configuration_that_is_not_a_config():
    with pytest.raises(TypeError, match="Config"):
        TypeKey("06", "3Z11", "30", "24", "E02", False)  # type: ignore[arg-type]


def test_add_emulated_valve_takes_the_parts_chosen(window):
    from prm9tool.views.hid_dialog import EmulatorDialog

    dialog = EmulatorDialog(window)
    dialog.selection.config.setCurrentIndex(1)
    dialog.selection.canopen.setChecked(False)
    assert dialog.spec().startswith("PRM9-06.3Z11/30-24E04S02:")


def test_valve_selection_from_an_edited_file_replaces_it_whole(window, answers, tmp_path,
                                                              monkeypatch):  # fmt: skip
    window.files.save_to(tmp_path / "edited.prm")
    window.doc.set_value("LIMTA", 2000)

    def untick_canopen(dialog):
        dialog.canopen.setChecked(False)
        return Accepted

    monkeypatch.setattr(ValveSelectionDialog, "exec", untick_canopen)
    answers.answers = [prompts.Button.Discard]
    assert window.commands["valve_selection"].trigger() is None
    assert str(window.doc.type_key) == E02 and window.doc.value("LIMTA") == 2400
    assert not window.doc.modified and not window.isWindowModified()
    assert window.status.type_key_label.text() == E02
    assert "*" not in window.status.file_label.text()
    window.doc.set_value("LIMTA", 2100)
    answers.answers = [prompts.Button.Cancel]
    assert not window.close()  # quitting asks about the edit, and Cancel keeps the window
    assert "Unsaved changes" in answers.asked[-1]
    assert window.doc.value("LIMTA") == 2100


def test_an_exception_in_a_slot_is_shown_not_swallowed(window, answers):
    from prm9tool.app import show_internal_error

    try:
        raise AttributeError("'str' object has no attribute 'value'")
    except AttributeError as exc:
        show_internal_error(window, type(exc), exc, exc.__traceback__)
    assert "Internal error" in answers.informed[-1]
    assert "'str' object has no attribute 'value'" in answers.informed[-1]
    assert window.isVisible() and Qt.WindowType.Window & window.windowFlags()

"""The parameter list: rows by variant and access level, highlighting, search, edit dialog."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt
from support.gui_support import E02, E04_CA

from prm9tool.catalogue import Access
from prm9tool.model.access import AccessModel
from prm9tool.model.document import ParameterDocument
from prm9tool.model.undo import DocumentUndo
from prm9tool.views.parameters.dialog import ParameterEditDialog
from prm9tool.views.parameters.model import MNEMONIC_ROLE, Column
from prm9tool.views.parameters.view import ParameterListView


@pytest.fixture
def doc(qapp):
    return ParameterDocument(E02)


@pytest.fixture
def access(qapp):
    return AccessModel()


@pytest.fixture
def view(qtbot, doc, access):
    widget = ParameterListView(doc, access)
    qtbot.addWidget(widget)
    return widget


def _shown(view):
    proxy = view.proxy
    return [proxy.data(proxy.index(row, 0), MNEMONIC_ROLE) for row in range(proxy.rowCount())]


def _cell(view, mnemonic, column):
    model = view.model
    return model.data(model.index(model.row_of(mnemonic), column))


def test_basic_level_shows_the_manuals_basic_list_without_controllers(view):
    shown = _shown(view)
    for mnemonic in ("PCODE", "SNV", "ERROR", "PWR", "AINSETP", "THRESETP", "LIMTA", "DTAMP"):
        assert mnemonic in shown
    assert "POSKP" not in shown and "SETPLINXA" not in shown


def test_expert_level_adds_controllers_and_linearization(view, access):
    access.set_level(Access.EXPERT)
    shown = _shown(view)
    assert {"POSKP", "POSKI", "SETPLINXA", "SETPLINON"} <= set(shown)
    assert "PRCKP" not in shown  # E02 has no process controller


def test_rows_follow_the_variant(view, doc, access):
    access.set_level(Access.EXPERT)
    doc.set_type_key(E04_CA)
    shown = _shown(view)
    assert {"PRCKP", "SENSTYPE", "NODEID"} <= set(shown)


def test_cells_show_value_unit_and_translated_choice(view):
    assert _cell(view, "LIMTA", Column.VALUE) == "2400"
    assert _cell(view, "LIMTA", Column.UNIT) == "mA"
    assert _cell(view, "AINSETP", Column.VALUE) == "9: ±10 V bipolar"
    assert _cell(view, "PCODE", Column.VALUE) == E02
    assert _cell(view, "PWR", Column.VALUE) == "—"  # never read from a valve


def test_non_default_values_are_highlighted_and_filtered(view, doc):
    model = view.model
    index = model.index(model.row_of("LIMTA"), Column.VALUE)
    assert model.data(index, Qt.ItemDataRole.BackgroundRole) is None
    doc.set_value("LIMTA", 2000)
    assert model.data(index, Qt.ItemDataRole.BackgroundRole) is not None
    assert model.data(index, Qt.ItemDataRole.FontRole).bold()
    view.modified_only.setChecked(True)
    assert _shown(view) == ["LIMTA"]
    doc.set_value("DTAMP", 1000)
    assert _shown(view) == ["LIMTA", "DTAMP"]


def test_search_matches_mnemonic_and_description(view):
    view.search.setText("dither")
    assert set(_shown(view)) == {"DTAMP", "DYNFREQ"}
    view.search.setText("limta")
    assert _shown(view) == ["LIMTA"]


def test_live_values_refresh_the_table(view, doc):
    doc.set_live({"PWR": 23950, "TEMP": 41})
    assert _cell(view, "PWR", Column.VALUE) == "23.95"
    assert _cell(view, "TEMP", Column.VALUE) == "41.0"  # the measured-value rule (format_measured)


def test_a_current_limit_shows_the_range_the_valve_accepts(view, doc):
    dialog = view.make_edit_dialog("LIMTA")
    assert dialog._labels["range"].text() == "0 … 2600 mA (CURNORM)"  # not the 4000 of its type
    doc.set_live({"CURNORM": 2000})  # a valve with a smaller coil
    dialog.retranslate()
    assert dialog._labels["range"].text() == "0 … 2000 mA (CURNORM)"


def test_edit_dialog_shows_limits_and_default_and_sets_the_value(view, doc):
    dialog = view.make_edit_dialog("DTAMP")
    assert dialog._labels["range"].text() == "0 … 100 %"
    assert dialog._labels["default"].text() == "15 %"
    dialog.set_text("20")
    dialog._buttons.accepted.emit()
    assert dialog.result() == dialog.DialogCode.Accepted
    assert doc.display("DTAMP") == "20"


def test_a_value_finer_than_the_resolution_is_set_rounded_and_the_status_bar_says_so(
    view, doc, qtbot
):
    dialog = view.make_edit_dialog("LIMTB")
    dialog.set_text("2100.7")
    with qtbot.waitSignal(view.message_posted) as posted:
        dialog._buttons.accepted.emit()
    assert dialog.result() == dialog.DialogCode.Accepted
    assert doc.value("LIMTB") == 2101
    assert posted.args == ["2100.7 mA rounded to 2101 mA (resolution 1 mA)"]


def test_an_exact_value_posts_no_rounding_note(view, doc, qtbot):
    dialog = view.make_edit_dialog("LIMTB")
    dialog.set_text("2100")
    with qtbot.assertNotEmitted(view.message_posted):
        dialog._buttons.accepted.emit()
    assert doc.value("LIMTB") == 2100


@pytest.mark.parametrize(
    ("mnemonic", "text", "reason"),
    [
        ("DYNFREQ", "70000", "DYNFREQ: 70000 Hz is outside the allowed range"),
        ("LIMTA", "3500", "CURNORM"),
        ("DTAMP", "a lot", "DTAMP: “a lot” is not a number"),
    ],
)
def test_edit_dialog_refuses_invalid_values_with_the_reason(view, doc, mnemonic, text, reason):
    before = doc.value(mnemonic)
    dialog = view.make_edit_dialog(mnemonic)
    dialog.set_text(text)
    dialog._buttons.accepted.emit()
    assert reason in dialog.error_label.text().replace("\xa0", " ")
    assert not dialog.error_label.isHidden()
    assert dialog.result() != dialog.DialogCode.Accepted
    assert doc.value(mnemonic) == before and not doc.modified


def test_read_only_parameters_open_without_an_input(view):
    dialog = view.make_edit_dialog("PWR")
    assert not dialog._editor.isEnabled()
    assert "Read-only" in dialog._labels["hint"].text()


def test_at_basic_level_one_ramp_edit_sets_all_four_as_one_undo_step(view, doc, access):
    undo = DocumentUndo(doc)
    dialog = view.make_edit_dialog("RAMPSETNEGUP")
    assert "all ramps are set together" in dialog._labels["hint"].text()
    dialog.set_text("250")
    dialog._buttons.accepted.emit()
    ramps = ("RAMPSETPOSUP", "RAMPSETPOSDOWN", "RAMPSETNEGUP", "RAMPSETNEGDOWN")
    assert [doc.value(mn) for mn in ramps] == [250] * 4
    assert undo.stack.count() == 1
    undo.stack.undo()
    assert [doc.value(mn) for mn in ramps] == [0] * 4
    access.set_level(Access.EXPERT)
    dialog = view.make_edit_dialog("RAMPSETNEGUP")
    dialog.set_text("300")
    dialog._buttons.accepted.emit()
    assert [doc.value(mn) for mn in ramps] == [0, 0, 300, 0]


def test_double_click_opens_one_edit_dialog(view, qtbot):
    # A real double-click: emitting doubleClicked alone (as this test once did) never showed
    # that activated, emitted by the same double-click, opened a second, stale dialog.
    opened = []
    view.edit_requested.connect(opened.append)
    view.show()
    qtbot.waitExposed(view)
    index = view.proxy.mapFromSource(view.model.index(view.model.row_of("LIMTB"), 1))
    view.table.scrollTo(index)
    centre = view.table.visualRect(index).center()
    qtbot.mouseClick(view.table.viewport(), Qt.MouseButton.LeftButton, pos=centre)
    qtbot.mouseDClick(view.table.viewport(), Qt.MouseButton.LeftButton, pos=centre)  # press 2
    assert opened == ["LIMTB"]
    dialogs = [w for w in view.findChildren(ParameterEditDialog) if w.isVisible()]
    assert len(dialogs) == 1 and dialogs[0].param.mnemonic == "LIMTB"
    view.table.activated.emit(index)  # Enter on the row while the dialog is open
    assert opened == ["LIMTB"]
    dialogs[0].reject()


def test_measured_values_follow_one_rule_in_the_list_and_the_diagram(view, doc):
    from prm9tool.views.diagram import format_signal

    doc.set_live({"PWR": 24000, "TEMP": 25})
    model = view.model
    shown = {mn: model.data(model.index(model.row_of(mn), Column.VALUE)) for mn in ("PWR", "TEMP")}
    assert shown == {"PWR": "24.00", "TEMP": "25.0"}  # was "24" and "25"
    assert format_signal("supply_voltage", 24000) == "24.00 V"
    assert format_signal("temperature", 250) == "25.0 °C"


def test_the_main_window_status_bar_says_a_value_was_rounded(qtbot, tmp_path):
    import os

    from support.gui_support import main_window

    with main_window(qtbot, tmp_path) as window:
        dialog = window.parameter_view.make_edit_dialog("LIMTB")
        dialog.set_text("2100.7")
        dialog._buttons.accepted.emit()
        assert window.doc.value("LIMTB") == 2101
        assert window.status.currentMessage() == ("2100.7 mA rounded to 2101 mA (resolution 1 mA)")
        if os.environ.get("PRM9TOOL_SCREENSHOTS"):
            window.resize(1024, 700)
            window.grab().save(os.path.join(os.environ["PRM9TOOL_SCREENSHOTS"], "rounded.png"))
        window.doc.mark_saved(None)  # closing asks nothing


def test_a_value_shown_as_typed_posts_no_rounding_note_and_a_note_gives_the_real_step(
    view, doc, qtbot
):
    """Issue 34, item 15: "7 % rounded to 7 % (resolution 0.006 %)" — DTAMP's step is
    100/16384 % = 0.0061 %: 7 % is stored as 7.0007 %, which every view shows as 7 %."""
    posted: list[str] = []
    view.message_posted.connect(posted.append)
    dialog = view.make_edit_dialog("DTAMP")
    dialog.set_text("7")
    dialog._buttons.accepted.emit()
    assert doc.display("DTAMP") == "7" and posted == []
    dialog = view.make_edit_dialog("DTAMP")
    dialog.set_text("7.003")
    dialog._buttons.accepted.emit()
    assert posted == ["7.003 % rounded to 7 % (resolution 0.0061 %)"]


@pytest.mark.parametrize("language", ["en", "de", "cs"])
def test_the_edit_dialog_is_wide_enough_for_its_title(view, qtbot, language):
    """Issue 34, item 20: the title showed as "Paramete… SETPOSUP" (the window manager elides
    a title longer than the dialog, which was as narrow as its form)."""
    from PySide6.QtGui import QFont, QFontMetrics

    from prm9tool import i18n

    i18n.set_language(language)
    try:
        dialog = view.make_edit_dialog("RAMPSETPOSUP")
        qtbot.addWidget(dialog)
        dialog.show()
        bold = QFont(dialog.font())
        bold.setBold(True)
        title = dialog.windowTitle()
        assert "RAMPSETPOSUP" in title
        assert dialog.width() >= QFontMetrics(bold).horizontalAdvance(title) + 120
    finally:
        i18n.set_language("en")


def test_the_columns_keep_their_width_when_a_search_leaves_the_list_empty(view, qtbot):
    """Issue 34, item 20: the mnemonic, value and unit columns collapsed to their headers."""
    from prm9tool.views.parameters.model import Column

    view.resize(900, 500)
    view.show()
    header = view.table.horizontalHeader()
    columns = (Column.MNEMONIC, Column.VALUE, Column.UNIT)
    before = [header.sectionSize(c) for c in columns]
    view.search.setText("no parameter is called so")
    assert view.proxy.rowCount() == 0
    qtbot.wait(20)
    assert [header.sectionSize(c) for c in columns] == before
    view.search.setText("LIMT")  # a few rows: as wide as with all of them
    assert [header.sectionSize(c) for c in columns] == before

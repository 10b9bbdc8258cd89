"""Numbers in the program language: ``9,766 %`` shown and ``0,4`` typed in German and Czech,
while files keep the point (issue 14, item 14)."""

from __future__ import annotations

import pytest
from PySide6.QtCore import QLocale
from support.gui_support import E02, E04_CA

from prm9tool import i18n
from prm9tool.catalogue import CATALOGUE, Access
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.errors import ValueRangeError
from prm9tool.files import prmdocument, prmfile
from prm9tool.messages import DECIMAL_POINT
from prm9tool.model.access import AccessModel
from prm9tool.model.document import ParameterDocument
from prm9tool.model.undo import DocumentUndo
from prm9tool.translate import error_text
from prm9tool.views.diagram.dialogs import BlockContext, create_block_dialog
from prm9tool.views.diagram.summary import block_lines
from prm9tool.views.diagram.view import format_signal
from prm9tool.views.localized_axis import LocalizedAxis
from prm9tool.views.online_dialogs import OnlineDiffDialog
from prm9tool.views.parameters.model import Column
from prm9tool.views.parameters.view import ParameterListView
from prm9tool.views.record.document import record_rows

COMMA = ["de", "cs"]


@pytest.fixture
def language(qapp):
    """Switch the program language; English again afterwards."""
    yield i18n.set_language
    i18n.set_language("en")


@pytest.mark.parametrize("lang", i18n.LANGUAGES)
def test_the_decimal_separator_of_each_language_is_qlocales(qapp, lang):
    assert DECIMAL_POINT[lang] == QLocale(lang).decimalPoint()


@pytest.mark.parametrize("lang", COMMA)
def test_the_parameter_list_and_its_dialog_show_decimal_commas(qtbot, language, lang):
    language(lang)
    doc, access = ParameterDocument(E04_CA), AccessModel(Access.EXPERT)
    view = ParameterListView(doc, access)
    qtbot.addWidget(view)
    model = view.model
    assert model.data(model.index(model.row_of("MONTHRES"), Column.VALUE)) == "9,766"
    assert model.data(model.index(model.row_of("POSKP"), Column.VALUE)) == "0,4"
    dialog = view.make_edit_dialog("MONTHRES")
    assert dialog._labels["current"].text() == "9,766 %"
    assert dialog._labels["default"].text() == "9,766 %"
    assert dialog._editor.text() == "9,766"


@pytest.mark.parametrize("lang", COMMA)
@pytest.mark.parametrize("typed", ["0,5", "0.5"])
def test_the_parameter_dialog_takes_a_decimal_comma_and_the_file_keeps_the_point(
    qtbot, tmp_path, language, lang, typed
):
    language(lang)
    doc, access = ParameterDocument(E04_CA), AccessModel(Access.EXPERT)
    view = ParameterListView(doc, access)
    qtbot.addWidget(view)
    dialog = view.make_edit_dialog("POSKP")
    dialog.set_text(typed)
    dialog._buttons.accepted.emit()
    assert dialog.result() == dialog.DialogCode.Accepted and doc.value("POSKP") == 50
    path = tmp_path / "valve.prm"
    prmdocument.save_document(doc, path)
    text = path.read_text(encoding="utf-8")
    assert "\nPOSKP = 0.5  #" in text and "\nMONTHRES = 9.766  #" in text
    assert prmfile.read_file(path).values["POSKP"] == 50


def test_a_number_that_may_hold_a_thousands_separator_is_refused_not_guessed(qtbot, language):
    language("de")
    doc, access = ParameterDocument(E02), AccessModel()
    view = ParameterListView(doc, access)
    qtbot.addWidget(view)
    dialog = view.make_edit_dialog("LIMTA")
    dialog.set_text("2.400")  # 2400 mA to a German reader, 2.4 mA in a file
    dialog._buttons.accepted.emit()
    assert dialog.result() != dialog.DialogCode.Accepted
    assert dialog.error_label.text().startswith("LIMTA: '2.400' ist mehrdeutig")
    assert doc.value("LIMTA") == 2400 and not doc.modified


@pytest.mark.parametrize("lang", COMMA)
def test_block_dialogs_show_and_take_decimal_commas(qtbot, language, lang):
    language(lang)
    doc = ParameterDocument(E04_CA)
    ctx = BlockContext(doc, AccessModel(Access.EXPERT), None, None)
    dialog = create_block_dialog("position_controller", ctx, "position_controller")
    qtbot.addWidget(dialog)
    field = dialog.gain_fields["POSKP"]
    assert field.text() == "0,4"
    field.setText("0,7")
    field.editingFinished.emit()
    assert doc.value("POSKP") == 70


@pytest.mark.parametrize("lang", COMMA)
def test_the_diagram_shows_decimal_commas(qapp, language, lang):
    language(lang)
    doc = ParameterDocument(E04_CA)
    assert block_lines(doc, "position_controller")[0].startswith("Kp 0,4 ")


def test_measuring_point_values_in_the_diagram_use_the_language(qapp, language):
    from prm9tool.catalogue.signals import BY_KEY

    key = next(k for k, s in BY_KEY.items() if s.unit == "%")
    english = format_signal(key, 1000.0)
    language("cs")
    czech = format_signal(key, 1000.0)
    assert "." in english and czech == english.replace(".", ",")


def test_scope_axes_readouts_and_the_printed_record_use_the_language(qapp, language):
    axis = LocalizedAxis("left")
    assert axis.tickStrings([0.5, 1.0, 1.5], 1.0, 0.5) == ["0.5", "1.0", "1.5"]
    language("de")
    assert axis.tickStrings([0.5, 1.0, 1.5], 1.0, 0.5) == ["0,5", "1,0", "1,5"]
    rows = {row[0]: row[2] for row in record_rows(ParameterDocument(E04_CA))}
    assert rows["MONTHRES"] == "9,766" and rows["POSKP"] == "0,4"
    assert i18n.format_number(25.24, 1) == "25,2" and i18n.format_number(-0.01, 1) == "0,0"
    assert i18n.format_significant(0.0125, 3) == "0,0125"


def test_the_differences_dialog_and_range_messages_use_the_language(qtbot, language):
    language("cs")
    dialog = OnlineDiffDialog({"POSKP": 40}, {"POSKP": 55}, E02, E02)
    qtbot.addWidget(dialog)
    assert [dialog.table.item(0, c).text() for c in (2, 3)] == ["0,4", "0,55"]
    with pytest.raises(ValueRangeError) as refused:
        CATALOGUE["POSKP"].check_raw(70000)
    shown = error_text(refused.value)
    assert shown == "POSKP: 700 je mimo přípustný rozsah 0 … 655,35"
    assert str(refused.value).endswith("700 is outside the allowed range 0 … 655.35")  # English


def test_an_undo_label_shows_the_value_in_the_language(qapp, language):
    language("de")
    doc = ParameterDocument(E04_CA)
    undo = DocumentUndo(doc, doc)
    doc.set_value("POSKP", 55)
    assert undo.stack.undoText() == "POSKP = 0,55"


def test_spin_boxes_of_open_windows_follow_a_change_of_language(qtbot, tmp_path, monkeypatch):
    from PySide6.QtWidgets import QDoubleSpinBox
    from support.gui_support import main_window, record_prompts

    record_prompts(monkeypatch)
    with main_window(qtbot, tmp_path) as window:
        box = QDoubleSpinBox(window)
        box.setDecimals(2)
        box.setValue(1.5)
        window.set_language("de")
        assert box.text() == "1,50"
        window.set_language("en")
        assert box.text() == "1.50"


def test_live_values_in_the_diagram_are_shown_again_in_a_new_language(qtbot, language):
    from support.diagram_fakes import EmulatorConnection

    from prm9tool.device.emulator import EmulatedValve
    from prm9tool.views.diagram.view import DiagramView

    valve = EmulatedValve(E02)
    valve.advance(2.0)
    valve.set_input("setpoint", 5.0)
    valve.advance(0.3)
    link = EmulatorConnection(valve)
    view = DiagramView(ParameterDocument(E02), AccessModel(), link)
    qtbot.addWidget(view)
    link.go_online()
    link.poll_signals()
    demand = view.diagram.dots["demand"]
    assert demand.value_text == "50.0 %"
    language("de")  # no new values from the valve meanwhile
    assert demand.value_text == "50,0 %"


def test_files_written_in_german_keep_the_point(qapp, language):
    import io

    import numpy as np

    from prm9tool.catalogue.signals import BY_KEY
    from prm9tool.scope.readout import write_csv

    language("de")
    out = io.StringIO()
    write_csv(out, np.array([0.0, 0.0002]), np.array([[12.5], [-0.25]]), [BY_KEY["demand"]])
    assert out.getvalue().splitlines()[1:] == ["0.000000,12.5", "0.000200,-0.25"]
    text = prmfile.PrmContents.factory(TypeKey.parse(E04_CA)).to_text()
    assert "\nMONTHRES = 9.766  #" in text and "\nPOSKP = 0.4  #" in text


def test_a_decimal_comma_in_the_english_program_is_an_error_in_words(qtbot, language):
    """Issue 34 item 17: "1,5" was taken as 1.5 in the English program."""
    doc, access = ParameterDocument(E04_CA), AccessModel(Access.EXPERT)
    view = ParameterListView(doc, access)
    qtbot.addWidget(view)
    dialog = view.make_edit_dialog("POSKP")
    dialog.set_text("1,5")
    dialog._buttons.accepted.emit()
    assert dialog.result() != dialog.DialogCode.Accepted
    assert dialog.error_label.text() == (
        "POSKP: '1,5' is not a number: the decimals follow a point (1.5)"
    )
    assert doc.value("POSKP") == 40 and not doc.modified
    ctx = BlockContext(doc, access, None, None)
    block = create_block_dialog("position_controller", ctx, "position_controller")
    qtbot.addWidget(block)
    field = block.gain_fields["POSKP"]
    field.setText("1,5")
    field.editingFinished.emit()
    assert doc.value("POSKP") == 40
    with pytest.raises(ValueRangeError, match="the decimals follow a point"):
        i18n.parse_value(CATALOGUE["POSKP"], "1,5")
    language("de")  # the German program writes the comma, and takes the point too
    assert i18n.parse_value(CATALOGUE["POSKP"], "1,5") == 150
    assert i18n.parse_value(CATALOGUE["POSKP"], "1.5") == 150


def test_a_decimal_comma_in_a_file_is_an_error_with_its_line(qapp, language):
    """Issue 34 item 17: ``POSKP = 0,9`` read as 0.9 with only the checksum warning."""
    language("de")  # the file format is the same in every program language
    text = prmfile.PrmContents.factory(TypeKey.parse(E04_CA)).to_text()
    lines = text.splitlines()
    number = next(i for i, line in enumerate(lines, 1) if line.startswith("POSKP ="))
    lines[number - 1] = "POSKP = 0,9"
    result = prmfile.check_bytes(("\n".join(lines) + "\n").encode())
    assert result.contents is None
    assert [(p.line, p.message) for p in result.errors] == [
        (number, "POSKP: '0,9' is not a number: the decimals follow a point (0.9)")
    ]


@pytest.mark.parametrize(
    ("value", "digits", "shown"),
    [(4999.0, 3, "5000"), (123456.0, 3, "123000"), (0.000012345, 3, "1.23e-05"), (2.5, 3, "2.5")],
)
def test_significant_digits_are_written_out_for_large_numbers(language, value, digits, shown):
    language("en")
    assert i18n.format_significant(value, digits) == shown

"""Messages of the model layer (refusals, type-key errors, lock reasons, undo texts) in German
and Czech when the program runs in that language; English again after switching back."""

from __future__ import annotations

import json
from dataclasses import dataclass

import pytest
from support.gui_support import E02, settings_in

from prm9tool import i18n
from prm9tool.catalogue import CATALOGUE
from prm9tool.model.access import AccessModel
from prm9tool.model.document import ParameterDocument
from prm9tool.model.editing import apply_edit
from prm9tool.model.undo import DocumentUndo
from prm9tool.views.hid_dialog import HidConfigurationDialog
from prm9tool.views.parameters.view import ParameterListView
from prm9tool.views.valve.selection import ValveSelectionDialog


@pytest.fixture
def language(qapp):
    """Switch the program language for one test; English again afterwards."""
    yield i18n.set_language
    i18n.set_language("en")


@pytest.fixture
def doc(qapp):
    return ParameterDocument(E02)


def _refusal(qtbot, doc, mnemonic: str, entered: str):
    view = ParameterListView(doc, AccessModel())
    qtbot.addWidget(view)
    dialog = view.make_edit_dialog(mnemonic)
    qtbot.addWidget(dialog)
    dialog.set_text(entered)
    dialog._buttons.accepted.emit()
    assert not dialog.error_label.isHidden()
    return dialog


def test_parameter_dialog_refuses_limta_above_curnorm_in_german(qtbot, doc, language):
    language("de")
    dialog = _refusal(qtbot, doc, "LIMTA", "2650")
    assert dialog.error_label.text().replace("\xa0", " ") == (
        "LIMTA = 2650 mA liegt über dem Nennstrom der Spule CURNORM = 2600 mA"
    )
    assert "2650\xa0mA" in dialog.error_label.text()  # value and unit never wrap apart
    assert doc.value("LIMTA") == 2400 and not doc.modified


def test_an_open_refusal_follows_the_language(qtbot, doc, language):
    language("cs")
    dialog = _refusal(qtbot, doc, "LIMTA", "2650")
    assert dialog.error_label.text().replace("\xa0", " ") == (
        "LIMTA = 2650 mA je vyšší než jmenovitý proud cívky CURNORM = 2600 mA"
    )
    language("en")
    assert dialog.error_label.text().replace("\xa0", " ") == (
        "LIMTA = 2650 mA is above the nominal coil current CURNORM = 2600 mA"
    )


def test_a_curve_that_falls_is_refused_in_german(doc, language):
    language("de")
    from prm9tool.errors import ValueRangeError
    from prm9tool.translate import error_text

    access = AccessModel()
    access.set_level(access.level.EXPERT)
    with pytest.raises(ValueRangeError) as caught:
        apply_edit(doc, access, "SETPLINYC", doc.value("SETPLINYB") - 1)
    assert error_text(caught.value) == (
        "SETPLIN: Die Ausgangswerte der Linearisierung dürfen nicht fallen: SETPLINYC < SETPLINYB"
    )
    assert str(caught.value).startswith("SETPLIN linearization outputs must not decrease")


@pytest.mark.parametrize(
    ("typed", "german"),
    [
        (
            "PRM9-07.3Z11/30-24E02S02",
            "Typschlüssel 'PRM9-07.3Z11/30-24E02S02': Nenngröße '07' muss 06 oder 10 sein",
        ),
        (
            "PRM9-06-3Z11/30-24E02S02",
            "Typschlüssel 'PRM9-06-3Z11/30-24E02S02': Zwischen Nenngröße '06' und Schieber "
            "wird '.' erwartet, gefunden: '-'",
        ),
        (
            "PRM9-06.3Z11/30",
            "Typschlüssel 'PRM9-06.3Z11/30': Zwischen Nennvolumenstrom '30' und "
            "Versorgungsspannung wird '-' erwartet, gefunden: das Ende des Schlüssels",
        ),
        (
            "PRM9-06.3Z11/30-24",
            "Typschlüssel 'PRM9-06.3Z11/30-24': die Konfiguration (E02 oder E04) fehlt",
        ),
    ],
)
def test_valve_selection_explains_a_bad_type_key_in_german(qtbot, language, typed, german):
    language("de")
    dialog = ValveSelectionDialog()
    qtbot.addWidget(dialog)
    dialog._on_key_edited(typed)
    assert dialog.error_label.text() == german
    assert not dialog.buttons.button(dialog.buttons.StandardButton.Ok).isEnabled()


def test_valve_selection_error_follows_the_language(qtbot, language):
    dialog = ValveSelectionDialog()
    qtbot.addWidget(dialog)
    dialog._on_key_edited("PRM9-06.3Z11/30-24E02X02")
    assert dialog.error_label.text() == (
        "type key 'PRM9-06.3Z11/30-24E02X02': electronics series 'X02' must be S02"
    )
    language("cs")
    assert dialog.error_label.text() == (
        "typový klíč 'PRM9-06.3Z11/30-24E02X02': řada elektroniky 'X02' musí být S02"
    )


def test_lock_reason_and_undo_text_in_german(doc, language):
    language("de")
    access = AccessModel()
    assert access.why_locked(CATALOGUE["POSKP"]) == (
        "POSKP kann nur in der Expertenstufe geändert werden."
    )
    assert access.why_locked(CATALOGUE["PWR"]) == "PWR ist ein nur lesbarer Wert des Ventils."
    undo = DocumentUndo(doc)
    apply_edit(doc, access, "RAMPSETPOSUP", 100)  # Basic level: all four ramps
    assert undo.stack.undoText() == "Alle Rampen = 100 ms"
    doc.set_type_key("PRM9-06.2Z51/30-24E02S02")
    assert undo.stack.undoText() == "Ventilauswahl PRM9-06.2Z51/30-24E02S02"


@dataclass(frozen=True)
class _Entry:
    device_id: str = "emulator:PRM9-06.3Z11/30-24E02S02-CA:1001"
    kind: str = "emulator"
    type_key: str = "PRM9-06.3Z11/30-24E02S02-CA"
    serial: int = 1001
    firmware: str = "V0.35.16"
    description: str = "emulated PRM9-06.3Z11/30-24E02S02-CA, serial 1001"


def test_hid_dialog_describes_emulated_valves_in_german(qtbot, tmp_path, language):
    language("de")
    dialog = HidConfigurationDialog(
        lambda _emulators, deliver: deliver([_Entry()]), settings_in(tmp_path)
    )
    qtbot.addWidget(dialog)
    assert dialog.table.item(0, 4).text() == (
        "emuliertes Ventil PRM9-06.3Z11/30-24E02S02-CA, Seriennummer 1001"
    )


@pytest.mark.parametrize(
    ("lang", "label"),
    [("en", "E04 coil A -CA"), ("de", "E04 Spule A -CA"), ("cs", "E04 cívka A -CA")],
)
def test_the_variant_label_is_shown_in_the_program_language(language, lang, label):
    from prm9tool.catalogue.variant import Coils, Config, Variant, variant_label
    from prm9tool.translate import translated

    language(lang)
    assert translated(variant_label(Variant(Config.E04, Coils.A, canopen=True))) == label


def test_valve_selection_marks_the_spools_of_the_users_spools_json(
    qtbot, tmp_path, spools, language
):
    from prm9tool.catalogue.typekey import USER_SPOOLS_FILE, load_user_spools

    user = [{"code": "4Z21", "coils": "B"}, {"code": "3Z12", "coils": "AB"}]
    (tmp_path / USER_SPOOLS_FILE).write_text(json.dumps(user), encoding="utf-8")
    load_user_spools(tmp_path)
    language("de")
    dialog = ValveSelectionDialog()
    qtbot.addWidget(dialog)
    items = {dialog.spool.itemData(row): dialog.spool.itemText(row) for row in range(len(spools))}
    assert items["3Z11"] == "3Z11 – zwei Spulen A und B"
    assert items["3Y11"] == "3Y11 – zwei Spulen A und B (Annahme)"
    assert items["3Z12"] == "3Z12 – zwei Spulen A und B (Ihre spools.json)"  # replaced ours
    assert items["4Z21"] == "4Z21 – eine Spule auf Seite B (Ihre spools.json)"
    language("en")
    assert dialog.spool.itemText(dialog.spool.findData("4Z21")) == (
        "4Z21 – one solenoid on side B (your spools.json)"
    )


@pytest.mark.parametrize(
    ("error", "czech"),
    [
        ("DeviceTimeoutError", "Ventil neodpověděl včas. (no answer)"),
        ("DeviceDisconnectedError", "Spojení s ventilem je přerušeno. (no answer)"),
        ("ProtocolError", "Ventil odpověděl něco, čemu prm9tool nerozumí. (no answer)"),
        ("CommunicationError", "Ventil není dostupný. (no answer)"),
    ],
)
def test_device_errors_lead_with_a_sentence_in_the_program_language(language, error, czech):
    from prm9tool import errors
    from prm9tool.translate import error_text

    exc = getattr(errors, error)("no answer")
    assert error_text(exc).endswith(". (no answer)") and error_text(exc) != "no answer"
    language("cs")
    assert error_text(exc) == czech


def test_a_refused_value_leads_with_the_refusal_and_keeps_the_abort_code(language):
    from prm9tool.device.records import RefusedError
    from prm9tool.errors import AbortCode, SdoAbortError
    from prm9tool.translate import error_text

    exc = RefusedError("LIMTA", SdoAbortError(0x2200, 1, AbortCode.VALUE_TOO_HIGH), 0)
    assert error_text(exc) == (
        "The valve refused the access. "
        "(LIMTA: 0x2200/1: abort 0x06090031 (value of parameter written too high))"
    )
    language("de")
    assert error_text(exc) == (
        "Das Ventil hat den Zugriff abgelehnt. "
        "(LIMTA: 0x2200/1: abort 0x06090031 (value of parameter written too high))"
    )


def test_a_model_error_with_its_own_message_gets_no_lead(language):
    from prm9tool.errors import ValueRangeError
    from prm9tool.translate import error_text

    language("de")
    assert error_text(ValueRangeError("plain")) == "plain"

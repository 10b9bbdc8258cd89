"""Languages: complete German and Czech translations, switched at run time and remembered."""

from __future__ import annotations

import shutil
import subprocess
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QDialogButtonBox
from support.gui_support import main_window, record_prompts

from prm9tool import i18n
from prm9tool.views.parameters.model import Column

ROOT = Path(__file__).resolve().parent.parent
TS = {lang: ROOT / "translations" / f"prm9tool_{lang}.ts" for lang in ("de", "cs")}
EN_TS = ROOT / "translations" / "prm9tool_en.ts"  # English plural forms only


def _tool(name: str) -> str:
    path = shutil.which(name) or str(Path(__import__("sys").executable).parent / name)
    if not Path(path).exists():
        pytest.skip(f"{name} is not installed")
    return path


def _messages(path: Path) -> dict[tuple[str, str], ET.Element]:
    root = ET.parse(path).getroot()
    return {
        (context.findtext("name") or "", message.findtext("source") or ""): message
        for context in root.iter("context")
        for message in context.iter("message")
        if message.find("translation").get("type") not in ("vanished", "obsolete")
    }


@pytest.fixture
def window(qtbot, tmp_path, monkeypatch):
    record_prompts(monkeypatch)
    with main_window(qtbot, tmp_path) as win:
        yield win


@pytest.mark.parametrize("language", ["de", "cs"])
def test_every_text_is_translated(language):
    unfinished = [
        source
        for (_context, source), message in _messages(TS[language]).items()
        if message.find("translation").get("type") == "unfinished"
        or not "".join(message.find("translation").itertext()).strip()
    ]
    assert unfinished == []


# the compiled resources hold no texts to translate, and pyside6-lupdate 6.x crashes (SIGSEGV)
# on some of their compressed byte strings (it did after the tuning help page grew)
GENERATED = "resources_rc.py"


def test_the_translations_cover_every_text_of_the_program(tmp_path):
    sources = sorted(str(p) for p in (ROOT / "prm9tool").rglob("*.py") if p.name != GENERATED)
    fresh = tmp_path / "fresh.ts"
    subprocess.run(
        [_tool("pyside6-lupdate"), *sources, "-ts", str(fresh)],
        check=True,
        capture_output=True,
        timeout=120,
    )
    wanted = set(_messages(fresh))
    for language, path in TS.items():
        assert wanted - set(_messages(path)) == set(), language
    plurals = {key for key, message in _messages(fresh).items() if message.get("numerus")}
    assert plurals and set(_messages(EN_TS)) == plurals


@pytest.mark.parametrize(("language", "forms"), [("en", 2), ("de", 2), ("cs", 3)])
def test_plural_messages_have_every_form_of_the_language(language, forms):
    plurals = [m for m in _messages(TS.get(language, EN_TS)).values() if m.get("numerus")]
    assert plurals
    for message in plurals:
        texts = [form.text or "" for form in message.iter("numerusform")]
        assert len(texts) == forms and all("%n" in text for text in texts), texts
        assert message.find("translation").get("type") != "unfinished"


@pytest.mark.parametrize("language", ["de", "cs", "en"])
def test_shipped_qm_files_are_compiled_from_the_ts_files(tmp_path, language):
    compiled = tmp_path / f"prm9tool_{language}.qm"
    subprocess.run(
        [_tool("pyside6-lrelease"), str(TS.get(language, EN_TS)), "-qm", str(compiled)],
        check=True,
        capture_output=True,
        timeout=60,
    )
    shipped = i18n.translations_dir() / f"prm9tool_{language}.qm"
    assert shipped.read_bytes() == compiled.read_bytes()


def test_switching_to_german_changes_visible_texts_at_once(window):
    window.show_view("parameters")
    model = window.parameter_view.model
    window.commands.language_actions["de"].trigger()
    assert i18n.current_language() == "de"
    assert window.commands.menus["file"].title() == "&Datei"
    assert window.commands["online"].text() == "O&nline-Modus"
    assert window.status.mode_label.text() == "Modus: OFFLINE"
    assert model.headerData(Column.VALUE, Qt.Orientation.Horizontal) == "Wert"
    row = model.row_of("PWR")
    assert model.data(model.index(row, Column.DESCRIPTION)) == "Versorgungsspannung"
    assert window.parameter_view.modified_only.text() == "Nur geänderte"
    assert window.settings.value("language") == "de"


def test_czech_uses_the_manuals_terms(window):
    window.set_language("cs")
    titles = [a.text() for a in window.menuBar().actions()]
    assert titles == ["&Soubor", "Ná&hled", "&Ventil", "&Komunikace", "&Nápověda"]
    assert window.commands["view_diagram"].text() == "&Postupový diagram"
    assert window.status.file_label.text() == "nepojmenovaná"
    window.set_language("en")
    assert window.commands.menus["file"].title() == "&File"


def test_qt_own_dialog_texts_are_translated_too(window):
    window.set_language("de")
    box = QDialogButtonBox(QDialogButtonBox.StandardButton.Cancel)
    assert box.button(QDialogButtonBox.StandardButton.Cancel).text() == "Abbrechen"


def test_open_dialogs_follow_the_language(window):
    help_window = window.show_help()
    status = window.show_status_window()
    window.set_language("de")
    assert status.windowTitle() == "Ventilstatus"
    assert "Berechtigungsstufen" in help_window.browser.toPlainText()


def test_unknown_language_is_refused():
    with pytest.raises(ValueError, match="unknown language 'fr'"):
        i18n.set_language("fr")


def test_the_canopen_error_codes_have_texts_in_every_language(qapp):
    from prm9tool.views.emcy import emcy_text

    device_text = "CANopen RPDO shorter than its mapping: not processed"
    try:
        i18n.set_language("de")
        assert emcy_text(0x8210, device_text) == "CANopen-RPDO zu kurz: nicht verarbeitet"
        assert emcy_text(0x8100).startswith("CANopen-Kommunikationsfehler")
        i18n.set_language("cs")
        assert emcy_text(0x8210, device_text) == "CANopen RPDO je příliš krátké: nezpracováno"
    finally:
        i18n.set_language("en")
    assert emcy_text(0x8210, device_text) == "CANopen RPDO too short: not processed"

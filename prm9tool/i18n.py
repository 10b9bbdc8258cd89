"""Program languages: English (source), German and Czech, switched at run time.

Installing or removing a QTranslator makes Qt send a ``LanguageChange`` event to every widget,
so views retranslate themselves in ``changeEvent``. Parameter and signal texts do not go through
Qt: they come from the catalogue's :class:`~prm9tool.catalogue.Texts` by
:func:`current_language`. QtCore only.
"""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import QCoreApplication, QEvent, QLibraryInfo, QLocale, QTranslator

from prm9tool.catalogue.schema import Texts

LANGUAGES: tuple[str, ...] = ("en", "de", "cs")
LANGUAGE_NAMES: dict[str, str] = {"en": "English", "de": "Deutsch", "cs": "Čeština"}
DEFAULT_LANGUAGE = "en"

_state: dict[str, object] = {"language": DEFAULT_LANGUAGE, "translators": []}


def translations_dir() -> Path:
    """Folder of the compiled ``prm9tool_<lang>.qm`` files shipped inside the package."""
    return Path(__file__).resolve().parent / "translations"


def current_language() -> str:
    """The language in use: ``en``, ``de`` or ``cs``."""
    return str(_state["language"])


def text(texts: Texts) -> str:
    """A catalogue text in the current language."""
    return texts.get(current_language())


def system_language() -> str:
    """The system locale's language if the program speaks it, else English."""
    name = QLocale.system().name().split("_")[0]
    return name if name in LANGUAGES else DEFAULT_LANGUAGE


def set_language(language: str) -> None:
    """Switch the program language; raises ValueError for a language we do not ship.

    Must be called with a QCoreApplication running. English, the source language, installs
    only its plural forms ("1 value", "2 values" for the source text "%n value(s)").
    """
    if language not in LANGUAGES:
        raise ValueError(f"unknown language {language!r}; choose one of {', '.join(LANGUAGES)}")
    app = QCoreApplication.instance()
    if app is None:
        raise RuntimeError("set_language needs a running QCoreApplication")
    translators = _load_translators(language)
    for old in _installed():
        QCoreApplication.removeTranslator(old)
    _state["language"] = language
    _state["translators"] = translators
    for translator in translators:
        QCoreApplication.installTranslator(translator)
    QLocale.setDefault(QLocale(language))
    # Deliver the LanguageChange events now, so every open window shows the new language
    # when this call returns (not at the next turn of the event loop).
    QCoreApplication.sendPostedEvents(None, QEvent.Type.LanguageChange)


def _installed() -> list[QTranslator]:
    translators = _state["translators"]
    assert isinstance(translators, list)
    return translators


def _load_translators(language: str) -> list[QTranslator]:
    ours = QTranslator()
    if not ours.load(f"prm9tool_{language}", str(translations_dir())):
        raise FileNotFoundError(
            f"translation prm9tool_{language}.qm is missing in {translations_dir()}"
        )
    result = [ours]
    if language == DEFAULT_LANGUAGE:
        return result  # plural forms only: Qt's own texts are English already
    qt_dir = QLibraryInfo.path(QLibraryInfo.LibraryPath.TranslationsPath)
    qtbase = QTranslator()
    if qtbase.load(f"qtbase_{language}", qt_dir):
        result.append(qtbase)  # Qt's own dialogs and buttons; optional on stripped installs
    return result

"""Program languages: English (source), German and Czech, switched at run time.

Installing or removing a QTranslator makes Qt send a ``LanguageChange`` event to every widget,
so views retranslate themselves in ``changeEvent``. Parameter and signal texts do not go through
Qt: they come from the catalogue's :class:`~prm9tool.catalogue.Texts` by
:func:`current_language`.

Numbers are shown and typed the way the program language writes them (``9,766 %`` in German
and Czech): :func:`format_value` and :func:`format_number` are the one formatting rule of every
view (table, dialogs, diagram, scope, printed record), :func:`parse_value` the one input rule.
Files (*.prm, CSV, JSON) stay locale-independent: they use ``Parameter.format_display``, which
always writes a point. QtCore only.
"""

from __future__ import annotations

import re
from pathlib import Path

from PySide6.QtCore import QCoreApplication, QEvent, QLibraryInfo, QLocale, QTranslator

from prm9tool.catalogue.schema import Parameter, Texts
from prm9tool.catalogue.signals import MEASURED_DECIMALS
from prm9tool.errors import ValueRangeError
from prm9tool.messages import DECIMAL_POINT, QT_TRANSLATE_NOOP, Message, localized_number

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


def decimal_point() -> str:
    """The decimal separator of the program language (``,`` in German and Czech)."""
    return DECIMAL_POINT.get(current_language(), ".")


def format_number(value: float, decimals: int) -> str:
    """``value`` with ``decimals`` decimals as the program language writes it (no grouping;
    no ``-0``)."""
    return localized_number(f"{round(value, decimals) + 0.0:.{decimals}f}", current_language())


def format_measured(value: float, unit: str) -> str:
    """A measured ``value`` in ``unit`` as every view shows it, without the unit: ``24.00`` in
    English, ``24,00`` in German (decimals per unit: ``catalogue.signals.MEASURED_DECIMALS``)."""
    return format_number(value, MEASURED_DECIMALS.get(unit, 1))


def format_significant(value: float, digits: int) -> str:
    """``value`` to ``digits`` significant digits (``%g``) as the program language writes it;
    a large number written out (4999 to three digits is ``5000``, not ``5e+03``)."""
    text = f"{value:.{digits}g}"
    if "e+" in text and abs(value) < 1e15:
        text = f"{float(text):.0f}"
    return localized_number(text, current_language())


# A value and its unit stay on one line where a text wraps ("53 s", never "53" / "s").
_VALUE_UNIT = re.compile(r"(\d) (?=(?:mA|mV|ms|Hz|V|s|%|°C|dB)(?![\w])|%)")


def unbroken_units(text: str) -> str:
    """``text`` with a no-break space between each number and its unit."""
    return _VALUE_UNIT.sub("\\1\u00a0", text)


def format_value(param: Parameter, raw: int | str) -> str:
    """A parameter value as the views show it: the shortest exact decimal (as in a file), with
    the decimal separator of the program language; texts are shown as they are."""
    if param.is_string or isinstance(raw, str):
        return str(raw)
    return localized_number(param.format_display(raw), current_language())


def format_shown(param: Parameter, raw: int | str) -> str:
    """A value with its unit as the parameter list shows it: a choice with its meaning
    (``-1: on (9-point curve)``), a number with its unit (``2400 mA``)."""
    if param.choices and isinstance(raw, int):
        return f"{raw}: {param.choice_text(raw, current_language())}"
    return f"{format_value(param, raw)} {param.unit}".strip()


_AMBIGUOUS = QT_TRANSLATE_NOOP(
    "Problems",
    "{0}: {1} is ambiguous (a thousands separator?); write the number without one, "
    "with '{2}' before the decimals",
)


def ambiguous_number(param: Parameter, text: str) -> Message | None:
    """Why ``text`` cannot be taken as a number of ``param`` without guessing, or None.

    What reads as a thousands group in the program language (``2.400`` in German, ``2,400``
    in English: 2400 or 2.4?) is refused rather than guessed.
    """
    if param.is_string or param.choices:
        return None
    group = "." if decimal_point() == "," else ","
    if re.fullmatch(rf"\s*[+-]?[1-9][0-9]{{0,2}}(\{group}[0-9]{{3}})+\s*", text):
        return _AMBIGUOUS(param.mnemonic, repr(text.strip()), decimal_point())
    return None


def parse_value(param: Parameter, text: str) -> int | str:
    """A value typed in a view, to raw; raises ValueRangeError with the reason.

    Takes the decimal separator of the program language and the point (``0,4`` and ``0.4``
    in German and Czech; in English ``1,5`` is refused in words), but not a number that could
    be meant with a thousands separator (:func:`ambiguous_number`).
    """
    ambiguous = ambiguous_number(param, text)
    if ambiguous is not None:
        raise ValueRangeError(ambiguous)
    return param.parse_display(text, decimal_point())


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

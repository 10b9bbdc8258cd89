"""User-facing texts of the model layer: English for the command line, translatable for the GUI.

A model module (no Qt) marks the English template with :func:`QT_TRANSLATE_NOOP`, which
pyside6-lupdate extracts into the .ts files, and calls the result with the arguments::

    raise ValueRangeError(QT_TRANSLATE_NOOP("Problems", "{0}: {1} is not a number")(name, text))

``str()`` of the :class:`Message` (and so of an exception carrying it) is the English sentence:
``--check`` and ``--batch`` print it, tests match it. A view shows
``prm9tool.i18n.translated(message)`` (or ``i18n.error_text(exc)``), which looks the template up
with ``QCoreApplication.translate(context, template)`` and formats the same arguments; arguments
that are messages or catalogue :class:`~prm9tool.catalogue.schema.Texts` are translated too.
Templates use ``{0}``, ``{1}``… as the rest of the program's translated texts do. No Qt here.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Protocol

Translate = Callable[[str, str], str]  # (context, English source) -> text in the language


class Localized(Protocol):
    """Anything with a text per language (the catalogue's ``Texts``)."""

    def get(self, language: str) -> str:
        """The text in ``language`` (``en``, ``de``, ``cs``)."""
        ...


def QT_TRANSLATE_NOOP(context: str, source: str) -> Template:
    """Mark ``source`` for pyside6-lupdate under ``context``; call the result with the arguments.

    Named like Qt's macro because that name is what lupdate looks for in Python sources.
    """
    return Template(context, source)


@dataclass(frozen=True)
class Template:
    """An English text with ``{0}``-style placeholders, and the translation context it is in."""

    context: str
    source: str

    def __call__(self, *args: Arg) -> Message:
        """The message with ``args`` filled in."""
        return Message(self, tuple(args))

    def __str__(self) -> str:
        return self.source


@dataclass(frozen=True)
class Message:
    """A template and its arguments; ``str()`` gives the English sentence."""

    template: Template
    args: tuple[Arg, ...] = ()

    def render(self, translate: Translate, language: str) -> str:
        """The text in ``language``; ``translate`` looks templates up (English if none fits)."""
        values = [_render(arg, translate, language) for arg in self.args]
        text = translate(self.template.context, self.template.source)
        try:
            return text.format(*values)
        except (IndexError, KeyError, ValueError):  # a broken translation: say it in English
            return self.template.source.format(*values)

    def __str__(self) -> str:
        return self.render(_english, "en")


def _english(_context: str, source: str) -> str:
    return source


Arg = str | int | float | Message | Localized  # what a message's placeholders take

# The decimal separator of each program language: what QLocale(language).decimalPoint() gives
# (tests/test_locale_numbers.py checks that they agree). Files are locale-independent and always
# use the point; the program shows numbers with the separator of its language.
DECIMAL_POINT: dict[str, str] = {"en": ".", "de": ",", "cs": ","}


def localized_number(text: str, language: str) -> str:
    """A number as the program writes it in files (``9.766``) as ``language`` writes it.

    The one rule for every number the program shows: the decimal point becomes the language's
    separator (``9,766`` in German and Czech); no group separators, so ``2400`` stays ``2400``
    (in German ``2.400`` would read as 2.4 in a file and as 2400 to a person).
    """
    return text.replace(".", DECIMAL_POINT.get(language, "."))


@dataclass(frozen=True)
class Number:
    """A message argument that is a number: ``str()`` (files, command line) keeps the point,
    a message shown in German or Czech gets the decimal comma."""

    text: str

    def get(self, language: str) -> str:
        """The number as ``language`` writes it."""
        return localized_number(self.text, language)

    def __str__(self) -> str:
        return self.text


def message_of(error: BaseException) -> Message | str:
    """The message ``error`` was raised with, or ``str(error)`` if it was not one."""
    if len(error.args) == 1 and isinstance(error.args[0], Message):
        return error.args[0]
    return str(error)


def _render(arg: Arg, translate: Translate, language: str) -> str:
    if isinstance(arg, Message):
        return arg.render(translate, language)
    if isinstance(arg, (str, int, float)):
        return str(arg)
    return arg.get(language)


SHOWN_CHARACTERS = 40  # a value longer than this is cut in a message (its length is said)


def quoted(text: str, limit: int = SHOWN_CHARACTERS) -> str:
    """``text`` quoted for a message (``repr``), cut in the middle when it is longer than
    ``limit`` characters: ``'99999999999999999999…9999999999999999999x' (20001 characters)``.
    A message must not repeat an 8000-digit value from a file."""
    if len(text) <= limit:
        return repr(text)
    half = limit // 2
    return f"{text[:half] + '…' + text[-half:]!r} ({len(text)} characters)"

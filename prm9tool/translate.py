"""Messages of the model layer in the program language, for the views (QtCore only).

The model builds :class:`~prm9tool.messages.Message` objects whose ``str()`` is English; this
module is where a view (or a QtCore model that produces view texts, such as the access level's
tooltips) turns one into the current language through Qt's translators.
"""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication

from prm9tool.errors import FileFormatError
from prm9tool.i18n import current_language
from prm9tool.messages import Message, message_of


def translated(message: Message | str) -> str:
    """``message`` in the current language (a plain string is returned as it is)."""
    if isinstance(message, Message):
        return message.render(QCoreApplication.translate, current_language())
    return message


def error_text(error: BaseException) -> str:
    """What to show a user for ``error``, in the current language.

    An error raised with a :class:`~prm9tool.messages.Message` (catalogue, document, type key,
    access level) is translated; a device error with a ``summary`` gives that lead sentence
    translated, with its technical English text in brackets; any other gives ``str(error)``.
    """
    if isinstance(error, FileFormatError) and error.problems:  # each problem translated
        return "\n".join(translated(p.located(error.path)) for p in error.problems)
    message = message_of(error)
    summary = getattr(error, "summary", None)
    if isinstance(message, Message) or summary is None:
        return translated(message)
    return f"{translated(summary())} ({message})"

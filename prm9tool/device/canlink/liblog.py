"""The CAN libraries' log records as prm9tool's own messages.

python-can and the ``canopen`` package log what they meet on the logging module's loggers
``can`` and ``canopen``. Left alone, Python's last-resort handler prints their warnings and
errors raw on standard error ("Transfer aborted by client with code 0x05040000"), in the
library's words and next to prm9tool's own report of the same event. :func:`route_library_logs`
takes those two loggers over: each record of level WARNING or above becomes a translatable
:class:`~prm9tool.messages.Message` that says what happened in the user's terms (the SDO abort
code with its CiA 301 meaning, for instance) and goes to the caller's sink — on the command
line standard error with prm9tool's prefix, in the GUI also the status
bar. Records below WARNING (the libraries' debugging) are dropped, as before.
"""

from __future__ import annotations

import logging
from collections.abc import Callable

from prm9tool.errors import AbortCode
from prm9tool.messages import QT_TRANSLATE_NOOP, Message

LIBRARY_LOGGERS = ("canopen", "can")  # the ``canopen`` package and python-can

CLIENT_ABORT = "Transfer aborted by client with code 0x%08X"  # canopen.sdo.client
RECEIVE_STOPPED = "An error has caused receiving of messages to stop"  # canopen.network

ABORTED = QT_TRANSLATE_NOOP(
    "CanLink", "CANopen: prm9tool abandoned an SDO transfer: {0} (abort code {1})"
)
NO_ANSWER = QT_TRANSLATE_NOOP(
    "CanLink", "CANopen: the node did not answer an SDO request in time; asking again"
)
STOPPED = QT_TRANSLATE_NOOP(
    "CanLink",
    "CANopen: receiving stopped after an error of the CAN interface; go offline and connect again",
)
CALLBACK = QT_TRANSLATE_NOOP("CanLink", "CANopen: a received frame could not be processed: {0}")
OTHER = QT_TRANSLATE_NOOP("CanLink", "CAN interface ({0}): {1}")

Sink = Callable[[Message], None]


def describe(record: logging.LogRecord) -> Message:
    """prm9tool's message for a record of the ``canopen`` or ``can`` loggers."""
    name = record.name
    if record.msg == CLIENT_ABORT and record.args and isinstance(record.args, tuple):
        code = int(str(record.args[0]))
        try:
            meaning = AbortCode(code).text
        except ValueError:
            meaning = "unknown abort code"
        return ABORTED(meaning, f"{code:#010x}")
    text = record.getMessage()
    if name == "canopen.sdo.client" and text.startswith("No SDO response"):
        return NO_ANSWER()
    if record.msg == RECEIVE_STOPPED:
        return STOPPED()
    if name == "canopen.network":  # an exception raised in a subscriber (a PDO callback)
        return CALLBACK(text)
    if record.exc_info and record.exc_info[1] is not None:
        text = f"{text}: {record.exc_info[1]}"
    return OTHER(name, text)


class LibraryLogHandler(logging.Handler):
    """Turns each record into :func:`describe`'s message and hands it to ``sink``."""

    def __init__(self, sink: Sink) -> None:
        super().__init__(logging.WARNING)
        self.sink = sink

    def emit(self, record: logging.LogRecord) -> None:
        """Describe and hand over (a failing sink is logging's own error handling)."""
        try:
            self.sink(describe(record))
        except Exception:  # logging's contract: emit never raises
            self.handleError(record)


def route_library_logs(sink: Sink) -> Callable[[], None]:
    """Send the CAN libraries' warnings and errors to ``sink`` instead of standard error.

    Returns the callable that undoes it (the loggers propagate again). Calling it again adds
    a second sink: the CLI prints, the GUI prints and shows.
    """
    handler = LibraryLogHandler(sink)
    saved = []
    for name in LIBRARY_LOGGERS:
        logger = logging.getLogger(name)
        saved.append((logger, logger.propagate, logger.level))
        logger.addHandler(handler)
        logger.propagate = False  # not to the root logger, so not to the last-resort handler
        if logger.level == logging.NOTSET or logger.level > logging.WARNING:
            logger.setLevel(logging.WARNING)

    def undo() -> None:
        for logger, propagate, level in saved:
            logger.removeHandler(handler)
            logger.propagate = propagate
            logger.setLevel(level)

    return undo

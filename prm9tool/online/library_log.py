"""The CAN libraries' log messages on the GUI thread (QtCore only).

:func:`prm9tool.device.canlink.liblog.route_library_logs` turns the records of the ``canopen``
and ``can`` loggers into prm9tool's messages; they are logged in whichever thread met the event
(the bus's receive thread, the valve's worker). :class:`LibraryLog` carries each one to the GUI
thread as :attr:`LibraryLog.message_posted`, translated into the program language, for the
status bar.
"""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtCore import QObject, Signal

from prm9tool.device.canlink.liblog import route_library_logs
from prm9tool.messages import Message
from prm9tool.translate import translated


class LibraryLog(QObject):
    """Posts the CAN libraries' warnings and errors, as prm9tool's messages, to the GUI thread."""

    message_posted = Signal(str)  # a short status-bar message, translated
    _received = Signal(object)  # a Message, from any thread (queued to this object's thread)

    def __init__(self, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self._received.connect(self._post)
        self._undo: Callable[[], None] | None = route_library_logs(self._received.emit)

    def _post(self, message: Message) -> None:
        self.message_posted.emit(translated(message))

    def close(self) -> None:
        """Stop receiving (the loggers are put back as they were)."""
        if self._undo is not None:
            self._undo()
            self._undo = None

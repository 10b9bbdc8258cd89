"""Status bar (manual §8.8): ``Mode | Status | FW | type key | file name *``, plus the access
level.

Mode is ONLINE only while the document and the valve agree and edits go to the valve; between
connecting and the user's answer to the differences question it says CONNECTING, and
Cancel there makes it OFFLINE again.

A message (:meth:`MainStatusBar.showMessage`) is shown in a label of its own, left of the
fields, that wraps onto a second line when it is longer than the room left (the bar always
has the room for two lines, so a message never moves the window's buttons): it is read whole
and the fields (type key and file name too) stay (issue 34 item 20; before, the fields stepped
aside for a long message and the window did not say which file or valve it showed).
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from PySide6.QtCore import QEvent, Qt, QTimer
from PySide6.QtGui import QFontMetrics, QResizeEvent
from PySide6.QtWidgets import QFrame, QLabel, QSizePolicy, QStatusBar, QWidget

from prm9tool.catalogue import Access
from prm9tool.views.emcy import status_summary

if TYPE_CHECKING:
    from prm9tool.model.access import AccessModel
    from prm9tool.model.document import ParameterDocument
    from prm9tool.online.connection import ValveConnection
    from prm9tool.online.sync import ValveSync


def two_lines(text: str, metrics: QFontMetrics, width: int) -> str:
    """``text`` on at most two lines of ``width`` pixels, broken at spaces only (never inside
    a type key or a file name at its hyphens); what does not fit ends in "…"."""
    words, first = text.split(" "), ""
    taken = 0
    for word in words:
        candidate = f"{first} {word}" if first else word
        if first and metrics.horizontalAdvance(candidate) > width:
            break
        first, taken = candidate, taken + 1
    first = metrics.elidedText(first, Qt.TextElideMode.ElideRight, width)
    rest = " ".join(words[taken:])
    if not rest:
        return first
    return f"{first}\n{metrics.elidedText(rest, Qt.TextElideMode.ElideRight, width)}"


class MessageLabel(QLabel):
    """The status bar's message on the two lines the bar has room for (:func:`two_lines`),
    laid out again when its width changes; the whole message is the bar's tip (issue 34: a
    message wrapped at a hyphen and its third line hid under the bar's edge)."""

    def __init__(self) -> None:
        super().__init__()
        self._message = ""

    def set_message(self, message: str) -> None:
        """Show ``message``."""
        self._message = message
        self._fit()

    def resizeEvent(self, event: QResizeEvent) -> None:
        """Lay the message out again for the new width."""
        super().resizeEvent(event)
        self._fit()

    def _fit(self) -> None:
        width = max(1, self.contentsRect().width())
        self.setText(two_lines(self._message, self.fontMetrics(), width) if self._message else "")


class MainStatusBar(QStatusBar):
    """Six permanent fields, following the models (:meth:`observe`)."""

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.mode_label = QLabel()
        self.status_label = QLabel()
        self.firmware_label = QLabel()
        self.type_key_label = QLabel()
        self.file_label = QLabel()
        self.level_label = QLabel()
        self.message_label = MessageLabel()  # the message on two lines at most
        self.message_label.setSizePolicy(QSizePolicy.Policy.Ignored, QSizePolicy.Policy.Preferred)
        # room for two lines, always: a message that wraps must not grow the bar and move every
        # button above it while the user aims (issue 25 item 14); a longer one is the bar's tip
        self.message_label.setFixedHeight(2 * self.message_label.fontMetrics().lineSpacing())
        self.addWidget(self.message_label, 1)
        self._message = ""
        self._message_timer = QTimer(self)
        self._message_timer.setSingleShot(True)
        self._message_timer.timeout.connect(self.clearMessage)
        self.lost_label = QLabel()  # shown only while the oscilloscope stream loses samples
        self.lost_label.hide()
        self.addPermanentWidget(self.lost_label)
        for label in self.labels():
            label.setFrameShape(QFrame.Shape.StyledPanel)
            label.setContentsMargins(6, 0, 6, 0)
            self.addPermanentWidget(label)
        self._online = False
        self._synchronised = False
        self._expert = False
        self._status = ""
        self._firmware = ""
        self._path: Path | None = None
        self._modified = False
        self._lost = 0
        self._reconnecting: tuple[float, int] | None = None  # (seconds, serial) while looking
        self.retranslate()

    def showMessage(self, message: str, timeout: int | None = 0) -> None:
        """Show ``message`` (for ``timeout`` ms; 0: until the next); the bar's tip is the
        whole message too."""
        self._message = message
        self.message_label.set_message(message)
        self.setToolTip(message)
        if timeout:
            self._message_timer.start(timeout)
        else:
            self._message_timer.stop()
        self.messageChanged.emit(message)

    def clearMessage(self) -> None:
        """Remove the message."""
        if self._message:
            self.showMessage("")

    def currentMessage(self) -> str:
        """The message shown ("" none)."""
        return self._message

    def labels(self) -> list[QLabel]:
        """The six fields from left to right."""
        return [
            self.mode_label,
            self.status_label,
            self.firmware_label,
            self.type_key_label,
            self.file_label,
            self.level_label,
        ]

    def observe(
        self,
        connection: ValveConnection,
        doc: ParameterDocument,
        sync: ValveSync,
        access: AccessModel,
    ) -> None:
        """Follow the connection, the document, the synchronisation and the access level:
        every field is set from their signals from now on."""
        c = connection
        c.online_changed.connect(self.set_online)
        sync.active_changed.connect(self.set_synchronised)
        access.level_changed.connect(lambda _l: self.set_expert(access.level is Access.EXPERT))
        self.set_expert(access.level is Access.EXPERT)
        c.device_changed.connect(lambda info: self.set_firmware(info.firmware if info else ""))
        c.status_changed.connect(lambda status: self.set_device_status(status_summary(status)))
        c.samples_lost_changed.connect(self.set_samples_lost)
        c.reconnecting.connect(
            lambda seconds: self.set_reconnecting(
                seconds, c.lost_valve.serial if c.lost_valve else 0
            )
        )
        c.reconnect_ended.connect(lambda: self.set_reconnecting(None))
        doc.type_key_changed.connect(self.set_type_key)

    def set_online(self, online: bool) -> None:
        """Show the communication mode."""
        self._online = online
        if not online:
            self._status = ""
            self._firmware = ""
            self._synchronised = False
        self.retranslate()

    def set_synchronised(self, synchronised: bool) -> None:
        """Show whether document and valve agree and edits go to the valve."""
        self._synchronised = synchronised
        self.retranslate()

    def set_expert(self, expert: bool) -> None:
        """Show the access level (Basic or Expert)."""
        self._expert = expert
        self.retranslate()

    def set_device_status(self, status: str) -> None:
        """Show the valve's state (``ok``, or the active error) — only meaningful online."""
        self._status = status
        self.retranslate()

    def set_firmware(self, firmware: str) -> None:
        """Show the firmware version of the connected valve."""
        self._firmware = firmware
        self.retranslate()

    def set_samples_lost(self, count: int) -> None:
        """Show how many samples the running oscilloscope stream lost (hidden while none)."""
        self._lost = count
        self.retranslate()

    def set_reconnecting(self, seconds: float | None, serial: int = 0) -> None:
        """Show that the lost valve ``serial`` is looked for since ``seconds`` (None: not)."""
        self._reconnecting = None if seconds is None else (seconds, serial)
        self.retranslate()

    def set_type_key(self, type_key: str) -> None:
        """Show the valve type of the document."""
        self.type_key_label.setText(type_key)

    def set_file(self, path: Path | None, modified: bool) -> None:
        """Show the file name and a ``*`` when there are unsaved changes."""
        self._path = path
        self._modified = modified
        self.retranslate()

    def retranslate(self) -> None:
        """Set every text in the current language."""
        mode = self.tr("OFFLINE")
        if self._online:
            mode = self.tr("ONLINE") if self._synchronised else self.tr("CONNECTING")
        tip = ""
        if self._online and not self._synchronised:
            tip = self.tr(
                "Connected, but the document and the valve do not agree yet: edits are not sent to the valve"
            )
        elif self._reconnecting is not None and not self._online:
            seconds, serial = self._reconnecting
            mode = self.tr("RECONNECTING… {0} s").format(int(seconds))
            tip = self.tr(
                "The link to the valve {0} broke. prm9tool looks for it and compares when it is "
                "back; nothing is written to the valve without you."
            ).format(serial)
        self.mode_label.setText(self.tr("Mode: {0}").format(mode))
        self.mode_label.setToolTip(tip)
        self.mode_label.setMinimumWidth(self.mode_label.sizeHint().width())  # never clipped
        levels = [self.tr("Level: {0}").format(t) for t in (self.tr("Basic"), self.tr("Expert"))]
        self.level_label.setText(levels[self._expert])
        margins = self.level_label.contentsMargins()  # as wide as the longer: no jump, no clip
        widest = max(self.level_label.fontMetrics().horizontalAdvance(t) for t in levels)
        self.level_label.setMinimumWidth(widest + margins.left() + margins.right() + 4)
        self.status_label.setText(self.tr("Status: {0}").format(self._status or "—"))
        self.firmware_label.setText(self.tr("FW: {0}").format(self._firmware or "—"))
        name = self._path.name if self._path is not None else self.tr("untitled")
        self.file_label.setText(f"{name} *" if self._modified else name)
        self.file_label.setToolTip(str(self._path) if self._path is not None else "")
        self.lost_label.setText(self.tr("%n sample(s) lost", "", self._lost))
        self.lost_label.setToolTip(
            self.tr(
                "The oscilloscope stream lost samples: the USB link or the computer could not "
                "keep up. The curves have gaps there."
            )
        )
        self.lost_label.setVisible(self._lost > 0)

    def changeEvent(self, event: QEvent) -> None:
        """Retranslate when the program language changes."""
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate()
        super().changeEvent(event)

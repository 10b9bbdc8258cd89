"""A top-level window destroyed from outside (``xdotool windowclose``, a window manager's or a
session's XDestroyWindow) is closed as its close button closes it.

Qt's xcb plugin does not tell the widget: it stays "visible" with no window on screen, so
``lastWindowClosed`` never comes and the program runs on with no window at all (issue 28; the
main window destroyed while the valve was still connecting). The X server's DestroyNotify
reaches the application's native event filter, though: the widget is given a new native window
and closed the ordinary way, with its questions (unsaved changes, values not stored in the
valve) asked in it; refused, it stays on screen, as after a refused close button.
"""

from __future__ import annotations

import ctypes
import logging

from PySide6.QtCore import QAbstractNativeEventFilter, QByteArray, QTimer
from PySide6.QtWidgets import QApplication, QWidget

__all__ = ["OutsideClose", "watch_outside_close"]

log = logging.getLogger(__name__)

XCB_EVENT = b"xcb_generic_event_t"
XCB_DESTROY_NOTIFY = 17  # xcb_destroy_notify_event_t: type, pad, sequence, event, window
_WINDOW_AT = slice(8, 12)


class OutsideClose(QAbstractNativeEventFilter):
    """The native event filter: a DestroyNotify of a shown top-level widget's own window
    closes that widget (queued: the event is handled inside Qt's event dispatch)."""

    def nativeEventFilter(
        self,
        event_type: QByteArray | bytes | bytearray | memoryview[int],
        message: int,
    ) -> tuple[bool, int]:
        """Look at an X event; never swallow it."""
        # a shiboken VoidPtr: its truth raises (it has no size), its int is the address
        address = int(message)
        kind = event_type.data() if isinstance(event_type, QByteArray) else bytes(event_type)
        if kind == XCB_EVENT and address:
            raw = ctypes.string_at(address, 12)
            if raw[0] & 0x7F == XCB_DESTROY_NOTIFY:
                widget = _top_level_of(int.from_bytes(raw[_WINDOW_AT], "little"))
                if widget is not None:
                    QTimer.singleShot(0, lambda: close_destroyed(widget))
        return False, 0


def _top_level_of(window_id: int) -> QWidget | None:
    if not window_id:
        return None
    for widget in QApplication.topLevelWidgets():
        if widget.isVisible() and int(widget.internalWinId() or 0) == window_id:
            return widget
    return None


def close_destroyed(widget: QWidget) -> None:
    """``widget``'s native window is gone: a new one, then the close of its close button."""
    if not widget.isVisible():
        return
    log.info("%s: its window was destroyed from outside; closing it", type(widget).__name__)
    # Qt's platform window names a window that no longer exists: let it go, so that show()
    # makes a new one (the close may be refused, and the widget must be on screen then)
    widget.destroy(True, True)
    widget.show()
    widget.close()


def watch_outside_close(app: QApplication) -> OutsideClose | None:
    """Install the filter where windows are X11 windows (the xcb platform); returns it (keep
    a reference: Qt does not own it), None on other platforms."""
    if QApplication.platformName() != "xcb":
        return None
    watcher = OutsideClose()
    app.installNativeEventFilter(watcher)
    return watcher

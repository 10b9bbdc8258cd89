"""Message boxes in one place, so that tests can answer them without a blocking event loop.

``ask`` is modal and returns the button pressed; ``inform`` shows a message without blocking
(the window keeps working, e.g. while the valve is lost) and returns the box.
"""

from __future__ import annotations

from PySide6.QtCore import Qt
from PySide6.QtWidgets import QMessageBox, QWidget

Button = QMessageBox.StandardButton
Icon = QMessageBox.Icon


def make_box(
    parent: QWidget | None,
    icon: Icon,
    title: str,
    text: str,
    buttons: Button = Button.Ok,
    default: Button = Button.NoButton,
    details: str = "",
) -> QMessageBox:
    """A configured message box (not shown)."""
    box = QMessageBox(icon, title, text, buttons, parent)
    box.setObjectName("prm9tool_message")
    if default != Button.NoButton:
        box.setDefaultButton(default)
    if details:
        box.setDetailedText(details)
    return box


def ask(
    parent: QWidget | None,
    icon: Icon,
    title: str,
    text: str,
    buttons: Button,
    default: Button = Button.NoButton,
    details: str = "",
) -> Button:
    """Show a modal question and return the button the user pressed."""
    box = make_box(parent, icon, title, text, buttons, default, details)
    return Button(box.exec())


def inform(
    parent: QWidget | None,
    icon: Icon,
    title: str,
    text: str,
    details: str = "",
) -> QMessageBox:
    """Show a message without blocking; it deletes itself when closed."""
    box = make_box(parent, icon, title, text, Button.Ok, Button.Ok, details)
    box.setAttribute(Qt.WidgetAttribute.WA_DeleteOnClose)
    box.setWindowModality(Qt.WindowModality.WindowModal)
    box.open()
    return box

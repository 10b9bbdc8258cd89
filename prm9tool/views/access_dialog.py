"""Password dialogs of the Expert access level (manual §8.5, View / Access level)."""

from __future__ import annotations

from PySide6.QtGui import QShowEvent
from PySide6.QtWidgets import (
    QApplication,
    QDialog,
    QDialogButtonBox,
    QFormLayout,
    QLabel,
    QLineEdit,
    QVBoxLayout,
    QWidget,
)

from prm9tool.model.password import MIN_LENGTH, PasswordStore
from prm9tool.views.diagram.colours import toned_style
from prm9tool.views.help_dialog import add_context_help, show_help


def _password_field() -> QLineEdit:
    field = QLineEdit()
    field.setEchoMode(QLineEdit.EchoMode.Password)
    return field


def grow_to_contents(dialog: QDialog) -> None:
    """Make ``dialog`` tall enough for its word-wrapped texts at its current width.

    A top-level window sizes itself by its layout's minimum size, which ignores the height a
    wrapped label needs at a given width; an explanation shown later was then squeezed and
    clipped (issue 14, item 9).
    """
    layout = dialog.layout()
    if layout is None:
        return
    layout.activate()
    needed = layout.totalHeightForWidth(dialog.width())
    if layout.hasHeightForWidth() and needed > dialog.height():
        dialog.setMinimumHeight(needed)
        dialog.resize(dialog.width(), needed)


class _GrowingDialog(QDialog):
    """A dialog that is never shorter than its wrapped texts need."""

    def _fit(self) -> None:
        self.setMinimumWidth(self.fontMetrics().averageCharWidth() * 48)
        grow_to_contents(self)

    def showEvent(self, event: QShowEvent) -> None:
        """Fit the height to the texts at the width shown."""
        super().showEvent(event)
        grow_to_contents(self)

    def show_error(self, label: QLabel, text: str) -> None:
        """Show ``text`` in ``label`` and grow so that nothing is clipped."""
        label.setText(text)
        label.show()
        grow_to_contents(self)


def _error_label() -> QLabel:
    label = QLabel()
    label.setStyleSheet(toned_style("color: #d03030;", QApplication.palette()))
    label.setWordWrap(True)
    label.hide()
    return label


class PasswordDialog(_GrowingDialog):
    """Asks for the Expert password; accepts only the right one."""

    def __init__(self, store: PasswordStore, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._store = store
        self.setWindowTitle(self.tr("Expert access level"))
        self.password = _password_field()
        self.error_label = _error_label()
        intro = QLabel(
            self.tr(
                "The Expert level unlocks the controllers and the linearizations. "
                "Changing them needs the appropriate qualification."
            )
        )
        intro.setWordWrap(True)
        # the manual says only that Expert is password-protected (§8.5): where to look
        self.hint = QLabel(
            self.tr(
                "The password as delivered is written in the help, under “Access levels” "
                '(F1, or <a href="help">open the help</a>). A password changed since is '
                "known to whoever changed it."
            )
        )
        self.hint.setWordWrap(True)
        self.hint.linkActivated.connect(self._on_hint_link)
        add_context_help(self, "help")
        buttons = QDialogButtonBox(
            QDialogButtonBox.StandardButton.Ok | QDialogButtonBox.StandardButton.Cancel
        )
        buttons.accepted.connect(self._on_accepted)
        buttons.rejected.connect(self.reject)
        form = QFormLayout()
        form.addRow(self.tr("Password:"), self.password)
        layout = QVBoxLayout(self)
        layout.addWidget(intro)
        layout.addWidget(self.hint)
        layout.addLayout(form)
        layout.addWidget(self.error_label)
        layout.addWidget(buttons)
        self._fit()

    def _on_hint_link(self, topic: str) -> None:
        show_help(self, topic)

    def _on_accepted(self) -> None:
        if self._store.check(self.password.text()):
            self.accept()
            return
        self.show_error(self.error_label, self.tr("Wrong password."))
        self.password.selectAll()


class ChangePasswordDialog(_GrowingDialog):
    """Changes the Expert password (offered only at Expert level)."""

    def __init__(self, store: PasswordStore, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._store = store
        self.setWindowTitle(self.tr("Change Expert password"))
        self.old = _password_field()
        self.new = _password_field()
        self.repeat = _password_field()
        self.error_label = _error_label()
        buttons = QDialogButtonBox(
            QDialogButtonBox.StandardButton.Ok | QDialogButtonBox.StandardButton.Cancel
        )
        buttons.accepted.connect(self._on_accepted)
        buttons.rejected.connect(self.reject)
        form = QFormLayout()
        form.addRow(self.tr("Current password:"), self.old)
        form.addRow(self.tr("New password:"), self.new)
        form.addRow(self.tr("Repeat new password:"), self.repeat)
        layout = QVBoxLayout(self)
        layout.addLayout(form)
        layout.addWidget(self.error_label)
        layout.addWidget(buttons)
        self._fit()

    def _problem(self) -> str:
        if not self._store.check(self.old.text()):
            return self.tr("The current password is wrong.")
        if len(self.new.text()) < MIN_LENGTH:
            return self.tr("The new password must have at least {0} characters.").format(MIN_LENGTH)
        if self.new.text() != self.repeat.text():
            return self.tr("The two new passwords differ.")
        return ""

    def _on_accepted(self) -> None:
        problem = self._problem()
        if problem:
            self.show_error(self.error_label, problem)
            return
        self._store.change(self.old.text(), self.new.text())
        self.accept()

"""One small binding per control: a catalogue parameter shown in a line edit or a combo box.

The binding pushes the document's value into the control (with the control's signals blocked)
and hands a user's entry to its dialog on ``editingFinished`` / ``activated``; the dialog
applies it as one undoable edit or shows why it was refused.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import Protocol

from PySide6.QtCore import QSignalBlocker, Qt
from PySide6.QtGui import QKeyEvent
from PySide6.QtWidgets import QComboBox, QDialogButtonBox, QLineEdit, QPushButton, QWidget

from prm9tool.catalogue import CATALOGUE
from prm9tool.errors import ValueRangeError
from prm9tool.i18n import current_language, format_value, parse_value
from prm9tool.model.access import AccessModel
from prm9tool.model.document import ParameterDocument, Raw
from prm9tool.model.editing import range_text
from prm9tool.translate import error_text


class Apply(Protocol):
    """Sets a value (``entered``: as typed); returns False (and shows the reason) if refused."""

    def __call__(self, mnemonic: str, raw: Raw, entered: str | None = None, /) -> bool:
        """Set ``mnemonic`` to ``raw``."""
        ...


Report = Callable[[str], None]  # shows a refusal reason
ERROR_STYLE = "border: 2px solid #d03030;"


def not_on_enter(buttons: QDialogButtonBox) -> None:
    """No button of ``buttons`` answers Enter: in a window of fields, Enter takes a field's
    value (the dialog's default button would close the window instead)."""
    for button in buttons.findChildren(QPushButton):
        button.setAutoDefault(False)
        button.setDefault(False)


class ValueField(QLineEdit):
    """A numeric parameter typed in display units; refused text stays, marked red."""

    def __init__(
        self, mnemonic: str, apply: Apply, report: Report, parent: QWidget | None = None
    ) -> None:
        super().__init__(parent)
        self.param = CATALOGUE[mnemonic]
        self._apply = apply
        self._report = report
        self._shown = ""
        self.range = range_text(self.param, None)  # the allowed range, capped once a doc is shown
        self.setMaximumWidth(110)
        self.setPlaceholderText(self.range)
        self.editingFinished.connect(self._on_editing_finished)
        self.textEdited.connect(self._on_text_edited)

    @property
    def mnemonic(self) -> str:
        """The parameter this field edits."""
        return self.param.mnemonic

    def show_value(self, doc: ParameterDocument) -> None:
        """Display the document's value (does not emit edit signals)."""
        self._shown = format_value(self.param, doc.value(self.mnemonic))
        self.range = range_text(self.param, doc)
        self.setPlaceholderText(self.range)
        if self.toolTip().startswith(f"{self.mnemonic}: "):  # the range, not a lock reason
            self.setToolTip(f"{self.mnemonic}: {self.range}")
        with QSignalBlocker(self):
            self.setText(self._shown)
        self.setStyleSheet("")

    def show_blank(self, placeholder: str) -> None:
        """Show no value (e.g. the ramps it sets together differ): any entry is then new."""
        self._shown = ""
        with QSignalBlocker(self):
            self.clear()
        self.setPlaceholderText(placeholder)
        self.setStyleSheet("")

    def update_access(self, access: AccessModel, read_only: bool) -> None:
        """Enable the field if the access level may change the parameter."""
        allowed = access.may_edit(self.param) and not read_only
        self.setEnabled(allowed)
        reason = access.why_locked(self.param)
        self.setToolTip(reason or f"{self.mnemonic}: {self.range}")

    def keyPressEvent(self, event: QKeyEvent) -> None:
        """Enter commits the field (``editingFinished``) and stays in the dialog.

        The line edit passes Enter on to its dialog, whose default button (Close) would
        otherwise close the dialog instead of showing the value's effect or its refusal.
        """
        super().keyPressEvent(event)
        if event.key() in (Qt.Key.Key_Return, Qt.Key.Key_Enter):
            self.selectAll()
            event.accept()

    def _on_text_edited(self, _text: str) -> None:
        self.setStyleSheet("")

    def _on_editing_finished(self) -> None:
        text = self.text().strip()
        if text == self._shown:
            return
        try:
            raw = parse_value(self.param, text)
        except ValueRangeError as exc:
            self.setStyleSheet(ERROR_STYLE)
            self._report(error_text(exc))
            return
        if not self._apply(self.mnemonic, raw, text):
            self.setStyleSheet(ERROR_STYLE)


class ChoiceField(QComboBox):
    """An enumerated parameter (signal type, polarity, on/off) as a combo box."""

    def __init__(
        self,
        mnemonic: str,
        apply: Apply,
        codes: Iterable[int] | None = None,
        decorate: Callable[[int, str], str] | None = None,
        parent: QWidget | None = None,
    ) -> None:
        super().__init__(parent)
        self.param = CATALOGUE[mnemonic]
        self._apply = apply
        self._codes = list(codes) if codes is not None else [c for c, _ in self.param.choices]
        self._decorate = decorate or (lambda _code, label: label)
        self.fill()
        self.activated.connect(self._on_activated)

    @property
    def mnemonic(self) -> str:
        """The parameter this field edits."""
        return self.param.mnemonic

    def fill(self) -> None:
        """(Re)build the items in the current language."""
        with QSignalBlocker(self):
            current = self.currentData()
            self.clear()
            for code in self._codes:
                label = self.param.choice_text(code, current_language())
                self.addItem(self._decorate(code, label), code)
            if current is not None:
                self.setCurrentIndex(max(0, self.findData(current)))

    def show_value(self, doc: ParameterDocument) -> None:
        """Select the document's value; an unlisted value is added so nothing is hidden."""
        raw = doc.value(self.mnemonic)
        with QSignalBlocker(self):
            index = self.findData(raw)
            if index < 0 and isinstance(raw, int):
                self.addItem(self.param.choice_text(raw, current_language()), raw)
                index = self.count() - 1
            self.setCurrentIndex(index)

    def update_access(self, access: AccessModel, read_only: bool) -> None:
        """Enable the box if the access level may change the parameter."""
        self.setEnabled(access.may_edit(self.param) and not read_only)
        self.setToolTip(access.why_locked(self.param))

    def _on_activated(self, index: int) -> None:
        self._apply(self.mnemonic, self.itemData(index))

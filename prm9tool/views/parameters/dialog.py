"""Edit one parameter: limits, unit, default and an input field (manual figure 8-19).

The dialog refuses a value the document refuses and shows the reason; it closes only when
the edit went through (as one undo step, or all four ramps at once at Basic level).
"""

from __future__ import annotations

import re

from PySide6.QtCore import QEvent, Signal
from PySide6.QtGui import QFont, QFontMetrics
from PySide6.QtWidgets import (
    QComboBox,
    QDialog,
    QDialogButtonBox,
    QFormLayout,
    QLabel,
    QLineEdit,
    QVBoxLayout,
    QWidget,
)

from prm9tool.catalogue import CATALOGUE, Access, Parameter
from prm9tool.errors import AccessDeniedError, ValueRangeError
from prm9tool.i18n import ambiguous_number, current_language, decimal_point, format_value, text
from prm9tool.model.access import AccessModel
from prm9tool.model.document import ParameterDocument, Raw
from prm9tool.model.editing import allowed_range, apply_edit, linked_mnemonics, range_text
from prm9tool.translate import error_text, translated
from prm9tool.views.diagram.colours import toned_style

# A value and its unit stay on one line when the reason wraps ("2600 mA", not "2600 / mA").
_VALUE_UNIT = re.compile(r"(\d) (?=(?:mA|mV|ms|Hz|V|s|%|°C)\b|%)")


def _unbroken_units(text: str) -> str:
    return _VALUE_UNIT.sub("\\1\u00a0", text)


TITLE_BAR_EXTRA_PX = 150  # a window manager's icon and buttons beside the title


def title_width(dialog: QWidget, title: str) -> int:
    """A width at which the window manager shows ``title`` whole ("Paramete… SETPOSUP" was
    elided in a dialog as narrow as its form, issue 34 item 20): the title in a bold title-bar
    font, and the bar's icon and buttons."""
    font = QFont(dialog.font())
    font.setBold(True)
    return QFontMetrics(font).horizontalAdvance(title) + TITLE_BAR_EXTRA_PX


class ParameterEditDialog(QDialog):
    """Shows a parameter's limits and default and lets the user enter a new value."""

    # The value was taken, but not exactly as typed ("2100.7 mA rounded to 2101 mA …"): the
    # dialog closes, so the parameter list passes this on to the status bar.
    value_rounded = Signal(str)

    def __init__(
        self,
        doc: ParameterDocument,
        access: AccessModel,
        mnemonic: str,
        parent: QWidget | None = None,
    ) -> None:
        super().__init__(parent)
        self._doc = doc
        self._access = access
        self.param: Parameter = CATALOGUE[mnemonic]
        self._editor: QLineEdit | QComboBox = self._make_editor()
        self.error_label = QLabel()
        self.error_label.setWordWrap(True)
        self.error_label.setStyleSheet(toned_style("color: #d03030;", self.palette()))
        self.error_label.hide()
        self._error: Exception | None = None  # the refusal shown, retranslated with the dialog
        self._labels = {name: QLabel() for name in ("current", "range", "default", "hint")}
        self._form_titles = {name: QLabel() for name in ("current", "range", "default", "new")}
        self._buttons = QDialogButtonBox(
            QDialogButtonBox.StandardButton.Ok | QDialogButtonBox.StandardButton.Cancel
        )
        self._buttons.accepted.connect(self._on_accepted)
        self._buttons.rejected.connect(self.reject)
        self._build_layout()
        self.editable = access.may_edit(self.param)
        if not self.editable:
            self._editor.setEnabled(False)
            self._buttons.setStandardButtons(QDialogButtonBox.StandardButton.Close)
        self.retranslate()

    def _make_editor(self) -> QLineEdit | QComboBox:
        value = self._doc.value(self.param.mnemonic)
        if self.param.choices:
            combo = QComboBox()
            for code, label in self.param.choices:
                combo.addItem(f"{code}: {label.get(current_language())}", code)
            combo.setCurrentIndex(max(0, combo.findData(value)))
            return combo
        line = QLineEdit(format_value(self.param, value))
        line.selectAll()
        line.textEdited.connect(lambda _text: self._clear_error())
        return line

    def _build_layout(self) -> None:
        self._heading = QLabel()
        self._heading.setWordWrap(True)
        form = QFormLayout()
        for name in ("current", "range", "default"):
            form.addRow(self._form_titles[name], self._labels[name])
        form.addRow(self._form_titles["new"], self._editor)
        layout = QVBoxLayout(self)
        layout.addWidget(self._heading)
        layout.addLayout(form)
        layout.addWidget(self._labels["hint"])
        layout.addWidget(self.error_label)
        layout.addWidget(self._buttons)
        self._labels["hint"].setWordWrap(True)

    def retranslate(self) -> None:
        """Set every text in the current language."""
        p = self.param
        title = self.tr("Parameter {0}").format(p.mnemonic)
        self.setWindowTitle(title)
        self.setMinimumWidth(title_width(self, title))
        heading = f"<b>[{p.mnemonic}] {text(p.text)}</b>"
        if p.help is not None:
            heading += f"<br>{text(p.help)}"
        self._heading.setText(heading)
        self._form_titles["current"].setText(self.tr("Current value:"))
        self._form_titles["range"].setText(self.tr("Allowed range:"))
        self._form_titles["default"].setText(self.tr("Factory default:"))
        self._form_titles["new"].setText(self.tr("New value:"))
        unit = f" {p.unit}" if p.unit else ""
        self._labels["current"].setText(format_value(p, self._doc.value(p.mnemonic)) + unit)
        self._labels["range"].setText(range_text(p, self._doc))
        self._labels["default"].setText(format_value(p, p.default_for(self._doc.variant)) + unit)
        linked = linked_mnemonics(self._doc, self._access, p.mnemonic)
        hint = ""
        if not self.editable:
            hint = self._lock_reason()
        elif len(linked) > 1:
            hint = self.tr("At Basic access level all ramps are set together: {0}.").format(
                ", ".join(linked)
            )
        self._labels["hint"].setText(hint)
        self._labels["hint"].setVisible(bool(hint))
        if self._error is not None:
            self.error_label.setText(_unbroken_units(error_text(self._error)))

    def _lock_reason(self) -> str:
        if not self.param.writable or self.param.access is Access.READ_ONLY:
            return self.tr("Read-only value of the valve.")
        return self.tr("Can only be changed at Expert access level.")

    def changeEvent(self, event: QEvent) -> None:
        """Retranslate when the program language changes."""
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate()
        super().changeEvent(event)

    def set_text(self, value: str) -> None:
        """Put ``value`` into the input field (choices: select the matching code or label)."""
        if isinstance(self._editor, QComboBox):
            raw = self.param.parse_display(value)
            self._editor.setCurrentIndex(self._editor.findData(raw))
        else:
            self._editor.setText(value)

    def _entered_raw(self) -> Raw:
        if isinstance(self._editor, QComboBox):
            return int(self._editor.currentData())
        entered = self._editor.text()
        ambiguous = ambiguous_number(self.param, entered)
        if ambiguous is not None:
            raise ValueRangeError(ambiguous)
        try:
            raw = self.param.parse_display(entered, decimal_point())
        except ValueRangeError:
            if "," in entered and decimal_point() == ".":
                raise  # the catalogue's words: the decimals follow a point
            raise ValueRangeError(
                self.tr("{0}: “{1}” is not a number.").format(self.param.mnemonic, entered.strip())
            ) from None
        if isinstance(raw, int) and not self.param.raw_min <= raw <= self.param.raw_max:
            unit = f" {self.param.unit}" if self.param.unit else ""
            raise ValueRangeError(
                self.tr("{0}: {1}{2} is outside the allowed range {3}{2}.").format(
                    self.param.mnemonic,
                    entered.strip(),
                    unit,
                    capped_range(self.param, self._doc),
                )
            )
        return raw

    def _on_accepted(self) -> None:
        try:
            raw = self._entered_raw()
            entered = self._editor.text() if isinstance(self._editor, QLineEdit) else None
            note = apply_edit(self._doc, self._access, self.param.mnemonic, raw, entered)
        except (ValueRangeError, AccessDeniedError) as exc:
            self.show_error(exc)
            return
        if note is not None:
            self.value_rounded.emit(translated(note))
        self.accept()

    def show_error(self, error: Exception) -> None:
        """Show why the value was refused (in the program language); the dialog stays open."""
        self._error = error
        self.error_label.setText(_unbroken_units(error_text(self._error)))
        self.error_label.show()
        self.adjustSize()  # room for the wrapped reason without squeezing the form rows

    def _clear_error(self) -> None:
        self._error = None
        self.error_label.hide()


def capped_range(param: Parameter, doc: ParameterDocument) -> str:
    """``0 … 2600`` for LIMTA under CURNORM 2600 mA: the range the dialog shows, without unit."""
    low, high, _cap = allowed_range(param, doc)
    return f"{format_value(param, low)} … {format_value(param, high)}"

"""Common frame of the block dialogs: fields bound to the document, refusals, access lock.

Every change a dialog makes is an undoable document edit (``ParameterDocument.set_value`` /
``set_values`` through :mod:`prm9tool.model.editing`); the diagram and the parameter list observe
the document, and online the main window forwards edits to the valve.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass

from PySide6.QtCore import QCoreApplication, QEvent
from PySide6.QtWidgets import (
    QDialog,
    QDialogButtonBox,
    QFormLayout,
    QHBoxLayout,
    QLabel,
    QVBoxLayout,
    QWidget,
)

from prm9tool.catalogue import CAPPED_BY, CATALOGUE
from prm9tool.errors import AccessDeniedError, ValueRangeError
from prm9tool.i18n import text
from prm9tool.model.access import AccessModel
from prm9tool.model.document import ParameterDocument, Raw
from prm9tool.model.editing import apply_edit
from prm9tool.online.connection_protocol import DiagramConnection, StepSimulation
from prm9tool.translate import error_text, translated
from prm9tool.views.diagram.colours import toned_style
from prm9tool.views.diagram.dialogs.fields import ChoiceField, ValueField, not_on_enter

Field = ValueField | ChoiceField
ERROR_LABEL_STYLE = "color: #d03030; font-weight: bold;"  # a refused entry
NOTE_LABEL_STYLE = "color: #1a5fb4;"  # a remark on an entry that was taken
MAX_SIZE = (1000, 690)  # a 1024 × 768 screen less the title bar and a task bar


SimulatorFactory = Callable[[ParameterDocument, str], StepSimulation]  # (document, loop)


@dataclass
class BlockContext:
    """What a block dialog works on: the document, the access level and (optionally) the valve.

    ``simulator_factory(document, loop)`` returns a step-response simulator (see
    :mod:`prm9tool.online.tuning`); the controller dialogs use it.
    """

    document: ParameterDocument
    access: AccessModel
    connection: DiagramConnection | None = None
    simulator_factory: SimulatorFactory | None = None
    open_tuning: Callable[[str], None] | None = None  # opens the Tuning window for a loop


class BlockDialog(QDialog):
    """A non-modal dialog editing the parameters of one diagram block."""

    DEFAULT_SIZE = (760, 440)

    def __init__(
        self, ctx: BlockContext, block_id: str, title: str, parent: QWidget | None = None
    ) -> None:
        super().__init__(parent)
        self.ctx = ctx
        self.doc = ctx.document
        self.access = ctx.access
        self.block_id = block_id
        self._title_source = title
        self.fields: dict[str, Field] = {}
        self._captions: dict[str, QLabel] = {}  # captions taken from the catalogue texts
        self._watched: set[str] = set()
        self._styles: dict[QWidget, str] = {}  # style sheets written for paper
        self.lock_label = QLabel()
        self.lock_label.setWordWrap(True)
        self.set_paper_style(
            self.lock_label, "background: #f1f1f1; color: #555; padding: 6px; border-radius: 4px;"
        )
        self.error_label = QLabel()
        self.error_label.setWordWrap(True)
        self.set_paper_style(self.error_label, ERROR_LABEL_STYLE)
        self.error_label.hide()
        self.form = QFormLayout()
        self.form.setRowWrapPolicy(QFormLayout.RowWrapPolicy.WrapAllRows)  # caption above field
        self.side = QVBoxLayout()
        self.buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Close)
        self.buttons.rejected.connect(self.close)
        not_on_enter(self.buttons)
        self._assemble()
        self.doc.value_changed.connect(self._on_document_value_changed)
        self.doc.values_reset.connect(self.refresh)
        self.access.level_changed.connect(self._on_access_level_changed)

    def _assemble(self) -> None:
        root = QVBoxLayout(self)
        root.addWidget(self.lock_label)
        body = QHBoxLayout()
        left = QVBoxLayout()
        left.addLayout(self.form)
        left.addStretch(1)
        body.addLayout(left, 0)
        body.addLayout(self.side, 1)
        root.addLayout(body, 1)
        root.addWidget(self.error_label)
        root.addWidget(self.buttons)

    # --- building --------------------------------------------------------------------------
    def value_field(self, mnemonic: str, label: str | None = None) -> ValueField:
        """Add a numeric field for ``mnemonic`` to the form."""
        field = ValueField(mnemonic, self.apply_value, self.show_error)
        self._add(field, label)
        return field

    def choice_field(
        self,
        mnemonic: str,
        codes: Iterable[int] | None = None,
        decorate: Callable[[int, str], str] | None = None,
        label: str | None = None,
    ) -> ChoiceField:
        """Add a combo box for an enumerated ``mnemonic`` to the form."""
        field = ChoiceField(mnemonic, self.apply_value, codes, decorate)
        self._add(field, label)
        return field

    def _add(self, field: Field, label: str | None) -> None:
        self.fields[field.mnemonic] = field
        self.watch(field.mnemonic)
        row = QWidget()
        layout = QHBoxLayout(row)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addWidget(field)
        unit = field.param.unit if isinstance(field, ValueField) else ""
        if unit:
            layout.addWidget(QLabel(unit))
        layout.addStretch(1)
        caption = QLabel(label or text(field.param.text))
        if label is None:
            self._captions[field.mnemonic] = caption
        self.form.addRow(caption, row)

    def set_paper_style(self, widget: QWidget, style: str) -> None:
        """Give ``widget`` the style sheet ``style``, its colours written as on white paper and
        shown moved onto the palette (again whenever the palette changes)."""
        self._styles[widget] = style
        widget.setStyleSheet(toned_style(style, self.palette()))

    def watch(self, *mnemonics: str) -> None:
        """Refresh the dialog when any of ``mnemonics`` changes in the document."""
        self._watched.update(mnemonics)

    def finish(self) -> None:
        """Call at the end of a subclass constructor: fill values, lock state and texts."""
        self.retranslate()
        self._update_access()
        self.refresh()
        self._resize_to_default()

    def _resize_to_default(self) -> None:
        """Open at DEFAULT_SIZE (room for the plot), larger if the content needs it, but
        never beyond a 1024 × 768 screen."""
        hint = self.sizeHint()
        width = min(max(self.DEFAULT_SIZE[0], hint.width()), MAX_SIZE[0])
        height = min(max(self.DEFAULT_SIZE[1], hint.height()), MAX_SIZE[1])
        self.resize(width, height)

    # --- editing -----------------------------------------------------------------------------
    def apply_value(self, mnemonic: str, raw: Raw, entered: str | None = None, /) -> bool:
        """Set one value as the user at the current level would; show the reason if refused,
        or that the value ``entered`` (as typed) was rounded to the parameter's resolution."""
        try:
            note = apply_edit(self.doc, self.access, mnemonic, raw, entered)
        except (ValueRangeError, AccessDeniedError) as exc:
            self.show_error(error_text(exc))
            return False
        if note is None:
            self.clear_error()
        else:
            self.show_note(translated(note))
        return True

    def apply_values(self, values: Mapping[str, Raw], label: str) -> bool:
        """Set several values as ONE undo step after checking access, ranges and rules."""
        try:
            self.check_values(values)
        except (ValueRangeError, AccessDeniedError) as exc:
            self.show_error(error_text(exc))
            return False
        self.doc.set_values(values, label)
        self.clear_error()
        return True

    def check_values(self, values: Mapping[str, Raw]) -> None:
        """Raise AccessDeniedError / ValueRangeError if ``values`` may not be set together."""
        trial = {**self.doc.values, **values}
        for mnemonic, raw in values.items():
            param = CATALOGUE[mnemonic]
            if not self.access.may_edit(param):
                raise AccessDeniedError(self.access.why_locked(param))
            cap = CAPPED_BY.get(mnemonic)  # LIMTA: 0 … CURNORM, as every editor says
            param.check_raw(raw, trial.get(cap) if cap else None)
        for problem in CATALOGUE.check_rules(self.doc.variant, trial):
            if problem.severity == "error" and set(problem.mnemonics) & set(values):
                raise ValueRangeError(problem.message)

    def show_error(self, message: str) -> None:
        """Show why an entry was refused."""
        self.set_paper_style(self.error_label, ERROR_LABEL_STYLE)
        self.error_label.setText(message)
        self.error_label.show()

    def show_note(self, message: str) -> None:
        """Show a remark on an entry that was taken (where a refusal would be, not in red)."""
        self.set_paper_style(self.error_label, NOTE_LABEL_STYLE)
        self.error_label.setText(message)
        self.error_label.show()

    def clear_error(self) -> None:
        """Hide the refusal message."""
        self.error_label.clear()
        self.error_label.hide()

    # --- state ---------------------------------------------------------------------------------
    @property
    def read_only(self) -> bool:
        """True when the access level may change none of the block's parameters."""
        params = [CATALOGUE[mn] for mn in self._watched if mn in CATALOGUE]
        return not any(self.access.may_edit(p) for p in params)

    def refresh(self) -> None:
        """Show the document's values in every field and redraw."""
        for field in self.fields.values():
            field.show_value(self.doc)
        self.refresh_extra()

    def refresh_extra(self) -> None:
        """Hook: redraw plots and other derived widgets."""

    def _update_access(self) -> None:
        read_only = self.read_only
        for field in self.fields.values():
            field.update_access(self.access, read_only)
        if read_only:
            names = [*self.fields, *sorted(self._watched)]
            locked = next((CATALOGUE[mn] for mn in names if CATALOGUE[mn].writable), None)
            reason = self.access.why_locked(locked) if locked is not None else ""
            self.lock_label.setText(
                self.tr("Read only: %1 (View → Access level)").replace("%1", reason)
            )
        self.lock_label.setVisible(read_only)
        self.update_access_extra(read_only)

    def update_access_extra(self, read_only: bool) -> None:
        """Hook: enable or disable graphical editing."""

    def retranslate(self) -> None:
        """Set the window title (and subclass texts) in the current language."""
        self.setWindowTitle(QCoreApplication.translate("DiagramBlock", self._title_source))

    def changeEvent(self, event: QEvent) -> None:
        if event.type() in (QEvent.Type.PaletteChange, QEvent.Type.ApplicationPaletteChange):
            for widget, style in self._styles.items():
                widget.setStyleSheet(toned_style(style, self.palette()))
        elif event.type() == QEvent.Type.LanguageChange:
            self.retranslate()
            for mnemonic, caption in self._captions.items():
                caption.setText(text(CATALOGUE[mnemonic].text))
            for field in self.fields.values():
                if isinstance(field, ChoiceField):
                    field.fill()
            self.refresh()
        super().changeEvent(event)

    def _on_document_value_changed(self, mnemonic: str) -> None:
        if mnemonic in self._watched:
            self.refresh()

    def _on_access_level_changed(self, _level: object) -> None:
        self._update_access()
        self.refresh()

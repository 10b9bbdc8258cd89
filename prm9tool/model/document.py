"""The parameter document: a valve's parameter set being edited, with undo/redo.

The document holds raw values (as the object dictionary does) for every parameter of its
variant that belongs in a *.prm file, plus the read-only values last read from a valve. It
emits Qt signals (QtCore only) so views can observe it; every user edit is one QUndoCommand.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from pathlib import Path

from PySide6.QtCore import QObject, Signal

from prm9tool.catalogue import CATALOGUE, Parameter, Problem, variant_label
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.catalogue.variant import Variant
from prm9tool.errors import ValueRangeError
from prm9tool.i18n import format_value
from prm9tool.messages import QT_TRANSLATE_NOOP, Message

Raw = int | str


@dataclass
class Edit:
    """One user edit as data: what changes, and how to go back (the undo layer stores these).

    ``text`` names the edit (the undo command's text): a translated string from a view, or a
    :class:`~prm9tool.messages.Message` from the model layer.
    """

    text: str | Message
    new: dict[str, Raw]
    old: dict[str, Raw]
    new_key: TypeKey | None = None
    old_key: TypeKey | None = None
    replace: bool = field(default=False)  # True: ``new`` replaces the whole value set


class ParameterDocument(QObject):
    """A parameter set for one valve type; the model every view observes."""

    value_changed = Signal(str)  # mnemonic; emitted once per changed value
    values_reset = Signal()  # many values or the type key changed at once
    type_key_changed = Signal(str)
    modified_changed = Signal(bool)
    path_changed = Signal(str)
    source_changed = Signal()  # source_serial / source_firmware: the valve it belongs to
    validity_changed = Signal()  # problems() may have changed

    def __init__(self, type_key: TypeKey | str, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self._type_key = TypeKey.parse(type_key) if isinstance(type_key, str) else type_key
        self._values: dict[str, Raw] = self._factory_values(self._type_key)
        self._live: dict[str, Raw] = {}
        self._path: Path | None = None
        self.source_serial: int | None = None
        self.source_firmware: str | None = None
        self.unknown_entries: list[tuple[str, str]] = []  # kept from files, written back
        # Comment lines before each file entry, and the comment after its value (prmfile.py);
        # kept from files and written back so that comments survive a load/save round trip.
        self.comments: dict[str, list[str]] = {}
        self.inline_comments: dict[str, str] = {}
        self._saved: tuple[TypeKey, dict[str, Raw]] = (self._type_key, dict(self._values))
        self._was_modified = False
        self._edit_sink: Callable[[Edit], None] | None = None

    # --- properties ------------------------------------------------------------------
    @property
    def type_key(self) -> TypeKey:
        """The valve type this document is for."""
        return self._type_key

    @property
    def variant(self) -> Variant:
        """The electronics variant derived from the type key."""
        return self._type_key.variant

    @property
    def values(self) -> Mapping[str, Raw]:
        """Raw values of the file parameter set (read-only view)."""
        return self._values

    @property
    def path(self) -> Path | None:
        """The file the document was loaded from or saved to."""
        return self._path

    def set_source(self, serial: int | None, firmware: str | None) -> None:
        """The valve the values were last read from or written to (SNV, FWVER offline; the
        serial a file is saved with): not an edit, not undoable, not a modification."""
        if (serial, firmware) == (self.source_serial, self.source_firmware):
            return
        self.source_serial, self.source_firmware = serial, firmware
        self.source_changed.emit()

    @property
    def file_type_key(self) -> TypeKey | None:
        """The valve type of the file at :attr:`path` (as last opened or saved), None
        without a file: Save writes into that file only while the document is of its type."""
        return self._saved[0] if self._path is not None else None

    def detach_file(self) -> None:
        """The document becomes a new, unsaved one (its values kept): the file it came from
        stays as it is, and Save asks for a name."""
        if self._path is None:
            return
        self._path = None
        self.path_changed.emit("")
        self._emit_modified()

    @property
    def modified(self) -> bool:
        """True when the values differ from the last load/save (undo back to it clears it)."""
        return (self._type_key, self._values) != self._saved

    def set_edit_sink(self, sink: Callable[[Edit], None] | None) -> None:
        """Route edits through ``sink`` (the undo stack), which must call :meth:`redo_edit`."""
        self._edit_sink = sink

    def redo_edit(self, edit: Edit) -> None:
        """Apply an edit (used by the undo layer and when no undo layer is attached)."""
        if edit.new_key is not None:
            self._replace(edit.new_key, edit.new)
        else:
            self._apply(edit.new)

    def undo_edit(self, edit: Edit) -> None:
        """Revert an edit."""
        if edit.old_key is not None:
            self._replace(edit.old_key, edit.old)
        else:
            self._apply(edit.old)

    def _commit(self, edit: Edit) -> None:
        if self._edit_sink is not None:
            self._edit_sink(edit)
        else:
            self.redo_edit(edit)

    def parameters(self) -> list[Parameter]:
        """The file parameters of this document's variant, in catalogue order."""
        return CATALOGUE.file_parameters(self.variant)

    # --- values ----------------------------------------------------------------------------
    def value(self, mnemonic: str) -> Raw:
        """Raw value of a file parameter, or the last live/read-only value, or its default."""
        if mnemonic in self._values:
            return self._values[mnemonic]
        if mnemonic in self._live:
            return self._live[mnemonic]
        return CATALOGUE[mnemonic].default_for(self.variant)

    def display(self, mnemonic: str) -> str:
        """The value as shown to a user (shortest exact decimal, in display units, with the
        decimal separator of the program language)."""
        return format_value(CATALOGUE[mnemonic], self.value(mnemonic))

    def is_default(self, mnemonic: str) -> bool:
        """True if the value equals the factory default of this variant."""
        return self.value(mnemonic) == CATALOGUE[mnemonic].default_for(self.variant)

    def validate(self, mnemonic: str, raw: Raw) -> None:
        """Raise ValueRangeError if ``raw`` may not be set (range, existence, cross rules)."""
        param = CATALOGUE.get(mnemonic)
        if param is None or mnemonic not in self._values:
            raise ValueRangeError(
                QT_TRANSLATE_NOOP("Problems", "{0}: no such parameter on a {1} valve")(
                    mnemonic, variant_label(self.variant)
                )
            )
        param.check_raw(raw)
        trial = dict(self._values)
        trial[mnemonic] = raw
        trial.update({k: v for k, v in self._live.items() if k == "CURNORM"})
        errors = [
            p
            for p in CATALOGUE.check_rules(self.variant, trial)
            if p.severity == "error" and mnemonic in p.mnemonics
        ]
        if errors:
            raise ValueRangeError(errors[0].text)

    def set_value(self, mnemonic: str, raw: Raw, text: str | None = None) -> None:
        """Set one value as one undoable user edit; raises ValueRangeError with the reason."""
        self.validate(mnemonic, raw)
        if self._values[mnemonic] == raw:
            return
        label = text or f"{mnemonic} = {format_value(CATALOGUE[mnemonic], raw)}"
        self._commit(Edit(label, {mnemonic: raw}, {mnemonic: self._values[mnemonic]}))

    def set_values(
        self, values: Mapping[str, Raw], text: str | Message, validate: bool = True
    ) -> None:
        """Set many values as ONE undoable step (e.g. "Download from valve", "all ramps")."""
        changed = {
            mn: v for mn, v in values.items() if mn in self._values and self._values[mn] != v
        }
        if validate:
            for mn, v in changed.items():
                CATALOGUE[mn].check_raw(v)
        if changed:
            self._commit(Edit(text, changed, {mn: self._values[mn] for mn in changed}))

    def set_type_key(self, key: TypeKey | str) -> None:
        """Change the valve type: one undoable step; values become that type's defaults."""
        key = TypeKey.parse(key) if isinstance(key, str) else key
        if key == self._type_key:
            return
        self._commit(
            Edit(
                QT_TRANSLATE_NOOP("Edits", "Valve selection {0}")(str(key)),
                self._factory_values(key),
                dict(self._values),
                new_key=key,
                old_key=self._type_key,
            )
        )

    def set_live(self, values: Mapping[str, Raw]) -> None:
        """Record read-only values read from a valve (not undoable, not a modification)."""
        for mn, v in values.items():
            if self._live.get(mn) != v:
                self._live[mn] = v
                self.value_changed.emit(mn)

    def problems(self) -> list[Problem]:
        """Cross-parameter problems of the current values (errors and warnings)."""
        values = dict(self._values)
        if "CURNORM" in self._live:
            values["CURNORM"] = self._live["CURNORM"]
        return CATALOGUE.check_rules(self.variant, values)

    def unsaved_mnemonics(self) -> list[str]:
        """The parameters whose value differs from the one last saved (or opened)."""
        saved = self._saved[1]
        return [mn for mn, value in self._values.items() if saved.get(mn) != value]

    def mark_saved(self, path: Path | None = None) -> None:
        """Record that the document now equals the file at ``path``."""
        if path is not None and path != self._path:
            self._path = path
            self.path_changed.emit(str(path))
        self._saved = (self._type_key, dict(self._values))
        self._emit_modified()

    def replace_with(self, other: ParameterDocument) -> None:
        """Take over everything ``other`` holds (file opened, new valve type); not undoable.

        The main window keeps one document object for its lifetime so that every view stays
        connected to it; live values read from a valve are kept.
        """
        path_differs = self._path != other._path
        self._type_key = other._type_key
        self._values = dict(other._values)
        self._path = other._path
        self.source_serial = other.source_serial
        self.source_firmware = other.source_firmware
        self.unknown_entries = list(other.unknown_entries)
        self.comments = {name: list(lines) for name, lines in other.comments.items()}
        self.inline_comments = dict(other.inline_comments)
        self._saved = (other._saved[0], dict(other._saved[1]))
        # Every field is taken over before any view hears of it: a failing view must not
        # leave the document half replaced or the modified state unannounced.
        self._emit_modified()
        self.type_key_changed.emit(str(self._type_key))
        self.values_reset.emit()
        self.validity_changed.emit()
        if path_differs:
            self.path_changed.emit(str(self._path) if self._path is not None else "")

    def _emit_modified(self) -> None:
        if self.modified != self._was_modified:
            self._was_modified = self.modified
            self.modified_changed.emit(self._was_modified)

    # --- internals used by the undo commands ------------------------------------------------
    def _apply(self, values: Mapping[str, Raw]) -> None:
        for mn, v in values.items():
            self._values[mn] = v
        if len(values) > 8:
            self.values_reset.emit()
        else:
            for mn in values:
                self.value_changed.emit(mn)
        self.validity_changed.emit()
        self._emit_modified()

    def _replace(self, key: TypeKey, values: Mapping[str, Raw]) -> None:
        self._type_key = key
        self._values = dict(values)
        self.type_key_changed.emit(str(key))
        self.values_reset.emit()
        self.validity_changed.emit()
        self._emit_modified()

    @staticmethod
    def _factory_values(key: TypeKey) -> dict[str, Raw]:
        return {
            p.mnemonic: p.default_for(key.variant) for p in CATALOGUE.file_parameters(key.variant)
        }

"""Undo/redo of document edits through Qt's undo framework (QUndoStack lives in QtGui)."""

from __future__ import annotations

from PySide6.QtCore import QObject
from PySide6.QtGui import QUndoCommand, QUndoStack

from prm9tool.model.document import Edit, ParameterDocument
from prm9tool.translate import translated


class _EditCommand(QUndoCommand):
    def __init__(self, doc: ParameterDocument, edit: Edit) -> None:
        super().__init__(translated(edit.text))
        self._doc = doc
        self._edit = edit

    def redo(self) -> None:
        self._doc.redo_edit(self._edit)

    def undo(self) -> None:
        self._doc.undo_edit(self._edit)


class DocumentUndo(QObject):
    """Owns the QUndoStack of one document: every document edit becomes one undo command."""

    def __init__(self, doc: ParameterDocument, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self.doc = doc
        self.stack = QUndoStack(self)
        doc.set_edit_sink(self._push)

    def _push(self, edit: Edit) -> None:
        self.stack.push(_EditCommand(self.doc, edit))

    def detach(self) -> None:
        """Stop recording edits (e.g. when the document is replaced)."""
        self.doc.set_edit_sink(None)
        self.stack.clear()

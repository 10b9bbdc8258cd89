"""A *.prm file as a parameter document and back: the one place the file format meets the model.

:mod:`prm9tool.files.prmfile` reads and writes files without Qt; the document being edited
(:class:`prm9tool.model.document.ParameterDocument`) is a QtCore object the views bind to, so
turning one into the other lives here, apart (the import-linter contract that keeps ``files``
free of Qt names this module as its one exception).
"""

from __future__ import annotations

import os
from pathlib import Path

from prm9tool.files.prmfile import PrmContents, read_file, write_file
from prm9tool.model.document import ParameterDocument


def document_from(contents: PrmContents, path: Path | None = None) -> ParameterDocument:
    """A new, unmodified document holding ``contents`` (``path``: where it was read from)."""
    doc = ParameterDocument(contents.type_key)
    doc.set_values(contents.values, "Open file", validate=False)
    doc.source_serial = contents.serial
    doc.source_firmware = contents.firmware
    doc.unknown_entries = list(contents.unknown)
    doc.comments = {name: list(lines) for name, lines in contents.comments.items()}
    doc.inline_comments = dict(contents.inline_comments)
    doc.mark_saved(path)
    return doc


def contents_of(doc: ParameterDocument) -> PrmContents:
    """What saving ``doc`` writes."""
    return PrmContents(
        doc.type_key,
        dict(doc.values),
        doc.source_serial,
        doc.source_firmware,
        list(doc.unknown_entries),
        {name: list(lines) for name, lines in doc.comments.items()},
        dict(doc.inline_comments),
    )


def load_document(path: str | os.PathLike[str]) -> ParameterDocument:
    """Read a *.prm file into a new document; raises FileFormatError with every problem."""
    return document_from(read_file(path), Path(path))


def save_document(doc: ParameterDocument, path: str | os.PathLike[str]) -> None:
    """Save ``doc`` atomically, keep the old file as ``.bak``, mark the document saved."""
    written = write_file(contents_of(doc), path)
    doc.comments = written.comments  # so that the next save reproduces this file exactly
    doc.inline_comments = written.inline_comments
    doc.mark_saved(Path(path))

"""The printed parameter record: header, every parameter with its unit, the diagram picture,
a signature line; on every page type key, serial number and the page number.

The same QTextDocument is printed (print dialog) and written to PDF, so the two agree. Values
that differ from the file the record names are marked: a record of unsaved edits must not pass
for the file's contents.
"""

from __future__ import annotations

import html
from collections.abc import Callable
from dataclasses import dataclass
from datetime import datetime
from pathlib import Path

from PySide6.QtCore import QCoreApplication, QRectF, QUrl
from PySide6.QtGui import QImage, QPageLayout, QPainter, QTextDocument
from PySide6.QtPrintSupport import QPrinter

from prm9tool.i18n import current_language, format_value, text
from prm9tool.model.document import ParameterDocument
from prm9tool.views.paged_print import (
    A4_LAYOUT,
    PageFrame,
    body_size,
    configure_pdf,
    print_paged,
)

__all__ = ["A4_LAYOUT", "RecordHeader", "build_record", "configure_pdf", "record_frame"]
translate = QCoreApplication.translate
DiagramPainter = Callable[[QPainter, QRectF], None]
DIAGRAM_URL = "prm9tool://diagram.png"
UNSAVED_MARK = "*"


@dataclass
class RecordHeader:
    """What the record's header shows besides the document's own data."""

    access_level: str
    serial: str = ""
    firmware: str = ""
    date: datetime | None = None


def record_rows(doc: ParameterDocument) -> list[tuple[str, str, str, str]]:
    """(mnemonic, description, value, unit) of every file parameter, in catalogue order; a
    value not saved in the document's file ends in :data:`UNSAVED_MARK`."""
    rows = []
    unsaved = set(doc.unsaved_mnemonics()) if doc.path is not None else set()
    for param in doc.parameters():
        raw = doc.value(param.mnemonic)
        value = format_value(param, raw)
        if param.choices and isinstance(raw, int):
            value = f"{raw}: {param.choice_text(raw, current_language())}"
        if param.mnemonic in unsaved:
            value += f" {UNSAVED_MARK}"
        rows.append((param.mnemonic, text(param.text), value, param.unit))
    return rows


def record_file_stem(type_key: str, serial: str = "") -> str:
    """A file name (without suffix) for a record or report: type key and serial number.

    The type key's "/" would make a folder; its dots stay (a name ends in ".pdf").
    """
    key = type_key.replace("/", "_").replace("\\", "_")
    return f"{key}_{serial}" if serial else key


def record_frame(doc: ParameterDocument, header: RecordHeader) -> PageFrame:
    """What each page of the record repeats: the valve, the title, the file and the date."""
    serial = _serial(doc, header)
    subject = str(doc.type_key)
    if serial != "—":
        subject += " · " + translate("Record", "serial number {0}").format(serial)
    return PageFrame(
        subject,
        translate("Record", "PRM9 parameter record"),
        f"{_file_name(doc)} · {_date(header)}",
    )


def _serial(doc: ParameterDocument, header: RecordHeader) -> str:
    return header.serial or (str(doc.source_serial) if doc.source_serial else "—")


def _date(header: RecordHeader) -> str:
    return (header.date or datetime.now()).strftime("%Y-%m-%d %H:%M")


def _file_name(doc: ParameterDocument) -> str:
    return str(doc.path) if doc.path else translate("Record", "untitled")


def _file_fact(doc: ParameterDocument) -> str:
    """The file line: the file, and whether the values printed are what it holds."""
    if doc.path is None:
        return translate("Record", "untitled (the values are not saved in a file)")
    if not doc.modified:
        return str(doc.path)
    if not doc.unsaved_mnemonics():  # another valve type than the file's
        return translate("Record", "{0} (changed, not saved: the file holds another valve type)"
                         ).format(str(doc.path))  # fmt: skip
    return translate(
        "Record", "{0} (changed, not saved: the values marked {1} differ from the file)"
    ).format(str(doc.path), UNSAVED_MARK)


def build_record(
    doc: ParameterDocument,
    header: RecordHeader,
    diagram: DiagramPainter | None = None,
    layout: QPageLayout = A4_LAYOUT,
) -> QTextDocument:
    """The record as a text document laid out on the pages of ``layout``, ready to print."""
    record = QTextDocument()
    record.setDocumentMargin(0)
    size = body_size(layout)
    record.setPageSize(size)
    if diagram is not None:
        record.addResource(
            QTextDocument.ResourceType.ImageResource, QUrl(DIAGRAM_URL), _picture(diagram)
        )
    record.setHtml(_html(doc, header, size.width() if diagram is not None else None))
    return record


def _picture(diagram: DiagramPainter) -> QImage:
    image = QImage(2000, 1000, QImage.Format.Format_ARGB32)
    image.fill(0xFFFFFFFF)
    painter = QPainter(image)
    painter.setRenderHint(QPainter.RenderHint.Antialiasing)
    diagram(painter, QRectF(0, 0, image.width(), image.height()))
    painter.end()
    return _trimmed(image)


def _trimmed(image: QImage, margin: int = 12) -> QImage:
    """The image without its white border (the diagram keeps its aspect inside the target)."""
    import numpy as np  # printing only; not needed to start the program

    pixels = np.frombuffer(image.constBits(), np.uint32, image.width() * image.height())
    ink = np.argwhere(pixels.reshape(image.height(), image.width()) != 0xFFFFFFFF)
    if not len(ink):
        return image
    (top, left), (bottom, right) = ink.min(axis=0), ink.max(axis=0)
    top, left = max(0, top - margin), max(0, left - margin)
    bottom = min(image.height() - 1, bottom + margin)
    right = min(image.width() - 1, right + margin)
    return image.copy(int(left), int(top), int(right - left + 1), int(bottom - top + 1))


def _html(doc: ParameterDocument, header: RecordHeader, picture_width: float | None) -> str:
    t = html.escape
    firmware = header.firmware or doc.source_firmware or "—"
    facts = [
        (translate("Record", "Type key"), str(doc.type_key)),
        (translate("Record", "Serial number"), _serial(doc, header)),
        (translate("Record", "Firmware"), firmware),
        (translate("Record", "File"), _file_fact(doc)),
        (translate("Record", "Date"), _date(header)),
        (translate("Record", "Access level"), header.access_level),
    ]
    head = "".join(f"<tr><td><b>{t(k)}:</b></td><td>{t(v)}</td></tr>" for k, v in facts)
    rows = "".join(
        f"<tr><td>{t(mn)}</td><td>{t(desc)}</td><td align='right'>{t(value)}</td>"
        f"<td>{t(unit)}</td></tr>"
        for mn, desc, value, unit in record_rows(doc)
    )
    picture = ""
    if picture_width is not None:  # the whole text width, never wider (a pixel spare)
        picture = f"<p><img src='{DIAGRAM_URL}' width='{int(picture_width) - 1}'></p>"
    titles = (
        translate("Record", "Mnemonic"),
        translate("Record", "Description"),
        translate("Record", "Value"),
        translate("Record", "Unit"),
    )
    heading = "".join(f"<th align='left'>{t(title)}</th>" for title in titles)
    return (
        f"<h2>{t(translate('Record', 'PRM9 parameter record'))}</h2>"
        f"<table cellspacing='2'>{head}</table>{picture}"
        f"<table border='1' cellspacing='0' cellpadding='3' width='100%' style='border-collapse: collapse; border-color: #808080'>"
        f"<thead><tr>{heading}</tr></thead>{rows}</table>{signature_line()}"
    )


def signature_line() -> str:
    """Date, name and signature of whoever checked the record, to be filled in by hand."""
    blank = "_" * 22
    cells = "".join(
        f"<td>{html.escape(label)} {blank}</td>"
        for label in (
            translate("Record", "Date:"),
            translate("Record", "Name:"),
            translate("Record", "Signature:"),
        )
    )
    return f"<p>&nbsp;</p><table width='100%' cellspacing='0'><tr>{cells}</tr></table>"


def write_pdf(record: QTextDocument, path: Path, title: str, frame: PageFrame) -> None:
    """Write ``record`` as a PDF of :data:`A4_LAYOUT` pages, each with ``frame``, to ``path``.

    Raises OSError if it cannot be written.
    """
    printer = QPrinter(QPrinter.PrinterMode.HighResolution)
    configure_pdf(printer, path, title)
    print_paged(record, printer, frame)
    if not path.exists() or path.stat().st_size == 0:
        raise OSError(f"cannot write {path}")

"""The printed parameter record: header, every parameter with its unit, the diagram picture.

The same QTextDocument is printed (print dialog) and written to PDF, so the two agree.
"""

from __future__ import annotations

import html
from collections.abc import Callable
from dataclasses import dataclass
from datetime import datetime
from pathlib import Path

from PySide6.QtCore import QCoreApplication, QMarginsF, QRectF, QSizeF, QUrl
from PySide6.QtGui import (
    QGuiApplication,
    QImage,
    QPageLayout,
    QPageSize,
    QPainter,
    QTextDocument,
)
from PySide6.QtPrintSupport import QPrinter

from prm9tool.i18n import current_language, format_value, text
from prm9tool.model.document import ParameterDocument

translate = QCoreApplication.translate
DiagramPainter = Callable[[QPainter, QRectF], None]
DIAGRAM_URL = "prm9tool://diagram.png"
A4_LAYOUT = QPageLayout(
    QPageSize(QPageSize.PageSizeId.A4),
    QPageLayout.Orientation.Portrait,
    QMarginsF(15, 15, 15, 15),
    QPageLayout.Unit.Millimeter,
)


@dataclass
class RecordHeader:
    """What the record's header shows besides the document's own data."""

    access_level: str
    serial: str = ""
    firmware: str = ""
    date: datetime | None = None


def record_rows(doc: ParameterDocument) -> list[tuple[str, str, str, str]]:
    """(mnemonic, description, value, unit) of every file parameter, in catalogue order."""
    rows = []
    for param in doc.parameters():
        raw = doc.value(param.mnemonic)
        value = format_value(param, raw)
        if param.choices and isinstance(raw, int):
            value = f"{raw}: {param.choice_text(raw, current_language())}"
        rows.append((param.mnemonic, text(param.text), value, param.unit))
    return rows


def page_size(layout: QPageLayout) -> QSizeF:
    """The printable part of a page in the units a text document lays out in (screen pixels).

    A record laid out on this page size is printed page by page as it is, scaled to the
    printer's page. Without a page size ``QTextDocument.print_`` adds margins of its own and
    a picture as wide as the text overflowed the page (issue 14, item 3).
    """
    screen = QGuiApplication.primaryScreen()
    dpi = screen.logicalDotsPerInchX() if screen is not None else 96.0
    points = layout.paintRect(QPageLayout.Unit.Point).size()
    return QSizeF(points.width() * dpi / 72, points.height() * dpi / 72)


def build_record(
    doc: ParameterDocument,
    header: RecordHeader,
    diagram: DiagramPainter | None = None,
    layout: QPageLayout = A4_LAYOUT,
) -> QTextDocument:
    """The record as a text document laid out on the pages of ``layout``, ready to print."""
    record = QTextDocument()
    record.setDocumentMargin(0)
    size = page_size(layout)
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
    date = (header.date or datetime.now()).strftime("%Y-%m-%d %H:%M")
    file_name = str(doc.path) if doc.path else translate("Record", "untitled")
    serial = header.serial or (str(doc.source_serial) if doc.source_serial else "—")
    firmware = header.firmware or doc.source_firmware or "—"
    facts = [
        (translate("Record", "Type key"), str(doc.type_key)),
        (translate("Record", "Serial number"), serial),
        (translate("Record", "Firmware"), firmware),
        (translate("Record", "File"), file_name),
        (translate("Record", "Date"), date),
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
        f"<table border='1' cellspacing='0' cellpadding='3' width='100%'>"
        f"<thead><tr>{heading}</tr></thead>{rows}</table>"
    )


def configure_pdf(printer: QPrinter, path: Path, title: str) -> None:
    """Make ``printer`` write a PDF of :data:`A4_LAYOUT` pages to ``path``."""
    printer.setOutputFormat(QPrinter.OutputFormat.PdfFormat)
    printer.setOutputFileName(str(path))
    printer.setDocName(title)
    printer.setCreator("prm9tool")
    printer.setPageLayout(A4_LAYOUT)


def write_pdf(record: QTextDocument, path: Path, title: str) -> None:
    """Write ``record`` (built for :data:`A4_LAYOUT`) as a PDF to ``path``.

    Raises OSError if it cannot be written.
    """
    printer = QPrinter(QPrinter.PrinterMode.HighResolution)
    configure_pdf(printer, path, title)
    record.print_(printer)
    if not path.exists() or path.stat().st_size == 0:
        raise OSError(f"cannot write {path}")

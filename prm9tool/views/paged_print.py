"""Printing a text document page by page, each page with a running header and footer.

The parameter record and the test report go to paper (or PDF) the same way: the document is
laid out on the page's printable part less a header and a footer band, and each page is
painted with the header (what the record is about: type key and serial number, and its title)
and the footer (file and date, "Page 2 of 3"). ``QTextDocument.print_`` alone numbers the
pages but repeats nothing of the header, so page 2 of a record did not say which valve it
belonged to (issue 25, item 9).
"""

from __future__ import annotations

import html
import os
from dataclasses import dataclass

from PySide6.QtCore import QCoreApplication, QMarginsF, QPointF, QRectF, QSizeF
from PySide6.QtGui import (
    QAbstractTextDocumentLayout,
    QColor,
    QGuiApplication,
    QPageLayout,
    QPageSize,
    QPainter,
    QPalette,
    QPen,
    QTextDocument,
    QTextFrame,
    QTextTable,
)
from PySide6.QtPrintSupport import QPrinter

translate = QCoreApplication.translate
MARGIN_MM = 15.0
BAND_MM = 9.0  # the header's and the footer's height, taken from the printable part
A4_LAYOUT = QPageLayout(
    QPageSize(QPageSize.PageSizeId.A4),
    QPageLayout.Orientation.Portrait,
    QMarginsF(MARGIN_MM, MARGIN_MM, MARGIN_MM, MARGIN_MM),
    QPageLayout.Unit.Millimeter,
)


@dataclass(frozen=True)
class PageFrame:
    """What every page repeats: the header's left and right text, the footer's left text
    (the right one is the page number)."""

    subject: str  # e.g. "PRM9-06.3Z11/30-24E02S02 · serial number 4711"
    title: str  # e.g. "PRM9 parameter record"
    footer: str = ""  # e.g. the file and the date


def layout_dpi() -> float:
    """The resolution a text document lays out in (the screen's logical DPI)."""
    screen = QGuiApplication.primaryScreen()
    return screen.logicalDotsPerInchX() if screen is not None else 96.0


def printable_size(layout: QPageLayout) -> QSizeF:
    """The printable part of a page in the units a text document lays out in."""
    points = layout.paintRect(QPageLayout.Unit.Point).size()
    scale = layout_dpi() / 72
    return QSizeF(points.width() * scale, points.height() * scale)


def body_size(layout: QPageLayout) -> QSizeF:
    """The part of a page that holds the document: printable less header and footer."""
    page = printable_size(layout)
    return QSizeF(page.width(), page.height() - 2 * _band())


def _band() -> float:
    return BAND_MM / 25.4 * layout_dpi()


def configure_pdf(printer: QPrinter, path: str | os.PathLike[str], title: str) -> None:
    """Make ``printer`` write a PDF of :data:`A4_LAYOUT` pages to ``path``."""
    printer.setOutputFormat(QPrinter.OutputFormat.PdfFormat)
    printer.setOutputFileName(os.fspath(path))
    printer.setDocName(title)
    printer.setCreator("prm9tool")
    printer.setPageLayout(A4_LAYOUT)


def print_paged(document: QTextDocument, printer: QPrinter, frame: PageFrame) -> int:
    """Print ``document`` on ``printer``'s pages with ``frame``; returns the page count.

    The document is laid out anew on the printer's page (less the two bands); its pictures
    should be no wider than :func:`body_size`.
    """
    page = printable_size(printer.pageLayout())
    band = _band()
    body = QSizeF(page.width(), page.height() - 2 * band)
    document.setPageSize(body)
    pages = document.pageCount()
    cuts = page_cuts(document, body.height(), pages)
    painter = QPainter(printer)
    try:
        scale = printer.width() / page.width()  # device pixels per layout unit
        painter.scale(scale, scale)
        for index in range(pages):
            if index and not printer.newPage():
                raise OSError("the printer refused a new page")
            _paint_body(painter, document, body, band, index, cuts[index])
            _paint_bands(painter, frame, page, band, index, pages)
    finally:
        painter.end()
    return pages


@dataclass(frozen=True)
class Cut:
    """Where a page's body ends: at ``y`` (document units), with a table's bottom border from
    ``left`` to ``right`` drawn there when a table goes on on the next page."""

    y: float
    left: float = 0.0
    right: float = 0.0


def page_cuts(document: QTextDocument, height: float, pages: int) -> list[Cut]:
    """Each page's end. Where a table goes on on the next page, Qt stretches the page's last
    row down to the page's end: that page ends below the row's text instead."""
    cuts = [Cut((index + 1) * height) for index in range(pages)]
    layout = document.documentLayout()
    for table in tables_in(document.rootFrame()):
        edge = table.format().cellPadding() + table.format().border()
        first = layout.blockBoundingRect(table.cellAt(0, 0).firstCursorPosition().block())
        last = table.cellAt(0, table.columns() - 1).firstCursorPosition().block()
        left, right = first.left() - edge, layout.blockBoundingRect(last).right() + edge
        for row in range(table.rows() - 1):
            top, bottom = row_top(document, table, row), _row_bottom(document, table, row)
            page = int(top // height)
            if page < pages and row_top(document, table, row + 1) >= (page + 1) * height:
                cuts[page] = Cut(min(bottom, cuts[page].y), left, right)
    return cuts


def tables_in(frame: QTextFrame) -> list[QTextTable]:
    """Every table inside ``frame``, nested ones too."""
    found: list[QTextTable] = []
    for child in frame.childFrames():
        if isinstance(child, QTextTable):
            found.append(child)
        found.extend(tables_in(child))
    return found


def row_top(document: QTextDocument, table: QTextTable, row: int) -> float:
    """Where the text of ``table``'s row ``row`` starts (document units)."""
    block = table.cellAt(row, 0).firstCursorPosition().block()
    return document.documentLayout().blockBoundingRect(block).top()


def _row_bottom(document: QTextDocument, table: QTextTable, row: int) -> float:
    """Below the text of the row's tallest cell, its padding and border included."""
    layout, style = document.documentLayout(), table.format()
    bottoms = [
        layout.blockBoundingRect(table.cellAt(row, column).lastCursorPosition().block()).bottom()
        for column in range(table.columns())
    ]
    return max(bottoms) + style.cellPadding() + style.border()


def _paint_body(
    painter: QPainter, document: QTextDocument, body: QSizeF, band: float, index: int, cut: Cut
) -> None:
    painter.save()
    top = index * body.height()
    painter.translate(0, band - top)
    view = QRectF(0, top, body.width(), cut.y - top)
    painter.setClipRect(view)
    context = QAbstractTextDocumentLayout.PaintContext()
    context.clip = view
    context.palette.setColor(QPalette.ColorRole.Text, QColor("black"))
    document.documentLayout().draw(painter, context)
    if cut.right > cut.left:  # the table's bottom border where this page cuts it
        painter.setClipping(False)
        painter.setPen(QPen(QColor("#808080"), 1))
        painter.drawLine(QPointF(cut.left, cut.y - 0.5), QPointF(cut.right, cut.y - 0.5))
    painter.restore()


def _paint_bands(
    painter: QPainter, frame: PageFrame, page: QSizeF, band: float, index: int, pages: int
) -> None:
    number = translate("PagedPrint", "Page {0} of {1}").format(index + 1, pages)
    header = _line(frame.subject, frame.title, page.width(), bold=True)
    footer = _line(frame.footer, number, page.width())
    painter.save()
    painter.setPen(QPen(QColor("#808080"), 0))
    painter.drawLine(0, int(band * 0.8), int(page.width()), int(band * 0.8))
    bottom = page.height() - band
    painter.drawLine(0, int(bottom + band * 0.2), int(page.width()), int(bottom + band * 0.2))
    painter.translate(0, max(0.0, band * 0.75 - header.size().height()))
    header.drawContents(painter)
    painter.translate(0, bottom + band * 0.25 - max(0.0, band * 0.75 - header.size().height()))
    footer.drawContents(painter)
    painter.restore()


def _line(left: str, right: str, width: float, bold: bool = False) -> QTextDocument:
    """One line of small text, ``left`` at the left edge and ``right`` at the right one."""
    e = html.escape
    weight = "font-weight:600;" if bold else ""
    text = QTextDocument()
    text.setDocumentMargin(0)
    text.setTextWidth(width)
    text.setHtml(
        f"<table width='100%' cellspacing='0' cellpadding='0' style='font-size:8pt;{weight}'>"
        f"<tr><td>{e(left)}</td><td align='right'>{e(right)}</td></tr></table>"
    )
    return text

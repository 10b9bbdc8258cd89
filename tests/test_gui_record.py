"""The printed and PDF parameter record, checked on the PDF itself: where its picture lands.

The older record tests read the PDF's words and the picture's pixel size, never where the
picture is drawn on the page; so a diagram running off the right edge of the page passed
(issue 14, item 3).
"""

from __future__ import annotations

import shutil
import subprocess

import numpy as np
import pytest
from gui_support import E02, E04_CA, main_window
from pypdf import PdfReader

MM = 72 / 25.4  # PDF points per millimetre


def _pictures(path) -> list[tuple[float, float, float, float]]:
    """(left, bottom, right, top) in points of every image drawn on the first page."""
    placed = []

    def visit(operator, operands, matrix, _text_matrix):
        if operator == b"Do":  # an image draws the unit square through the current matrix
            a, _b, _c, d, e, f = matrix
            placed.append((e, f, e + a, f + d))

    PdfReader(path).pages[0].extract_text(visitor_operand_before=visit)
    return placed


def _rendered_first_page(path, dpi: int = 40) -> np.ndarray:
    """The first page rendered by poppler's pdftoppm, grey levels 0 (ink) … 255 (paper)."""
    out = subprocess.run(
        ["pdftoppm", "-r", str(dpi), "-gray", "-f", "1", "-l", "1", str(path)],
        check=True,
        capture_output=True,
    ).stdout
    magic, width, height, _maxval, pixels = out.split(maxsplit=4)
    assert magic == b"P5"
    return np.frombuffer(pixels, np.uint8).reshape(int(height), int(width))


@pytest.mark.parametrize("type_key", [E02, E04_CA])
def test_the_pdf_record_holds_the_whole_diagram_inside_the_margins(
    qtbot, tmp_path, answers, type_key
):
    with main_window(qtbot, tmp_path, type_key) as window:
        pdf = tmp_path / "record.pdf"
        assert window.records.export_pdf(pdf)
    box = PdfReader(pdf).pages[0].mediabox
    page_width, page_height = float(box.width), float(box.height)
    (left, _bottom, right, top), *_ = _pictures(pdf)
    assert left >= 15 * MM - 1 and right <= page_width - 15 * MM + 1  # within the margins
    assert right - left > 0.95 * (page_width - 30 * MM)  # as wide as the text, not shrunk
    if shutil.which("pdftoppm") is None:
        return  # the geometry above already read the PDF; poppler adds the rendered check
    page = _rendered_first_page(pdf)
    dots_per_mm = page.shape[1] / (page_width / MM)
    margin = int(12 * dots_per_mm)
    picture_top = int((page_height - top) / MM * dots_per_mm)
    picture = page[picture_top : picture_top + int(40 * dots_per_mm)]
    assert (page[:, -margin:] > 200).all()  # no ink in the right margin: nothing cut off
    assert (picture[:, -int(25 * dots_per_mm) : -margin] < 200).any()  # … yet ink up to it


def test_the_printed_record_fits_the_printers_page(qtbot, tmp_path, answers, monkeypatch):
    from PySide6.QtCore import QMarginsF
    from PySide6.QtGui import QPageLayout, QPageSize
    from PySide6.QtPrintSupport import QPrintDialog, QPrinter

    out = tmp_path / "printed.pdf"

    def accept(dialog):  # a US Letter printer with narrow margins
        printer = dialog.printer()
        printer.setOutputFormat(QPrinter.OutputFormat.PdfFormat)
        printer.setOutputFileName(str(out))
        printer.setPageSize(QPageSize(QPageSize.PageSizeId.Letter))
        printer.setPageMargins(QMarginsF(10, 10, 10, 10), QPageLayout.Unit.Millimeter)
        return QPrintDialog.DialogCode.Accepted

    monkeypatch.setattr(QPrintDialog, "exec", accept)
    with main_window(qtbot, tmp_path, E04_CA) as window:
        assert window.records.print_record()
    page_width = float(PdfReader(out).pages[0].mediabox.width)
    assert round(page_width) == 612  # Letter
    (left, _bottom, right, _top), *_ = _pictures(out)
    assert left >= 10 * MM - 1 and right <= page_width - 10 * MM + 1
    assert right - left > 0.95 * (page_width - 20 * MM)

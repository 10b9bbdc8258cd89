"""The printed and PDF parameter record, checked on the PDF itself: where its picture lands.

The older record tests read the PDF's words and the picture's pixel size, never where the
picture is drawn on the page; so a diagram running off the right edge of the page passed
(issue 14, item 3).
"""

from __future__ import annotations

import re
import shutil
import subprocess
import unicodedata

import numpy as np
import pytest
from pypdf import PdfReader
from support.gui_support import E02, E04_CA, main_window

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


def _page_texts(path) -> list[str]:
    """Each page's words, one space apart, ligatures ("ﬁ") as letters."""
    texts = [unicodedata.normalize("NFKC", page.extract_text()) for page in PdfReader(path).pages]
    return [" ".join(text.split()) for text in texts]


def test_a_record_of_unsaved_values_says_so_and_marks_them(qtbot, tmp_path, answers):
    """Issue 25 item 9: the record named the file but printed unsaved values (ramp 150 ms
    against the file's 0) without saying so."""
    with main_window(qtbot, tmp_path) as window:
        pdf = tmp_path / "untitled.pdf"
        assert window.records.export_pdf(pdf)
        assert "untitled (the values are not saved in a file)" in _page_texts(pdf)[0]
        window.files.save_to(tmp_path / "valve.prm")
        window.doc.set_value("RAMPSETPOSUP", 150)
        assert window.records.export_pdf(pdf)
        first = _page_texts(pdf)[0]
        assert "(changed, not saved: the values marked * differ from the file)" in first
        assert "150 * ms" in first and "RAMPSETPOSDOWN" in first
        assert len(re.findall(r"\d \*", first)) == 1  # only the changed value is marked
        window.files.save()
        assert window.records.export_pdf(pdf)
        assert "*" not in _page_texts(pdf)[0] and "not saved" not in _page_texts(pdf)[0]


def test_every_page_names_the_valve_and_its_number_and_the_last_one_has_a_signature_line(
    qtbot, tmp_path, answers
):
    """Issue 25 item 9: page 2 had no type key or serial number."""
    with main_window(qtbot, tmp_path, E04_CA) as window:
        window.doc.source_serial = 4711
        pdf = tmp_path / "record.pdf"
        assert window.records.export_pdf(pdf)
    pages = _page_texts(pdf)
    assert len(pages) >= 2
    for number, text in enumerate(pages, start=1):
        assert f"{E04_CA} · serial number 4711" in text
        assert "PRM9 parameter record" in text
        assert f"Page {number} of {len(pages)}" in text
    assert "Signature:" in pages[-1] and "Signature:" not in pages[0]


@pytest.mark.skipif(shutil.which("pdftoppm") is None, reason="needs poppler's pdftoppm")
def test_every_page_keeps_15_mm_margins(qtbot, tmp_path, answers):
    with main_window(qtbot, tmp_path, E04_CA) as window:
        pdf = tmp_path / "record.pdf"
        assert window.records.export_pdf(pdf)
    for number in range(1, len(PdfReader(pdf).pages) + 1):
        page = _rendered_page(pdf, number)
        dots_per_mm = page.shape[1] / 210
        ink = np.argwhere(page < 200)
        (top, left), (bottom, right) = ink.min(axis=0), ink.max(axis=0)
        margins = np.array([top, left, page.shape[0] - bottom, page.shape[1] - right])
        assert ((margins / dots_per_mm > 14) & (margins / dots_per_mm < 22)).all(), margins


def _rendered_page(path, number: int, dpi: int = 40) -> np.ndarray:
    out = subprocess.run(
        ["pdftoppm", "-r", str(dpi), "-gray", "-f", str(number), "-l", str(number), str(path)],
        check=True,
        capture_output=True,
    ).stdout
    _magic, width, height, _maxval, pixels = out.split(maxsplit=4)
    return np.frombuffer(pixels, np.uint8).reshape(int(height), int(width))


def test_the_last_row_of_a_page_is_not_stretched_to_the_page_end(qtbot, tmp_path, answers):
    """Qt stretches the last table row of a page down to the page's end; the page ends
    below that row's text instead, one row height below its top like every other row."""
    from prm9tool.views.paged_print import page_cuts, row_top, tables_in

    with main_window(qtbot, tmp_path, E04_CA) as window:
        record = window.records.record()
    height = record.pageSize().height()
    table = max(tables_in(record.rootFrame()), key=lambda t: t.rows())  # the parameters
    tops = [row_top(record, table, row) for row in range(table.rows())]
    row_height = float(np.median(np.diff(tops)))
    last = max(top for top in tops if top < height)  # the last row on page 1
    cut = page_cuts(record, height, record.pageCount())[0]
    assert height - cut.y > 2  # cut above the page end, where Qt's stretched row ended
    padding = table.format().cellPadding()  # the next row's text starts below its own padding
    assert row_height - padding - 1 <= cut.y - last <= row_height


def test_print_to_file_proposes_type_key_and_serial(qtbot, tmp_path, answers, monkeypatch):
    """Issue 25 item 9: Qt's print dialog proposes the job name up to its last dot, plus
    ".pdf" (QUnixPrintWidget, regular expression ``(.*)\\.\\S+``): the record's name was cut
    at the first dot of the type key, "PRM9 parameter record PRM9-06.pdf"."""
    import re

    from PySide6.QtPrintSupport import QPrintDialog

    names = []
    monkeypatch.setattr(QPrintDialog, "exec", lambda d: (names.append(d.printer().docName()), 0)[1])
    with main_window(qtbot, tmp_path) as window:
        window.doc.source_serial = 1001
        assert not window.records.print_record()
    proposed = re.match(r"(.*)\.\S+", names[0]).group(1) + ".pdf"
    assert proposed == "PRM9-06.3Z11_30-24E02S02_1001.pdf"

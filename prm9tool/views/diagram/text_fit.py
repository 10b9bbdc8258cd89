"""How the texts of a diagram block fit its width: title on one or two lines, value lines,
13 px then 12 px, elided as a last resort; the font sizes and line metrics of a block."""

from __future__ import annotations

from PySide6.QtCore import Qt
from PySide6.QtGui import QFont, QFontMetricsF


def pixel_font(pixels: int, bold: bool = False) -> QFont:
    """The default font at ``pixels`` pixels (the diagram is drawn in scene pixels)."""
    font = QFont()
    font.setPixelSize(pixels)
    font.setBold(bold)
    return font


TITLE_PIXELS = (13, 12)  # bold title sizes, largest first (12 px stays ≥ 9 px at 1024 × 768)
LINE_PIXELS = (13, 12)  # value-line sizes
PAD = 5.0  # left/right padding of a block's texts
TITLE_TOP = 3.0
TITLE_LINE_H = 16.0
LINE_H = 17.0


def _two_lines(text: str, metrics: QFontMetricsF, width: float) -> list[str] | None:
    """``text`` split once (at a space, else after a hyphen) into the best-balanced two lines
    that both fit ``width``; None if no split fits."""
    splits = [(text[:i], text[i + 1 :]) for i, c in enumerate(text) if c == " "]
    if not splits:
        splits = [(text[: i + 1], text[i + 1 :]) for i, c in enumerate(text[:-1]) if c == "-"]
    best: tuple[float, list[str]] | None = None
    for head, tail in splits:
        widest = max(metrics.horizontalAdvance(head), metrics.horizontalAdvance(tail))
        if widest <= width and (best is None or widest < best[0]):
            best = (widest, [head, tail])
    return best[1] if best else None


def fit_title(text: str, width: float, max_lines: int) -> tuple[QFont, list[str], bool]:
    """Font and lines of a block title in ``width``: one line, else two, at 13 then 12 px.

    Returns ``(font, lines, fits)``; a title that fits nowhere is elided (``fits`` False).
    """
    for pixels in TITLE_PIXELS:
        font = pixel_font(pixels, bold=True)
        metrics = QFontMetricsF(font)
        if metrics.horizontalAdvance(text) <= width:
            return font, [text], True
        lines = _two_lines(text, metrics, width) if max_lines > 1 else None
        if lines:
            return font, lines, True
    font = pixel_font(TITLE_PIXELS[-1], bold=True)
    elided = QFontMetricsF(font).elidedText(text, Qt.TextElideMode.ElideRight, width)
    return font, [elided], False


def fit_lines(lines: list[str], width: float) -> tuple[QFont, list[str], bool]:
    """Font and shown text of value ``lines`` in ``width``: 13 px, else 12 px, else elided."""
    for pixels in LINE_PIXELS:
        font = pixel_font(pixels)
        metrics = QFontMetricsF(font)
        if all(metrics.horizontalAdvance(line) <= width for line in lines):
            return font, list(lines), True
    font = pixel_font(LINE_PIXELS[-1])
    metrics = QFontMetricsF(font)
    shown = [metrics.elidedText(line, Qt.TextElideMode.ElideRight, width) for line in lines]
    return font, shown, False

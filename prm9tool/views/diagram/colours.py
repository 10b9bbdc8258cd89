"""Colours of the diagram and of the block dialogs' plots, taken from the application palette.

Every colour is written as it looks on paper: white sheet, black ink (the light look of the
screenshots and of the printed record). On another palette :func:`on_palette` moves its
lightness to the same place between the palette's Base (sheet) and Text (ink) colours and
keeps hue and saturation: pale fills stay near the background, dark ink near the text colour,
the blocks stay blue and the measuring points red. Base and Text are all it reads, so a palette
that sets only those two still gets a consistent diagram; a light palette with white Base and
black Text gets the paper colours unchanged.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from PySide6.QtGui import QColor, QPalette

TEXT_CONTRAST = 4.5  # WCAG AA for normal text
LOCKED_CONTRAST = 3.0  # greyed-out text: faint, but still legible


def on_palette(colour: QColor, palette: QPalette) -> QColor:
    """``colour`` (as on white paper with black ink) moved onto ``palette``'s Base and Text."""
    sheet = palette.color(QPalette.ColorRole.Base).lightnessF()
    ink = palette.color(QPalette.ColorRole.Text).lightnessF()
    hue, saturation, lightness, alpha = _hsla(colour)
    moved = sheet + (1.0 - lightness) * (ink - sheet)
    chroma = saturation * (1.0 - abs(2.0 * lightness - 1.0))
    room = 1.0 - abs(2.0 * moved - 1.0)
    result = QColor.fromHslF(hue, min(1.0, chroma / room) if room > 0 else 0.0, moved, alpha)
    return QColor.fromRgba(result.rgba())  # plain 8-bit RGB, comparable with paper colours


def _hsla(colour: QColor) -> tuple[float, float, float, float]:
    """Hue (-1 when achromatic), saturation, lightness and alpha, each 0 … 1, as
    ``QColor.getHslF`` gives them (whose binding is typed as returning ``object``)."""
    return colour.hslHueF(), colour.hslSaturationF(), colour.lightnessF(), colour.alphaF()


def luminance(colour: QColor) -> float:
    """Relative luminance (WCAG 2) of an opaque colour."""

    def linear(channel: float) -> float:
        return channel / 12.92 if channel <= 0.04045 else ((channel + 0.055) / 1.055) ** 2.4

    return (
        0.2126 * linear(colour.redF())
        + 0.7152 * linear(colour.greenF())
        + 0.0722 * linear(colour.blueF())
    )


def contrast_ratio(first: QColor, second: QColor) -> float:
    """WCAG contrast ratio of two opaque colours (1 … 21)."""
    light, dark = sorted((luminance(first), luminance(second)), reverse=True)
    return (light + 0.05) / (dark + 0.05)


def readable(colour: QColor, background: QColor, ratio: float = TEXT_CONTRAST) -> QColor:
    """``colour``, made lighter on a dark ``background`` (darker on a light one) until the
    two reach ``ratio``; hue and saturation are kept."""
    hue, saturation, lightness, alpha = _hsla(colour)
    step = 0.02 if luminance(background) < 0.18 else -0.02
    result = QColor(colour)
    while contrast_ratio(result, background) < ratio and 0.0 < lightness < 1.0:
        lightness = min(1.0, max(0.0, lightness + step))
        result = QColor.fromRgba(QColor.fromHslF(hue, saturation, lightness, alpha).rgba())
    return result


_COLOUR_PROPERTY = re.compile(r"([\w-]+):\s*(#[0-9a-fA-F]{3,6})\b")


def toned_style(style: str, palette: QPalette) -> str:
    """A style sheet written for paper with its colours moved onto ``palette``; a text
    ``color`` is kept readable on the palette's Window colour."""
    window = palette.color(QPalette.ColorRole.Window)

    def tone(match: re.Match[str]) -> str:
        colour = on_palette(QColor(match.group(2)), palette)
        if match.group(1) == "color":
            colour = readable(colour, window)
        return f"{match.group(1)}: {colour.name()}"

    return _COLOUR_PROPERTY.sub(tone, style)


# Paper colours (white sheet, black ink): the light look and the printed picture.
_PAPER = {
    "sheet": "#ffffff",  # background; inside of the summing junctions
    "ink": "#1f2d3a",  # titles, values, arrows, junctions
    "edit_fill": "#eaf2fb",
    "hover_fill": "#d3e5f7",
    "edit_edge": "#2f6592",
    "edit_rule": "#3d83be",  # the line under a block's title
    "locked_fill": "#e4e4e4",
    "locked_edge": "#a0a0a0",
    "locked_rule": "#d0d0d0",
    "locked_ink": "#808080",
    "info_fill": "#f7f7f2",
    "dot_on": "#d91e18",
    "dot_off": "#eaa3a0",
    "dot_edge_on": "#9b1511",
    "dot_edge_off": "#a77472",
    "value_ink": "#a3140f",  # live values beside the dots
    "value_plate": "#e6ffffff",  # under a live value where it crosses a line
}


@dataclass(frozen=True)
class DiagramColours:
    """The colours one diagram is drawn in; see :data:`_PAPER` for what each one paints."""

    sheet: QColor
    ink: QColor
    edit_fill: QColor
    hover_fill: QColor
    edit_edge: QColor
    edit_rule: QColor
    locked_fill: QColor
    locked_edge: QColor
    locked_rule: QColor
    locked_ink: QColor
    info_fill: QColor
    dot_on: QColor
    dot_off: QColor
    dot_edge_on: QColor
    dot_edge_off: QColor
    value_ink: QColor
    value_plate: QColor

    @classmethod
    def paper(cls) -> DiagramColours:
        """Dark ink on white."""
        return cls(**{name: QColor(code) for name, code in _PAPER.items()})

    @classmethod
    def for_palette(cls, palette: QPalette) -> DiagramColours:
        """The paper colours moved onto ``palette``, texts kept readable on their fills."""
        moved = {name: on_palette(QColor(code), palette) for name, code in _PAPER.items()}
        moved["ink"] = readable(moved["ink"], moved["hover_fill"])
        moved["locked_ink"] = readable(moved["locked_ink"], moved["locked_fill"], LOCKED_CONTRAST)
        moved["value_ink"] = readable(moved["value_ink"], moved["sheet"])
        return cls(**moved)


PAPER = DiagramColours.paper()  # the printed record's picture, whatever the screen's palette

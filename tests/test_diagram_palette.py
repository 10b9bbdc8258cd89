"""The diagram and the block dialogs' plots follow the application palette (light or dark);
the printed picture stays dark ink on white paper."""

from __future__ import annotations

from collections.abc import Iterator

import pytest
from PySide6.QtCore import QPoint, QRectF
from PySide6.QtGui import QColor, QImage, QPainter, QPalette
from PySide6.QtWidgets import QApplication
from support.diagram_fakes import EmulatorConnection
from test_diagram import E04_CA, make_view

from prm9tool.catalogue import Access
from prm9tool.device.emulator import EmulatedValve
from prm9tool.views.diagram.colours import (
    PAPER,
    DiagramColours,
    contrast_ratio,
    luminance,
    on_palette,
    readable,
    toned_style,
)

Role = QPalette.ColorRole


def dark_palette() -> QPalette:
    """A dark palette as a desktop's dark mode sets it."""
    palette = QPalette(QColor("#2b2b2b"))
    palette.setColor(Role.Base, QColor("#1e1e1e"))
    for role in (Role.Text, Role.WindowText, Role.ButtonText):
        palette.setColor(role, QColor("#e0e0e0"))
    return palette


def light_palette() -> QPalette:
    """White Base, black Text: the paper the diagram's colours are written for."""
    palette = QPalette(QColor("#efefef"))
    palette.setColor(Role.Base, QColor("white"))
    palette.setColor(Role.Text, QColor("black"))
    return palette


@pytest.fixture
def dark(qapp: QApplication) -> Iterator[QPalette]:
    """The application in a dark palette for one test."""
    before = QPalette(qapp.palette())
    qapp.setPalette(dark_palette())
    yield qapp.palette()
    qapp.setPalette(before)


def is_dark(colour: QColor) -> bool:
    return luminance(colour) < 0.05


# --- colour arithmetic ----------------------------------------------------------------------------
def test_paper_colours_are_unchanged_on_white_base_and_black_text():
    assert DiagramColours.for_palette(light_palette()) == PAPER
    assert on_palette(QColor("#2f6592"), light_palette()) == QColor("#2f6592")


def test_on_a_dark_palette_light_tints_turn_dark_and_dark_ink_light_keeping_the_hue():
    fill = on_palette(QColor("#eaf2fb"), dark_palette())
    ink = on_palette(QColor("#1f2d3a"), dark_palette())
    assert is_dark(fill) and luminance(ink) > 0.4
    assert abs(fill.hslHue() - QColor("#eaf2fb").hslHue()) <= 2


def test_readable_moves_a_colour_away_from_its_background_until_the_contrast_is_enough():
    background = QColor("#2b2b2b")
    red = readable(QColor("#d03030"), background)
    assert contrast_ratio(red, background) >= 4.5
    assert red.lightness() > QColor("#d03030").lightness()
    assert readable(QColor("black"), QColor("white")) == QColor("black")  # already enough


def test_a_style_sheet_written_for_paper_is_moved_onto_the_palette():
    style = toned_style("background: #f1f1f1; color: #d03030; padding: 6px;", dark_palette())
    background, text = (QColor(part.split(": ")[1]) for part in style.split("; ")[:2])
    assert is_dark(background)
    assert contrast_ratio(text, QColor("#2b2b2b")) >= 4.5
    assert style.endswith("padding: 6px;")


# --- the diagram --------------------------------------------------------------------------------------
def test_on_a_dark_palette_the_diagram_is_dark_with_light_readable_writing(qtbot, dark):
    view = make_view(qtbot, E04_CA, Access.BASIC)
    colours = view.diagram.colours
    assert is_dark(view.diagram.backgroundBrush().color())
    editable = view.diagram.blocks["threshold"]
    assert not editable.locked
    fill, _edge, _rule, ink = editable.look()
    assert is_dark(fill) and luminance(ink) > 0.4
    assert contrast_ratio(ink, fill) >= 4.5
    assert contrast_ratio(ink, colours.hover_fill) >= 4.5
    assert contrast_ratio(colours.ink, colours.sheet) >= 4.5  # arrows, feedback label
    assert view.diagram.feedback_label.brush().color() == colours.ink


def test_on_a_dark_palette_locked_blocks_stay_grey_legible_and_distinct(qtbot, dark):
    view = make_view(qtbot, E04_CA, Access.BASIC)
    locked, editable = view.diagram.blocks["position_controller"], view.diagram.blocks["ramps"]
    assert locked.locked and not editable.locked
    fill, edge, _rule, ink = locked.look()
    assert contrast_ratio(ink, fill) >= 3.0
    assert fill.hslSaturation() == 0 and ink.hslSaturation() == 0  # grey, not blue
    assert contrast_ratio(ink, editable.look().ink) >= 1.8  # fainter than the normal ink
    assert edge != editable.look().edge


def test_on_a_dark_palette_the_measuring_points_stay_red_and_live_values_readable(qtbot, dark):
    valve = EmulatedValve(E04_CA, switches=(0, 0))
    valve.advance(2.0)
    link = EmulatorConnection(valve)
    view = make_view(qtbot, E04_CA, Access.EXPERT, connection=link)
    link.go_online()
    link.poll_signals()
    colours = view.diagram.colours
    assert view.diagram.dots["demand"].value_text
    for red in (colours.dot_on, colours.value_ink):
        assert red.hslHue() <= 10 and red.hslSaturation() > 150
    assert contrast_ratio(colours.value_ink, colours.sheet) >= 4.5
    assert contrast_ratio(colours.dot_on, colours.sheet) >= 3.0


def test_the_diagram_recolours_when_the_application_palette_changes(qtbot, qapp):
    view = make_view(qtbot, E04_CA)
    before = QPalette(qapp.palette())
    try:
        qapp.setPalette(dark_palette())
        qtbot.waitUntil(lambda: is_dark(view.diagram.backgroundBrush().color()))
        assert is_dark(view.diagram.blocks["threshold"].look().fill)
    finally:
        qapp.setPalette(before)
    qtbot.waitUntil(lambda: not is_dark(view.diagram.backgroundBrush().color()))
    assert view.diagram.colours == DiagramColours.for_palette(view.palette())


def test_on_a_dark_palette_the_printed_picture_stays_dark_ink_on_white(qtbot, dark):
    view = make_view(qtbot, E04_CA, Access.BASIC)
    picture = view.picture_scene()
    assert picture.colours == PAPER
    assert picture.backgroundBrush().color() == QColor("white")
    image = QImage(800, 400, QImage.Format.Format_RGB32)
    image.fill(QColor("white"))  # as the record's picture
    painter = QPainter(image)
    view.render_picture(painter, QRectF(0, 0, 800, 400))
    painter.end()
    pixels = [image.pixelColor(QPoint(x, y)) for x in range(0, 800, 3) for y in range(0, 400, 3)]
    light = sum(1 for p in pixels if luminance(p) > 0.8)
    assert light > 0.8 * len(pixels)  # white paper, pale block fills
    assert any(luminance(p) < 0.05 for p in pixels)  # dark ink


# --- the dialogs' plots and labels ----------------------------------------------------------
def test_on_a_dark_palette_a_dialog_plot_is_dark_and_its_curves_keep_their_hue(qtbot, dark):
    view = make_view(qtbot, E04_CA, Access.EXPERT)
    dialog = view.open_block("threshold")
    assert dialog is not None
    plot = dialog.plot
    image = plot.grab().toImage()
    assert is_dark(image.pixelColor(QPoint(3, 3)))
    blue = plot.tone(plot.curves[-1].colour)
    assert contrast_ratio(blue, plot.tone(QColor("white"))) >= 3.0
    assert abs(blue.hslHue() - plot.curves[-1].colour.hslHue()) <= 2
    dialog.close()


def test_a_dialog_plot_and_labels_follow_a_palette_change(qtbot, qapp):
    view = make_view(qtbot, E04_CA, Access.BASIC)
    dialog = view.open_block("position_controller")
    assert dialog is not None
    assert "#f1f1f1" in dialog.lock_label.styleSheet()
    before = QPalette(qapp.palette())
    try:
        qapp.setPalette(dark_palette())
        qtbot.waitUntil(lambda: "#f1f1f1" not in dialog.lock_label.styleSheet())
        qtbot.waitUntil(lambda: is_dark(dialog.plot.grab().toImage().pixelColor(QPoint(3, 3))))
    finally:
        qapp.setPalette(before)
    qtbot.waitUntil(lambda: "#f1f1f1" in dialog.lock_label.styleSheet())
    dialog.close()

"""The diagram reads clearly in every language and variant: texts fit their blocks, every
measuring point sits on the line it measures, and the values of one block can be told apart."""

from __future__ import annotations

import itertools
import math

import pytest
from PySide6.QtCore import QPointF, QRectF

from prm9tool import i18n
from prm9tool.catalogue.signals import BY_KEY
from prm9tool.device.emulator import EmulatedValve
from prm9tool.model.access import AccessModel
from prm9tool.model.document import ParameterDocument
from prm9tool.model.undo import DocumentUndo
from prm9tool.views.diagram import DiagramView, format_signal
from prm9tool.views.diagram.items import BlockItem

E02 = "PRM9-06.3Z11/30-24E02S02"
E02_A = "PRM9-06.2Z51/30-24E02S02"
E02_B = "PRM9-06.2Z61/30-24E02S02"
E04 = "PRM9-06.3Z11/30-24E04S02"
E04_CA = "PRM9-06.3Z11/30-24E04S02-CA"
VARIANTS = [E02, E02_A, E02_B, E04, E04_CA]


def make_view(qtbot, key: str) -> DiagramView:
    doc = ParameterDocument(key)
    view = DiagramView(doc, AccessModel())
    view.undo = DocumentUndo(doc, doc)
    qtbot.addWidget(view)
    return view


@pytest.fixture(params=["en", "de", "cs"])
def language(request, qapp):
    i18n.set_language(request.param)
    yield request.param
    i18n.set_language("en")


# --- texts -------------------------------------------------------------------------------------------
@pytest.mark.parametrize("key", VARIANTS)
def test_every_title_and_value_line_fits_its_block(qtbot, language, key):
    view = make_view(qtbot, key)
    for block_id, block in view.diagram.blocks.items():
        assert block.title and block.title != block_id.upper()
        assert block.fits, (language, block_id, block.title, block.lines)
        assert " ".join(block.shown_title).replace("- ", "-") == block.title  # wrapped, whole
        assert block.shown_lines == block.lines
        assert len(block.shown_title) <= block.title_lines
        assert block.title_font.pixelSize() >= 12 and block.line_font.pixelSize() >= 12


def test_long_titles_wrap_onto_two_lines(qtbot):
    i18n.set_language("de")
    try:
        view = make_view(qtbot, E04)
        block = view.diagram.blocks["gain_offset"]
        assert block.title == "Abweichung: Verstärkung & Offset"
        assert block.shown_title == ["Abweichung:", "Verstärkung & Offset"]
        assert block.fits
    finally:
        i18n.set_language("en")


def test_a_line_too_long_is_elided_and_the_tooltip_has_it_in_full(qtbot):
    block = BlockItem("x", QRectF(0, 0, 168, 100))
    block.set_locked(False, "Click to edit: X")
    long_line = "a value line much too long for any block of the diagram"
    block.set_content("Title", ["short", long_line])
    assert not block.fits
    assert block.shown_lines[0] == "short"
    assert block.shown_lines[1].endswith("…") and len(block.shown_lines[1]) < len(long_line)
    assert long_line in block.toolTip() and "Click to edit: X" in block.toolTip()
    block.set_content("Title", ["short"])
    assert block.fits and block.toolTip() == "Click to edit: X"


# --- measuring points ----------------------------------------------------------------------------------
def _distance_to_segment(p: QPointF, a: QPointF, b: QPointF) -> float:
    ax, ay, bx, by = a.x(), a.y(), b.x(), b.y()
    length2 = (bx - ax) ** 2 + (by - ay) ** 2
    t = 0.0 if length2 == 0 else ((p.x() - ax) * (bx - ax) + (p.y() - ay) * (by - ay)) / length2
    t = min(1.0, max(0.0, t))
    return math.hypot(p.x() - (ax + t * (bx - ax)), p.y() - (ay + t * (by - ay)))


def _on_edge(p: QPointF, rect: QRectF) -> bool:
    inside_x = rect.left() - 0.5 <= p.x() <= rect.right() + 0.5
    inside_y = rect.top() - 0.5 <= p.y() <= rect.bottom() + 0.5
    on_x = min(abs(p.x() - rect.left()), abs(p.x() - rect.right())) <= 0.5
    on_y = min(abs(p.y() - rect.top()), abs(p.y() - rect.bottom())) <= 0.5
    return (on_x and inside_y) or (on_y and inside_x)


@pytest.mark.parametrize("key", VARIANTS)
def test_every_dot_lies_on_an_arrow_or_a_block_edge(qtbot, key):
    scene = make_view(qtbot, key).diagram
    for dot_key, dot in scene.dots.items():
        centre = dot.scenePos()
        on_arrow = any(
            _distance_to_segment(centre, a, b) <= 0.5
            for arrow in scene.arrows
            for a, b in zip(arrow.points, arrow.points[1:], strict=False)
        )
        block_id = scene.layout.dots[dot_key][0]
        own = scene.blocks.get(block_id)
        on_block = own is not None and _on_edge(centre, own.scene_rect())
        assert on_arrow or on_block, dot_key
        # and inside no other block
        for other_id, other in scene.blocks.items():
            if other_id != block_id:
                assert not other.scene_rect().adjusted(1, 1, -1, -1).contains(centre), dot_key


@pytest.mark.parametrize("key", VARIANTS)
def test_stacked_values_carry_tags_or_units_that_tell_them_apart(qtbot, key):
    layout = make_view(qtbot, key).diagram.layout
    by_place: dict[tuple[str, str], list[str]] = {}
    for dot_key, (block_id, side, _index) in layout.dots.items():
        by_place.setdefault((block_id, side), []).append(dot_key)
    for keys in by_place.values():
        if len(keys) > 1:
            # the text around the number: "A 12 mA" -> ("A", "mA")
            labels = {
                tuple(part for part in format_signal(k, 0).split() if part[0] not in "0-")
                for k in keys
            }
            assert len(labels) == len(keys), keys


def _samples(key: str, keys: list[str]) -> list[dict[str, float]]:
    """The measuring points of an emulated valve at a few setpoints (analog input)."""
    valve = EmulatedValve(key, switches=(0, 0))
    valve.advance(2.5)
    samples = []
    for volts in (3.0, -4.0, 6.0):
        valve.set_input("setpoint", volts)
        valve.advance(0.4)
        samples.append({k: valve.signal(k) for k in keys})
    return samples


@pytest.mark.parametrize("key", VARIANTS)
def test_no_two_dots_of_a_block_show_the_same_signal(qtbot, key):
    layout = make_view(qtbot, key).diagram.layout
    samples = _samples(key, [*layout.dots, *layout.same_as])
    # a measuring point left out is a copy of one that is drawn
    for hidden, shown in layout.same_as.items():
        assert hidden not in layout.dots and shown in layout.dots
        assert all(s[hidden] == s[shown] for s in samples), hidden
    blocks: dict[str, list[str]] = {}
    for dot_key, (block_id, _side, _index) in layout.dots.items():
        blocks.setdefault(block_id, []).append(dot_key)
    for block_id, keys in blocks.items():
        for a, b in itertools.combinations(keys, 2):
            if BY_KEY[a].unit == BY_KEY[b].unit:
                assert any(s[a] != s[b] for s in samples), (block_id, a, b)

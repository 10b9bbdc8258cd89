"""The signal-flow diagram: blocks per variant, block clicks, locking, live measuring points."""

from __future__ import annotations

import pytest
from PySide6.QtCore import QCoreApplication, QObject, QPoint, QRectF, Qt, QTranslator, Signal
from PySide6.QtGui import QColor, QImage, QPainter
from PySide6.QtWidgets import QWidget
from support.diagram_fakes import EmulatorConnection

from prm9tool.catalogue import Access
from prm9tool.catalogue.signals import signals_for
from prm9tool.device.emulator import EmulatedValve
from prm9tool.model.access import AccessModel
from prm9tool.model.document import ParameterDocument
from prm9tool.model.undo import DocumentUndo
from prm9tool.views.diagram import DiagramView, format_signal
from prm9tool.views.diagram.dialogs import BlockDialog
from prm9tool.views.valve.selection import ValveSelectionDialog

E02 = "PRM9-06.3Z11/30-24E02S02"
E02_A = "PRM9-06.2Z51/30-24E02S02"
E02_B = "PRM9-06.2Z61/30-24E02S02"
E04 = "PRM9-06.3Z11/30-24E04S02"
E04_CA = "PRM9-06.3Z11/30-24E04S02-CA"

E02_CHAIN = [
    "setpoint_input",
    "threshold",
    "gain_offset",
    "setpoint_linearization",
    "ramps",
    "position_controller",
    "current_limit",
    "dither",
    "valve",
    "supply",
]
E04_CHAIN = [
    "setpoint_input",
    "threshold",
    "setpoint_linearization",
    "ramps",
    "gain_offset",
    "process_controller",
    "ext_sensor",
    "ext_sensor_scaling",
    "ext_sensor_linearization",
    "position_controller",
    "current_limit",
    "dither",
    "valve",
    "supply",
]


class NoSimulator(QObject):
    """Controller dialogs in these tests do not simulate (see test_tuning.py)."""

    response_ready = Signal(object)
    failed = Signal(str)

    def request(self, values: dict) -> None:
        """Ignore the request."""

    def stop(self) -> None:
        """Nothing runs."""


def make_view(qtbot, key: str, level: Access = Access.BASIC, connection=None) -> DiagramView:
    doc = ParameterDocument(key)
    undo = DocumentUndo(doc, doc)
    view = DiagramView(
        doc, AccessModel(level), connection, simulator_factory=lambda _d, _l: NoSimulator()
    )
    view.undo = undo  # keep it alive with the view
    qtbot.addWidget(view)
    view.resize(1024, 640)
    view.show()
    return view


def click_item(qtbot, view: DiagramView, item) -> None:
    centre = view.mapFromScene(item.sceneBoundingRect().center())
    qtbot.mouseClick(view.viewport(), Qt.MouseButton.LeftButton, pos=centre)


# --- structure ------------------------------------------------------------------------------------
@pytest.mark.parametrize(
    ("key", "blocks", "coils"),
    [
        (E02, E02_CHAIN, ["Coil A", "Coil B"]),
        (E02_A, E02_CHAIN, ["Coil A"]),
        (E02_B, E02_CHAIN, ["Coil B"]),
        (E04, E04_CHAIN, ["Coil A", "Coil B"]),
        (E04_CA, [*E04_CHAIN[:-1], "canopen", "supply"], ["Coil A", "Coil B"]),
    ],
)
def test_each_variant_draws_its_blocks_in_signal_order(qtbot, key, blocks, coils):
    view = make_view(qtbot, key)
    assert view.block_ids() == blocks
    limiter = view.diagram.blocks["current_limit"].lines
    assert [line.split(":")[0] for line in limiter] == coils
    layout = view.diagram.layout
    every = {s.key for s in signals_for(layout.variant)}
    assert set(view.diagram.dots) == every - set(layout.same_as)
    assert set(layout.same_as.values()) <= set(view.diagram.dots)


def test_single_coil_valves_show_one_ramp_pair_and_one_gain(qtbot):
    view = make_view(qtbot, E02_B)
    assert view.diagram.blocks["ramps"].lines == ["↑ 0 ms  ↓ 0 ms"]
    assert view.diagram.blocks["gain_offset"].lines == ["Gain 1", "Offset 0 %"]
    two = make_view(qtbot, E02)
    assert two.diagram.blocks["gain_offset"].lines == ["Gain +1 / −1", "Offset +0 / −0 %"]


def test_arrows_follow_the_signal_chain_and_close_the_loops():
    from prm9tool.catalogue.typekey import TypeKey
    from prm9tool.views.diagram.layout import layout_for

    layout = layout_for(TypeKey.parse(E04_CA).variant)
    links = {(link.source, link.target) for link in layout.links}
    assert ("ramps", "sum_process") in links
    assert ("ext_sensor_linearization", "sum_process") in links
    assert ("process_controller", "sum_position") in links
    assert ("valve", "sum_position") in links
    assert ("canopen", "setpoint_input") in links


def test_changing_the_valve_type_redraws_the_diagram(qtbot):
    view = make_view(qtbot, E02)
    view._doc.set_type_key(E04_CA)
    assert "ext_sensor" in view.block_ids()
    assert "canopen" in view.block_ids()
    view.undo.stack.undo()
    assert view.block_ids() == E02_CHAIN


# --- block clicks ---------------------------------------------------------------------------------
VARIANTS = [E02, E02_A, E02_B, E04, E04_CA]
MAIN_WINDOW_BLOCKS = {"valve": "valve_selection_requested", "canopen": "canopen_requested"}


@pytest.mark.parametrize("key", VARIANTS)
def test_a_click_on_each_block_opens_its_dialog(qtbot, key):
    view = make_view(qtbot, key, Access.EXPERT)
    for block_id in view.block_ids():
        if block_id == "supply":
            continue
        if block_id in MAIN_WINDOW_BLOCKS:  # the main window's windows: the view asks for them
            with (
                qtbot.waitSignal(getattr(view, MAIN_WINDOW_BLOCKS[block_id])),
                qtbot.assertNotEmitted(view.dialog_opened),
            ):
                click_item(qtbot, view, view.diagram.blocks[block_id])
            continue
        with qtbot.waitSignal(view.dialog_opened) as opened:
            click_item(qtbot, view, view.diagram.blocks[block_id])
        opened_id, dialog = opened.args
        assert opened_id == block_id
        assert isinstance(dialog, BlockDialog) and dialog.isVisible()
        dialog.close()


def test_the_supply_block_shows_values_only(qtbot):
    view = make_view(qtbot, E02)
    with qtbot.assertNotEmitted(view.dialog_opened):
        click_item(qtbot, view, view.diagram.blocks["supply"])
    assert view.open_block("supply") is None


def test_the_valve_block_asks_the_main_window_and_changes_nothing_itself(qtbot):
    view = make_view(qtbot, E02)
    with qtbot.waitSignal(view.valve_selection_requested):
        assert view.open_block("valve") is None
    assert str(view._doc.type_key) == E02 and view.undo.stack.count() == 0
    assert not any(isinstance(w, ValveSelectionDialog) for w in view.findChildren(QWidget))


# --- edits and labels -----------------------------------------------------------------------------
def test_a_dialog_edit_changes_the_document_is_undoable_and_updates_the_block(qtbot):
    view = make_view(qtbot, E02)
    dialog = view.open_block("threshold")
    field = dialog.fields["THRESETP"]
    field.setText("7.5")
    field.editingFinished.emit()
    assert view._doc.display("THRESETP") == "7.5"
    assert view.diagram.blocks["threshold"].lines == ["Threshold 7.5 %"]
    view.undo.stack.undo()
    assert view._doc.display("THRESETP") == "5"
    assert view.diagram.blocks["threshold"].lines == ["Threshold 5 %"]
    assert field.text() == "5"


def test_a_bad_value_is_refused_with_the_reason_and_changes_nothing(qtbot):
    view = make_view(qtbot, E02)
    dialog = view.open_block("threshold")
    field = dialog.fields["THRESETP"]
    field.setText("150")
    field.editingFinished.emit()
    assert "outside the allowed range 0 … 100 %" in dialog.error_label.text()
    assert not dialog.error_label.isHidden()
    assert view._doc.display("THRESETP") == "5"
    assert view.undo.stack.count() == 0
    assert field.text() == "150"  # the user's entry stays for correction


def test_the_canopen_block_shows_the_settings_that_apply(qtbot):
    view = make_view(qtbot, E04_CA, Access.EXPERT)
    block = view.diagram.blocks["canopen"]
    # delivery state (table 7-22): interface switch 6 = 500 kbit/s, node switch 2 = node 10
    assert block.lines == ["Node ID 10 · 500 kbit/s", "Terminator off"]
    assert "interface 6, node ID 2" in block.toolTip()
    doc = view._doc
    doc.set_values({"NODEID": 42, "BITRATE": 3}, "software node ID and bit rate")
    assert block.lines[0] == "Node ID 10 · 500 kbit/s"  # the switch sets them
    doc.set_live({"SWBAUD": 0xC, "SWNODE": 0})  # read from a valve
    assert block.lines == ["Node ID 42 · 250 kbit/s", "Terminator on"]
    assert "interface C, node ID 0" in block.toolTip()
    doc.set_live({"SWNODE": 1})
    assert block.lines == ["Node ID 42 · auto bit rate", "Terminator off"]
    doc.set_live({"SWBAUD": 0})
    assert block.lines == ["CANopen off", "analog setpoint"]


def test_document_changes_from_elsewhere_update_the_block(qtbot):
    view = make_view(qtbot, E04, Access.EXPERT)
    view._doc.set_value("PRCKP", 1234)
    assert view.diagram.blocks["process_controller"].lines[0].startswith("Kp 12.34")


# --- access level -----------------------------------------------------------------------------------
def test_blocks_the_basic_level_may_not_change_are_grey_with_a_reason(qtbot):
    view = make_view(qtbot, E04)
    locked = {b for b, item in view.diagram.blocks.items() if item.locked}
    assert locked == {
        "setpoint_linearization",
        "process_controller",
        "position_controller",
        "ext_sensor",
        "ext_sensor_scaling",
        "ext_sensor_linearization",
    }
    tip = view.diagram.blocks["position_controller"].toolTip()
    assert "Expert access level" in tip
    view._access.set_level(Access.EXPERT)
    assert not any(item.locked for item in view.diagram.blocks.values())


def test_a_grey_block_cannot_be_edited(qtbot):
    view = make_view(qtbot, E02)
    dialog = view.open_block("position_controller")
    assert dialog.read_only
    assert not dialog.lock_label.isHidden()
    assert "Expert access level" in dialog.lock_label.text()
    assert all(not field.isEnabled() for field in dialog.fields.values())
    assert all(not slider.isEnabled() for slider in dialog.sliders.values())
    assert not dialog.apply_value("POSKP", 1000)
    assert "Expert" in dialog.error_label.text()
    assert view._doc.value("POSKP") != 1000
    view._access.set_level(Access.EXPERT)
    assert all(field.isEnabled() for field in dialog.fields.values())


# --- measuring points ---------------------------------------------------------------------------
def test_offline_measuring_points_are_inert_and_say_why(qtbot):
    view = make_view(qtbot, E02)
    dot = view.diagram.dots["position_actual"]
    assert not dot.active
    assert "offline" in dot.toolTip()
    with qtbot.assertNotEmitted(view.measuring_point_clicked):
        click_item(qtbot, view, dot)


def test_online_measuring_points_show_live_values_and_ask_for_the_scope(qtbot):
    valve = EmulatedValve(E02)
    valve.advance(2.0)
    valve.set_input("setpoint", 5.0)
    valve.advance(0.3)
    link = EmulatorConnection(valve)
    view = make_view(qtbot, E02, connection=link)
    link.go_online()
    assert set(link.watched) == set(view.diagram.dots)
    link.poll_signals()
    demand = view.diagram.dots["demand"]
    assert demand.active
    assert demand.value_text == format_signal("demand", valve.signal("demand"))
    assert demand.value_text == "50.0 %"
    assert view.diagram.dots["current_a"].value_text.startswith("A ")
    with qtbot.waitSignal(view.measuring_point_clicked) as clicked:
        click_item(qtbot, view, view.diagram.dots["position_actual"])
    assert clicked.args == ["position_actual"]
    link.go_offline()
    assert demand.value_text == ""
    assert not demand.active


def test_a_point_without_a_live_value_says_why_and_shows_no_old_value(qtbot):
    """Issue 25 item 1: while the oscilloscope holds the valve's stream, the other points
    arrive as NaN; the dot shows a dash with the reason instead of the value from before."""
    valve = EmulatedValve(E02)
    link = EmulatorConnection(valve)
    view = make_view(qtbot, E02, connection=link)
    link.go_online()
    link.signal_values_changed.emit({"pwm_a": 0.0})
    dot = view.diagram.dots["pwm_a"]
    assert dot.value_text == "PWM A 0.0 %"
    link.signal_values_changed.emit({"pwm_a": float("nan")})
    assert dot.value_text == "PWM A —"
    assert "no live value now" in dot.toolTip() and "oscilloscope" in dot.toolTip()
    link.signal_values_changed.emit({"pwm_a": 120.0})
    assert "click to show it in the oscilloscope" in dot.toolTip()


def test_online_the_valve_type_is_locked(qtbot):
    link = EmulatorConnection(EmulatedValve(E02))
    view = make_view(qtbot, E02, connection=link)
    link.go_online()
    assert view.diagram.blocks["valve"].locked
    with qtbot.assertNotEmitted(view.valve_selection_requested):
        assert view.open_block("valve") is None
        click_item(qtbot, view, view.diagram.blocks["valve"])


def test_zoom_keeps_the_diagram_vector_and_fits_again(qtbot):
    view = make_view(qtbot, E02)
    fitted = view.transform().m11()
    view.zoom_in()
    assert view.transform().m11() == pytest.approx(fitted * 1.15)
    view.resize(800, 500)  # a zoomed view keeps its zoom when resized
    assert view.transform().m11() == pytest.approx(fitted * 1.15)
    view.zoom_to_fit()
    assert view.transform().m11() < fitted
    visible = view.mapToScene(view.viewport().rect()).boundingRect()
    assert visible.contains(view.diagram.sceneRect().adjusted(1, 1, -1, -1))


class ShoutingTranslator(QTranslator):
    """Translates every diagram text to upper case (a stand-in for a real language)."""

    def translate(self, context, source, disambiguation=None, n=-1):
        return source.upper() if context.startswith("Diagram") else ""

    def isEmpty(self):
        return False  # an empty translator is skipped


def test_a_language_change_retranslates_the_diagram(qtbot):
    view = make_view(qtbot, E02)
    dialog = view.open_block("threshold")
    translator = ShoutingTranslator()
    QCoreApplication.installTranslator(translator)
    try:
        qtbot.waitUntil(lambda: view.diagram.blocks["ramps"].title == "RAMPS")
        assert view.diagram.blocks["threshold"].lines == ["THRESHOLD 5 %"]
        assert view.diagram.feedback_label.text() == "SPOOL POSITION (LVDT)"
        assert dialog.windowTitle() == "THRESHOLD"
    finally:
        QCoreApplication.removeTranslator(translator)
    qtbot.waitUntil(lambda: view.diagram.blocks["ramps"].title == "Ramps")


# --- picture ------------------------------------------------------------------------------------------
def test_render_picture_paints_the_diagram(qtbot):
    view = make_view(qtbot, E04_CA)
    image = QImage(800, 400, QImage.Format.Format_RGB32)
    image.fill(QColor("white"))
    painter = QPainter(image)
    view.render_picture(painter, QRectF(0, 0, 800, 400))
    painter.end()
    inked = sum(
        1
        for x in range(0, 800, 4)
        for y in range(0, 400, 4)
        if image.pixelColor(QPoint(x, y)) != QColor("white")
    )
    assert inked > 500


def test_the_printed_picture_shows_the_parameters_not_the_live_state(qtbot):
    valve = EmulatedValve(E02)
    valve.advance(2.0)
    link = EmulatorConnection(valve)
    view = make_view(qtbot, E02, Access.BASIC, connection=link)
    link.go_online()
    link.poll_signals()
    assert view.diagram.dots["demand"].value_text  # live on screen
    assert view.diagram.blocks["valve"].locked and view.diagram.blocks["position_controller"].locked
    picture = view.picture_scene()
    assert not any(block.locked for block in picture.blocks.values())
    assert all(dot.active and dot.value_text == "" for dot in picture.dots.values())
    for block_id, block in view.diagram.blocks.items():
        assert picture.blocks[block_id].lines == block.lines
        assert picture.blocks[block_id].title == block.title


def test_a_measuring_point_without_data_shows_a_dash_not_nan():
    """Online over CANopen most points have no object (NaN): the diagram showed "nan %"."""
    nan = float("nan")
    assert format_signal("demand", nan) == "—"
    assert format_signal("current_a", nan) == "A —"
    assert format_signal("pwm_a", nan) == "PWM A —"

"""The oscilloscope in German and Czech (issue 25 item 16): nothing cut off, numbers and
messages in the language switched to, the shared axis named, the legend after Stop."""

from __future__ import annotations

import numpy as np
import pytest
from PySide6.QtCore import QEvent
from PySide6.QtWidgets import QComboBox
from support.scope_fakes import FakeConnection

from prm9tool import i18n
from prm9tool.model.document import ParameterDocument
from prm9tool.views.scope.widget import ScopeWidget

E02 = "PRM9-06.3Z11/30-24E02S02"


@pytest.fixture
def conn():
    return FakeConnection()


@pytest.fixture
def scope(qtbot, conn):
    i18n.set_language("en")
    widget = ScopeWidget(conn, ParameterDocument(E02))
    qtbot.addWidget(widget)
    widget.resize(1024, 700)
    widget.show()
    yield widget
    i18n.set_language("en")


def _switch(qtbot, scope, language):
    i18n.set_language(language)
    qtbot.wait(10)  # the layout follows the new texts in the event loop


@pytest.mark.parametrize("language", ["de", "cs"])
def test_the_drop_downs_are_as_wide_as_their_texts_after_a_switch(qtbot, scope, language):
    """ "Rollen (ohne Trig", "Náběžná hra", the generator's "Rechtec": their width was that
    of the English texts."""
    _switch(qtbot, scope, language)
    c = scope.controls
    for combo in (c.mode, c.edge, c.rate, c.time_window, scope.generator_panel.waveform):
        metrics = combo.fontMetrics()
        widest = max(metrics.horizontalAdvance(combo.itemText(i)) for i in range(combo.count()))
        assert combo.width() > widest + 16, (combo.currentText(), combo.width(), widest)


@pytest.mark.parametrize("language", ["de", "cs"])
def test_the_waveform_is_as_wide_as_a_new_drop_down_of_its_texts(qtbot, scope, language):
    """ "Rechtec" on a real screen: the waveform kept the width of "Square" after the switch."""
    _switch(qtbot, scope, language)
    combo = scope.generator_panel.waveform
    fresh = QComboBox()
    qtbot.addWidget(fresh)
    fresh.addItems([combo.itemText(i) for i in range(combo.count())])
    assert combo.width() >= fresh.sizeHint().width(), [combo.itemText(i) for i in range(3)]


def test_the_interval_takes_the_decimal_comma_of_german(qtbot, scope):
    assert scope.controls.rate.itemText(0) == "0.2 ms (5 kHz)"
    _switch(qtbot, scope, "de")
    assert scope.controls.rate.itemText(0) == "0,2 ms (5 kHz)"
    assert "0,5 s" in [scope.controls.time_window.itemText(i) for i in range(6)]


def test_a_note_made_in_english_is_shown_in_german_after_the_switch(qtbot, scope):
    scope._on_generator_stopped_by_operation()
    assert "The setpoint generator has stopped" in scope.status.text()
    _switch(qtbot, scope, "de")
    assert "Sollwertgenerator" in scope.status.text()
    assert "The setpoint generator" not in scope.status.text()


def test_an_axis_two_channels_share_is_named_in_czech_not_numbered(qtbot, scope, conn):
    """The Czech axis read "1, 2 [%]": the joined names were too long, so channel numbers
    replaced them."""
    _switch(qtbot, scope, "cs")
    for key in ("setpoint_threshold", "position_actual"):
        scope.preselect(key)
    scope.start()
    conn.samples_received.emit(np.zeros((100, 2)))
    scope._redraw()
    assert scope.plot.shared_axes() == {1: 0}
    label = scope.plot.axes[0].labelText
    assert ">1</span>" not in label and ">2</span>" not in label
    assert "Skutečná poloha šoupátka" in label and label.endswith("[%]")


def test_after_stop_the_legend_marks_the_values_as_those_at_stop(qtbot, scope, conn):
    """The legend went on showing the values of the recording as if they were the valve's."""
    scope.preselect("demand")
    scope.start()
    conn.samples_received.emit(np.full((100, 1), 2048))  # 12.5 %
    scope._redraw()
    value = scope.plot.legend[0].value
    assert value.text() == "12.5 %"
    scope.stop()
    assert value.text() == "at stop: 12.5 %" and "before Stop" in value.toolTip()
    _switch(qtbot, scope, "de")
    assert value.text() == "bei Stopp: 12,5 %"
    scope.start()
    conn.samples_received.emit(np.full((100, 1), 4096))
    scope._redraw()
    assert value.text() == "25 %"


def test_language_change_events_alone_keep_the_scope_consistent(scope):
    scope.changeEvent(QEvent(QEvent.Type.LanguageChange))  # no exception, nothing lost
    assert scope.controls.rate.count() > 0


@pytest.mark.parametrize("language", ["de", "cs"])
def test_a_long_measuring_point_name_is_read_whole_in_the_list(qtbot, conn, language, tmp_path):
    """Issue 34, item 20: "Prozessabweichung nach Verstärkung und Offset …" was cut in the
    list of a 1024-pixel window: a longer name goes on onto a second line instead."""
    import os

    from PySide6.QtCore import QRect, Qt
    from PySide6.QtWidgets import QStyle, QStyleOptionViewItem

    i18n.set_language(language)
    try:
        widget = ScopeWidget(conn, ParameterDocument("PRM9-10.3Z11/60-24E04S02-CA"))
        qtbot.addWidget(widget)
        widget.resize(1024, 700)
        widget.show()
        qtbot.wait(20)
        points = widget.channels.list
        assert points.textElideMode() == Qt.TextElideMode.ElideNone
        wrapped = 0
        style, metrics = points.style(), points.fontMetrics()
        for row in range(points.count()):
            item = points.item(row)
            option = QStyleOptionViewItem()
            option.initFrom(points.viewport())
            option.rect = points.visualItemRect(item)
            option.features |= QStyleOptionViewItem.ViewItemFeature.WrapText
            points.itemDelegate().initStyleOption(option, points.indexFromItem(item))
            room = style.subElementRect(QStyle.SubElement.SE_ItemViewItemText, option, points)
            flags = Qt.TextFlag.TextWordWrap
            needed = metrics.boundingRect(QRect(0, 0, room.width() - 4, 10_000), flags, item.text())
            assert needed.height() <= room.height(), item.text()  # every line of it shown
            wrapped += needed.height() > metrics.height() + 2
        assert wrapped >= (language == "de")  # "Prozessabweichung …" took a second line
        if os.environ.get("PRM9TOOL_SCREENSHOTS"):
            widget.grab().save(
                os.path.join(os.environ["PRM9TOOL_SCREENSHOTS"], f"scope_e04_{language}.png")
            )
    finally:
        i18n.set_language("en")


@pytest.mark.parametrize("language", ["en", "de", "cs"])
def test_the_export_button_has_room_for_its_arrow_beside_its_text(qtbot, scope, language):
    """Issue 34 (a new user): the Export button's menu arrow was drawn over its text (a tool
    button squeezed to its text); it is a push button with its menu, as high as Start."""
    from PySide6.QtWidgets import QPushButton

    _switch(qtbot, scope, language)
    export = scope.controls.export
    assert isinstance(export, QPushButton) and export.menu() is not None
    text = export.fontMetrics().horizontalAdvance(export.text())
    assert export.width() >= text + export.style().pixelMetric(
        export.style().PixelMetric.PM_MenuButtonIndicator
    )
    assert export.height() == scope.controls.start.height()


@pytest.mark.parametrize("height", range(600, 640, 5))
def test_the_names_on_a_shared_german_axis_are_not_cut_at_its_end(qtbot, scope, conn, height):
    """ "Sollwert nach Rampe (0x6310), Schieberlage Ist (0x630" at a 1200 × 615 scope: the
    names were fitted to the axis without the margins and the space pyqtgraph draws around
    them, and were cut at the top."""
    _switch(qtbot, scope, "de")
    scope.resize(1200, height)
    qtbot.wait(10)
    for key in ("demand", "position_actual"):
        scope.preselect(key)
    scope.start()
    conn.samples_received.emit(np.zeros((100, 2)))
    scope._redraw()
    qtbot.wait(10)
    axis = scope.plot.axes[0]
    assert scope.plot.shared_axes() == {1: 0}
    assert axis.label.boundingRect().width() <= axis.size().height(), axis.labelText

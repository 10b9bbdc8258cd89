"""The oscilloscope widget against a fake connection: channels, capture, triggers, export."""

from __future__ import annotations

import math
import re

import numpy as np
import pyqtgraph as pg
import pytest
from PySide6.QtCore import QCoreApplication, QEvent, Qt
from PySide6.QtGui import QFontMetrics
from support.scope_fakes import FakeConnection

from prm9tool import i18n
from prm9tool.catalogue.signals import signals_for
from prm9tool.model.document import ParameterDocument
from prm9tool.scope import TriggerMode
from prm9tool.views.scope.legend import COLOURS
from prm9tool.views.scope.widget import ScopeWidget

E02 = "PRM9-06.3Z11/30-24E02S02"
E04 = "PRM9-10.2Z51/60-24E04S02-CA"


@pytest.fixture
def conn():
    return FakeConnection()


@pytest.fixture
def doc():
    return ParameterDocument(E02)


@pytest.fixture
def scope(qtbot, conn, doc):
    widget = ScopeWidget(conn, doc)
    qtbot.addWidget(widget)
    widget.resize(1400, 800)
    widget.show()
    return widget


def _check(scope: ScopeWidget, row: int) -> None:
    scope.channels.list.item(row).setCheckState(Qt.CheckState.Checked)


def _step_block(count: int, at: int, channels: int = 2) -> np.ndarray:
    """Raw block: channel 0 steps from 0 to 8192 (50 %) at ``at``; others follow with lag."""
    ref = np.where(np.arange(count) >= at, 8192, 0)
    lagged = np.where(np.arange(count) >= at + 50, 8192, 0)
    return np.column_stack([ref, lagged, np.full(count, 700)][:channels])


def _showing_demand(scope, conn):
    """The scope recording the demand value, one block received and drawn."""
    scope.preselect("demand")
    scope.start()
    conn.samples_received.emit(np.full((100, 1), 8192))
    scope._redraw()
    return scope.plot


def test_lists_every_measuring_point_of_the_variant(scope, doc):
    names = [scope.channels.list.item(r).text() for r in range(scope.channels.list.count())]
    assert len(names) == len(signals_for(doc.variant))
    assert not any("Process actual" in name for name in names)  # E04 only


def test_a_new_valve_type_relists_the_points_and_keeps_those_that_exist(scope, doc):
    scope.preselect("position_actual")
    doc.set_type_key(E04)
    names = [scope.channels.list.item(r).text() for r in range(scope.channels.list.count())]
    assert len(names) == len(signals_for(doc.variant))
    assert any("Process actual" in name for name in names)
    assert scope.channels.selected() == ["position_actual"]


def test_a_fourth_channel_is_refused_with_a_message(scope):
    for row in range(4):
        _check(scope, row)
    assert len(scope.channels.selected()) == 3
    assert scope.channels.list.item(3).checkState() == Qt.CheckState.Unchecked
    assert "At most three measuring points" in scope.channels.message.text()
    scope.channels.list.item(0).setCheckState(Qt.CheckState.Unchecked)
    _check(scope, 3)
    assert len(scope.channels.selected()) == 3
    assert scope.channels.message.text() == ""


def test_preselect_activates_the_signal_and_shows_its_axis(scope):
    scope.preselect("position_actual")
    assert scope.channels.selected() == ["position_actual"]
    assert scope.plot.legend[0].isVisibleTo(scope)
    assert "Spool position actual" in scope.plot.axes[0].labelText


def test_preselect_with_three_active_replaces_the_third(scope):
    for key in ("setpoint_raw", "demand", "position_setpoint", "position_actual"):
        scope.preselect(key)
    assert scope.channels.selected() == ["setpoint_raw", "demand", "position_actual"]
    assert "replaces" in scope.channels.message.text()


def test_the_three_points_notice_goes_when_it_no_longer_applies(qtbot, scope):
    for row in range(4):
        _check(scope, row)
    message = scope.channels.message
    assert message.isVisibleTo(scope)
    scope.channels.set_selected(["demand"])  # one point now: the refusal is void
    assert not message.isVisibleTo(scope) and message.text() == ""
    for key in ("setpoint_raw", "position_setpoint", "position_actual"):
        scope.preselect(key)
    assert "replaces" in message.text()
    scope.channels._message_timer.setInterval(20)  # shortened here: the notice is shown a while
    scope.channels._message_timer.start()
    qtbot.waitUntil(lambda: not message.isVisibleTo(scope), timeout=5000)
    assert scope.channels.selected() == ["demand", "setpoint_raw", "position_actual"]


def test_offline_the_scope_cannot_start_and_says_why(qtbot, doc):
    conn = FakeConnection(online=False)
    widget = ScopeWidget(conn, doc)
    qtbot.addWidget(widget)
    widget.preselect("current_a")
    assert not widget.controls.start.isEnabled()
    assert not widget.generator_panel.isEnabled()
    assert "needs a connected valve" in widget.status.text()
    widget.start()
    assert conn.streams == []
    conn.go_online()
    assert widget.controls.start.isEnabled()


def test_start_streams_the_selected_points_into_the_buffer_and_draws(scope, conn):
    scope.preselect("demand")
    scope.preselect("position_actual")
    scope.controls.rate.setCurrentIndex(scope.controls.rate.findData(1000))
    scope.start()
    assert conn.streams == [(["demand", "position_actual"], 1000)]
    conn.samples_received.emit(_step_block(500, 100))
    scope._redraw()
    assert scope.capture.buffer.total == 500
    x, y = scope.plot.curves[1].getData()
    assert len(x) > 0 and y.max() == pytest.approx(50.0)
    assert scope.plot.legend[0].value.text() == "50 %"


def test_a_stream_stopped_by_someone_else_stops_the_recording_and_says_so(scope, conn):
    """A tuning test stops the stream to stream itself: the scope used to keep saying
    "Recording at 5000 Hz" over a frozen trace."""
    scope.preselect("demand")
    scope.start()
    conn.samples_received.emit(_step_block(100, 10, channels=1))
    conn.stream_stopped.emit()
    assert not scope.running
    assert scope.controls.start.isEnabled()
    assert "recording stopped" in scope.status.text()
    assert scope.capture.buffer.total == 100  # what came is kept
    scope.start()
    assert scope.running and "recording stopped" not in scope.status.text()


def test_a_stream_gone_dead_stops_the_recording_in_the_captures_words(scope, conn):
    """The worker stopped a stream that sent nothing (tests/test_stream_contract.py): the note
    says why, not "another operation took the stream"."""
    scope.preselect("demand")
    scope.start()
    conn.samples_received.emit(_step_block(100, 10, channels=1))
    conn.stream_silent.emit("the valve sent no samples for 1.0 s (100 received)")
    conn.stream_stopped.emit()
    assert not scope.running
    status = scope.status.text()
    assert "The recording stopped: the valve sent no samples for 1.0 s (100 received)" in status
    assert "another operation" not in status
    scope.start()
    conn.stream_stopped.emit()  # a later stop by a tuning test says its own words again
    assert "another operation" in scope.status.text()


def test_changing_channels_or_rate_while_running_restarts_cleanly(scope, conn):
    scope.preselect("demand")
    scope.start()
    conn.samples_received.emit(_step_block(100, 10, channels=1))
    scope.preselect("current_a")
    assert conn.streams[-1] == (["demand", "current_a"], 5000)
    assert scope.capture.buffer.total == 0
    conn.samples_received.emit(np.zeros((20, 1)))  # a late block of the old stream
    assert scope.capture.buffer.total == 0
    scope.controls.rate.setCurrentIndex(scope.controls.rate.findData(500))
    assert conn.streams[-1] == (["demand", "current_a"], 500)
    assert scope.capture.rate_hz == 500


def test_changing_the_time_window_while_running_restarts_cleanly(scope, conn):
    scope.preselect("demand")
    scope.start()
    conn.samples_received.emit(np.zeros((100, 1)))
    scope.controls.pause.click()  # a held display is released by the restart
    old = scope.capture
    stops = conn.stream_stops
    scope.controls.time_window.setCurrentIndex(scope.controls.time_window.findData(0.5))
    assert conn.streams == [(["demand"], 5000)] * 2
    assert conn.stream_stops == stops + 1
    assert scope.capture is not old and scope.capture.buffer.total == 0
    assert scope.display.engine.window == 2500
    assert not scope.display.frozen and not scope.controls.pause.isChecked()
    conn.samples_received.emit(np.ones((10, 1)))
    assert scope.capture.buffer.total == 10


def test_changing_the_time_window_while_stopped_starts_nothing(scope, conn):
    scope.preselect("demand")
    scope.controls.time_window.setCurrentIndex(scope.controls.time_window.findData(2.0))
    assert conn.streams == []
    assert scope.controls.window_s() == 2.0


def test_single_trigger_holds_the_captured_step(scope, conn):
    scope.preselect("demand")
    scope.preselect("position_actual")
    c = scope.controls
    c.mode.setCurrentIndex(c.mode.findData(TriggerMode.SINGLE))
    c.level.setValue(25.0)
    c.time_window.setCurrentIndex(c.time_window.findData(0.1))  # 500 samples at 5 kHz
    scope.start()
    conn.samples_received.emit(np.zeros((300, 2)))
    scope._redraw()
    assert "Waiting for the trigger" in scope.status.text()
    conn.samples_received.emit(_step_block(1000, 200))
    scope._redraw()
    assert "Single capture complete" in scope.status.text()
    assert scope.controls.pause.isChecked()
    x0, x1 = scope.plot.x_range()
    assert x0 == pytest.approx(-0.02) and x1 == pytest.approx(0.08)
    conn.samples_received.emit(_step_block(1000, 200))  # recording goes on, display holds
    assert scope.capture.buffer.total == 2300
    assert len(scope.display.data()[0]) == 1300


def test_pause_holds_the_display_and_allows_time_zoom(scope, conn):
    scope.preselect("demand")
    scope.start()
    conn.samples_received.emit(np.zeros((100, 1)))
    scope._redraw()
    scope.controls.pause.click()
    held = scope.display.data()[0].copy()
    conn.samples_received.emit(np.ones((100, 1)))
    scope._redraw()
    np.testing.assert_array_equal(scope.display.data()[0], held)
    assert scope.plot.views[0].state["mouseEnabled"][0]
    scope.controls.pause.click()
    scope._redraw()
    assert len(scope.display.data()[0]) == 200
    assert not scope.plot.views[0].state["mouseEnabled"][0]


def test_cursors_read_values_and_differences(scope, conn):
    scope.preselect("demand")
    scope.preselect("current_a")
    scope.start()
    ramp = np.column_stack([np.arange(5000) * 2, np.full(5000, 650)])  # 0.2 s at 5 kHz
    conn.samples_received.emit(ramp)
    scope._redraw()
    scope.stop()
    scope.cursor_panel.show_cursors.setChecked(True)
    scope.plot.set_cursor_times(0.1, 0.5)
    cells = scope.cursor_panel.cells
    expected_a = 500 * 2 * 100 / 16384  # sample 500 at 0.1 s, in %
    assert cells[0][1].text() == f"{expected_a:.4g} %"
    assert cells[1][3].text() == "0 mA"
    assert "Δt = 400 ms" in scope.cursor_panel.dt.text()
    assert "2.5 Hz" in scope.cursor_panel.dt.text()


STEP_UP = 0.1  # s: where the demand steps from 0 to 50 % in the captures below


def _step_captured(scope, conn, response, demand=None) -> None:
    """0.5 s of demand (default: 0 → 50 % at STEP_UP) and ``response(t)`` as the position,
    received, drawn and held."""
    scope.preselect("demand")
    scope.preselect("position_actual")
    scope.controls.time_window.setCurrentIndex(scope.controls.time_window.findData(0.5))
    scope.start()
    t = np.arange(2500) / 5000.0
    ref = np.where(t >= STEP_UP, 8192, 0) if demand is None else demand(t)
    conn.samples_received.emit(np.column_stack([ref, response(t)]))
    scope._redraw()
    scope.stop()


def test_step_figures_are_shown_for_the_captured_step(scope, conn):
    _step_captured(
        scope, conn, lambda t: np.where(t >= 0.1, 8192 * (1 - np.exp(-(t - 0.1) / 0.01)), 0)
    )
    scope.display.update_readouts()
    figures = scope.step_panel.figures
    assert figures["rise"].text() == "21.97 ms"  # τ·ln 9
    assert figures["overshoot"].text() == "0.0 %"


def test_a_response_that_does_not_follow_the_step_gets_no_figures(scope, conn):
    noise = np.random.default_rng(5).normal(0.0, 40.0, 2500).round()
    _step_captured(scope, conn, lambda t: noise)  # noise only
    figures = scope.step_panel.figures
    assert figures["rise"].text() == figures["overshoot"].text() == "—"
    assert "No response to the step" in scope.step_panel.region.text()


def test_csv_export_of_the_whole_recording_and_of_the_visible_window(scope, conn, tmp_path):
    scope.preselect("demand")
    scope.preselect("current_a")
    scope.start()
    conn.samples_received.emit(np.column_stack([np.arange(1000), np.full(1000, 700)]))
    scope._redraw()
    scope.stop()
    whole = tmp_path / "whole.csv"
    assert scope.export_csv(whole, whole=True) == 1000
    lines = whole.read_text(encoding="utf-8").splitlines()
    assert lines[0] == "time [s],demand [%],current_a [mA]"
    assert lines[2].startswith("0.000200,0.0061")
    scope.plot.set_x_range(0.05, 0.1)
    part = tmp_path / "part.csv"
    rows = scope.export_csv(part, whole=False)
    assert 240 <= rows <= 252
    assert part.read_text(encoding="utf-8").splitlines()[1].startswith("0.05")


def test_csv_of_the_whole_recording_goes_on_past_a_pause(scope, conn, tmp_path):
    scope.preselect("demand")
    scope.start()
    conn.samples_received.emit(np.arange(1000).reshape(-1, 1))
    scope._redraw()
    scope.controls.pause.click()  # the picture holds; the recording goes on
    assert scope.display.frozen
    conn.samples_received.emit(np.arange(1000, 1500).reshape(-1, 1))
    scope._redraw()
    whole = tmp_path / "whole.csv"
    assert scope.export_csv(whole, whole=True) == 1500
    assert len(scope.display.data()[0]) == 1000  # the held picture is unchanged


def test_png_export_writes_an_image(scope, conn, tmp_path):
    scope.preselect("demand")
    scope.start()
    conn.samples_received.emit(np.zeros((100, 1)))
    scope._redraw()
    scope.export_png(tmp_path / "scope.png")
    assert (tmp_path / "scope.png").read_bytes()[:4] == b"\x89PNG"
    scope.export_png(tmp_path / "no_suffix")  # the dialog may return a name without .png
    assert (tmp_path / "no_suffix").read_bytes()[:4] == b"\x89PNG"
    with pytest.raises(OSError, match=r"Could not write .*missing"):
        scope.export_png(tmp_path / "missing" / "scope.png")


def test_link_loss_stops_the_recording_and_keeps_the_data(scope, conn):
    scope.preselect("demand")
    scope.start()
    conn.samples_received.emit(np.zeros((100, 1)))
    conn.drop_link()
    assert not scope.running
    assert len(scope.display.data()[0]) == 100
    assert "needs a connected valve" in scope.status.text()


def test_each_channel_has_its_own_scale_and_same_units_can_share_one(scope, conn):
    scope.preselect("demand")
    scope.preselect("position_actual")
    scope.preselect("current_a")
    scope.start()
    block = np.column_stack([np.full(100, 8192), np.full(100, -4096), np.full(100, 900)])
    block[50:, 0] = 0
    conn.samples_received.emit(block)
    scope._redraw()
    plot = scope.plot
    assert plot.y_range(0) == plot.y_range(1)  # both in %: one scale
    assert plot.y_range(0)[0] < -25 and plot.y_range(0)[1] > 50
    assert plot.y_range(2)[0] > 800  # mA on its own axis
    assert plot.shared_axes() == {1: 0}  # one axis for both, named for both
    assert not plot.axes[1].isVisible() and plot.axes[2].isVisible()
    assert "Spool position actual" in plot.axes[0].labelText
    scope.channels.same_scale.setChecked(False)
    assert plot.y_range(1)[1] < 0  # position alone: around -25 %
    assert plot.shared_axes() == {} and plot.axes[1].isVisible()
    assert "Spool position actual" not in plot.axes[0].labelText


def _plain_width(axis, label: str) -> int:
    plain = re.sub(r"<[^>]+>", "", label)
    return QFontMetrics(axis.label.font()).horizontalAdvance(plain)


def test_an_axis_shared_by_names_too_long_for_it_shows_the_legends_colour_squares(
    qtbot, scope, conn
):
    """At 1000 × 620 the three joined names were cut: "Demand value…, Spool position
    actual (…". The axis now shows the legend's squares in the channels' colours (the legend
    above names them) and names them all in its tooltip; a taller plot names them on it."""
    scope.resize(1000, 620)
    for key in ("demand", "position_actual", "position_setpoint"):
        scope.preselect(key)
    scope.start()
    conn.samples_received.emit(np.zeros((100, 3)))
    scope._redraw()
    qtbot.waitUntil(lambda: scope.plot._label_room > 0)
    assert scope.plot.shared_axes() == {1: 0, 2: 0}
    axis = scope.plot.axes[0]
    label = axis.labelText
    assert re.sub(r"<[^>]+>", "", label) == "■ ■ ■ [%]"
    for slot in range(3):  # each square in its channel's colour, as in the legend
        assert f'color:{COLOURS[slot]}">■</span>' in label
    assert axis.toolTip() == (
        "Demand value after ramp (0x6310), Spool position actual (0x6301), Position setpoint [%]"
    )
    scope.resize(1000, 1000)  # room for the names: they come back, whole
    qtbot.waitUntil(lambda: "Spool position actual" in axis.labelText)
    assert _plain_width(axis, axis.labelText) <= scope.plot.views[0].height()
    assert "…" not in axis.labelText


def test_zooming_an_axis_by_hand_stops_its_autoscale_until_auto(scope, conn):
    plot = _showing_demand(scope, conn)
    plot.views[0].setYRange(-200, 200, padding=0)
    plot.views[0].sigRangeChangedManually.emit([True, True])
    conn.samples_received.emit(np.full((100, 1), 16384))
    scope._redraw()
    assert not plot.is_autoscaled(0) and plot.y_range(0) == pytest.approx((-200, 200))
    assert not plot.legend[0].autoscale.autoRaise()  # framed: it looks like a button
    plot.legend[0].autoscale.click()
    assert plot.is_autoscaled(0) and plot.y_range(0)[1] < 150


def test_the_grid_lies_under_every_curve_at_the_labelled_ticks(scope, conn, qtbot):
    plot = _showing_demand(scope, conn)
    plot.views[0].setRange(xRange=(0, 10), yRange=(-60, 60), padding=0)
    xs, ys = plot.grid.lines()
    assert xs == pytest.approx([0, 2, 4, 6, 8, 10]) and ys == pytest.approx(
        [-60, -40, -20, 0, 20, 40, 60]
    )
    below = plot.grid.zValue()
    assert all(below < view.zValue() for view in plot.views[1:]) and below < plot.item.zValue()
    assert plot.grid.boundingRect() == plot.views[0].sceneBoundingRect()
    # a grid line is drawn in the plot where no curve is: the background there is lighter
    qtbot.wait(20)
    image = plot.graphics.grab().toImage()
    top_left = plot.graphics.mapFromScene(plot.views[0].sceneBoundingRect().topLeft())
    y20 = plot.graphics.mapFromScene(plot.views[0].mapViewToScene(pg.Point(5, 20))).y()
    x = top_left.x() + 40
    line = max(image.pixelColor(x, y20 + d).lightness() for d in (-1, 0, 1))
    assert line > image.pixelColor(x, y20 + 6).lightness()


def test_the_cached_axes_are_redrawn_when_their_range_changes(scope, conn, qtbot):
    """The axes are cached pixmaps (a benchmark finding): a new range must still show."""
    plot = _showing_demand(scope, conn)
    left = plot.axes[0]

    def picture():
        qtbot.wait(20)
        return plot.graphics.grab(
            plot.graphics.mapFromScene(left.sceneBoundingRect()).boundingRect()
        )

    plot.views[0].setYRange(-200, 200, padding=0)
    before = picture().toImage()
    assert picture().toImage() == before  # nothing changed: the same picture
    plot.views[0].setYRange(-20, 20, padding=0)
    assert picture().toImage() != before


def test_while_the_plot_holds_the_legend_marks_its_values_as_live(scope, conn):
    scope.preselect("demand")
    scope.start()
    conn.samples_received.emit(np.full((100, 1), 8192))
    scope._redraw()
    value = scope.plot.legend[0].value
    assert value.text() == "50 %"
    scope.controls.pause.click()
    conn.samples_received.emit(np.full((100, 1), 4096))
    scope._redraw()
    assert value.text() == "live: 25 %"  # newer than the held trace, and says so
    scope.controls.pause.click()
    conn.samples_received.emit(np.full((100, 1), 4096))
    scope._redraw()
    assert value.text() == "25 %"
    scope.controls.pause.click()
    conn.samples_received.emit(np.full((100, 1), 0))
    scope._redraw()
    assert value.text() == "live: 0 %"
    scope.stop()  # the recording ended: the plot holds all of it, the legend its last values
    assert value.text() == "at stop: 0 %"  # issue 25: not as if they were the valve's now
    assert len(scope.display.data()[0]) == 400


@pytest.mark.parametrize("language", ["en", "de", "cs"])
@pytest.mark.parametrize("type_key", [E02, E04])
def test_the_scope_fits_a_1024_by_768_screen(qtbot, conn, language, type_key):
    """No scroll bars in the main window (pages up to 960 px wide are not put in a scroll
    area) with three channels, in every language: up to 600 px high below the menu bar,
    tool bar and status bar."""
    i18n.set_language(language)
    try:
        widget = ScopeWidget(conn, ParameterDocument(type_key))
        qtbot.addWidget(widget)
        for key in ("setpoint_raw", "position_actual", "current_a"):
            widget.preselect(key)
        widget.show()
        hint = widget.minimumSizeHint()
    finally:
        i18n.set_language("en")
    assert hint.width() <= 960 and hint.height() <= 600


def test_step_figures_can_be_limited_to_the_cursor_span(scope, conn):
    def demand(t):
        return np.where(t >= 0.1, 8192, 0) - np.where(t >= 0.3, 4096, 0)  # up 50 %, down 25 %

    def response(t):
        resp = np.where(t >= 0.1, 8192 * (1 - np.exp(-(t - 0.1) / 0.01)), 0)
        return np.where(t >= 0.3, 4096 + 4096 * np.exp(-(t - 0.3) / 0.01), resp)

    _step_captured(scope, conn, response, demand)
    panel = scope.step_panel
    assert not panel.between_cursors.isEnabled()
    scope.cursor_panel.show_cursors.setChecked(True)
    scope.plot.set_cursor_times(0.05, 0.28)
    panel.between_cursors.setChecked(True)
    assert panel.figures["rise"].text() == "21.97 ms"
    assert panel.figures["error"].text() == "0.0 %"
    assert "between cursors" in panel.region.text()
    panel.between_cursors.setChecked(False)
    assert panel.region.text() == "Measured on step 1 of 2 in the visible window."
    assert panel.figures["rise"].text() == "21.97 ms"  # the first step, up to the second
    scope.plot.set_cursor_times(0.05, 0.11)  # B 10 ms after the step: the response is cut
    panel.between_cursors.setChecked(True)
    assert panel.figures["overshoot"].text() == "—"
    assert panel.region.text().startswith(
        "Window too short: in the samples between cursors A and B the response has not come"
    )


def test_a_square_wave_in_view_is_measured_not_called_no_response(scope, conn):
    def demand(t):  # a 0.2 s square wave: five edges in the window
        return np.where(np.mod(np.round(t * 5000) - 250, 1000) < 500, 8192, 0) * (t >= 0.05)

    def response(t):
        y, a = np.zeros_like(t), math.exp(-1 / 50)  # τ = 10 ms at 5 kHz
        ref = demand(t)
        for k in range(1, len(t)):
            y[k] = a * y[k - 1] + (1 - a) * ref[k - 1]
        return y

    _step_captured(scope, conn, response, demand)
    panel = scope.step_panel
    assert panel.region.text() == "Measured on step 1 of 5 in the visible window."
    assert panel.figures["rise"].text() == "21.97 ms"
    assert panel.figures["overshoot"].text() == "0.0 %"


def test_a_refused_stream_start_stops_and_says_why(qtbot, doc):
    conn = FakeConnection()
    conn.start_stream = lambda keys, rate: conn.failed.emit("stream rate 3000 Hz: use 5000 Hz …")
    widget = ScopeWidget(conn, doc)
    qtbot.addWidget(widget)
    widget.preselect("demand")
    widget.start()
    assert not widget.running
    assert widget.controls.start.isEnabled()
    assert widget.status.text() == (
        "The recording could not start: stream rate 3000 Hz: use 5000 Hz …"
    )


def test_a_language_change_relabels_the_channels_and_keeps_the_data(scope, conn, monkeypatch):
    scope.preselect("position_actual")
    scope.start()
    conn.samples_received.emit(np.full((100, 1), 8192))
    scope._redraw()
    monkeypatch.setattr(i18n, "current_language", lambda: "de")  # catalogue texts follow it
    QCoreApplication.sendEvent(scope, QEvent(QEvent.Type.LanguageChange))
    assert "Schieberlage Ist" in scope.plot.axes[0].labelText
    items = [scope.channels.list.item(r) for r in range(scope.channels.list.count())]
    assert any(item.text() == "Schieberlage Ist (0x6301) [%]" for item in items)
    assert scope.channels.selected() == ["position_actual"]
    assert scope.capture.buffer.total == 100


def test_cursors_keep_their_place_on_the_screen_when_new_data_arrives(scope, conn):
    plot = _showing_demand(scope, conn)
    scope.cursor_panel.show_cursors.setChecked(True)
    x0, x1 = plot.x_range()
    assert plot.cursor_times() == pytest.approx((x0 + 0.25 * (x1 - x0), x0 + 0.75 * (x1 - x0)))
    scope.stop()
    scope.start()  # a new capture: 20 s later the window shows other times
    conn.samples_received.emit(np.full((100_000, 1), 4096))
    scope._redraw()
    n0, n1 = plot.x_range()
    assert n0 > x1  # the old times are off the plot
    assert plot.cursor_times() == pytest.approx((n0 + 0.25 * (n1 - n0), n0 + 0.75 * (n1 - n0)))
    assert scope.cursor_panel.cells[0][1].text() == "25 %"  # not "—"


def _drag(plot, x_from: float, x_to: float) -> None:
    """A left-button drag across the middle of the plot from pixel ``x_from`` to ``x_to``."""
    from PySide6.QtCore import QPointF
    from PySide6.QtGui import QMouseEvent
    from PySide6.QtTest import QTest
    from PySide6.QtWidgets import QApplication

    viewport = plot.graphics.viewport()
    y = viewport.height() / 2
    left, none = Qt.MouseButton.LeftButton, Qt.MouseButton.NoButton
    events = [(QEvent.Type.MouseMove, x_from, none, none)]  # hover first, as a real mouse does
    events += [(QEvent.Type.MouseButtonPress, x_from, left, left)]
    events += [
        (QEvent.Type.MouseMove, x_from + (x_to - x_from) * k / 5, none, left) for k in range(1, 6)
    ]
    events += [(QEvent.Type.MouseButtonRelease, x_to, left, none)]
    for kind, x, button, buttons in events:
        point = QPointF(x, y)
        global_point = QPointF(viewport.mapToGlobal(point.toPoint()))
        event = QMouseEvent(
            kind, point, global_point, button, buttons, Qt.KeyboardModifier.NoModifier
        )
        QApplication.sendEvent(viewport, event)
        QTest.qWait(25)  # pyqtgraph drops mouse moves closer together than its rate limit


def test_a_press_next_to_a_cursor_line_drags_the_cursor_not_the_plot(scope, conn):
    plot = _showing_demand(scope, conn)
    scope.stop()  # held: the mouse pans the time axis
    scope.cursor_panel.show_cursors.setChecked(True)
    before = plot.x_range()
    t_a, _ = plot.cursor_times()
    view = plot.views[0]
    x = plot.graphics.mapFromScene(view.mapViewToScene(pg.Point(t_a, 0))).x()
    _drag(plot, x + 4, x + 64)  # 4 pixels right of cursor A
    assert plot.x_range() == pytest.approx(before)  # no pan
    pixel = (before[1] - before[0]) / view.width()
    assert plot.cursor_times()[0] == pytest.approx(t_a + 60 * pixel, abs=3 * pixel)


def test_over_canopen_the_intervals_offered_are_those_the_link_delivers(qtbot, doc):
    """The 0.2 ms default lost ~14 000 samples in seconds over CANopen: there the scope offers
    only the intervals the link's SYNC + TPDO1 pace allows, the fastest selected."""
    from types import SimpleNamespace

    conn = FakeConnection(online=False)
    widget = ScopeWidget(conn, doc)
    qtbot.addWidget(widget)
    assert widget.controls.rate_hz() == 5000  # USB and emulator: the valve's full stream
    conn.device = SimpleNamespace(stream_rate_limit_hz=1000.0)
    conn.go_online()
    rates = [widget.controls.rate.itemData(i) for i in range(widget.controls.rate.count())]
    assert rates == [1000, 500, 250, 100, 50]
    widget.preselect("position_actual")
    widget.start()
    assert conn.streams == [(["position_actual"], 1000)]
    conn.drop_link()
    conn.device = SimpleNamespace(stream_rate_limit_hz=0.0)
    conn.go_online()
    assert widget.controls.rate.itemData(0) == 5000


def test_the_status_shows_the_rate_the_link_really_delivers(scope, conn):
    scope.preselect("position_actual")
    scope.controls.rate.setCurrentIndex(scope.controls.rate.findData(1000))
    scope.start()
    conn.samples_received.emit(_step_block(500, 100, channels=1))
    conn.samples_lost = 500
    scope._update_status()
    assert scope.status.text() == (
        "Recording at 500 Hz of the 1000 Hz asked for: 500 samples lost on the link."
    )


def test_a_rate_near_the_one_asked_for_is_written_out_not_in_powers_of_ten(scope, conn):
    """One sample lost of 5000 at 5 kHz: the link delivers 4999 Hz, shown as 5000 (three digits),
    not as "5e+03", which a user at the screen read as a fault."""
    scope.preselect("position_actual")
    scope.controls.rate.setCurrentIndex(scope.controls.rate.findData(5000))
    scope.start()
    conn.samples_received.emit(_step_block(5000, 100, channels=1))
    conn.samples_lost = 1
    scope._update_status()
    assert scope.status.text() == (
        "Recording at 5000 Hz of the 5000 Hz asked for: 1 samples lost on the link."
    )


def test_the_settling_time_stands_on_the_line_of_its_name(qtbot, scope):
    """ "Einschwingzeit ±2 %" and its "—" a line apart: the figure keeps three lines of room
    for a "did not settle" and was centred in them."""
    panel = scope.step_panel
    panel.parentWidget().parentWidget().setCurrentWidget(panel)  # the tab of the panel
    qtbot.waitUntil(panel.isVisible)
    field, label = panel.figures["settling"], panel.labels[5]
    assert field.height() > 2 * field.fontMetrics().lineSpacing()
    assert field.alignment() & label.alignment() & Qt.AlignmentFlag.AlignTop
    assert abs(field.geometry().top() - label.geometry().top()) <= 4

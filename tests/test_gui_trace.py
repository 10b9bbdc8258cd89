"""Communication → CAN trace: the window decodes a trace off the GUI thread, filters its table
by node and kind, plots the PDO values, jumps to an incident's frame, shows a malformed file's
line without raising, and records the bus with Record… / Stop (also in the CAN bus dialog)."""

from __future__ import annotations

from pathlib import Path

import can
import pytest
from PySide6.QtCore import QSettings, Qt
from support.canopen_rig import unique_channel
from support.trace_rig import record_commissioning

import prm9tool.trace as trace
from prm9tool.online.trace_recording import BusRecording
from prm9tool.trace.events import Kind
from prm9tool.views.trace.window import TraceWindow

DECODE_TIMEOUT_MS = 60_000  # a decode of a few thousand frames; generous for a loaded PC


@pytest.fixture(scope="module")
def golden(tmp_path_factory: pytest.TempPathFactory) -> Path:
    path = tmp_path_factory.mktemp("gui-trace") / "commissioning.blf"
    record_commissioning(path, "gui-golden")
    return path


@pytest.fixture
def window(qtbot, tmp_path):
    settings = QSettings(str(tmp_path / "settings.ini"), QSettings.Format.IniFormat)
    recording = BusRecording()
    bus = {"interface": "virtual", "channel": unique_channel("gui-trace"), "bitrate": None}
    window = TraceWindow(recording, lambda: bus, settings)
    qtbot.addWidget(window)
    yield window
    recording.stop()


def _open(qtbot, window: TraceWindow, path: Path) -> None:
    with qtbot.waitSignal(window.decoded, timeout=DECODE_TIMEOUT_MS):
        window.open_trace(str(path))


def test_the_table_filters_by_node_and_kind(qtbot, window, golden):
    _open(qtbot, window, golden)
    every = window.model.rowCount()
    assert every == len(window.trace.events)
    window.node.setCurrentIndex(window.node.findData(15))
    window.kind.setCurrentIndex(window.kind.findData(Kind.STATE))
    rows = [window.model.event_at(r).text for r in range(window.model.rowCount())]
    assert [t for t in rows if t.startswith("device state")][-1].startswith(
        "device state HOLD → DEVICE_MODE_ACTIVE"
    )
    assert all(window.model.event_at(r).node == 15 for r in range(window.model.rowCount()))
    window.node.setCurrentIndex(0)
    window.kind.setCurrentIndex(0)
    assert window.model.rowCount() == every


def test_the_timeline_plots_the_pdo_values(qtbot, window, golden):
    _open(qtbot, window, golden)
    assert (10, "POSACT") in window._curves and (15, "PRCSETP") in window._curves
    times, values = window._curves[(10, "POSACT")].getData()
    assert len(times) > 100 and max(values) > 10.0
    shown = {k for k, curve in window._curves.items() if curve.isVisible()}
    assert shown == {(10, "POSSETP"), (10, "POSACT"), (15, "PRCSETP"), (15, "PRCACT")}
    item = next(
        window.series.item(r) for r in range(window.series.count())
        if window.series.item(r).data(Qt.ItemDataRole.UserRole) == (10, "POSACT")
    )  # fmt: skip
    item.setCheckState(Qt.CheckState.Unchecked)
    assert not window._curves[(10, "POSACT")].isVisible()


def test_choosing_an_incident_selects_its_frame(qtbot, window, golden):
    _open(qtbot, window, golden)
    texts = [window.incidents.item(r).text() for r in range(window.incidents.count())]
    row = next(r for r, t in enumerate(texts) if "left DEVICE_MODE_ACTIVE" in t)
    window.incidents.setCurrentRow(row)
    chosen = window.model.event_at(window.table.currentIndex().row())
    assert chosen.kind is Kind.STATE and "DEVICE_MODE_ACTIVE →" in chosen.text


def test_a_malformed_trace_is_reported_with_its_line(qtbot, window, tmp_path):
    path = tmp_path / "bad.log"
    path.write_text("(1.000000) can0 70A#05\n(1.0 can0\n")
    window.open_trace(str(path))
    qtbot.waitUntil(window.open_button.isEnabled, timeout=DECODE_TIMEOUT_MS)
    assert "cannot be read" in window.summary.text() and "line 2" in window.summary.text()
    assert window.trace is None


def test_record_and_stop_write_a_trace_of_the_bus(qtbot, window, tmp_path):
    controls = window.recording
    path = tmp_path / "recorded.asc"
    sender = can.Bus(interface="virtual", channel=controls._bus()["channel"])
    try:
        with qtbot.waitSignal(controls._recording.started, timeout=DECODE_TIMEOUT_MS):
            controls.start(str(path))
        assert not controls.record.isEnabled() and controls.stop.isEnabled()
        for _ in range(20):
            sender.send(can.Message(arbitration_id=0x080, data=b"", is_extended_id=False))
        qtbot.waitUntil(lambda: controls._recording.frames == 20, timeout=DECODE_TIMEOUT_MS)
        with qtbot.waitSignal(controls._recording.stopped):
            controls.stop.click()
    finally:
        sender.shutdown()
    assert controls.record.isEnabled() and "20 frames recorded" in controls.state.text()
    assert trace.read(path).sync.count == 20


def test_the_can_bus_dialog_offers_record_and_stop(qtbot, tmp_path):
    from prm9tool.views.canbus.bus_dialog import CanBusDialog

    settings = QSettings(str(tmp_path / "settings.ini"), QSettings.Format.IniFormat)
    recording = BusRecording()
    dialog = CanBusDialog(lambda bus, deliver: None, settings, recording=recording)
    qtbot.addWidget(dialog)
    assert dialog.record_controls is not None
    assert dialog.record_controls.record.isEnabled()
    assert not dialog.record_controls.stop.isEnabled()


def test_communication_can_trace_opens_the_window_with_the_dialogs_recording(qtbot, tmp_path):
    from support.gui_support import main_window

    with main_window(qtbot, tmp_path) as window:
        window.commands["can_trace"].trigger()
        shown = window.trace_window
        assert isinstance(shown, TraceWindow) and shown.isVisible()
        assert shown.recording._recording is window.valve.finder.recording
        window.commands["can_trace"].trigger()
        assert window.trace_window is shown  # one window, raised again


def test_the_window_fits_the_screen(window):
    free = window.screen().availableGeometry()
    assert window.width() <= free.width()
    assert window.height() <= free.height()


def test_a_long_failure_wraps_and_does_not_widen_the_window(qtbot, window):
    """Record… without an adapter: the reason (a long line of python-can's) grew the trace window
    beyond a 1366-pixel screen; it wraps in the window's width and is whole in the tip."""
    window.show()
    width = window.width()
    reason = "cannot open the CAN interface 'socketcan', channel 'can0': " + "x" * 40 + " y" * 200
    window.recording._recording.failed.emit(reason)
    qtbot.wait(10)  # the layout follows in the event loop
    assert window.width() == width
    assert window.minimumSizeHint().width() <= width
    assert reason in window.recording.state.toolTip()


def test_an_empty_trace_plots_a_plain_time_axis(qtbot, window, tmp_path):
    """Issue 34 (a new user): the empty trace's plot read "Time (s) (x0.001)" from −500 to
    500: no scale factor appended to the label, and the first second from the start."""
    path = tmp_path / "empty.log"
    path.write_text("", encoding="utf-8")
    _open(qtbot, window, path)
    for name in ("left", "bottom"):
        assert "x0.001" not in window.plot.getAxis(name).labelString()
        assert "×" not in window.plot.getAxis(name).labelString()
    (x_low, x_high), _y = window.plot.viewRange()
    assert x_low >= 0.0 and x_high == pytest.approx(1.0)

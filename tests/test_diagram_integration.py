"""The diagram and the CANopen window inside the main window, online on an emulated valve.

These run the real ValveConnection (worker thread, USB protocol, emulator session).
"""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt
from support.gui_support import (
    E02,
    E02_CA,
    emulated,
    emulator_connection,
    go_online,
    main_window,
    record_prompts,
    settings_in,
)

from prm9tool import i18n
from prm9tool.catalogue import Access
from prm9tool.device import emulated_valves
from prm9tool.model.access import AccessModel
from prm9tool.model.document import ParameterDocument
from prm9tool.model.undo import DocumentUndo
from prm9tool.views.diagram import DiagramView

TIMEOUT = 10_000


@pytest.fixture
def window(qtbot, tmp_path, monkeypatch):
    record_prompts(monkeypatch)
    with main_window(qtbot, tmp_path) as win:
        yield win


def _online(qtbot, window, spec: str) -> DiagramView:
    go_online(qtbot, window, spec)
    qtbot.waitUntil(lambda: window.sync.active, timeout=TIMEOUT)
    view = window.views["diagram"]
    assert isinstance(view, DiagramView)
    return view


def test_the_diagram_is_the_default_central_view(window):
    assert window.current_view() == "diagram"
    assert isinstance(window.views["diagram"], DiagramView)


@pytest.mark.parametrize("language", ["en", "de", "cs"])
def test_on_a_1024_x_768_screen_the_block_texts_stay_readable(qtbot, window, language):
    window.set_language(language)
    window.resize(1024, 738)  # 768 less a title bar
    qtbot.waitUntil(lambda: window.width() == 1024)
    view = window.views["diagram"]
    qtbot.wait(50)  # the view fits the diagram on its resize event
    scale = view.transform().m11()
    for block in view.diagram.blocks.values():
        assert block.fits
        assert block.title_font.pixelSize() * scale >= 9.0, block.block_id
        assert block.line_font.pixelSize() * scale >= 9.0, block.block_id
    window.set_language("en")


@pytest.fixture
def paced_window(qtbot, tmp_path, monkeypatch):
    """A main window whose emulated valve runs in real time (its measuring points move)."""
    from prm9tool.views.main_window import MainWindow

    record_prompts(monkeypatch)
    i18n.set_language("en")
    doc = ParameterDocument(E02)
    connection = emulator_connection(paced=True)
    win = MainWindow(doc, DocumentUndo(doc), AccessModel(), connection, settings_in(tmp_path))
    qtbot.addWidget(win)
    win.show()
    yield win
    connection.shutdown()
    emulated_valves.forget_emulated_valves()


def test_a_red_dot_opens_the_scope_with_its_measuring_point(qtbot, paced_window):
    window = paced_window
    view = _online(qtbot, window, f"{E02}:4701")
    dot = view.diagram.dots["current_a"]
    qtbot.waitUntil(lambda: dot.value_text.endswith("mA"), timeout=TIMEOUT)
    centre = view.mapFromScene(dot.sceneBoundingRect().center())
    qtbot.mouseClick(view.viewport(), Qt.MouseButton.LeftButton, pos=centre)
    assert window.current_view() == "scope"
    assert "current_a" in window.views["scope"].channels.selected()


def test_canopen_window_node_id_and_terminator_survive_a_restart(qtbot, window, monkeypatch):
    window.access.set_level(Access.EXPERT)  # Basic may only look at the CANopen settings
    view = _online(qtbot, window, f"{E02_CA}:4702")
    valve = emulated(4702)
    valve.set_input("switch_node", 0)  # node ID set by software; read at the next power-up
    with qtbot.waitSignal(window.connection.operation_finished, timeout=TIMEOUT):
        window.connection.restart()
    view.open_block("canopen")  # the diagram's block opens the main window's CANopen window
    canopen = window.canopen_window
    qtbot.waitUntil(lambda: canopen.switches is not None, timeout=TIMEOUT)
    assert canopen.switches[1] == 0 and canopen.node_id.isEnabled()

    writes = []
    write = window.connection.write
    monkeypatch.setattr(
        window.connection, "write", lambda mn, raw: (writes.append(mn), write(mn, raw))
    )
    canopen.node_id.setValue(42)
    canopen.node_id.editingFinished.emit()
    canopen.terminator.setChecked(True)
    assert writes == ["NODEID", "CANTERM"]  # once each, by the sync
    assert "after the valve restarts" in canopen.restart_label.text()
    with qtbot.waitSignal(
        window.connection.operation_finished,
        check_params_cb=lambda name, _result: name == "restart",
        timeout=TIMEOUT,
    ):
        window.connection.restart()
    qtbot.waitUntil(lambda: canopen.valve_values.get("NODEID") == 42, timeout=TIMEOUT)
    assert valve.node_id == 42
    assert canopen.valve_values["CANTERM"] == 1
    assert "node ID 42" in canopen.effective_label.text()
    assert "terminator on" in canopen.effective_label.text()
    assert canopen.restart_label.isHidden()


def test_the_canopen_block_and_the_toolbar_show_one_canopen_window(qtbot, tmp_path, monkeypatch):
    from prm9tool.views.canbus.canopen_window import CanopenWindow

    record_prompts(monkeypatch)
    with main_window(qtbot, tmp_path, E02_CA) as window:
        view = window.views["diagram"]
        assert window.canopen_window is None
        with qtbot.assertNotEmitted(view.dialog_opened):
            view.open_block("canopen")
        first = window.canopen_window
        assert isinstance(first, CanopenWindow) and first.isVisible()
        first.close()
        view.open_block("canopen")
        assert window.canopen_window is first and first.isVisible()
        window.commands["canopen"].trigger()
        assert window.canopen_window is first
        assert window.findChildren(CanopenWindow) == [first]


def test_the_diagram_says_why_its_points_read_a_dash_while_the_scope_records(qtbot, paced_window):
    """Issue 34 (a new user): with a recording running in the background, most measuring
    points of the diagram showed "—" and only their tooltips said why (the valve streams three
    points at a time). Shown while the oscilloscope records, the diagram says it."""
    window = paced_window
    view = _online(qtbot, window, f"{E02}:4709")
    window.open_scope("position_actual")
    scope = window.views["scope"]
    scope.start()
    qtbot.waitUntil(lambda: scope.capture is not None and scope.capture.buffer.total > 100,
                    timeout=TIMEOUT)  # fmt: skip
    window.show_view("diagram")
    assert "records in the background" in window.status.currentMessage()
    assert "show — until the recording stops" in window.status.currentMessage()
    dot = view.diagram.dots["current_a"]
    qtbot.waitUntil(lambda: dot.value_text.endswith("—"), timeout=TIMEOUT)
    scope.stop()
    window.show_view("parameters")
    window.show_view("diagram")
    assert "records in the background" not in window.status.currentMessage()

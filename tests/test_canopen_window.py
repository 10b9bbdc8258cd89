"""The CANopen window against an emulated valve: switch tables, node ID, terminator, restart."""

from __future__ import annotations

import os

import pytest
from support.diagram_fakes import EmulatorConnection

from prm9tool import i18n
from prm9tool.catalogue import CATALOGUE, Access
from prm9tool.catalogue.canopen_switches import (
    Overridden,
    baud_position,
    effective,
    node_position,
    overridden,
)
from prm9tool.device.emulator import EmulatedValve
from prm9tool.model.access import AccessModel
from prm9tool.model.document import ParameterDocument
from prm9tool.model.undo import DocumentUndo
from prm9tool.online.sync import ValveSync
from prm9tool.views.canbus.canopen_window import CanopenWindow

E02_CA = "PRM9-06.3Z11/30-24E02S02-CA"


def open_window(qtbot, switches=(6, 0), online=True):
    """The window as the main window makes it: online, a ValveSync writes document edits."""
    valve = EmulatedValve(E02_CA, switches=switches)
    link = EmulatorConnection(valve)
    doc = ParameterDocument(E02_CA)
    sync = ValveSync(doc, link)
    if online:
        link.go_online()
        sync.start({mn: valve_value(valve, mn) for mn in doc.values})
    undo = DocumentUndo(doc, doc)
    window = CanopenWindow(doc, link, sync=sync)
    qtbot.addWidget(window)
    window.show()
    window.keep = (doc, undo, link, sync)  # keep the models alive as long as the window
    return window, valve, link, doc, undo


def marked_rows(table) -> list[int]:
    return [row for row in range(table.rowCount()) if table.item(row, 0).text().startswith("▶")]


def valve_value(valve: EmulatedValve, mnemonic: str) -> int | str:
    return valve.read(*CATALOGUE[mnemonic].key)


def test_the_tables_mark_the_switch_positions_read_at_power_up(qtbot):
    window, *_ = open_window(qtbot, switches=(0xB, 5))
    assert window.switches == (0xB, 5)
    assert marked_rows(window.baud_table) == [0xB]
    assert marked_rows(window.node_table) == [5]
    assert window.baud_table.item(0xB, 1).text() == "CANopen, 125 kbit/s"
    assert window.baud_table.item(0xB, 2).text() == "on"
    assert window.node_table.item(5, 1).text() == "25"
    assert not window.node_id.isEnabled()  # the switch sets the node ID
    assert "node ID 25, 125 kbit/s, terminator on" in window.effective_label.text()


def test_enter_in_the_node_id_takes_it_and_keeps_the_window_open(qtbot):
    from PySide6.QtCore import Qt

    window, _valve, _link, doc, _undo = open_window(qtbot, switches=(6, 0))
    window.node_id.setFocus()
    window.node_id.lineEdit().selectAll()
    qtbot.keyClicks(window.node_id, "42")
    qtbot.keyClick(window.node_id, Qt.Key.Key_Return)
    assert doc.value("NODEID") == 42 and window.isVisible()


def test_node_id_and_terminator_go_to_the_valve_and_show_after_restart(qtbot):
    window, valve, link, doc, _undo = open_window(qtbot, switches=(6, 0))
    assert marked_rows(window.node_table) == [0]
    assert window.node_id.isEnabled()
    window.node_id.setValue(42)
    window.node_id.editingFinished.emit()
    window.terminator.setChecked(True)
    assert doc.value("NODEID") == 42 and doc.value("CANTERM") == 1
    assert valve_value(valve, "NODEID") == 42 and valve_value(valve, "CANTERM") == 1
    assert link.writes == [("NODEID", 42), ("CANTERM", 1)]  # once each: by the sync
    assert link.stores == 2  # stored, so the restart keeps them
    assert not window.restart_label.isHidden()
    assert "after the valve restarts" in window.restart_label.text()
    assert "After the next restart" in window.effective_label.text()

    link.restart()
    assert valve.node_id == 42  # the emulated firmware latched the new node ID
    assert valve.bitrate == 500_000
    assert window.restart_label.isHidden()
    assert window.switches == (6, 0)
    assert window.valve_values == {"NODEID": 42, "BITRATE": 2, "CANTERM": 1}
    assert window.effective_label.text() == (
        "The valve uses: node ID 42, 500 kbit/s, terminator on."
    )


def test_changes_are_undoable_in_the_document(qtbot):
    window, _valve, _link, doc, undo = open_window(qtbot, online=False)
    window.node_id.setValue(77)
    window.node_id.editingFinished.emit()
    assert doc.value("NODEID") == 77
    undo.stack.undo()
    assert window.node_id.value() == CATALOGUE["NODEID"].default


def test_offline_changes_stay_in_the_document_and_the_window_says_so(qtbot):
    window, valve, link, doc, _undo = open_window(qtbot, online=False)
    assert window.switches is None
    assert "Offline" in window.state_label.text()
    assert marked_rows(window.baud_table) == []
    window.terminator.setChecked(True)
    assert doc.value("CANTERM") == 1
    assert link.writes == []
    assert valve_value(valve, "CANTERM") == 0
    assert "Upload" in window.restart_label.text()


def test_going_online_reads_the_switches(qtbot):
    window, _valve, link, *_ = open_window(qtbot, switches=(3, 9), online=False)
    link.go_online()
    assert window.switches == (3, 9)
    assert marked_rows(window.node_table) == [9]


def test_with_an_access_model_basic_level_may_only_look(qtbot):
    doc = ParameterDocument(E02_CA)
    access = AccessModel(Access.BASIC)
    window = CanopenWindow(doc, None, access=access)
    qtbot.addWidget(window)
    window.keep = (doc, access)
    assert not window.node_id.isEnabled() and not window.terminator.isEnabled()
    assert "Expert" in window.terminator.toolTip()
    assert not window.apply("CANTERM", 1)
    assert "Expert" in window.error_label.text()
    assert doc.value("CANTERM") == 0
    access.set_level(Access.EXPERT)
    assert window.terminator.isEnabled()


def test_a_valve_without_canopen_says_so(qtbot):
    doc = ParameterDocument("PRM9-06.3Z11/30-24E02S02")
    window = CanopenWindow(doc, None)
    qtbot.addWidget(window)
    window.keep = doc
    assert "no CANopen interface" in window.state_label.text()
    assert not window.terminator.isEnabled()
    assert not window.node_id.isEnabled()


# --- switch decoding (table 7-17) ------------------------------------------------------------------
@pytest.mark.parametrize(
    ("position", "enabled", "kbit", "terminator"),
    [
        (0, False, None, False),
        (1, False, None, False),
        (2, True, 20, False),
        (6, True, 500, False),
        (8, True, 1000, False),
        (9, True, 20, True),
        (0xD, True, 500, True),
        (0xF, True, 1000, True),
    ],
)
def test_interface_switch_positions(position, enabled, kbit, terminator):
    decoded = baud_position(position)
    assert (decoded.can_enabled, decoded.bitrate_kbit, decoded.terminator) == (
        enabled,
        kbit,
        terminator,
    )


def test_node_switch_positions():
    assert node_position(0).software
    assert node_position(1).lss
    assert [node_position(p).node_id for p in range(2, 16)] == list(range(10, 80, 5))
    with pytest.raises(ValueError, match="0…15"):
        node_position(16)


def test_effective_settings_follow_the_emulated_firmware():
    # node switch 0: node ID and bit rate from the parameters, terminator from either
    settings = effective(0x5, 0, 33, 4, 0)
    assert (settings.node_id, settings.bitrate_kbit, settings.terminator) == (33, 125, False)
    settings = effective(4, 3, 33, 0, 1)  # node 15 from the switch, 125 k, software terminator
    assert (settings.node_id, settings.bitrate_kbit, settings.terminator) == (15, 125, True)
    assert not effective(1, 3, 33, 0, 1).can_enabled


@pytest.mark.parametrize(
    ("switches", "canterm", "terminator", "kbit", "struck"),
    [
        ((0xC, 0), 0, True, 125, Overridden(bitrate=True, terminator=False)),  # 9…F: on
        ((0x5, 0), 1, True, 125, Overridden(bitrate=True, terminator=False)),  # by software
        ((0xC, 1), 0, False, None, Overridden(bitrate=True, terminator=True)),  # LSS: no function
        ((0xC, 1), 1, True, None, Overridden(bitrate=True, terminator=True)),
        ((0xC, 4), 0, True, 250, Overridden(bitrate=False, terminator=False)),
        ((0x0, 0), 1, False, None, Overridden(bitrate=False, terminator=False)),  # CAN off
    ],
)
def test_which_switch_settings_apply_table_7_17(switches, canterm, terminator, kbit, struck):
    # BITRATE code 4 = 125 kbit/s; interface 0xC = 250 kbit/s with terminator, 5 = 250 k without
    settings = effective(*switches, 33, 4, canterm)
    assert settings.bitrate_kbit == kbit  # None: automatic, or CAN off
    assert settings.terminator is terminator
    assert overridden(*switches) == struck


def _struck(table, row: int) -> list[int]:
    return [c for c in range(table.columnCount()) if table.item(row, c).font().strikeOut()]


@pytest.mark.parametrize(
    ("switches", "struck", "why"),
    [
        ((0xB, 0), [1], "bit rate set by software"),
        ((0xB, 1), [1, 2], "node-ID switch at 1"),
        ((0xB, 5), [], ""),
        ((0x4, 1), [1], "detects the bit rate"),
    ],
)
def test_the_table_strikes_out_what_the_node_switch_overrides(qtbot, switches, struck, why):
    window, *_ = open_window(qtbot, switches=switches)
    row = switches[0]
    assert marked_rows(window.baud_table) == [row]
    assert _struck(window.baud_table, row) == struck
    assert all(_struck(window.baud_table, r) == [] for r in range(16) if r != row)
    for column in struck:
        assert why in window.baud_table.item(row, column).toolTip()


def test_online_changes_are_not_stored_while_the_valve_does_not_follow_the_document(qtbot):
    window, valve, link, doc, _undo = open_window(qtbot, switches=(6, 0))
    window._sync.stop()  # e.g. the differences prompt after going online is still open
    window.terminator.setChecked(True)
    assert doc.value("CANTERM") == 1
    assert link.writes == [] and link.stores == 0
    assert valve_value(valve, "CANTERM") == 0
    assert "does not follow the document" in window.restart_label.text()


def test_a_restart_from_the_valve_menu_reads_the_switches_again(qtbot):
    window, valve, link, *_ = open_window(qtbot, switches=(6, 0))
    window.terminator.setChecked(True)
    assert window.restart_pending
    valve.set_input("switch_node", 3)
    valve.restart()
    link.operation_finished.emit("after_restart", {})  # ValveWorkflow's restart job
    assert not window.restart_pending and window.restart_label.isHidden()
    assert window.switches == (6, 3)


@pytest.mark.parametrize("language", ["en", "de", "cs"])
def test_the_window_fits_a_1024_x_768_screen(qtbot, language):
    i18n.set_language(language)
    try:
        window, *_ = open_window(qtbot, switches=(0xC, 1))
        qtbot.wait(10)
        assert window.height() <= 700 and window.width() <= 1000
        hint = window.minimumSizeHint()
        assert hint.height() <= 700 and hint.width() <= 1000
        # every switch position is visible without scrolling
        assert window.baud_table.viewport().height() >= 16 * window.baud_table.rowHeight(0)
    finally:
        i18n.set_language("en")


def test_the_window_follows_a_dark_palette(qtbot, qapp, tmp_path):
    from test_diagram_palette import dark_palette

    from prm9tool.views.diagram.colours import contrast_ratio

    window, *_ = open_window(qtbot, switches=(0xB, 1))
    light_mark = window.baud_table.item(0xB, 0).background().color()
    before = qapp.palette()
    qapp.setPalette(dark_palette())
    try:
        qtbot.waitUntil(lambda: window.baud_table.item(0xB, 0).background().color() != light_mark)
        mark = window.baud_table.item(0xB, 0).background().color()
        assert mark.lightness() < 128 and mark.hue() == light_mark.hue()  # the yellow, dark
        text = window.palette().color(window.palette().ColorRole.Text)
        assert contrast_ratio(text, mark) >= 4.5
        struck = window.baud_table.item(0xB, 1).foreground().color()
        assert contrast_ratio(struck, mark) >= 3.0
        assert "background: #fff4d6" not in window.restart_label.styleSheet()
        window.grab().save(
            str(os.environ.get("PRM9TOOL_SCREENSHOTS", tmp_path)) + "/canopen_dark.png"
        )
    finally:
        qapp.setPalette(before)
    qtbot.waitUntil(lambda: window.baud_table.item(0xB, 0).background().color() == light_mark)


@pytest.mark.parametrize(
    ("device_id", "title"),
    [
        ("can:10", "Settings made by software (over CANopen)"),
        ("usb:1-2", "Settings made by software (USB)"),
        (None, "Settings made by software"),
    ],
)
def test_the_settings_title_names_the_link_they_go_over(qtbot, monkeypatch, device_id, title):
    """Issue 34, item 15: the window said "(USB)" while connected over CAN."""
    from types import SimpleNamespace

    window, _valve, link, *_ = open_window(qtbot, online=device_id is not None)
    device = SimpleNamespace(type_key=E02_CA, device_id=device_id)
    monkeypatch.setattr(type(link), "device", property(lambda s: device if s.is_online else None))
    window.refresh()
    assert window.settings_box.title() == title

"""View → Object dictionary over CANopen: every object read from the valve, the objects a real
valve lacks said so, writing only at Expert level."""

from __future__ import annotations

import pytest
from PySide6.QtWidgets import QInputDialog
from support.can_link_rig import E02, make_link_rig

from prm9tool.catalogue import Access
from prm9tool.device import factory
from prm9tool.model.access import AccessModel
from prm9tool.online.connection import ValveConnection
from prm9tool.views.od_browser import ObjectDictionaryDialog


@pytest.fixture
def online(qtbot, tmp_path, monkeypatch):
    monkeypatch.setenv("PRM9TOOL_DATA_DIR", str(tmp_path / "data"))
    rig = make_link_rig("od", tmp_path, real_valve=True)
    connection = ValveConnection(
        opener=lambda e: factory.open_session(
            e, can_link=rig.options, type_key=str(rig.valve.type_key)
        )
    )
    with qtbot.waitSignal(connection.online_changed, timeout=10000):
        connection.go_online("can:10")
    yield rig, connection
    connection.shutdown()
    rig.close()


def rows(dialog):
    table = dialog.model
    return {
        (table.item(r, 0).text(), table.item(r, 1).text()): table.item(r, 5).text()
        for r in range(table.rowCount())
    }


def test_every_object_is_read_and_missing_ones_are_named(qtbot, online):
    rig, connection = online
    access = AccessModel()
    dialog = ObjectDictionaryDialog(connection, access, rig.valve.variant)
    qtbot.addWidget(dialog)
    dialog.read_all()
    qtbot.waitUntil(lambda: dialog.read.isEnabled(), timeout=10000)
    shown = rows(dialog)
    assert shown[("0x1018", "4")] == f"0x{rig.valve.serial:X}"
    assert shown[("0x1000", "0")] == "0x198"
    assert "not available over CANopen on this valve" in shown[("0x2020", "1")]
    assert shown[("0x1003", "0")] == "0"
    assert shown[("0x1003", "1")] == "— (no entry)"  # was "The valve refused the access."
    assert "writing needs the Expert level" in dialog.note.text()


def test_an_e02_lists_the_sensor_objects_of_all_valves(qtbot, tmp_path, monkeypatch):
    """Table 7-14: an E02 -CA has 0x2005-0x2008 and 0x2100 too; with no sensor input 0x2100
    reads 0 (docs/canopen.md)."""
    monkeypatch.setenv("PRM9TOOL_DATA_DIR", str(tmp_path / "data"))
    rig = make_link_rig("od-e02", tmp_path, E02, real_valve=True)
    connection = ValveConnection(
        opener=lambda e: factory.open_session(e, can_link=rig.options, type_key=E02)
    )
    try:
        with qtbot.waitSignal(connection.online_changed, timeout=10000):
            connection.go_online("can:10")
        dialog = ObjectDictionaryDialog(connection, AccessModel(), rig.valve.variant)
        qtbot.addWidget(dialog)
        dialog.read_all()
        qtbot.waitUntil(lambda: dialog.read.isEnabled(), timeout=10000)
        shown = rows(dialog)
        assert (shown[("0x2005", "1")], shown[("0x2008", "0")]) == ("9", "0")
        assert [shown[("0x2100", str(sub))] for sub in (1, 3, 4, 5, 6)] == ["0"] * 5
        assert shown[("0x1A01", "0")] == "2" and shown[("0x1601", "1")] == "0x21000210"
    finally:
        connection.shutdown()
        rig.close()


def test_expert_writes_an_object(qtbot, online, monkeypatch):
    rig, connection = online
    access = AccessModel()
    access.set_level(Access.EXPERT)
    dialog = ObjectDictionaryDialog(connection, access, rig.valve.variant)
    qtbot.addWidget(dialog)
    monkeypatch.setattr(QInputDialog, "getText", staticmethod(lambda *_a, **_k: ("0x1F4", True)))
    row = next(
        r for r in range(dialog.model.rowCount()) if dialog.model.item(r, 0).text() == "0x1017"
    )
    with qtbot.waitSignal(connection.operation_finished, timeout=10000):
        dialog._on_table_double_clicked(row, 5)
    qtbot.waitUntil(lambda: dialog.model.item(row, 5).text() == "500", timeout=10000)
    assert rig.valve.read(0x1017, 0) == 500


def test_the_search_line_filters_the_objects(qtbot, online):
    """Issue 25 item 15: the object dictionary browser had no search or filter."""
    rig, connection = online
    dialog = ObjectDictionaryDialog(connection, AccessModel(), rig.valve.variant)
    qtbot.addWidget(dialog)
    everything = dialog.proxy.rowCount()
    qtbot.keyClicks(dialog.search, "0x1018")  # the identity object's four entries and count
    shown = [dialog.proxy.index(r, 0).data() for r in range(dialog.proxy.rowCount())]
    assert 1 < len(shown) < everything and set(shown) == {"0x1018"}
    dialog.search.setText("heartbeat")  # a name, in any case
    names = [dialog.proxy.index(r, 2).data() for r in range(dialog.proxy.rowCount())]
    assert names and all("heartbeat" in name.lower() for name in names)
    dialog.search.clear()
    assert dialog.proxy.rowCount() == everything

"""Communication → CAN bus, devices without a node ID: the dialog lists a valve at node-ID
switch 1 (LSS) beside the configured nodes, "Assign node ID…" proposes the first free ID,
refuses one that answers, gives the valve its ID (stored) and goes online with it."""

from __future__ import annotations

import pytest
from PySide6.QtCore import QSettings
from PySide6.QtWidgets import QInputDialog
from support.lss_rig import make_lss_rig

from prm9tool.device import factory
from prm9tool.online.connection import ValveConnection
from prm9tool.online.lss_commissioning import LssCommissioning
from prm9tool.views.canbus.bus_dialog import CanBusDialog


@pytest.fixture
def settings(qapp, tmp_path):
    from prm9tool import i18n

    i18n.set_language("en")
    return QSettings(str(tmp_path / "settings.ini"), QSettings.Format.IniFormat)


@pytest.fixture
def rig(tmp_path, request, monkeypatch):
    monkeypatch.setenv("PRM9TOOL_DATA_DIR", str(tmp_path / "data"))
    rig = make_lss_rig(request.node.name)
    rig.add(4700, switches=(6, 2))  # a configured valve: node 10 by its switch
    rig.add(4711)  # node-ID switch at 1: no node ID
    yield rig
    rig.close()


@pytest.fixture
def dialog(qtbot, rig, settings):
    connection = ValveConnection(opener=lambda e: factory.open_session(e, can_link=rig.options))
    lss = LssCommissioning()
    dialog = CanBusDialog(
        lambda bus, deliver: connection.list_devices_async((), deliver, bus),
        settings,
        lss=lss,
    )
    qtbot.addWidget(dialog)
    dialog.interface.setCurrentText("virtual")
    dialog.channel.setText(rig.options.channel)
    qtbot.waitUntil(lambda: rig.valves[0].status().nmt_state == "pre-operational", timeout=10000)
    dialog.search.click()
    panel = dialog.lss_panel
    qtbot.waitUntil(lambda: panel.table.rowCount() == 1 and panel.look.isEnabled(), timeout=90000)
    yield dialog
    connection.shutdown()


def test_assign_node_id_proposes_the_first_free_id_and_goes_online(qtbot, dialog, rig, monkeypatch):
    panel = dialog.lss_panel
    assert dialog.table.item(0, 0).text() == "can:10"
    assert [panel.table.item(0, c).text() for c in range(5)] == [
        "4711", "PRM9", "0xE6", "0x9", "0x10000",
    ]  # fmt: skip
    assert panel.state.text() == "1 device without a node ID."
    asked = []

    def answer(_parent, _title, label, value, low, high):
        asked.append((label, value, low, high))
        return 21, True

    monkeypatch.setattr(QInputDialog, "getInt", answer)
    with qtbot.waitSignal(dialog.accepted, timeout=90000):
        panel.assign.click()
    assert asked == [
        (
            "Node ID for serial 4711 (1…127; stored in the valve, used from now on and after "
            "every power-up):",
            1,
            1,
            127,
        )
    ]
    assert dialog.selected_device_id() == "can:21"
    valve = rig.valves[1]
    assert (valve.node_id, valve.firmware.nv.lss["node_id"]) == (21, 21)
    assert panel.state.text() == "Serial 4711 answers as can:21 (stored). Going online with it…"
    connection = ValveConnection(opener=lambda e: factory.open_session(e, can_link=rig.options))
    with qtbot.waitSignal(connection.online_changed, timeout=10000):
        connection.go_online(dialog.selected_device_id())
    assert connection.device.serial == 4711
    connection.go_offline()
    connection.shutdown()


def test_an_id_that_answers_is_refused_and_nothing_is_sent(qtbot, dialog, rig, monkeypatch):
    panel = dialog.lss_panel
    monkeypatch.setattr(QInputDialog, "getInt", lambda *_a: (10, True))
    rig.frames()
    panel.assign.click()
    assert panel.state.text() == "Node ID 10 is taken: a node answers there. Choose another one."
    assert not [f for f in rig.frames() if f.startswith("7E5")]
    assert (rig.valves[1].node_id, rig.valves[1].firmware.nv.lss) == (0, {})
    assert dialog.result() == 0  # still open


def test_an_id_taken_behind_the_dialogs_back_is_refused_by_the_job(qtbot, dialog, rig, monkeypatch):
    panel = dialog.lss_panel
    rig.add(4800, switches=(6, 3))  # node 15 joins after the search
    qtbot.waitUntil(lambda: rig.valves[2].status().nmt_state == "pre-operational", timeout=10000)
    monkeypatch.setattr(QInputDialog, "getInt", lambda *_a: (15, True))
    panel.table.selectRow(0)
    panel.assign.click()
    qtbot.waitUntil(lambda: panel.assign.isEnabled(), timeout=90000)
    assert panel.state.text() == (
        "Node ID assignment (LSS) did not complete. (node ID 15 is taken: serial 4800 answers "
        "there. Choose a free node ID; nothing was changed (free: 1, 2, 3, …))"
    )  # the words of --lss-assign and prm9tool.lss_assign: one LSS service (issue 28)
    assert (rig.valves[1].node_id, rig.valves[1].firmware.nv.lss) == (0, {})


def test_find_bit_rate_sets_the_rate_the_bus_runs_at(qtbot, settings):
    from prm9tool.online.lss_commissioning import FoundRate

    asked = []

    def find(bus):
        asked.append(dict(bus))
        return FoundRate(250_000, (10, 21))

    dialog = CanBusDialog(lambda _b, _d: None, settings, lss=LssCommissioning(find=find))
    qtbot.addWidget(dialog)
    dialog.interface.setCurrentText("pcan")
    dialog.channel.setText("PCAN_USBBUS1")
    dialog.find_rate.click()
    qtbot.waitUntil(lambda: dialog.find_rate.isEnabled(), timeout=10000)
    assert asked[0]["interface"] == "pcan"
    assert dialog.bitrate.currentData() == 250_000
    assert dialog.state.text() == (
        "The bus runs at 250 kbit/s (frames from nodes: 10, 21). Search the bus."
    )


def test_find_bit_rate_on_an_adapter_without_listen_only_says_what_to_try(qtbot, settings):
    dialog = CanBusDialog(lambda _b, _d: None, settings, lss=LssCommissioning())
    qtbot.addWidget(dialog)
    dialog.interface.setCurrentText("socketcan")
    dialog.channel.setText("can0")
    rate = dialog.bitrate.currentData()
    dialog.find_rate.click()
    qtbot.waitUntil(lambda: dialog.find_rate.isEnabled(), timeout=10000)
    assert dialog.state.text().startswith(
        "The bit rate cannot be found without transmitting on this adapter. (prm9tool cannot "
        "find the bit rate on socketcan channel can0: the socketcan interface has no listen-only "
        "mode prm9tool can switch on, and it never transmits at a guessed rate. Try: set the "
        "controller to listen-only yourself"
    )
    assert dialog.bitrate.currentData() == rate


def test_change_node_id_by_lss_warns_that_the_link_moves_and_goes_online_there(
    qtbot, settings, tmp_path, monkeypatch
):
    from support.gui_support import record_prompts

    from prm9tool.device.canlink.lss import LssAddress, LssMasterLink
    from prm9tool.views import prompts

    monkeypatch.setenv("PRM9TOOL_DATA_DIR", str(tmp_path / "data"))
    rig = make_lss_rig("renumber")
    try:
        valve = rig.add(4711)  # switch 1, given node 21 by LSS
        LssMasterLink(rig.shared).assign(LssAddress(0xE6, 0x9, 0x10000, 4711), 21)
        qtbot.waitUntil(lambda: valve.status().nmt_state == "pre-operational", timeout=10000)
        fixed = rig.add(4700, switches=(6, 2))  # node 10 by its switch: no LSS
        qtbot.waitUntil(lambda: fixed.status().nmt_state == "pre-operational", timeout=10000)
        connection = ValveConnection(opener=lambda e: factory.open_session(e, can_link=rig.options))
        dialog = CanBusDialog(
            lambda bus, deliver: connection.list_devices_async((), deliver, bus),
            settings,
            lss=LssCommissioning(),
        )
        qtbot.addWidget(dialog)
        dialog.interface.setCurrentText("virtual")
        dialog.channel.setText(rig.options.channel)
        dialog.search.click()
        qtbot.waitUntil(lambda: dialog.table.rowCount() == 2, timeout=90000)
        qtbot.waitUntil(lambda: dialog.lss_panel.look.isEnabled(), timeout=90000)
        assert [dialog.table.item(r, 0).text() for r in range(2)] == ["can:10", "can:21"]
        answers = record_prompts(monkeypatch)
        answers.answers = [prompts.Button.Yes, prompts.Button.Yes]
        monkeypatch.setattr(QInputDialog, "getInt", lambda *_a: (22, True))
        dialog.table.selectRow(0)  # node 10: its switch decides, LSS cannot move it
        dialog.renumber.click()
        qtbot.waitUntil(lambda: dialog.renumber.isEnabled(), timeout=90000)
        assert "node 10 (serial 4700) does not answer LSS: its node-ID switch is not at 1" in (
            dialog.state.text()
        )
        assert fixed.node_id == 10
        dialog.table.selectRow(1)
        with qtbot.waitSignal(dialog.accepted, timeout=90000):
            dialog.renumber.click()
        assert (
            "prm9tool's own link moves with it: a connection to can:21 ends" in (answers.asked[-1])
        )
        assert dialog.selected_device_id() == "can:22"
        assert (valve.node_id, valve.firmware.nv.lss["node_id"]) == (22, 22)
        connection.shutdown()
    finally:
        rig.close()


def test_assign_node_ids_to_all_gives_consecutive_free_ids_in_one_action(
    qtbot, dialog, rig, monkeypatch
):
    panel = dialog.lss_panel
    second = rig.add(4712)
    panel.start_scan()
    qtbot.waitUntil(lambda: panel.table.rowCount() == 2 and panel.look.isEnabled(), timeout=90000)
    asked = []

    def first_id(_parent, _title, label, value, low, high):
        asked.append((label, value))
        return 9, True  # 10 answers already: 9 and 11 are the next free ones

    monkeypatch.setattr(QInputDialog, "getInt", first_id)
    panel.assign_all.click()
    assert asked == [
        (
            "First node ID: the 2 valves get consecutive free node IDs from it, in the order of "
            "their serial numbers (stored in each valve):",
            1,
        )
    ]
    qtbot.waitUntil(lambda: dialog.table.rowCount() == 3, timeout=90000)
    assert [dialog.table.item(r, 0).text() for r in range(3)] == ["can:9", "can:10", "can:11"]
    assert [dialog.table.item(r, 2).text() for r in range(3)] == ["4711", "4700", "4712"]
    assert (rig.valves[1].firmware.nv.lss["node_id"], second.firmware.nv.lss["node_id"]) == (9, 11)
    qtbot.waitUntil(lambda: panel.look.isEnabled(), timeout=90000)
    assert panel.table.rowCount() == 0


def test_change_bit_rate_by_lss_moves_every_lss_valve_and_the_tools_link(
    qtbot, settings, tmp_path, monkeypatch
):
    from support.gui_support import record_prompts

    from prm9tool.device.canlink.lss import LssMasterLink
    from prm9tool.views import prompts

    monkeypatch.setenv("PRM9TOOL_DATA_DIR", str(tmp_path / "data"))
    rig = make_lss_rig("bus-rate")
    try:
        valves = [rig.add(4711), rig.add(4712)]
        link = LssMasterLink(rig.shared)
        for node, address in enumerate(link.scan(), start=21):
            link.assign(address, node)
        connection = ValveConnection(opener=lambda e: factory.open_session(e, can_link=rig.options))
        dialog = CanBusDialog(
            lambda bus, deliver: connection.list_devices_async((), deliver, bus),
            settings,
            lss=LssCommissioning(),
        )
        qtbot.addWidget(dialog)
        dialog.interface.setCurrentText("virtual")
        dialog.channel.setText(rig.options.channel)
        answers = record_prompts(monkeypatch)
        answers.answers = [prompts.Button.Yes]
        monkeypatch.setattr(QInputDialog, "getItem", lambda *_a: ("250 kbit/s", True))
        dialog.lss_actions.change_rate.click()
        assert answers.asked[-1].startswith(
            "Change bit rate by LSS: Every valve at node-ID switch 1 (LSS) switches from 500 "
            "kbit/s to 250 kbit/s together and stores it."
        )
        assert "prm9tool's own link moves to 250 kbit/s" in answers.asked[-1]
        qtbot.waitUntil(lambda: dialog.table.rowCount() == 2, timeout=90000)
        assert dialog.bitrate.currentData() == 250_000
        assert [v.bitrate for v in valves] == [250_000, 250_000]
        assert [v.firmware.nv.lss["bit_timing"] for v in valves] == [3, 3]
        assert [dialog.table.item(r, 0).text() for r in range(2)] == ["can:21", "can:22"]
        connection.shutdown()
    finally:
        rig.close()

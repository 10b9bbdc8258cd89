"""Communication → CAN bus: the dialog scans a real (virtual) bus through the connection, lists
the valve and other nodes, remembers the bus, and going online with the chosen node works."""

from __future__ import annotations

import pytest
from PySide6.QtCore import QSettings
from PySide6.QtWidgets import QDialogButtonBox, QInputDialog
from support.can_link_rig import E04, make_link_rig, unique_channel
from support.canopen_rig import foreign_node

from prm9tool.device import factory
from prm9tool.device.canlink.discovery import IDENTIFY_TIMEOUT_S, SCAN_WINDOW_S
from prm9tool.device.canlink.session import SDO_TIMEOUT_S
from prm9tool.online.connection import ValveConnection
from prm9tool.views.canbus.bus_dialog import BITRATE_KEY, CHANNEL_KEY, INTERFACE_KEY, CanBusDialog

IDENTIFY_READS = 7  # discovery.identify_node of a PRM9: 0x1000, 0x1018/1, 0x1008, 0x100A,
# 0x1018/4, the type key 0x2041 and 0x2005/1 (E04 or E02)
OPEN_READS = 40  # CanopenSession opening: identity, type key, the switches' objects ...


def search_bound_ms(nodes: int) -> int:
    """The longest a search of ``nodes`` nodes takes by its own timeouts (the scan window,
    then every identifying read timing out and tried twice, as canopen's SDO client does);
    doubled: on a loaded PC the test's own threads wait for the cores too."""
    worst = SCAN_WINDOW_S + nodes * IDENTIFY_READS * 2 * IDENTIFY_TIMEOUT_S
    return int(2 * worst * 1000)


@pytest.fixture
def settings(qapp, tmp_path):
    from prm9tool import i18n

    i18n.set_language("en")  # the English plural forms (prm9tool_en.qm)
    return QSettings(str(tmp_path / "settings.ini"), QSettings.Format.IniFormat)


@pytest.fixture
def rig(tmp_path, request, monkeypatch):
    monkeypatch.setenv("PRM9TOOL_DATA_DIR", str(tmp_path / "data"))
    rig = make_link_rig(request.node.name, tmp_path)
    yield rig
    rig.close()


def test_the_dialog_lists_the_nodes_and_goes_online_with_the_valve(qtbot, rig, settings):
    connection = ValveConnection(opener=lambda e: factory.open_session(e, can_link=rig.options))
    other = foreign_node(rig.options.channel)
    dialog = CanBusDialog(
        lambda bus, deliver: connection.list_devices_async((), deliver, bus), settings
    )
    qtbot.addWidget(dialog)
    dialog.interface.setCurrentText("virtual")
    dialog.channel.setText(rig.options.channel)
    ok = dialog.buttons.button(QDialogButtonBox.StandardButton.Ok)
    try:
        dialog.search.click()
        # the search ends (its button comes back) within its own timeouts, however slow the PC
        qtbot.waitUntil(dialog.search.isEnabled, timeout=search_bound_ms(2))
    finally:
        other.disconnect()
    assert dialog.table.rowCount() == 2, dialog.state.text()
    cells = [[dialog.table.item(r, c).text() for c in range(4)] for r in range(2)]
    assert cells[0] == ["can:5", "not a PRM9", "", ""]
    assert cells[1][:3] == ["can:10", E04, str(rig.valve.serial)]
    described = [dialog.table.item(r, 7).text() for r in range(2)]
    assert described[0].startswith("Node 5: not a PRM9 (device type 0x")
    assert described[1].startswith(f"CANopen node 10 on virtual channel {rig.options.channel}")
    assert "2 nodes answered. 1 of them a PRM9 valve." in dialog.state.text()
    assert not ok.isEnabled()
    dialog.table.selectRow(0)  # not a PRM9: not selectable
    assert dialog.selected_device_id() is None and not ok.isEnabled()
    dialog.table.selectRow(1)
    assert dialog.selected_device_id() == "can:10" and ok.isEnabled()
    ok.click()
    assert (settings.value(INTERFACE_KEY), settings.value(CHANNEL_KEY)) == (
        "virtual",
        rig.options.channel,
    )
    assert int(settings.value(BITRATE_KEY)) == 500000
    failed: list[str] = []
    connection.failed.connect(failed.append)
    connection.go_online(dialog.selected_device_id())
    qtbot.waitUntil(  # online, or refused: both come within the opening's SDO timeouts
        lambda: connection.is_online or bool(failed),
        timeout=int(2 * OPEN_READS * 2 * SDO_TIMEOUT_S * 1000),
    )
    assert connection.is_online, failed
    assert connection.device.type_key == E04
    connection.go_offline()
    connection.shutdown()


def test_a_bus_that_cannot_be_opened_is_said_in_the_dialog(qtbot, settings):
    connection = ValveConnection()
    dialog = CanBusDialog(
        lambda bus, deliver: connection.list_devices_async((), deliver, bus), settings
    )
    qtbot.addWidget(dialog)
    dialog.interface.setCurrentText("socketcan")
    dialog.channel.setText(unique_channel("x")[:12])
    dialog.search.click()
    qtbot.waitUntil(lambda: dialog.search.isEnabled(), timeout=10000)
    assert "The bus could not be searched" in dialog.state.text()
    assert "cannot open the CAN interface 'socketcan'" in dialog.state.text()
    assert dialog.table.rowCount() == 0
    connection.shutdown()


def test_a_valve_without_its_type_key_is_asked_for_it_once(qtbot, tmp_path, settings, monkeypatch):
    monkeypatch.setenv("PRM9TOOL_DATA_DIR", str(tmp_path / "data"))
    rig = make_link_rig("gui-real", tmp_path, real_valve=True)
    connection = ValveConnection(opener=lambda e: factory.open_session(e, can_link=rig.options))
    dialog = CanBusDialog(
        lambda bus, deliver: connection.list_devices_async((), deliver, bus), settings
    )
    qtbot.addWidget(dialog)
    dialog.interface.setCurrentText("virtual")
    dialog.channel.setText(rig.options.channel)
    answers = [("PRM9-06.3Z11/30-24E02S02-CA", True), ("PRM9-06.3Z11/30-24E04S02-CA", True)]
    asked: list[str] = []

    def answer(_parent, _title, label, text=""):
        asked.append(label)
        return answers.pop(0)

    monkeypatch.setattr(QInputDialog, "getText", staticmethod(answer))
    try:
        dialog.search.click()
        qtbot.waitUntil(lambda: dialog.table.rowCount() == 1, timeout=10000)
        assert dialog.table.item(0, 1).text() == "? (E04 -CA; type key unknown)"
        dialog.table.selectRow(0)
        ok = dialog.buttons.button(QDialogButtonBox.StandardButton.Ok)
        ok.click()  # an E02 key for an E04 valve: refused, the dialog stays
        assert "does not fit the valve: its objects say E04 -CA" in dialog.state.text()
        assert dialog.result() == 0
        ok.click()
        assert dialog.result() == 1
        assert "does not tell its type key; its objects say E04 -CA" in asked[0]
        with qtbot.waitSignal(connection.online_changed, timeout=10000):
            connection.go_online(dialog.selected_device_id())
        assert connection.device.type_key == E04  # remembered for its serial number
        connection.go_offline()
    finally:
        connection.shutdown()
        rig.close()


def test_the_node_table_is_live_while_the_dialog_is_open(qtbot, rig, settings):
    """The network view: after a search the monitor keeps NMT state, heartbeat age and last
    EMCY current off the GUI thread; a node that boots is added, one whose heartbeat stops is
    shown silent."""
    import time

    import can

    from prm9tool.online.bus_monitor import BusMonitor

    rig.valve.start()  # real time: the valve's heartbeat runs
    connection = ValveConnection(opener=lambda e: factory.open_session(e, can_link=rig.options))
    monitor = BusMonitor()
    dialog = CanBusDialog(
        lambda bus, deliver: connection.list_devices_async((), deliver, bus),
        settings,
        None,
        monitor,
    )
    qtbot.addWidget(dialog)
    dialog.interface.setCurrentText("virtual")
    dialog.channel.setText(rig.options.channel)
    other = can.Bus(interface="virtual", channel=rig.options.channel)
    try:
        rig.valve.write(0x1017, 0, 50)  # heartbeat every 50 ms
        dialog.search.click()
        qtbot.waitUntil(
            lambda: dialog.table.rowCount() == 1 and dialog.search.isEnabled(), timeout=10000
        )
        assert dialog.table.item(0, 0).text() == "can:10"
        qtbot.waitUntil(lambda: dialog.table.item(0, 4).text() == "pre-operational", timeout=3000)
        other.send(can.Message(arbitration_id=0x705, data=[0x00], is_extended_id=False))  # boot-up
        qtbot.waitUntil(lambda: dialog.table.rowCount() == 2, timeout=3000)
        assert dialog.table.item(1, 0).text() == "can:5"
        assert dialog.table.item(1, 1).text() == "new on the bus: search again to identify it"
        for _ in range(4):  # its heartbeat, every 50 ms, and an EMCY
            time.sleep(0.05)
            other.send(can.Message(arbitration_id=0x705, data=[0x7F], is_extended_id=False))
        other.send(can.Message(arbitration_id=0x085, data=[0x00, 0x81, 0x10, 0, 0, 0, 0, 0],
                               is_extended_id=False))  # fmt: skip
        qtbot.waitUntil(lambda: dialog.table.item(1, 6).text().startswith("8100 "), timeout=3000)
        assert dialog.table.item(1, 4).text().startswith("pre-operational (boot-up ")
        assert dialog.table.item(1, 5).text().endswith(" s ago")
        qtbot.waitUntil(
            lambda: dialog.table.item(1, 5).text().startswith("silent for"), timeout=4000
        )
        assert dialog.table.item(0, 5).text().endswith(" s ago")  # the valve still beats
        dialog.table.selectRow(1)  # a node not identified: not selectable
        assert dialog.selected_device_id() is None
    finally:
        other.shutdown()
        dialog.reject()
        rig.valve.stop()
        connection.shutdown()
    assert not monitor.running  # closing the dialog stops the watch


@pytest.mark.parametrize(
    ("language", "one", "three"),
    [
        ("en", "1 node answered. 1 of them a PRM9 valve.", "3 nodes answered. 0 of them PRM9 valves."),
        ("de", "1 Knoten hat geantwortet. Davon 1 PRM9-Ventil.", "3 Knoten haben geantwortet. Davon 0 PRM9-Ventile."),
        ("cs", "Odpověděl 1 uzel. Z toho 1 ventil PRM9.", "Odpověděly 3 uzly. Z toho 0 ventilů PRM9."),
    ],
)  # fmt: skip
def test_the_count_of_nodes_uses_the_plural_forms_of_the_language(
    qtbot, settings, language, one, three
):
    from types import SimpleNamespace

    from prm9tool import i18n

    def node(number: int, kind: str) -> SimpleNamespace:
        return SimpleNamespace(
            kind=kind, device_id=f"can:{number}", type_key=E04, serial=1, firmware="",
            nmt_state="", heartbeat_age_s=None, last_emcy="", description="", can=None,
        )  # fmt: skip

    answers = [[node(10, "can")], [node(n, "not-prm9") for n in (5, 6, 7)]]
    dialog = CanBusDialog(lambda _bus, deliver: deliver(answers.pop(0)), settings)
    qtbot.addWidget(dialog)
    try:
        i18n.set_language(language)
        dialog.search.click()
        assert dialog.state.text() == one
        dialog.search.click()
        assert dialog.state.text() == three
    finally:
        i18n.set_language("en")


def test_valve_store_over_canopen_uses_the_sessions_store(qtbot, rig, settings):
    """Issue 25 item 12: Valve → Store over CAN is the link's store (0x1010 here), and the
    values read back after it are the stored ones."""
    connection = ValveConnection(opener=lambda e: factory.open_session(e, can_link=rig.options))
    with qtbot.waitSignal(connection.online_changed, timeout=10000):
        connection.go_online("can:10")
    try:
        with qtbot.waitSignal(connection.operation_finished, timeout=10000):
            connection.write("DTAMP", 1234)
            connection.read_many(["DTAMP"], "probe")
        assert rig.working("DTAMP") == 1234 and rig.stored_set().get("DTAMP") != 1234
        with qtbot.waitSignal(connection.operation_finished, timeout=10000,
                              check_params_cb=lambda name, _r: name == "store") as done:  # fmt: skip
            connection.store_valve()
        assert rig.stored_set()["DTAMP"] == 1234 and done.args[1]["DTAMP"] == 1234
    finally:
        connection.go_offline()
        connection.shutdown()


def test_the_description_column_is_in_the_program_language(qtbot, settings):
    """The device layer's description is English ("CANopen node 10 on udp_multicast …"); the
    dialog words the node's facts in German and Czech."""
    from prm9tool import i18n
    from prm9tool.device.factory import DeviceEntry
    from prm9tool.device.records import CanNodeFacts

    bus = {"interface": "udp_multicast", "channel": "239.0.0.1", "bitrate": 500000}
    valve = DeviceEntry(
        "can:10", "can", E04, 7, "1.0", "CANopen node 10 on udp_multicast channel 239.0.0.1",
        can=CanNodeFacts(node_id=10, name="PRM9", **bus),
    )  # fmt: skip
    other = DeviceEntry(
        "can:5", "not-prm9", "", 0, "", "node 5: not a PRM9",
        can=CanNodeFacts(node_id=5, device_type=0x191, vendor=None, **bus),
    )  # fmt: skip
    mute = DeviceEntry(
        "can:6", "not-prm9", "", 0, "", "node 6: does not answer",
        can=CanNodeFacts(node_id=6, detail="SDO timeout", **bus),
    )  # fmt: skip
    dialog = CanBusDialog(lambda _bus, deliver: deliver([valve, other, mute]), settings)
    qtbot.addWidget(dialog)
    expected = {
        "de": [
            "CANopen-Knoten 10 an udp_multicast Kanal 239.0.0.1, 500000 bit/s: PRM9",
            "Knoten 5: kein PRM9 (Gerätetyp 0x191, Hersteller keiner)",
            "Knoten 6 antwortet nicht als CANopen-Knoten: SDO timeout",
        ],
        "cs": [
            "Uzel CANopen 10 na udp_multicast kanál 239.0.0.1, 500000 bit/s: PRM9",
            "Uzel 5: není PRM9 (typ zařízení 0x191, výrobce žádný)",
            "Uzel 6 neodpovídá jako uzel CANopen: SDO timeout",
        ],
    }
    try:
        for language, rows in expected.items():
            i18n.set_language(language)
            dialog.search.click()
            assert [dialog.table.item(r, 7).text() for r in range(3)] == rows
            kinds = {
                "de": ["kein PRM9", "nicht identifiziert"],
                "cs": ["není PRM9", "neidentifikováno"],
            }
            # a foreign device is no PRM9; a node that did not answer is not identified (issue 29)
            assert [dialog.table.item(r, 1).text() for r in (1, 2)] == kinds[language]
            if language == "de":
                dialog.resize(1000, 360)
                dialog.show()
                _shot(dialog, "can_bus_description_de")
    finally:
        i18n.set_language("en")


def _shot(widget, name: str) -> None:
    import os
    from pathlib import Path

    if os.environ.get("PRM9TOOL_SCREENSHOTS"):
        widget.grab().save(str(Path(os.environ["PRM9TOOL_SCREENSHOTS"]) / f"{name}.png"))


def test_the_network_view_watches_the_sessions_bus_while_online(
    qtbot, rig, tmp_path, answers, monkeypatch
):
    """Issue 34, item 12: Communication → CAN bus… was greyed out while online. Online over CAN
    it now shows the bus the session is on — through the session's own master (one adapter
    open on the channel, not two) — and sends nothing: no search, no LSS, no valve to pick."""
    from support.gui_support import main_window

    from prm9tool.device.canlink import bus as canbus

    rig.valve.start()  # real time: its heartbeat runs
    rig.valve.write(0x1017, 0, 50)
    connection = ValveConnection(opener=lambda e: factory.open_session(e, can_link=rig.options))
    seen: dict[str, object] = {}

    def look(dialog: CanBusDialog) -> int:
        qtbot.waitUntil(lambda: dialog.table.rowCount() == 1, timeout=5000)
        qtbot.waitUntil(lambda: dialog.table.item(0, 4).text() != "", timeout=5000)
        shared = [n for o, n in canbus._NETWORKS.items() if o.channel == rig.options.channel]
        seen.update(
            networks=len(shared), users=shared[0].users, search=dialog.search.isEnabled(),
            ok=dialog.buttons.button(QDialogButtonBox.StandardButton.Ok),
            node=dialog.table.item(0, 0).text(), what=dialog.table.item(0, 1).text(),
            state=dialog.state.text(), lss=dialog.lss_panel,
            described=dialog.table.item(0, 7).text(),
        )  # fmt: skip
        return 0

    monkeypatch.setattr(CanBusDialog, "exec", look)
    with main_window(qtbot, tmp_path, E04, connection) as window:
        with qtbot.waitSignal(window.connection.online_changed, timeout=10000):
            window.valve.go_online("can:10")
        action = window.commands["can_bus"]
        qtbot.waitUntil(action.isEnabled, timeout=10000)  # greyed out before
        action.trigger()
        assert seen["networks"] == 1 and seen["users"] == 2  # the session's master, shared
        assert seen["node"] == "can:10" and seen["what"] == E04  # its type key, as it told
        assert seen["described"] == "the valve prm9tool is online with"
        assert seen["search"] is False and seen["ok"] is None and seen["lss"] is None
        assert "Online with can:10 on this bus" in str(seen["state"])
    rig.valve.stop()


def test_online_over_usb_the_bus_can_be_searched_but_not_gone_online_with(
    qtbot, tmp_path, answers, monkeypatch
):
    """Issue 34, item 12, the other link: online over USB the dialog opens the bus itself (the
    session is not on it) and searches it; a node is gone online with only after going
    offline."""
    from support.gui_support import E02, go_online, main_window

    seen: dict[str, object] = {}

    def look(dialog: CanBusDialog) -> int:
        seen.update(
            search=dialog.search.isEnabled(), interface=dialog.interface.isEnabled(),
            ok=dialog.buttons.button(QDialogButtonBox.StandardButton.Ok),
            close=dialog.buttons.button(QDialogButtonBox.StandardButton.Close),
            state=dialog.state.text(),
        )  # fmt: skip
        return 0

    monkeypatch.setattr(CanBusDialog, "exec", look)
    with main_window(qtbot, tmp_path) as window:
        go_online(qtbot, window, f"{E02}:4751")
        action = window.commands["can_bus"]
        qtbot.waitUntil(action.isEnabled, timeout=10000)
        action.trigger()
    assert seen["search"] is True and seen["interface"] is True
    assert seen["ok"] is None and seen["close"] is not None
    assert str(seen["state"]).startswith("Online with emulator:")

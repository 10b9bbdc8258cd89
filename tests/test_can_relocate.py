"""Finding the valve again after a restart that moves it (prm9tool.device.canlink.relocate):
a stored node ID or bit rate that the node-ID switch leaves to the objects (position 0, manual
table 7-17) — the session follows; the switches deciding — it stays; a bus the tool cannot
move — the message says where the valve is and what to do. Emulated valve in real time."""

from __future__ import annotations

import pytest
from support.can_link_rig import make_link_rig

from prm9tool.device.canlink.bus import CanOptions
from prm9tool.device.canlink.relocate import (
    ValveMovedError,
    Whereabouts,
    moved_error,
    why_not_follow,
)
from prm9tool.device.canlink.session import CanopenSession
from prm9tool.device.canlink.watch import BusWatch

CODE_250K = 3  # BITRATE code (0 = 1 Mbit/s … 6 = 20 kbit/s)


def _rig(name, tmp_path, node_switch: int):
    rig = make_link_rig(name, tmp_path, switches=(6, node_switch))
    rig.valve.start()  # real time: the reset's boot takes its ~2 s
    return rig


def _open(rig, bitrate: int | None = 500_000) -> CanopenSession:
    options = CanOptions(rig.options.interface, rig.options.channel, bitrate)
    return CanopenSession(options, 10)


def test_a_stored_node_id_change_is_followed_after_the_restart(tmp_path, data_dir):
    rig = _rig("relocate-node", tmp_path, 0)
    try:
        with _open(rig) as session:
            session.write("NODEID", 15)
            session.store()
            session.restart()
            assert (session.node_id, session.info.device_id) == (15, "can:15")
            assert session.read("SNV") == rig.valve.serial  # it talks to the valve there
            assert rig.valve.node_id == 15
    finally:
        rig.valve.stop()
        rig.close()


def test_a_stored_bit_rate_change_moves_the_tools_bus_with_it(tmp_path, data_dir):
    rig = _rig("relocate-rate", tmp_path, 0)
    try:
        with _open(rig) as session:
            session.write_many({"NODEID": 20, "BITRATE": CODE_250K})
            session.store()
            session.restart()
            assert session.options.bitrate == 250_000
            assert session.info.device_id == "can:20"
            assert session.info.can_bus == ("virtual", rig.options.channel, 250_000)
            assert session.read("NODEID") == 20
    finally:
        rig.valve.stop()
        rig.close()


def test_when_the_switches_decide_the_valve_stays_and_the_session_with_it(tmp_path, data_dir):
    rig = _rig("relocate-switch", tmp_path, 2)  # node-ID switch 2: node 10
    try:
        with _open(rig) as session:
            session.write("NODEID", 15)
            session.store()
            session.restart()
            assert session.node_id == 10 and rig.valve.node_id == 10
    finally:
        rig.valve.stop()
        rig.close()


def test_a_bus_others_share_is_not_moved_and_the_message_says_where_the_valve_is(
    tmp_path, data_dir
):
    rig = _rig("relocate-shared", tmp_path, 0)
    try:
        with _open(rig) as session:
            watch = BusWatch(session.options)  # the CAN bus dialog's live view, say
            try:
                session.write("BITRATE", CODE_250K)
                session.store()
                with pytest.raises(ValveMovedError) as caught:
                    session.restart()
            finally:
                watch.close()
        assert str(caught.value) == (
            "the valve restarted at node 10, 250 kbit/s and other connections of prm9tool use "
            "this bus at its bit rate: set the adapter to 250 kbit/s, then go online with "
            "can:10 (Communication → CAN bus, bit rate 250 kbit/s)"
        )
    finally:
        rig.valve.stop()
        rig.close()


def test_socketcan_is_told_how_to_set_the_bit_rate():
    options = CanOptions("socketcan", "can0", 500_000)
    after = Whereabouts(True, 15, 125_000, False)
    reason = why_not_follow(options, 1)
    assert reason == "prm9tool cannot change the bit rate of a socketcan interface"
    assert "sudo ip link set can0 down && sudo ip link set can0 up type can bitrate 125000" in str(
        moved_error(options, after, reason)
    )
    assert "go online with can:15" in str(moved_error(options, after, reason))


def test_the_gui_connection_announces_where_the_restarted_valve_is(qtbot, tmp_path, data_dir):
    from prm9tool.device import factory
    from prm9tool.online.connection import ValveConnection

    rig = _rig("relocate-gui", tmp_path, 0)
    options = CanOptions(rig.options.interface, rig.options.channel, 500_000)
    connection = ValveConnection(opener=lambda e: factory.open_session(e, can_link=options))
    try:
        with qtbot.waitSignal(connection.online_changed, timeout=10000):
            connection.go_online("can:10")
        connection.write("NODEID", 25)
        connection.store()
        qtbot.waitUntil(lambda: not connection.is_busy, timeout=5000)
        with qtbot.waitSignal(connection.device_changed, timeout=15000) as moved:
            connection.run_job("after_restart", lambda s: s.restart())
        assert moved.args[0].device_id == "can:25"
        assert connection.device.device_id == "can:25" and connection.is_online
    finally:
        connection.go_offline()
        connection.shutdown()
        rig.valve.stop()
        rig.close()

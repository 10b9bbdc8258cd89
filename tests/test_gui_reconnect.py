"""A valve that drops off and comes back: the connection finds it again by its serial number
(emulated USB cable pulled and plugged back; the link's fault injection)."""

from __future__ import annotations

import dataclasses
from types import SimpleNamespace

import pytest
from PySide6.QtCore import QCoreApplication
from support.gui_support import E02, emulator_connection

from prm9tool.device import emulated_valves, factory
from prm9tool.device.emulated import cable_plugged, plug_cable
from prm9tool.device.usb.transport.emulator import LinkFaults

TIMEOUT = 10_000
SPEC = f"{E02}:5101"


@pytest.fixture
def connection(qtbot):
    conn = emulator_connection(reconnect=True)
    yield conn
    conn.shutdown()
    emulated_valves.forget_emulated_valves()


@pytest.fixture
def paced_connection(qtbot):
    conn = emulator_connection(paced=True, reconnect=True)
    yield conn
    conn.shutdown()
    emulated_valves.forget_emulated_valves()


def online(qtbot, connection, spec=SPEC):
    entry = factory.list_devices([spec])[-1]
    with qtbot.waitSignal(connection.online_changed, timeout=TIMEOUT):
        connection.go_online(entry)
    return entry


def pull_cable(qtbot, connection):
    """Pull the emulated valve's cable (in the worker, as the Emulated valve menu does) and
    wait until the connection has lost it and looks for it."""
    with qtbot.waitSignals([connection.lost, connection.reconnecting], timeout=TIMEOUT):
        connection.run("pull", lambda s: s.emulator.pull_cable())


def record(signal):
    seen = []
    signal.connect(lambda *args: seen.append(args))
    return seen


def test_a_pulled_cable_is_looked_for_and_the_same_valve_comes_back(qtbot, connection):
    online(qtbot, connection)
    ended = record(connection.reconnect_ended)
    pull_cable(qtbot, connection)
    assert not connection.is_online and connection.is_reconnecting
    assert connection.lost_valve.serial == 5101 and not cable_plugged(5101)
    assert factory.list_devices([SPEC]) == []  # not listed while its cable is out
    # it keeps looking while the cable is out: a few more attempts report the seconds
    seconds = []
    connection.reconnecting.connect(seconds.append)
    qtbot.waitUntil(lambda: len(seconds) >= 2, timeout=TIMEOUT)
    assert seconds == sorted(seconds) and not connection.is_online
    went_online = record(connection.online_changed)
    with qtbot.waitSignal(connection.reconnected, timeout=TIMEOUT) as back:
        plug_cable(5101)
    assert back.args[0].serial == 5101 and went_online == [(True,)]
    assert connection.is_online and not connection.is_reconnecting
    assert connection.device.serial == 5101 and ended == [()]
    with qtbot.waitSignal(connection.live_values_changed, timeout=TIMEOUT):
        pass  # polling resumed


def test_a_broken_link_of_the_same_valve_comes_back_at_once(qtbot, connection):
    """The link's fault injection (every report fails from now on): the valve itself is still
    there, so the next listing finds it and the connection is online again."""
    online(qtbot, connection)
    lost = record(connection.lost)
    with qtbot.waitSignal(connection.reconnected, timeout=TIMEOUT):
        connection.run(
            "break",
            lambda s: setattr(s.transport, "faults", LinkFaults(die_after=0)),
        )
        connection.read_many(["LIMTA"])
    assert lost and "link is down" in lost[0][0]
    assert connection.is_online and connection.device.serial == 5101


def test_going_offline_stops_looking(qtbot, connection):
    online(qtbot, connection)
    pull_cable(qtbot, connection)
    looking = connection._reconnect.looking  # the loop's thread, to see it end
    assert looking is not None and looking._thread is not None
    with qtbot.waitSignal(connection.reconnect_ended, timeout=TIMEOUT):
        connection.go_offline()
    assert not connection.is_reconnecting
    reconnected = record(connection.reconnected)
    plug_cable(5101)
    # a listing the loop might still have had running reports nothing: its thread ends, what it
    # posted is delivered, and nothing starts opening the valve (that would make it busy)
    qtbot.waitUntil(lambda: not looking._thread.is_alive(), timeout=TIMEOUT)
    QCoreApplication.sendPostedEvents()
    assert not connection.is_busy
    assert reconnected == [] and not connection.is_online


def test_another_valve_where_the_lost_one_was_is_not_connected(qtbot, connection):
    online(qtbot, connection)
    stranger = SimpleNamespace(device_id=connection.device.device_id, serial=777, kind="emulator")
    connection._lister = lambda emulators, can=None: [stranger]
    with qtbot.waitSignal(connection.other_valve, timeout=TIMEOUT) as other:
        connection.run("pull", lambda s: s.emulator.pull_cable())
    assert other.args == [5101, 777, f"emulator:{E02}:5101"]
    assert not connection.is_online and not connection.is_reconnecting


def test_the_serial_the_valve_tells_decides_not_the_listing(qtbot, connection):
    """A listing that says 5101 but opens a valve that identifies as another: not the valve."""
    online(qtbot, connection)
    impostor_spec = f"{E02}:5102"
    impostor = factory.list_devices([impostor_spec])[-1]
    liar = dataclasses.replace(impostor, serial=5101)
    connection._lister = lambda emulators, can=None: [liar]
    with qtbot.waitSignal(connection.other_valve, timeout=TIMEOUT) as other:
        connection.run("pull", lambda s: s.emulator.pull_cable())
    assert other.args == [5101, 5102, impostor.device_id]
    qtbot.waitUntil(lambda: not connection.is_busy, timeout=TIMEOUT)
    assert not connection.is_online and connection._worker.session is None


def test_the_stream_stops_with_the_link_and_is_restarted_by_its_owner(qtbot, paced_connection):
    conn = paced_connection
    online(qtbot, conn)
    with qtbot.waitSignal(conn.stream_started, timeout=TIMEOUT):
        conn.start_stream(["supply_voltage", "demand"], 1000)
    with qtbot.waitSignal(conn.stream_stopped, timeout=TIMEOUT):
        pull_cable_async = conn.run("pull", lambda s: s.emulator.pull_cable())
    assert pull_cable_async is None and conn.streaming_keys == []
    qtbot.waitUntil(lambda: conn.is_reconnecting, timeout=TIMEOUT)
    with qtbot.waitSignal(conn.reconnected, timeout=TIMEOUT):
        plug_cable(5101)
    with qtbot.waitSignal(conn.samples_received, timeout=TIMEOUT):
        conn.start_stream(["supply_voltage", "demand"], 1000)


def test_a_valve_found_that_cannot_be_opened_yet_is_tried_again(qtbot, connection):
    online(qtbot, connection)
    opener, refused = connection._worker._opener, []

    def refusing_once(entry):
        if not refused:
            refused.append(entry)
            raise factory.DeviceDisconnectedError("still starting up")
        return opener(entry)

    connection._worker._opener = refusing_once
    pull_cable(qtbot, connection)
    with qtbot.waitSignal(connection.reconnected, timeout=TIMEOUT):
        plug_cable(5101)
    assert len(refused) == 1 and connection.is_online

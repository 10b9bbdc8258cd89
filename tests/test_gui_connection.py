"""ValveConnection against the emulator: online/offline, writes, upload/download, a lost valve."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest
from PySide6.QtCore import QTimer
from support.gui_support import E02, E04_CA, emulator_connection

from prm9tool.device import emulated_valves, factory
from prm9tool.device.usb.transport.emulator import LinkFaults
from prm9tool.errors import CommunicationError
from prm9tool.files import backup
from prm9tool.online.connection import ValveConnection

TIMEOUT = 10_000


@pytest.fixture
def connection(qtbot):
    conn = emulator_connection()
    yield conn
    conn.shutdown()
    emulated_valves.forget_emulated_valves()


@pytest.fixture
def paced_connection(qtbot):
    """Streams need real time to fill their reports: the emulated valve runs paced."""
    conn = emulator_connection(paced=True)
    yield conn
    conn.shutdown()
    emulated_valves.forget_emulated_valves()


def _online(qtbot, connection, spec=f"{E02}:5001"):
    entry = factory.list_devices([spec])[-1]
    with qtbot.waitSignals([connection.online_changed, connection.device_changed], timeout=TIMEOUT):
        connection.go_online(entry)
    return entry


def _record(signal):
    seen = []
    signal.connect(lambda *args: seen.append(args))
    return seen


def _unplug(connection):
    transport = connection._worker.session.transport
    transport.faults = LinkFaults(die_after=transport.reports_on_link)


def test_going_online_reports_the_device_then_offline_clears_it(qtbot, connection):
    _online(qtbot, connection)
    assert connection.is_online
    assert connection.device.serial == 5001 and connection.device.type_key == E02
    with qtbot.waitSignal(connection.online_changed, timeout=TIMEOUT) as blocker:
        connection.go_offline()
    assert blocker.args == [False]
    assert not connection.is_online and connection.device is None


def test_status_and_live_values_arrive_while_online(qtbot, connection):
    _online(qtbot, connection)
    with qtbot.waitSignal(connection.status_changed, timeout=TIMEOUT) as status:
        pass
    assert str(status.args[0].device_state)
    with qtbot.waitSignal(connection.live_values_changed, timeout=TIMEOUT) as live:
        pass
    assert {"PWR", "TEMP", "ERROR"} <= set(live.args[0])


def test_write_reaches_the_valve_and_download_reads_it_back(qtbot, connection):
    _online(qtbot, connection)
    connection.write("LIMTA", 1800)
    with qtbot.waitSignal(connection.operation_finished, timeout=TIMEOUT) as done:
        connection.download()
    assert done.args[0] == "download"
    assert done.args[1]["LIMTA"] == 1800


def test_a_refused_write_reports_the_reason_and_the_mnemonic(qtbot, connection):
    _online(qtbot, connection)
    failed, write_failed = _record(connection.failed), _record(connection.write_failed)
    connection.write("DYNFREQ", 70_000)
    qtbot.waitUntil(lambda: bool(failed and write_failed), timeout=TIMEOUT)
    assert "DYNFREQ" in failed[0][0] and "outside the allowed range" in failed[0][0]
    assert write_failed[0][0] == ["DYNFREQ"]
    assert connection.is_online  # a refused value is no lost link


def test_upload_backs_up_the_valve_first_then_verifies_and_stores(qtbot, connection):
    _online(qtbot, connection)
    with qtbot.waitSignal(connection.operation_finished, timeout=TIMEOUT) as read:
        connection.download()
    values = dict(read.args[1], DTAMP=1000)
    written = _record(connection.backup_written)
    with qtbot.waitSignal(connection.operation_finished, timeout=TIMEOUT) as done:
        connection.upload(values)
    result = done.args[1]
    assert len(written) == 1
    assert result.verified and result.stored and result.failed_step is None
    backups = backup.existing_backups(5001)
    assert len(backups) == 1 and "DTAMP = 15" in backups[0].read_text(encoding="utf-8")
    with qtbot.waitSignal(connection.operation_finished, timeout=TIMEOUT):
        connection.upload(values)  # the second upload keeps the first backup
    assert backup.existing_backups(5001) == backups


def test_cancelled_upload_stores_nothing_and_says_so(qtbot, connection):
    _online(qtbot, connection)
    busy = _record(connection.busy_changed)
    with qtbot.waitSignal(connection.failed, timeout=TIMEOUT) as failed:
        connection.run_job("upload", lambda s: (connection.cancel(), s.upload({"DTAMP": 1000},
                                                None, connection._worker.cancel))[1])  # fmt: skip
    assert "cancelled" in failed.args[0] and "nothing was stored" in failed.args[0]
    qtbot.waitUntil(lambda: busy and busy[-1] == (False,), timeout=TIMEOUT)
    assert not connection.is_busy and connection.is_online


def test_valve_that_disappears_mid_session_goes_offline_with_a_message(qtbot, connection):
    _online(qtbot, connection)
    with qtbot.waitSignal(connection.status_changed, timeout=TIMEOUT):
        pass
    lost = _record(connection.lost)
    with qtbot.waitSignal(connection.online_changed, timeout=TIMEOUT):
        _unplug(connection)
    assert "link is down" in lost[0][0]
    assert not connection.is_online and connection.device is None
    with qtbot.waitSignal(connection.failed, timeout=TIMEOUT) as failed:
        connection.write("LIMTA", 1000)
    assert "Not connected" in failed.args[0]


def test_a_lost_valve_is_explained_in_the_program_language(qtbot, connection):
    from prm9tool import i18n

    _online(qtbot, connection)
    lost = _record(connection.lost)
    i18n.set_language("de")
    try:
        with qtbot.waitSignal(connection.online_changed, timeout=TIMEOUT):
            _unplug(connection)
    finally:
        i18n.set_language("en")
    # the lead sentence in German, the technical detail as the transport said it
    assert lost[0][0].startswith("Die Verbindung zum Ventil ist unterbrochen. (")
    assert "link is down" in lost[0][0]


def test_a_can_bus_that_cannot_be_opened_is_reported_and_the_valve_stays_online(qtbot):
    """The GUI joins the CAN bus after going online (app._joiner): a failure there is a
    message, not a lost valve."""
    from prm9tool import app
    from prm9tool.cli.main import build_parser

    args = build_parser().parse_args(["--can-interface", "no-such-interface"])
    conn = ValveConnection(
        opener=lambda entry: factory.open_session(entry, paced=False),
        lister=factory.list_devices,
        after_open=app._joiner(args),
    )
    try:
        failed = _record(conn.failed)
        _online(qtbot, conn, spec="PRM9-06.3Z11/30-24E04S02-CA:5003")
        qtbot.waitUntil(lambda: bool(failed), timeout=TIMEOUT)
        assert failed[0][0].startswith("The emulated valve could not join the CAN bus; it works")
        assert "cannot open CAN bus" in failed[0][0]
        assert conn.is_online
        with qtbot.waitSignal(conn.operation_finished, timeout=TIMEOUT) as read:
            conn.read_many(["LIMTA"])
        assert read.args[1] == {"LIMTA": 2400}
    finally:
        conn.shutdown()
        emulated_valves.forget_emulated_valves()


def test_a_valve_connected_while_the_window_closes_is_not_reported_online(qtbot, connection):
    """The window closed while the worker was still connecting: its late result reaches no one
    (it showed the differences' progress dialog after the window had gone, and Qt's quit was
    taken back: the program ran on with no window)."""
    seen = _record(connection.online_changed)
    connection.go_online(factory.list_devices([f"{E02}:5001"])[-1])
    connection.shutdown(timeout_s=60)  # the worker connects, posts its result, and ends
    qtbot.wait(50)  # the queued result is delivered now, if at all
    assert seen == []
    assert not connection.is_online


def test_watched_measuring_points_are_reported(qtbot, paced_connection):
    connection = paced_connection
    _online(qtbot, connection, f"{E04_CA}:5002")
    connection.watch_signals(["supply_voltage", "temperature", "position_actual", "demand"])
    seen: dict[str, float] = {}
    connection.signal_values_changed.connect(seen.update)
    qtbot.waitUntil(lambda: {"supply_voltage", "demand"} <= set(seen), timeout=TIMEOUT)
    assert 19.0 < seen["supply_voltage"] / 1000 < 29.0


def test_stream_delivers_samples_in_key_order(qtbot, paced_connection):
    connection = paced_connection
    _online(qtbot, connection)
    with qtbot.waitSignal(connection.stream_started, timeout=TIMEOUT) as started:
        connection.start_stream(["supply_voltage", "demand"], 1000)
    assert started.args[0] == ["supply_voltage", "demand"]
    with qtbot.waitSignal(connection.samples_received, timeout=TIMEOUT) as block:
        pass
    assert block.args[0].shape[1] == 2
    with qtbot.waitSignal(connection.stream_stopped, timeout=TIMEOUT):
        connection.stop_stream()
    assert connection.streaming_keys == []


def test_opening_a_missing_device_fails_with_a_message(qtbot, connection):
    with qtbot.waitSignal(connection.failed, timeout=TIMEOUT) as failed:
        connection.go_online("usb:/dev/does-not-exist")
    assert failed.args[0]
    assert not connection.is_online


def test_a_second_go_online_while_connecting_is_refused(qtbot, connection):
    entry = factory.list_devices([f"{E02}:5003"])[-1]
    failed = _record(connection.failed)
    with qtbot.waitSignal(connection.online_changed, timeout=TIMEOUT):
        connection.go_online(entry)
        assert connection.is_busy
        connection.go_online(entry)
    assert failed and "busy" in failed[0][0]
    assert not connection.is_busy


class _FakeSession:
    """A session whose stream yields one row per read; it logs what the worker did, in order."""

    def __init__(self) -> None:
        self.info = SimpleNamespace(type_key=E02, serial=7, firmware="1.0", device_id="fake:7")
        self.log: list[str] = []
        self.samples_lost = 0
        self.keys: list[str] = []

    def identify(self) -> object:
        return self.info

    def write_many(self, values: dict) -> None:
        self.log.append("write")

    def stream_start(self, keys: list[str], rate_hz: int) -> None:
        self.keys = list(keys)

    def stream_read(self) -> np.ndarray:
        self.log.append("read")
        return np.ones((1, len(self.keys)))

    def stream_stop(self) -> None:
        self.keys = []

    def status(self) -> object:
        return SimpleNamespace(device_state="ok")

    def read_many(self, names: list[str]) -> dict:
        return {}

    def close(self) -> None:
        pass


@pytest.fixture
def fake():
    session = _FakeSession()
    conn = ValveConnection(opener=lambda _entry: session, lister=lambda _specs: [])
    yield conn, session
    conn.shutdown()


def _online_with_stream(qtbot, connection):
    with qtbot.waitSignal(connection.online_changed, timeout=TIMEOUT):
        connection.go_online("fake:7")
    with qtbot.waitSignal(connection.stream_started, timeout=TIMEOUT):
        connection.start_stream(["demand"], 1000)


def test_samples_keep_flowing_while_writes_arrive_every_10_ms(qtbot, fake):
    """A setpoint generator writes faster than the stream period: the stream must not starve."""
    connection, session = fake
    _online_with_stream(qtbot, connection)
    blocks = _record(connection.samples_received)
    writes = 0

    def write() -> None:
        nonlocal writes
        writes += 1
        connection.write("LIMTA", 1000 + writes)

    timer = QTimer()
    timer.timeout.connect(write)
    timer.start(10)
    qtbot.waitUntil(lambda: writes >= 60, timeout=TIMEOUT)
    received_while_writing = len(blocks)
    timer.stop()
    qtbot.waitUntil(lambda: session.log.count("write") == writes, timeout=TIMEOUT)
    last_write = len(session.log) - 1 - session.log[::-1].index("write")
    reads_between_writes = session.log[:last_write].count("read")
    assert reads_between_writes >= 10, session.log
    assert received_while_writing >= 10


def test_lost_samples_of_the_stream_are_reported_and_cleared_on_stop(qtbot, fake):
    connection, session = fake
    _online_with_stream(qtbot, connection)
    assert connection.samples_lost == 0
    with qtbot.waitSignal(connection.samples_lost_changed, timeout=TIMEOUT) as lost:
        session.samples_lost = 30
    assert lost.args == [30] and connection.samples_lost == 30
    with qtbot.waitSignal(connection.samples_lost_changed, timeout=TIMEOUT) as cleared:
        connection.stop_stream()
    assert cleared.args == [0] and connection.samples_lost == 0


def test_listing_the_valves_does_not_hold_up_the_gui_thread(qtbot):
    """A USB valve that does not answer takes up to 0.6 s to identify: the listing runs in a
    thread of its own and the answer arrives on the GUI thread."""
    import threading

    from PySide6.QtCore import QThread

    release = threading.Event()
    threads = []

    def slow_lister(emulators):
        threads.append(QThread.currentThread())
        release.wait(10)  # a valve that takes its time
        return factory.emulator_entries(emulators)

    conn = ValveConnection(lister=slow_lister)
    delivered = []
    conn.list_devices_async([f"{E02}:5005"], delivered.append)  # returns while the lister waits
    assert delivered == []
    release.set()
    qtbot.waitUntil(lambda: bool(delivered), timeout=TIMEOUT)
    assert [e.serial for e in delivered[0]] == [5005]
    assert threads[0] is not QThread.currentThread()
    conn.shutdown()
    emulated_valves.forget_emulated_valves()


def test_a_listing_that_fails_delivers_the_error(qtbot):
    def broken(_emulators):
        raise CommunicationError("hidapi: libhidapi-hidraw.so.0 not found")

    conn = ValveConnection(lister=broken)
    delivered = []
    conn.list_devices_async([], delivered.append)
    qtbot.waitUntil(lambda: bool(delivered), timeout=TIMEOUT)
    assert isinstance(delivered[0], CommunicationError)
    conn.shutdown()

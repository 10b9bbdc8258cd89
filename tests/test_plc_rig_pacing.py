"""Served valves' simulation runs in the bus's receive thread (``--serve-emulator``): a paced
thread of its own took the GIL from the receive thread at each of its system calls, and at 16
valves the kernel dropped a third of the frames (docs/PERFORMANCE.md, "The PLC rig")."""

from __future__ import annotations

import itertools
import select
import socket
import struct
import sys
import threading
import time

import can
import can.interfaces.udp_multicast.utils as udp_utils
import pytest
from can.interfaces.udp_multicast.bus import SO_TIMESTAMPNS
from support.waiting import wait_for

from prm9tool.device.emulator import EmulatedValve, canopen_udp
from prm9tool.device.emulator.canopen_hub import SharedBus
from prm9tool.device.emulator.paced_group import PacedGroup

E02_CA = "PRM9-06.3Z11/30-24E02S02-CA"


@pytest.fixture
def hub_and_valves():
    bus = can.Bus(interface="virtual", channel=f"prm9tool-pacing-{time.monotonic_ns()}")
    hub = SharedBus(bus)
    valves = [EmulatedValve(E02_CA, serial) for serial in (8101, 8102)]
    for valve in valves:
        valve.advance(2.0)
        hub.attach(valve.connect_can(bus, receive=False))
    try:
        yield hub, valves
    finally:
        hub.stop()
        bus.shutdown()


def test_the_receive_thread_runs_every_valve_s_batches(hub_and_valves):
    hub, valves = hub_and_valves
    threads: dict[int, set[str]] = {valve.serial: set() for valve in valves}
    for valve in valves:
        valve.add_cycle_listener(
            lambda _t, s=valve.serial: threads[s].add(threading.current_thread().name)
        )
    group = PacedGroup(valves, driver=hub)
    group.start()
    try:
        assert all(valve.running for valve in valves)  # the watches judge wall-clock time
        before = [valve.time for valve in valves]
        wait_for(lambda: all(v.time - t > 0.05 for v, t in zip(valves, before, strict=True)))
        names = {thread.name for thread in threading.enumerate()}
    finally:
        group.stop()
    assert "prm9-paced-group" not in names  # no thread of its own
    assert threads == {valve.serial: {"prm9-canopen-hub"} for valve in valves}
    assert not any(valve.running for valve in valves)


def test_after_stop_no_batch_runs(hub_and_valves):
    hub, valves = hub_and_valves
    group = PacedGroup(valves, driver=hub)
    group.start()
    wait_for(lambda: all(valve.time > 2.05 for valve in valves))
    group.stop()
    stopped = [valve.time for valve in valves]
    hub_thread_waits = 0.05  # the receive thread's next few loops (it waits at most 1 ms each)
    time.sleep(hub_thread_waits)
    assert [valve.time for valve in valves] == stopped


class _Wrapper:
    """What python-can's udp_multicast socket wrapper has that the queued-datagram path uses."""

    timestamp_nanosecond = True
    max_buffer = 4096
    received_timestamp_struct = "@ll"
    received_ancillary_buffer_size = socket.CMSG_SPACE(struct.calcsize("@ll"))

    def __init__(self, sock: socket.socket) -> None:
        self._socket = sock


@pytest.mark.skipif(not hasattr(socket, "MSG_DONTWAIT"), reason="no MSG_DONTWAIT")
def test_a_queued_datagram_is_taken_with_its_kernel_time_stamp_without_waiting():
    """The receive thread takes each queued datagram without ``select`` first (one system
    call, not two); with none queued it says so at once and python-can's ``recv`` waits."""
    receiving = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    sending = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    try:
        receiving.bind(("127.0.0.1", 0))
        receiving.setsockopt(socket.SOL_SOCKET, SO_TIMESTAMPNS, 1)
        take = canopen_udp._queued(_Wrapper(receiving))
        assert take is not None
        assert take() is None  # nothing queued: no wait
        before = time.time()
        sending.sendto(canopen_udp.datagram(0x181, b"\x01\x02"), receiving.getsockname())
        wait_for(lambda: select.select([receiving], [], [], 0)[0])
        queued = take()
        assert queued is not None
        raw, stamp = queued
        assert canopen_udp.decode(raw) == (0x181, b"\x01\x02")
        assert before - 1.0 <= stamp <= time.time()  # the kernel's reception time
        assert take() is None
    finally:
        receiving.close()
        sending.close()


def test_a_socket_without_nanosecond_time_stamps_keeps_python_can_s_path():
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as sock:
        wrapper = _Wrapper(sock)
        wrapper.timestamp_nanosecond = False
        assert canopen_udp._queued(wrapper) is None


def _arrives(sending: socket.socket, receiving: socket.socket, raw: bytes) -> bool:
    """Whether ``raw`` sent to ``receiving`` arrives there (a later marker datagram, which
    always passes, proves the kernel handled the first one)."""
    marker = b"not a CAN frame"
    sending.sendto(raw, receiving.getsockname())
    sending.sendto(marker, receiving.getsockname())
    first = None
    while True:
        wait_for(lambda: select.select([receiving], [], [], 0)[0])
        got = receiving.recv(4096)
        if got == marker:
            return first == raw
        first = got


@pytest.mark.skipif(sys.platform != "linux", reason="Linux socket filters")
def test_the_kernel_lets_only_the_routed_can_ids_reach_the_served_valves():
    """The valves' own frames (looped back by multicast) and other nodes' never reach the
    socket; every routed CAN-ID does, in both python-can's and the lean datagrams, and any
    datagram that is not a classical frame as python-can lays it out still arrives."""
    receiving = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    sending = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    try:
        receiving.bind(("127.0.0.1", 0))
        routed = {0x000, 0x07F, 0x080, 0x20A, 0x60A, 0x7E5}
        assert canopen_udp.filter_ids(receiving.fileno(), routed)
        for can_id in (*routed, 0x18A, 0x58A, 0x70A, 0x005, 0x0FF):
            for raw in (
                canopen_udp.datagram(can_id, b"\x0f\x00"),
                udp_utils.pack_message(
                    can.Message(
                        arbitration_id=can_id,
                        data=b"\x0f",
                        is_extended_id=False,
                        timestamp=time.time(),
                    )
                ),
            ):
                assert _arrives(sending, receiving, raw) is (can_id in routed), hex(can_id)
        assert _arrives(sending, receiving, b"\x81\xa1x\x01")  # no frame: judged as before
        assert not canopen_udp.filter_ids(receiving.fileno(), set(range(300)))  # too many ...
        assert _arrives(sending, receiving, canopen_udp.datagram(0x18A, b""))  # ... none
    finally:
        receiving.close()
        sending.close()


class _Recorder:
    """A served valve and a paced group as the receive thread sees them, logging its calls."""

    routes = frozenset({0x080})

    def __init__(self) -> None:
        self.log: list[str] = []
        self.routes_changed = lambda: None
        self.next_due = 0.0
        self.first_batch_runs = threading.Event()
        self.release = threading.Event()

    def rx_wait_s(self) -> float:
        return 0.1

    def judge_quiet(self, _until_ms: float, wait: bool = True) -> None:
        pass

    def receive_data(self, can_id: int, data: bytes, _timestamp: float) -> None:
        self.log.append(f"frame {data.hex()}")

    def step_one(self) -> float:
        if not self.log:  # the first batch holds the thread while the frames queue up
            self.first_batch_runs.set()
            self.release.wait(5.0)
        self.log.append("batch")
        self.next_due = time.monotonic()  # another valve's batch is due at once
        time.sleep(0.0005)  # not a busy loop of batches while the test waits
        return 0.0


def test_queued_frames_are_taken_before_the_next_batch_of_the_simulation():
    """A SYNC waiting in the socket is answered before the simulation's next batch runs
    (a batch is 16 µs a valve: 32 of them between a SYNC and its TPDO1s cost its deadline)."""
    channel = f"prm9tool-order-{time.monotonic_ns()}"
    bus, master = (can.Bus(interface="virtual", channel=channel) for _ in range(2))
    hub = SharedBus(bus)
    recorder = _Recorder()
    try:
        hub.attach(recorder)  # type: ignore[arg-type]
        hub.pace(recorder)  # type: ignore[arg-type]
        assert recorder.first_batch_runs.wait(5.0)
        for k in range(3):
            master.send(can.Message(arbitration_id=0x080, data=bytes([k]), is_extended_id=False))
        recorder.release.set()
        wait_for(lambda: recorder.log.count("batch") >= 3)
    finally:
        hub.stop()
        bus.shutdown()
        master.shutdown()
    assert recorder.log[:5] == ["batch", "frame 00", "frame 01", "frame 02", "batch"]


class _Frames:
    """A bus as far as a CANopen slave without a receive thread sends on it."""

    def __init__(self) -> None:
        self.sent: list[tuple[int, bytes]] = []

    def send(self, msg: can.Message, timeout: float | None = None) -> None:
        self.sent.append((msg.arbitration_id, bytes(msg.data)))

    def recv(self, timeout: float | None = None) -> None:
        return None


def test_a_sync_samples_the_valve_advanced_to_its_arrival_not_the_last_batch():
    """Paced in batches of 2 ms or more, several 1 ms SYNCs found the same simulated moment
    (a real valve would not repeat a sample): the cycles due by a SYNC's arrival run first.
    No batch runs here but those (the pacer's time base is set back by 5 cycles each time)."""
    bus = _Frames()
    valve = EmulatedValve(E02_CA, 8103)
    slave = valve.connect_can(bus, receive=False)  # type: ignore[arg-type]
    valve.advance(2.0)
    for data in (bytes.fromhex("2F00180201000000"), bytes.fromhex("2B40600008000000")):
        slave.receive_data(0x60A, data, time.time())  # TPDO1 on every SYNC
    slave.receive_data(0, b"\x01\x0a", time.time())
    valve.paced_by_group(True)  # paced by a group, whose batches never run in this test
    times = []
    for _ in range(20):
        pacer = valve.pacer
        stamp, now = time.time(), time.monotonic()  # the SYNC arrived 5 cycles into a batch
        pacer.start = now - (pacer.cycles_done + 5) * pacer.cycle_s
        slave.receive_data(0x80, b"", stamp)
        times.append(valve.time)
    valve.paced_by_group(False)
    assert sum(1 for can_id, _ in bus.sent if can_id == 0x18A) == 20
    steps = [round((b - a) / valve.CYCLE_S) for a, b in itertools.pairwise(times)]
    assert all(1 <= step <= 10 for step in steps), steps  # each SYNC a moment of its own

"""Many emulated valves on one bus: one python-can bus, one receive thread, frames routed.

With a bus (and a receive thread) per valve, every frame on the bus is received, decoded and
looked at once per valve: N valves at one SYNC, N RPDOs and N TPDOs per millisecond cost
N·(2N + 1) decoded frames per millisecond in one Python process — 528 000 a second for 16
valves, far beyond what it can do (docs/PERFORMANCE.md, "The PLC rig"). :class:`SharedBus`
receives each frame once and hands it only to the valves that take its COB-ID
(:attr:`CanopenSlave.routes`: NMT, SYNC, LSS, their SDO and RPDO identifiers): 2N + 1 frames a
millisecond, each given to one valve (NMT, SYNC and LSS to all).

Deadlines stay judged at reception times (:mod:`.canopen_watch`): every frame on the shared
socket proves that nothing arrived before it, so at most every :data:`JUDGE_EVERY_MS` the
valves are judged at the arrival of the frame in hand, and when the bus is quiet at the moment
``recv`` timed out. How long ``recv`` may wait (the next deadline of any valve) is asked of the
valves at most every :data:`JUDGE_EVERY_MS` too, not per frame (N valves × 2N + 1 frames).

On udp_multicast the socket gets a kernel filter (:func:`.canopen_udp.filter_ids`) that lets
only the routed CAN-IDs through: every frame the valves send comes back to their own socket
(multicast loopback, which the PLC on the same PC needs), at 16 valves 16 TPDO1 a millisecond
that cost a system call and a decoding each and filled half the receive buffer, to be dropped.

The bus's socket (where it has one: udp_multicast, SocketCAN) gets a receive buffer of
:data:`RECEIVE_BUFFER` bytes (as far as ``net.core.rmem_max`` allows): the kernel's default
holds about 200 frames, a 20 ms hold-up of the process at 9 frames a millisecond, and a frame
the kernel drops for a full buffer is a SYNC or an RPDO the valves never see.

The valves' simulation runs in this thread too (:meth:`SharedBus.pace`, a
:class:`~.paced_group.PacedGroup` given the bus as its driver): one due batch between two
frames, and ``recv`` waits no longer than the next batch is due. A paced thread of its own
took the GIL from this one at every system call of ``recv`` (docs/PERFORMANCE.md).
"""

from __future__ import annotations

import logging
import math
import socket
import threading
import time
from typing import TYPE_CHECKING

import can

from prm9tool.device.emulator import canopen_udp
from prm9tool.device.emulator.canopen_lss import LSS_REQUEST
from prm9tool.device.emulator.canopen_slave import CanopenSlave

if TYPE_CHECKING:
    from prm9tool.device.emulator.paced_group import PacedGroup

log = logging.getLogger(__name__)

JUDGE_EVERY_MS = 1.0
RECEIVE_BUFFER = 4 * 1024 * 1024
BATCH_LAG_S = 0.005  # frames first while the simulation's due batch waits less than this
_EVERY_VALVE = (0, LSS_REQUEST)  # NMT and LSS, whatever a valve's state


class SharedBus:
    """One receive thread for every :class:`CanopenSlave` attached (made with
    ``receive=False`` on the same bus)."""

    def __init__(self, bus: can.BusABC) -> None:
        self._bus = bus
        self._slaves: list[CanopenSlave] = []
        self._routes: dict[int, tuple[CanopenSlave, ...]] = {}
        self._lock = threading.Lock()
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._receive, name="prm9-canopen-hub", daemon=True)
        self._started = False
        self._pacing: PacedGroup | None = None
        self._pacing_lock = threading.Lock()  # held while a batch of it runs
        # python-can's udp_multicast: datagrams decoded without can.Message (canopen_udp)
        udp = canopen_udp.receiver(bus)
        self._receive_frame = udp or self._receive_message
        self._filtered = udp is not None  # the socket's kernel filter follows the routes
        enlarge_receive_buffer(bus)

    def attach(self, slave: CanopenSlave) -> None:
        """Route frames to ``slave`` from now on (starts the receive thread on first use)."""
        with self._lock:
            self._slaves.append(slave)
            slave.routes_changed = self._reroute
        self._reroute()
        if not self._started:
            self._started = True
            self._thread.start()

    def stop(self) -> None:
        """End the receive thread (the bus belongs to the caller)."""
        self._stop.set()
        if self._started:
            self._thread.join()

    def pace(self, group: PacedGroup | None) -> None:
        """Run ``group``'s batches in the receive thread from now on (None: no longer;
        returns when none of its batches runs any more). Starts the thread if need be."""
        with self._pacing_lock:
            self._pacing = group
        if group is not None and not self._started:
            self._started = True
            self._thread.start()

    def _step_pacing(self) -> float:
        """One due batch of the paced group, if any; seconds until the next is due."""
        with self._pacing_lock:
            group = self._pacing
            if group is None:
                return math.inf
            if time.monotonic() < group.next_due:
                return group.next_due - time.monotonic()
            return group.step_one()

    def _pacing_behind_s(self) -> float:
        """How long the paced group's earliest batch has been due (0: none is)."""
        group = self._pacing
        return 0.0 if group is None else max(0.0, time.monotonic() - group.next_due)

    def _reroute(self) -> None:
        routes: dict[int, list[CanopenSlave]] = {}
        with self._lock:
            for slave in self._slaves:
                for can_id in (*_EVERY_VALVE, *slave.routes):
                    takers = routes.setdefault(can_id, [])
                    if slave not in takers:
                        takers.append(slave)
            self._routes = {can_id: tuple(takers) for can_id, takers in routes.items()}
            if self._filtered:  # the valves' own frames, looped back, never reach the socket
                self._filtered = canopen_udp.filter_ids(self._bus.fileno(), set(self._routes))

    def _receive(self) -> None:
        judged_ms = 0.0
        receive = self._receive_frame
        due_ms, asked_ms = 0.0, -math.inf  # when a watch is next due; when that was asked
        queued = False  # the last receive returned a frame: more may be waiting
        while not self._stop.is_set():
            slaves = self._slaves
            now_ms = time.monotonic() * 1000.0
            wait_ms = due_ms - now_ms
            if now_ms - asked_ms >= JUDGE_EVERY_MS:  # not per frame: N valves x N frames
                asked_ms = now_ms
                due_ms = now_ms + min((s.rx_wait_s() for s in slaves), default=0.1) * 1000.0
                wait_ms = due_ms - now_ms
            else:  # a frame since may have armed an earlier deadline: ask again within 1 ms
                wait_ms = min(wait_ms, JUDGE_EVERY_MS)
            if self._pacing is not None and not (queued and self._pacing_behind_s() < BATCH_LAG_S):
                # the next batch of the simulation, when no frame waits (a SYNC's TPDO1 goes
                # first) or the simulation fell BATCH_LAG_S behind its due time
                wait_ms = min(wait_ms, self._step_pacing() * 1000.0)
            elif queued:
                wait_ms = 0.0  # frames came one after another: take the next one at once
            try:
                frame = receive(max(0.0, wait_ms) / 1000.0)
            except Exception as exc:  # a closed or failing bus must not end the thread silently
                if self._stop.is_set():
                    return
                log.warning("CAN receive failed: %s", exc)
                self._stop.wait(0.1)
                continue
            queued = frame is not None
            now_ms = time.monotonic() * 1000.0
            if frame is None:  # quiet until now: judged if a deadline passed (or 1 ms went by)
                if now_ms >= due_ms or now_ms - judged_ms >= JUDGE_EVERY_MS:  # not when only
                    for slave in slaves:  # a batch of the simulation was due (8 a ms at 16)
                        slave.judge_quiet(now_ms)
                    judged_ms, asked_ms = now_ms, -math.inf  # judged: ask for the next due now
                continue
            can_id, data, timestamp = frame
            takers = self._routes.get(can_id, ())
            for slave in takers:
                slave.receive_data(can_id, data, timestamp)
            if now_ms - judged_ms >= JUDGE_EVERY_MS:
                judged_ms = now_ms
                arrival = now_ms - max(0.0, time.time() - timestamp) * 1000.0
                for slave in slaves:
                    if slave not in takers:  # frames keep coming: a busy valve waits for one
                        slave.judge_quiet(arrival, wait=False)

    def _receive_message(self, timeout: float | None) -> canopen_udp.Frame | None:
        """The next classical data frame through ``bus.recv`` (any python-can bus)."""
        deadline = time.monotonic() + (timeout or 0.0)
        while (msg := self._bus.recv(timeout)) is not None:
            if not (msg.is_error_frame or msg.is_remote_frame or msg.is_extended_id or msg.is_fd):
                return msg.arbitration_id, bytes(msg.data), msg.timestamp
            timeout = max(0.0, deadline - time.monotonic())  # a classical node ignores it
        return None


def enlarge_receive_buffer(bus: can.BusABC, size: int = RECEIVE_BUFFER) -> int:
    """Ask for a receive buffer of ``size`` bytes on the bus's socket; returns what the kernel
    granted (0: the bus has no socket, e.g. python-can's virtual bus)."""
    try:
        fd = bus.fileno()
    except (NotImplementedError, AttributeError, OSError):
        return 0
    if not isinstance(fd, int) or fd < 0:
        return 0
    try:
        sock = socket.socket(fileno=socket.dup(fd))  # the same socket; closing the copy is safe
    except OSError as exc:
        log.info("receive buffer of the CAN socket not enlarged: %s", exc)
        return 0
    try:
        sock.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, size)
        return int(sock.getsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF))
    except OSError as exc:
        log.info("receive buffer of the CAN socket not enlarged: %s", exc)
        return 0
    finally:
        sock.close()

"""The emulated valve as a CiA 301 slave on a python-can bus (manual chapter 7).

:class:`CanopenSlave` receives frames in a thread of its own and runs its timers (heartbeat,
PDO event timers) from the valve's 1 ms cycle listener, so the same code runs in simulated time
under :meth:`EmulatedValve.advance` and in real time under the paced thread. The SYNC and RPDO
deadline watches judge when frames arrived (:mod:`.canopen_watch`), not when the paced loop,
behind on a busy PC, gets round to them.
Every object-dictionary access goes through ``valve.read_bytes``/``valve.write_bytes``; every
public entry point takes ``valve.lock``.
"""

from __future__ import annotations

import logging
import struct
import threading
from collections.abc import Callable
from typing import TYPE_CHECKING

import can

from prm9tool.catalogue.commissioning import NmtCommand
from prm9tool.device.emulator import canopen_udp
from prm9tool.device.emulator.canopen_lss import LSS_REQUEST, LSS_RESPONSE, LssHost, LssSlave
from prm9tool.device.emulator.canopen_pdo import (
    EVENT_TYPES,
    SYNC_TYPES,
    PdoChannel,
    RpdoLogic,
    TpdoLogic,
    mapping,
)
from prm9tool.device.emulator.canopen_rules import check_comm_write
from prm9tool.device.emulator.canopen_sdo import SdoServer
from prm9tool.device.emulator.canopen_watch import (
    LATE_SYNC_MS,
    LATE_SYNC_PERIODS,
    QUIET_FOREVER,
    TimingWatches,
)
from prm9tool.device.records import NmtState

if TYPE_CHECKING:
    from prm9tool.device.emulator.valve_canopen import SlaveValve

log = logging.getLogger(__name__)

HEARTBEAT_CODES = {
    NmtState.INITIALISING: 0x00,
    NmtState.STOPPED: 0x04,
    NmtState.OPERATIONAL: 0x05,
    NmtState.PRE_OPERATIONAL: 0x7F,
}
NMT_EVENTS = {
    NmtState.OPERATIONAL: "operational",
    NmtState.STOPPED: "stopped",
    NmtState.PRE_OPERATIONAL: "preoperational",
}
SYNC_COB_ID, CYCLE_PERIOD, EMCY_COB_ID = 0x1005, 0x1006, 0x1014
HEARTBEAT_TIME, NMT_STARTUP = 0x1017, 0x1F80
_HEARTBEAT = ((HEARTBEAT_TIME, 0), (NMT_STARTUP, 0))  # read together (a look-up of two)
CONFIG_POLL_MS = 10  # PDO communication parameters are re-read every 10 ms


class CanopenSlave:
    """CiA 301 NMT slave, SDO server, 2 RPDO + 2 TPDO, SYNC consumer, heartbeat, EMCY."""

    def __init__(self, valve: SlaveValve, bus: can.BusABC, receive: bool = True) -> None:
        """``receive``: a receive thread of its own on ``bus``; False when a
        :class:`~.canopen_hub.SharedBus` hands it the frames (many valves on one bus)."""
        self._valve = valve
        self._bus = bus
        self._send_frame = canopen_udp.sender(bus) or self._send_message  # no Message on UDP
        self._sdo = SdoServer(self._sdo_read, self._sdo_write)
        self._rpdos = [PdoChannel(n, transmit=False) for n in (1, 2)]
        self._tpdos = [PdoChannel(n, transmit=True) for n in (1, 2)]
        self._rpdo_logic = [
            RpdoLogic(c, valve, self._rpdo_length_error, self._rpdo_length_ok) for c in self._rpdos
        ]
        self._length_error = False  # EMCY 8210 reported and not yet reset
        self._tpdo_logic = [TpdoLogic(c, valve) for c in self._tpdos]
        # the valid TPDOs a SYNC may send and those the 1 ms task may (_load_config): per frame
        # and per millisecond only these are asked
        self._sync_tpdos: tuple[TpdoLogic, ...] = ()
        self._tick_tpdos: tuple[TpdoLogic, ...] = ()
        self._rpdo_by_id: dict[int, RpdoLogic] = {}  # the valid RPDOs (_load_config)
        pdo_addresses = [  # what _load_config reads, in one call
            (index, sub)
            for c in (*self._rpdos, *self._tpdos)
            for index, sub in (
                (c.comm_index, 1),
                (c.map_index, 0),
                (c.comm_index, 2),
                (c.comm_index, 5),
            )
        ]
        self._config_addresses = (*pdo_addresses, (CYCLE_PERIOD, 0), (SYNC_COB_ID, 0))
        self._config_values: tuple[int | str, ...] = ()  # as last loaded (node ID first)
        self._quiet_addresses = (*self._config_addresses, (HEARTBEAT_TIME, 0))
        self._heartbeat_due_ms = 0
        self._watches = TimingWatches(self._rpdos, lambda: self._period_us, self._on_watch_event)
        self._period_us = 0  # 0x1006, read with the PDO parameters
        self._sync_id = 0x080  # 0x1005
        self.routes: frozenset[int] = frozenset()  # the COB-IDs it takes (SharedBus routing)
        self.routes_changed: Callable[[], None] = lambda: None
        self._watch_errors: set[str] = set()  # sync_error / rpdo_timeout reported, cause on
        self._unanswered_syncs = 0  # SYNCs it got to over LATE_SYNC_MS late (no TPDO)
        self._unanswered_worst_ms = 0.0
        self._sync_arrival_ms: float | None = None  # the last SYNC's (its interval: lateness)
        self._closed = False
        self._silent_until_ms = 0  # CiA 305 activate bit timing: no frames until then
        self.state = NmtState.OFF
        self.node_id = 0
        self.lss: LssSlave | None = None  # node-ID switch at 1 (table 7-17)
        with valve.lock:
            self._power_up()
            valve.add_cycle_listener(self._on_cycle, self._quiet_ticks)
            valve.add_error_listener(self._on_error)
            valve.add_restart_listener(self._on_restart)
            valve.canopen.set_nmt_handler(self._on_local_nmt)
        self._rx_stop = threading.Event()
        self._rx_thread: threading.Thread | None = None
        if receive:
            self._rx_thread = threading.Thread(
                target=self._receive, name=f"prm9-canopen-rx-{valve.serial}", daemon=True
            )
            self._rx_thread.start()

    # --- public --------------------------------------------------------------------------
    @property
    def bitrate(self) -> int:
        """The bit rate the switches (or 0x2030/2) selected at power-up, bit/s (0 = CAN off)."""
        return self._valve.bitrate

    def stop(self) -> None:
        """Stop receiving and transmitting for good (the bus itself belongs to the caller)."""
        self._rx_stop.set()
        if self._rx_thread is not None and self._rx_thread is not threading.current_thread():
            self._rx_thread.join()
        with self._valve.lock:
            self._closed = True
            self.state = NmtState.OFF
            self._valve.canopen.set_nmt_handler(None)

    def _on_local_nmt(self, command: int) -> None:
        """An NMT command from the valve's USB side: as if the master sent it to this node."""
        self._on_nmt(bytes((command, self.node_id)))

    # --- power-up, NMT ---------------------------------------------------------------------
    def _power_up(self) -> None:
        self.node_id = self._valve.node_id
        self._silent_until_ms = 0
        self.lss = LssSlave(self._lss_host()) if self._valve.lss_mode else None
        self._sdo.reset()
        self._length_error = False
        self._watch_errors.clear()
        self.state = NmtState.INITIALISING if self._valve.can_enabled else NmtState.OFF

    def _on_restart(self) -> None:
        if not self._closed:
            self._power_up()

    def _boot_up(self) -> None:
        """End of initialisation: reload the communication objects, boot-up, PRE-OPERATIONAL."""
        self._load_config()
        self._send(0x700 + self.node_id, b"\x00")
        self._heartbeat_due_ms = self._now_ms + self._heartbeat_ms()
        self._enter(NmtState.PRE_OPERATIONAL)
        status = self._valve.status()
        if status.error_code:
            self._send_emcy(status.error_code, status.error_register)
        if int(self._valve.read(NMT_STARTUP, 0)) == 0:
            self._enter(NmtState.OPERATIONAL)

    def _enter(self, state: NmtState) -> None:
        if state is self.state:
            return
        self.state = state
        self._sdo.reset()
        self._valve.canopen.nmt_event(NMT_EVENTS[state])
        if state is NmtState.OPERATIONAL:
            self._watches.disarm()
            for channel in (*self._rpdos, *self._tpdos):
                channel.restart(self._now_ms)
            for logic in self._tpdo_logic:
                if logic.channel.trans_type in (254, 255):
                    self._transmit(logic, logic.data())

    def _on_nmt(self, data: bytes) -> None:
        if len(data) < 2 or data[1] not in (0, self.node_id):
            return
        if self.state is NmtState.INITIALISING:
            return  # manual table 7-4: no NMT service while initialising
        command = data[0]
        if command == NmtCommand.START:
            self._watch_errors.clear()  # the "operational" event clears their errors
        if command == NmtCommand.START and self.state is NmtState.OPERATIONAL:
            self._valve.canopen.nmt_event("operational")  # confirms; clears a communication error
        elif command == NmtCommand.START:
            self._enter(NmtState.OPERATIONAL)
        elif command == NmtCommand.STOP:
            self._enter(NmtState.STOPPED)
        elif command == NmtCommand.PRE_OPERATIONAL:
            self._enter(NmtState.PRE_OPERATIONAL)
        elif command == NmtCommand.RESET_NODE:
            self.state = NmtState.INITIALISING
            self._valve.canopen.nmt_event("reset_node")  # restarts the valve -> _on_restart
        elif command == NmtCommand.RESET_COMMUNICATION:
            self.state = NmtState.INITIALISING
            self._valve.canopen.nmt_event("reset_comm")
            pending = self.lss.reset_communication() if self.lss is not None else None
            if pending is not None:  # CiA 305: the pending node ID becomes active now
                self._valve.canopen.lss_assign(pending)
                self.node_id = pending
            self._boot_up()

    # --- frames ------------------------------------------------------------------------------
    def _receive(self) -> None:
        """The receive thread: every frame in order; the watches judged at reception times."""
        while not self._rx_stop.is_set():
            try:
                msg = self._bus.recv(self._watches.wait_s())
            except Exception as exc:  # a closed or failing bus must not kill the thread silently
                if self._rx_stop.is_set():
                    return
                log.warning("CAN receive failed: %s", exc)
                self._rx_stop.wait(0.1)
                continue
            if msg is None:
                self._judge_quiet(self._watches.wall_ms())
            else:
                self._on_message(msg)

    def rx_wait_s(self) -> float:
        """How long a receiver may wait for a frame before :meth:`judge_quiet` is due."""
        return self._watches.wait_s()

    def judge_quiet(self, quiet_until_ms: float, wait: bool = True) -> None:
        """No frame for this valve arrived up to ``quiet_until_ms`` (wall clock, ms).
        ``wait=False``: not now if the valve is busy (its paced thread runs a batch): a later
        call judges what passed meanwhile, and the receiving thread is not held up."""
        if wait:
            self._judge_quiet(quiet_until_ms)
        elif self._valve.lock.acquire(blocking=False):
            try:
                self._judge_quiet(quiet_until_ms)
            finally:
                self._valve.lock.release()

    def receive_frame(self, msg: can.Message) -> None:
        """A frame from the bus."""
        self._on_message(msg)

    def _judge_quiet(self, quiet_until_ms: float) -> None:
        """``recv`` timed out at ``quiet_until_ms`` (wall clock) with no frame: deadlines before
        then passed unmet. Judged at that moment, not after waiting for the lock (frames that
        arrived meanwhile are still unread)."""
        with self._valve.lock:
            self._watches.follow(self._valve.running, self._now_ms)
            if self._watches.paced and self.state is NmtState.OPERATIONAL:
                self._watches.judge(quiet_until_ms)

    def _on_message(self, msg: can.Message) -> None:
        if msg.is_error_frame or msg.is_remote_frame or msg.is_extended_id or msg.is_fd:
            return  # a classical CAN node ignores CAN FD frames
        self._on_frame(msg.arbitration_id, bytes(msg.data), msg.timestamp)

    def receive_data(self, can_id: int, data: bytes, timestamp: float) -> None:
        """A classical data frame from the bus, received at ``timestamp`` (``time.time``'s
        epoch, s): a :class:`~.canopen_hub.SharedBus` calls this, without ``can.Message``."""
        valve = self._valve
        with valve.lock:
            watches = self._watches
            if watches.paced != valve.running:  # (a call fewer per frame when it is)
                watches.follow(valve.running, self._now_ms)
            arrival = watches.arrival_ms(timestamp, self._now_ms)
            if watches.paced and self.state is NmtState.OPERATIONAL:
                watches.judge(arrival)  # a frame after a deadline proves it passed unmet
            if can_id == LSS_REQUEST:
                if self.lss is not None and self.state is not NmtState.OFF:
                    self.lss.handle(data)
                return
            if self.state in (NmtState.OFF, NmtState.INITIALISING) and can_id:
                return
            try:
                if self.state is not NmtState.OFF:
                    self._dispatch(can_id, data, arrival)
            except Exception:  # a firmware bug must not stop the receive thread
                log.exception("CANopen frame 0x%03X not processed", can_id)

    _on_frame = receive_data  # every frame, whoever received it

    def _dispatch(self, can_id: int, data: bytes, arrival_ms: float) -> None:
        if can_id == 0:
            self._on_nmt(data)
            return
        if self.state is NmtState.STOPPED:
            return  # manual table 7-4: only NMT while stopped
        if can_id == 0x600 + self.node_id:
            self._valve.usb_activity()  # the override's watchdog: a request, as a USB report
            response = self._sdo.handle(data, self._now_ms)
            if response is not None:
                self._send(0x580 + self.node_id, response)
        elif can_id == self._sync_id:
            self._on_sync(arrival_ms)
        elif self.state is NmtState.OPERATIONAL:
            logic = self._rpdo_by_id.get(can_id)  # the valid RPDOs by CAN-ID (_load_config)
            if logic is not None and logic.received(data):
                self._watches.rpdo_received(logic.channel, arrival_ms)
                if self._watch_errors:
                    self._watch_error_gone("rpdo_timeout", "rpdo_ok")

    def _on_sync(self, arrival_ms: float) -> None:
        if self.state is not NmtState.OPERATIONAL:
            return
        watches = self._watches
        late_ms = watches.wall_ms() - arrival_ms if watches.paced else 0.0
        previous, self._sync_arrival_ms = self._sync_arrival_ms, arrival_ms
        interval_ms = arrival_ms - previous if previous is not None else 0.0
        answer = late_ms <= max(LATE_SYNC_MS, LATE_SYNC_PERIODS * interval_ms)
        if not answer:  # behind the bus: a TPDO now would carry a state sampled that late
            self._unanswered_syncs += 1
            self._unanswered_worst_ms = max(self._unanswered_worst_ms, late_ms)
        elif watches.paced:  # the TPDOs sample the moment the SYNC came, as a valve's
            self._valve.run_due_by(arrival_ms / 1000.0)  # (the watches' clock is monotonic)
            if self.state is not NmtState.OPERATIONAL:
                return  # those cycles' 1 ms tasks changed it (a power cycle, an NMT reset)
        if self._watch_errors:
            self._watch_error_gone("sync_error", "sync_ok")
        watches.sync_received(arrival_ms)
        for rpdo in self._rpdo_logic:
            if rpdo.channel.pending is not None:
                rpdo.on_sync()
        for tpdo in self._sync_tpdos:
            if not answer:
                tpdo.count_sync()
            elif (data := tpdo.on_sync()) is not None:
                self._transmit(tpdo, data)

    def take_unanswered_syncs(self) -> tuple[int, float]:
        """SYNCs left without TPDO since the last call, as they came to this valve over
        :data:`~.canopen_watch.LATE_SYNC_MS` and two SYNC intervals late (the PC fell behind
        the bus), and the most any of them was late (ms after it arrived); then counts
        afresh."""
        with self._valve.lock:
            taken = (self._unanswered_syncs, self._unanswered_worst_ms)
            self._unanswered_syncs, self._unanswered_worst_ms = 0, 0.0
        return taken

    def _send(self, can_id: int, data: bytes) -> None:
        if self._now_ms < self._silent_until_ms:
            return
        try:
            self._send_frame(can_id, data)
        except can.CanError as exc:
            log.warning("CAN transmit of 0x%03X failed: %s", can_id, exc)

    def _send_message(self, can_id: int, data: bytes) -> None:
        self._bus.send(can.Message(arbitration_id=can_id, data=data, is_extended_id=False))

    # --- timers ----------------------------------------------------------------------------
    @property
    def _now_ms(self) -> int:
        """The valve's simulated ms of its last 1 ms task (where :meth:`_on_cycle` was, or
        would have been, called: the compiled kernel passes the tasks :meth:`_quiet_ticks`
        allows)."""
        return self._valve.tick_ms

    def _quiet_ticks(self, first_ms: int) -> int:
        """How many 1 ms tasks from ``first_ms`` on :meth:`_on_cycle` would pass doing
        nothing: all while booting or waiting for a node ID (LSS), none while an SDO transfer
        may time out or while a TPDO sends on change of its data; else up to the next heartbeat and, while OPERATIONAL, the next
        TPDO event timer, (in simulated time) watch deadline and, if the PDO parameters differ
        from those loaded (a USB write), their next poll. Nothing else changes them between
        two calls: a batch of the compiled kernel runs with the valve's lock held."""
        if self._closed or self.state is NmtState.OFF:
            return QUIET_FOREVER
        if self.state is NmtState.INITIALISING:  # boot-up once booted, with a node ID (LSS)
            booting = self._valve.status().booting  # its end is a task the kernel leaves
            return QUIET_FOREVER if booting or not self.node_id else 0
        if self._sdo.busy:
            return 0
        values = self._valve.read_values(self._quiet_addresses)  # one look-up for both
        quiet = QUIET_FOREVER
        if int(values[-1]):  # 0x1017
            quiet = self._heartbeat_due_ms - first_ms  # sent at the task where now >= due
        if self.state is NmtState.OPERATIONAL:
            if (self.node_id, *values[:-1]) != self._config_values:  # written over USB:
                quiet = min(quiet, -first_ms % CONFIG_POLL_MS)  # taken where now % 10 == 0
            for tpdo in self._tick_tpdos:
                if not tpdo.channel.event_timer:
                    return 0  # its data is compared every millisecond
                quiet = min(quiet, tpdo.channel.next_due_ms - first_ms)
            if not self._watches.paced:
                quiet = min(quiet, self._watches.quiet_ticks(first_ms))
        return max(0, quiet)

    def _on_cycle(self, sim_time: float) -> None:
        if self._closed or self.state is NmtState.OFF:
            return
        if self.state is NmtState.INITIALISING:
            if self.node_id and not self._valve.status().booting:
                self._boot_up()  # without a node ID (LSS) it waits for an LSS master
            return
        if self._sdo.busy and (abort := self._sdo.expire(self._now_ms)) is not None:
            self._send(0x580 + self.node_id, abort)
        period = self._heartbeat_ms()
        if period and self._now_ms >= self._heartbeat_due_ms:
            self._send(0x700 + self.node_id, bytes([HEARTBEAT_CODES[self.state]]))
            self._heartbeat_due_ms = self._now_ms + period
        if self.state is NmtState.OPERATIONAL:
            if self._now_ms % CONFIG_POLL_MS == 0:
                self._load_config()  # PDO parameters written over USB take effect too
            if not self._watches.paced:  # paced: judged by the receive thread
                self._watches.judge(self._now_ms)
            for tpdo in self._tick_tpdos:
                self._transmit(tpdo, tpdo.on_tick(self._now_ms))

    def _on_watch_event(self, event: str) -> None:
        self._watch_errors.add(event)
        self._valve.canopen.nmt_event(event)

    def _watch_error_gone(self, error: str, event: str) -> None:
        """The frame a watch missed came again: its error's cause is gone (the fault can be
        reset, CiA 408); NMT start clears it too."""
        if error in self._watch_errors:
            self._watch_errors.discard(error)
            self._valve.canopen.nmt_event(event)

    def _heartbeat_ms(self) -> int:  # every 1 ms: with the poll's one look-up
        return int(self._valve.read_values(_HEARTBEAT)[0])

    def _transmit(self, logic: TpdoLogic, data: bytes | None) -> None:
        if data is None or not logic.channel.valid:
            return
        self._send(logic.channel.can_id, data)
        logic.sent(data, self._now_ms)

    # --- EMCY ------------------------------------------------------------------------------
    def _on_error(self, code: int, error_register: int) -> None:
        if self.state in (NmtState.PRE_OPERATIONAL, NmtState.OPERATIONAL):
            self._send_emcy(code, error_register)

    def _send_emcy(self, code: int, error_register: int) -> None:
        cob_id = int(self._valve.read(EMCY_COB_ID, 0))
        if not cob_id & 0x80000000:
            self._send(cob_id & 0x7FF, struct.pack("<HB5x", code, error_register))

    def _rpdo_length_error(self) -> None:
        """CiA 301: EMCY 8210, 0x1001 bit 4 and a 0x1003 entry, through the valve's error
        bookkeeping like every other error (the EMCY comes from :meth:`_on_error`)."""
        self._length_error = True
        self._valve.canopen.nmt_event("rpdo_length_error")

    def _rpdo_length_ok(self) -> None:
        """An RPDO of the right length ends the 8210 error (reset EMCY after the display hold)."""
        if self._length_error:
            self._length_error = False
            self._valve.canopen.nmt_event("rpdo_length_ok")

    # --- LSS (CiA 305) --------------------------------------------------------------------
    def _lss_host(self) -> LssHost:
        valve = self._valve
        return LssHost(
            identity=self._identity,
            active_node_id=lambda: self.node_id,
            send=lambda data: self._send(LSS_RESPONSE, data),
            boot_with=self._lss_boot,
            store=valve.canopen.lss_store,
            activate_bit_timing=self._lss_activate_bit_timing,
        )

    def _identity(self) -> tuple[int, int, int, int]:
        vendor, product, revision, serial = (int(self._valve.read(0x1018, s)) for s in (1, 2, 3, 4))
        return vendor, product, revision, serial

    def _lss_boot(self, node_id: int) -> None:
        """A node ID for a valve that had none: NMT initialisation with it (boot-up)."""
        self._valve.canopen.lss_assign(node_id)
        self.node_id = node_id
        if not self._valve.status().booting:
            self._boot_up()

    def _lss_activate_bit_timing(self, index: int, delay_ms: int) -> None:
        """CiA 305: silent for the switch delay, then at the new rate, silent once more."""
        self._valve.canopen.lss_bit_timing(index)
        self._silent_until_ms = self._now_ms + 2 * delay_ms

    # --- SDO access ------------------------------------------------------------------------
    def _sdo_read(self, index: int, subindex: int) -> bytes:
        if index in (0x1600, 0x1A00) and subindex == 2:
            self._valve.canopen.can_read_bytes(index, subindex)  # existence and access check
            entry_index, entry_sub, bits = mapping(self._valve, index)[subindex - 1]
            return struct.pack("<I", (entry_index << 16) | (entry_sub << 8) | bits)
        return self._valve.canopen.can_read_bytes(index, subindex)

    def _sdo_write(self, index: int, subindex: int, data: bytes) -> None:
        check_comm_write(index, subindex, data, self.state)
        self._valve.canopen.can_write_bytes(index, subindex, data)
        if 0x1000 <= index < 0x2000:
            self._load_config()
            if index == HEARTBEAT_TIME:
                self._heartbeat_due_ms = self._now_ms + self._heartbeat_ms()

    def _load_config(self) -> None:
        """The PDO, SYNC and cycle parameters from the object dictionary (every 10 ms while
        OPERATIONAL: one read of all of them; nothing more unless one or the node ID changed)."""
        values = (self.node_id, *self._valve.read_values(self._config_addresses))
        if values == self._config_values:
            return
        self._config_values = values
        for channel in (*self._rpdos, *self._tpdos):
            channel.load(self._valve, self._now_ms)
        self._period_us = int(self._valve.read(CYCLE_PERIOD, 0))
        self._sync_id = int(self._valve.read(SYNC_COB_ID, 0)) & 0x7FF
        self._sync_tpdos = tuple(
            t for t in self._tpdo_logic if t.channel.valid and t.channel.trans_type in SYNC_TYPES
        )
        self._tick_tpdos = tuple(
            t for t in self._tpdo_logic if t.channel.valid and t.channel.trans_type in EVENT_TYPES
        )
        self._rpdo_by_id = {}
        for logic in reversed(self._rpdo_logic):  # two on one CAN-ID: the first takes it
            if logic.channel.valid:
                self._rpdo_by_id[logic.channel.can_id] = logic
        rpdo_ids = tuple(self._rpdo_by_id)
        routes = frozenset((0, LSS_REQUEST, self._sync_id, 0x600 + self.node_id, *rpdo_ids))
        if routes != self.routes:
            self.routes = routes
            self.routes_changed()

"""The emulated valve's CANopen side: what its CANopen slave (``canopen_slave.py``) and its
LSS slave do to it — SDO access as the chosen object dictionary answers it, LSS (node ID, bit
timing, store), NMT events and commands — and :class:`SlaveValve`, all the slave uses of a
valve (this part, the lock, the listeners and what the valve tells: node ID, bit rate, …).

A part the :class:`~prm9tool.device.emulator.valve.EmulatedValve` holds as ``valve.canopen``
(API contract: docs/emulator.md): it is given the valve's lock, firmware, object-dictionary
profile and power cycle, not the valve; every method takes the valve's lock like the rest of it.
"""

from __future__ import annotations

import threading
from collections.abc import Callable
from typing import TYPE_CHECKING, Protocol

from prm9tool.catalogue.commissioning import NmtCommand
from prm9tool.device.emulator import manual_od
from prm9tool.device.emulator.canopen_pdo import Dictionary
from prm9tool.errors import ValueRangeError

if TYPE_CHECKING:
    from prm9tool.device.emulator.firmware import Firmware
    from prm9tool.device.records import ValveStatus

_NMT_EVENTS: dict[int, str] = {  # CiA 301 command specifier -> NMT event (nmt.NMT_EVENTS)
    NmtCommand.START: "operational",
    NmtCommand.STOP: "stopped",
    NmtCommand.PRE_OPERATIONAL: "preoperational",
    NmtCommand.RESET_NODE: "reset_node",
    NmtCommand.RESET_COMMUNICATION: "reset_comm",
}


class CanopenSide:
    """SDO access, LSS and NMT of an emulated valve (``valve.canopen``)."""

    def __init__(
        self, lock: threading.RLock, fw: Firmware, od: str, restart: Callable[[], None]
    ) -> None:
        """``od``: manual_od.FULL or manual_od.MANUAL; ``restart``: the valve's power cycle."""
        self.lock = lock
        self.od = od
        self._fw = fw
        self._restart = restart
        self._nmt_handler: Callable[[int], None] | None = None

    def can_read_bytes(self, index: int, subindex: int) -> bytes:
        """An SDO upload: :meth:`read_bytes` as this valve's CANopen interface answers it."""
        with self.lock:
            if self.od == manual_od.MANUAL:
                return manual_od.read_bytes(self._fw, index, subindex)
            return self._fw.od.read_bytes(index, subindex)

    def can_write_bytes(self, index: int, subindex: int, data: bytes) -> None:
        """An SDO download: :meth:`write_bytes` as this valve's CANopen interface takes it."""
        with self.lock:
            if self.od == manual_od.MANUAL:
                manual_od.write_bytes(self._fw, index, subindex, data)
            else:
                self._fw.od.write_bytes(index, subindex, data)

    def lss_assign(self, node_id: int) -> None:
        """Take ``node_id`` given by an LSS master now: node-relative communication objects
        follow it as at NMT reset communication."""
        with self.lock:
            self._fw.node_id = node_id
            self._fw.reset_communication()

    def lss_bit_timing(self, index: int) -> None:
        """CiA 305 activate bit timing: run at the rate of table-0 index ``index`` now."""
        from prm9tool.catalogue.canopen_switches import LSS_BIT_TIMINGS_KBIT

        with self.lock:
            self._fw.bitrate = LSS_BIT_TIMINGS_KBIT[index] * 1000

    def lss_store(self, node_id: int, bit_timing: int | None) -> None:
        """CiA 305 store configuration: the LSS record of the NV image (OSError if it fails)."""
        from prm9tool.catalogue.canopen_switches import LSS_BIT_TIMINGS_KBIT

        with self.lock:
            record = dict(self._fw.nv.lss)
            record["node_id"] = node_id
            if bit_timing is not None:
                record["bit_timing"] = bit_timing
            elif "bit_timing" not in record and self._fw.bitrate // 1000 in LSS_BIT_TIMINGS_KBIT:
                record["bit_timing"] = LSS_BIT_TIMINGS_KBIT.index(self._fw.bitrate // 1000)
            self._fw.nv.replace_lss(record)

    def nmt_event(self, event: str) -> None:
        """NMT state change reported by the CANopen slave (coupling: manual table 7-21)."""
        from prm9tool.device.emulator.nmt import apply_nmt_event

        with self.lock:
            if event == "reset_node":
                self._fw.sm.deactivate()
                self._restart()
                return
            apply_nmt_event(self._fw, event)

    def nmt_command(self, command: int) -> None:
        """An NMT command for this valve from its USB side (CiA 301 command specifier).

        With the valve on a CAN bus its CANopen slave takes it as if the master had sent it
        to the valve's node (the slave's NMT state, PDOs and heartbeat follow); otherwise the
        firmware's NMT state changes directly. Ignored while CANopen is switched off.
        """
        event = _NMT_EVENTS.get(int(command))
        if event is None:
            raise ValueRangeError(f"unknown NMT command 0x{int(command):02X}")
        with self.lock:
            if self._nmt_handler is not None:
                self._nmt_handler(int(command))
            elif self._fw.can_enabled and not self._fw.booting:
                self.nmt_event(event)

    def set_nmt_handler(self, handler: Callable[[int], None] | None) -> None:
        """The CANopen slave takes the NMT commands of :meth:`nmt_command` (None: it left)."""
        with self.lock:
            self._nmt_handler = handler


class SlaveValve(Dictionary, Protocol):
    """What the slave uses of an :class:`~.valve.EmulatedValve`: its CANopen part
    ``canopen`` (SDO access, LSS, NMT), its lock, listeners and what it tells."""

    lock: threading.RLock
    canopen: CanopenSide

    @property
    def serial(self) -> int: ...
    @property
    def node_id(self) -> int: ...
    @property
    def bitrate(self) -> int: ...
    @property
    def can_enabled(self) -> bool: ...
    @property
    def lss_mode(self) -> bool: ...
    @property
    def running(self) -> bool: ...
    def status(self) -> ValveStatus: ...
    def read_values(self, addresses: tuple[tuple[int, int], ...]) -> tuple[int | str, ...]: ...
    def usb_activity(self) -> None: ...
    def run_due_by(self, at: float) -> int: ...
    @property
    def tick_ms(self) -> int: ...
    def add_cycle_listener(
        self, fn: Callable[[float], None], quiet: Callable[[int], int] | None = None
    ) -> None: ...
    def add_error_listener(self, fn: Callable[[int, int], None]) -> None: ...
    def add_restart_listener(self, fn: Callable[[], None]) -> None: ...

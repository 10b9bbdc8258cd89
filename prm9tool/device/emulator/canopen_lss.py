"""The emulated valve as a CiA 305 LSS slave (node-ID switch at 1, manual table 7-17).

The slave side of the Layer Setting Services, as a CANopen device implements it: requests on
COB-ID 0x7E5, answers on 0x7E4, always 8 bytes. It knows the LSS states *waiting* and
*configuration*, the switch-state services (global and selective by the 128-bit LSS address:
0x1018 vendor ID, product code, revision number, serial number), Fastscan, the identify
services, the inquire services, configure node ID, configure / activate bit timing and store
configuration. What the services change is handed to the CANopen slave through
:class:`LssHost`; this module keeps only the protocol state.

CiA 305 rules followed here:

* Fastscan and "identify non-configured remote slave" are answered only by a slave without a
  node ID (active and pending both 0xFF); Fastscan only in the waiting state. The slave whose
  address the master completes enters the configuration state, so a master finds the next
  slave with the next Fastscan.
* Configure node ID sets the *pending* node ID (1…127, or 0xFF to remove it). A slave without
  an active node ID takes the pending one when it is switched back to the waiting state and
  boots (NMT initialisation); a configured slave takes it at NMT reset communication.
* Store configuration stores the pending node ID and bit timing together, or nothing.
"""

from __future__ import annotations

import struct
from collections.abc import Callable
from dataclasses import dataclass

from prm9tool.catalogue.canopen_switches import (
    BITRATES_KBIT,
    LSS_BIT_TIMINGS_KBIT,
    LSS_UNCONFIGURED,
)

LSS_REQUEST, LSS_RESPONSE = 0x7E5, 0x7E4
SWITCH_GLOBAL = 0x04
CONFIGURE_NODE_ID, CONFIGURE_BIT_TIMING, ACTIVATE_BIT_TIMING = 0x11, 0x13, 0x15
STORE_CONFIGURATION = 0x17
SELECTIVE_FIRST, SELECTIVE_LAST, SELECTIVE_RESPONSE = 0x40, 0x43, 0x44
IDENTIFY_FIRST, IDENTIFY_LAST = 0x46, 0x4B
IDENTIFY_NON_CONFIGURED, IDENTIFY_SLAVE, NON_CONFIGURED_SLAVE = 0x4C, 0x4F, 0x50
FASTSCAN = 0x51
INQUIRE_FIRST, INQUIRE_NODE_ID = 0x5A, 0x5E
FASTSCAN_CONFIRM = 0x80  # BitChecked 128: every non-configured slave answers, scan restarts
ERROR_NONE, ERROR_RANGE, ERROR_STORE_MEDIA = 0, 1, 2
WAITING, CONFIGURATION = 0, 1


@dataclass
class LssHost:
    """What the LSS slave asks of the valve it belongs to."""

    identity: Callable[[], tuple[int, int, int, int]]  # 0x1018/1…4
    active_node_id: Callable[[], int]  # 0: none
    send: Callable[[bytes], None]  # one frame on 0x7E4
    boot_with: Callable[[int], None]  # a node ID for a slave that had none: NMT initialisation
    store: Callable[[int, int | None], None]  # node ID, bit timing; OSError when it fails
    activate_bit_timing: Callable[[int, int], None]  # table-0 index, switch delay ms


class LssSlave:
    """CiA 305 LSS slave state machine; :meth:`handle` takes each 0x7E5 frame."""

    def __init__(self, host: LssHost) -> None:
        self._host = host
        self.state = WAITING
        self.pending_node_id = LSS_UNCONFIGURED
        self.pending_bit_timing: int | None = None
        self._selective: list[int] = []  # the address parts matched so far (0x40…0x43)
        self._identify: list[int] = []  # the identify-remote-slave bounds (0x46…0x4B)
        self._fastscan_sub = 0
        self.power_up()

    def power_up(self) -> None:
        """Power-up or restart: waiting state, pending node ID = the active one (CiA 305)."""
        self.state = WAITING
        active = self._host.active_node_id()
        self.pending_node_id = active if active else LSS_UNCONFIGURED
        self.pending_bit_timing = None
        self._selective, self._identify, self._fastscan_sub = [], [], 0

    def reset_communication(self) -> int | None:
        """NMT reset communication: the pending node ID if it differs from the active one."""
        pending = self.pending_node_id
        if pending != LSS_UNCONFIGURED and pending != self._host.active_node_id():
            return pending
        return None

    @property
    def non_configured(self) -> bool:
        """No node ID, neither active nor pending (CiA 305: answers Fastscan)."""
        return not self._host.active_node_id() and self.pending_node_id == LSS_UNCONFIGURED

    def handle(self, data: bytes) -> None:
        """One LSS request (COB-ID 0x7E5)."""
        if len(data) < 8:
            return  # CiA 305: LSS frames are 8 bytes
        cs = data[0]
        if cs == SWITCH_GLOBAL:
            self._switch_global(data[1])
        elif SELECTIVE_FIRST <= cs <= SELECTIVE_LAST:
            self._switch_selective(cs, _u32(data))
        elif IDENTIFY_FIRST <= cs <= IDENTIFY_LAST:
            self._identify_remote(cs, _u32(data))
        elif cs == IDENTIFY_NON_CONFIGURED and self.non_configured:
            self._reply(NON_CONFIGURED_SLAVE)
        elif cs == FASTSCAN:
            self._fastscan(data)
        elif self.state == CONFIGURATION:
            self._configuration_service(cs, data)

    # --- switch state --------------------------------------------------------------------
    def _switch_global(self, mode: int) -> None:
        if mode == CONFIGURATION:
            self.state = CONFIGURATION
        elif mode == WAITING and self.state == CONFIGURATION:
            self.state = WAITING
            if not self._host.active_node_id() and self.pending_node_id != LSS_UNCONFIGURED:
                self._host.boot_with(self.pending_node_id)
        self._selective, self._fastscan_sub = [], 0

    def _switch_selective(self, cs: int, value: int) -> None:
        if self.state != WAITING:
            return
        part = cs - SELECTIVE_FIRST
        if part != len(self._selective) or value != self._host.identity()[part]:
            self._selective = []  # out of sequence or another slave's address
            return
        self._selective.append(value)
        if cs == SELECTIVE_LAST:
            self._selective = []
            self.state = CONFIGURATION
            self._reply(SELECTIVE_RESPONSE)

    def _identify_remote(self, cs: int, value: int) -> None:
        part = cs - IDENTIFY_FIRST
        if part != len(self._identify):
            self._identify = []
            return
        self._identify.append(value)
        if cs != IDENTIFY_LAST:
            return
        vendor, product, rev_low, rev_high, serial_low, serial_high = self._identify
        self._identify = []
        own = self._host.identity()
        if (
            own[0] == vendor
            and own[1] == product
            and rev_low <= own[2] <= rev_high
            and serial_low <= own[3] <= serial_high
        ):
            self._reply(IDENTIFY_SLAVE)

    def _fastscan(self, data: bytes) -> None:
        if self.state != WAITING or not self.non_configured:
            return
        id_number = _u32(data)
        bit_checked, sub, following = data[5], data[6], data[7]
        if bit_checked == FASTSCAN_CONFIRM:
            self._fastscan_sub = 0
            self._reply(IDENTIFY_SLAVE)
            return
        if bit_checked > 31 or sub > 3 or following > 3 or sub != self._fastscan_sub:
            return
        mask = (0xFFFFFFFF << bit_checked) & 0xFFFFFFFF
        if (self._host.identity()[sub] ^ id_number) & mask:
            return
        self._fastscan_sub = following
        if bit_checked == 0 and following < sub:
            self.state = CONFIGURATION  # the whole address matched: this slave is the one
        self._reply(IDENTIFY_SLAVE)

    # --- configuration state -----------------------------------------------------------------
    def _configuration_service(self, cs: int, data: bytes) -> None:
        if cs == CONFIGURE_NODE_ID:
            node = data[1]
            ok = 1 <= node <= 127 or node == LSS_UNCONFIGURED
            if ok:
                self.pending_node_id = node
            self._reply(cs, bytes((ERROR_NONE if ok else ERROR_RANGE, 0)))
        elif cs == CONFIGURE_BIT_TIMING:
            table, index = data[1], data[2]
            ok = table == 0 and _supported(index)
            if ok:
                self.pending_bit_timing = index
            self._reply(cs, bytes((ERROR_NONE if ok else ERROR_RANGE, 0)))
        elif cs == ACTIVATE_BIT_TIMING:
            if self.pending_bit_timing is not None:
                delay = struct.unpack_from("<H", data, 1)[0]
                self._host.activate_bit_timing(self.pending_bit_timing, delay)
        elif cs == STORE_CONFIGURATION:
            try:
                self._host.store(self.pending_node_id, self.pending_bit_timing)
            except OSError:
                self._reply(cs, bytes((ERROR_STORE_MEDIA, 0)))
            else:
                self._reply(cs, bytes((ERROR_NONE, 0)))
        elif INQUIRE_FIRST <= cs < INQUIRE_NODE_ID:
            self._reply(cs, struct.pack("<I", self._host.identity()[cs - INQUIRE_FIRST]))
        elif cs == INQUIRE_NODE_ID:
            active = self._host.active_node_id()
            self._reply(cs, bytes((active if active else LSS_UNCONFIGURED,)))

    def _reply(self, cs: int, payload: bytes = b"") -> None:
        self._host.send((bytes((cs,)) + payload).ljust(8, b"\0"))


def _u32(data: bytes) -> int:
    return int(struct.unpack_from("<I", data, 1)[0])


def _supported(index: int) -> bool:
    """A CiA 305 table-0 index of a rate the valve runs at (manual table 7-17)."""
    return index < len(LSS_BIT_TIMINGS_KBIT) and LSS_BIT_TIMINGS_KBIT[index] in BITRATES_KBIT

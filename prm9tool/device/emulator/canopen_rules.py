"""Node ID and bit rate from the rotary switches (table 7-17), and CiA 301 write rules.

Switch meaning (SPEC §3, inference where table 7-17 is garbled):

* interface/bit-rate switch 0 and 1: analog only, CANopen off;
  2..8: 20 k, 50 k, 125 k, 250 k, 500 k, 800 k, 1 M without terminator; 9..F: the same with it.
* node-ID switch 0: node ID, bit rate and terminator from 0x2030/1..3 (NODEID, BITRATE, CANTERM);
  1: LSS + automatic bit rate. **Decision:** the emulator does not implement the LSS protocol
  (CiA 305); with the switch at 1 it takes the node ID from 0x2030/1 (the object an LSS
  master's "store configuration" writes) and follows the bit rate of the bus it was given
  (``bitrate`` None = automatic); 2..F: node ID 10, 15, ..., 75.

Positions are read at power-up only (they come from the valve's 0x2031 after each restart).
"""

from __future__ import annotations

import re
import struct
from dataclasses import dataclass
from enum import StrEnum
from typing import Protocol

from prm9tool.catalogue import CATALOGUE
from prm9tool.errors import AbortCode, SdoAbortError

SWITCH_BIT_RATES = (20_000, 50_000, 125_000, 250_000, 500_000, 800_000, 1_000_000)
FIRST_RATE_POSITION, FIRST_TERMINATED_POSITION = 2, 9
NODE_SWITCH_SOFTWARE, NODE_SWITCH_LSS = 0, 1
NODE_ID_FIRST, NODE_ID_STEP = 10, 5  # position 2 = node 10, +5 per position


class NmtState(StrEnum):
    """CiA 301 NMT states of the slave (``off``: no CANopen, switch at 0/1)."""

    OFF = "off"
    INITIALISING = "initialising"
    PRE_OPERATIONAL = "pre-operational"
    OPERATIONAL = "operational"
    STOPPED = "stopped"


@dataclass(frozen=True)
class CanSettings:
    """What the switches (and 0x2030) selected at power-up."""

    enabled: bool
    node_id: int
    bitrate: int | None  # bit/s; None = automatic bit rate (node switch at 1)
    terminator: bool


class _Readable(Protocol):
    def read(self, index: int, subindex: int) -> int | str: ...


def _address(mnemonic: str) -> tuple[int, int]:
    return CATALOGUE[mnemonic].key


def software_bit_rate(code: int) -> int:
    """Bit/s of a BITRATE (0x2030/2) code, parsed from the catalogue's choice label."""
    label = CATALOGUE["BITRATE"].choice_text(code)
    match = re.fullmatch(r"(\d+) ([kM])bit/s", label)
    if match is None:
        raise ValueError(f"BITRATE code {code} has no bit rate label")
    return int(match[1]) * (1000 if match[2] == "k" else 1_000_000)


def can_settings(valve: _Readable) -> CanSettings:
    """Decode the switch positions and the software settings of ``valve``."""
    try:
        baud_switch = int(valve.read(*_address("SWBAUD")))
    except SdoAbortError:  # a valve without -CA has no switches
        return CanSettings(False, 0, None, False)
    node_switch = int(valve.read(*_address("SWNODE")))
    enabled = baud_switch >= FIRST_RATE_POSITION
    software_terminator = bool(valve.read(*_address("CANTERM")))
    if node_switch in (NODE_SWITCH_SOFTWARE, NODE_SWITCH_LSS):
        node_id = int(valve.read(*_address("NODEID")))
        bitrate = None
        if node_switch == NODE_SWITCH_SOFTWARE:
            bitrate = software_bit_rate(int(valve.read(*_address("BITRATE"))))
        return CanSettings(enabled, node_id, bitrate, software_terminator)
    node_id = NODE_ID_FIRST + NODE_ID_STEP * (node_switch - 2)
    position = (baud_switch - FIRST_RATE_POSITION) % len(SWITCH_BIT_RATES)
    terminator = baud_switch >= FIRST_TERMINATED_POSITION or software_terminator
    return CanSettings(enabled, node_id, SWITCH_BIT_RATES[position], terminator)


# --- CiA 301 rules for writes to the communication objects -----------------------------------
PDO_COMM = (0x1400, 0x1401, 0x1800, 0x1801)
COB_ID_OBJECTS = {(index, 1) for index in PDO_COMM} | {(0x1005, 0), (0x1014, 0)}
TRANSMISSION_TYPES = {(index, 2) for index in PDO_COMM}
RESERVED_TYPES = range(241, 254)  # manual table 7-12
RESERVED_CAN_IDS = (  # CiA 301 §7.3.5: identifiers the CANopen services use
    range(0x080),
    range(0x101, 0x181),
    range(0x581, 0x600),
    range(0x601, 0x680),
    range(0x6E0, 0x700),
    range(0x701, 0x800),
)
COB_VALID_BIT, COB_RTR_BIT, COB_FRAME_BIT = 1 << 31, 1 << 30, 1 << 29


def check_comm_write(index: int, subindex: int, data: bytes, state: NmtState) -> None:
    """Raise the CiA 301 abort for a write the communication profile refuses."""
    key = (index, subindex)
    if key in COB_ID_OBJECTS and len(data) == 4:
        if index in PDO_COMM and state is NmtState.OPERATIONAL:
            raise SdoAbortError(index, subindex, AbortCode.CANNOT_STORE_DEVICE_STATE)
        _check_cob_id(index, subindex, struct.unpack("<I", data)[0])
    if key in TRANSMISSION_TYPES and len(data) == 1 and data[0] in RESERVED_TYPES:
        raise SdoAbortError(index, subindex, AbortCode.INVALID_VALUE)


def _check_cob_id(index: int, subindex: int, value: int) -> None:
    can_id = value & ~(COB_VALID_BIT | COB_RTR_BIT)
    invalid = bool(can_id & ~0x7FF)  # 29-bit identifiers are not supported
    reserved = any(can_id in ids for ids in RESERVED_CAN_IDS)
    if index == 0x1005:
        invalid = invalid or reserved or bool(value & COB_RTR_BIT)  # bit 30: we cannot generate
    elif not value & COB_VALID_BIT:
        invalid = invalid or reserved
    if invalid:
        raise SdoAbortError(index, subindex, AbortCode.INVALID_VALUE)

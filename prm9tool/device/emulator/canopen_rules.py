"""CiA 301 rules of the communication profile the PRM9 enforces on SDO writes, and NMT states.

Node ID and bit rate come from the firmware (``EmulatedValve.node_id``/``bitrate``, latched
from the rotary switches at power-up, manual §7.3.1 table 7-17); this module only knows CiA 301.
"""

from __future__ import annotations

import struct

from prm9tool.device.records import NmtState
from prm9tool.errors import AbortCode, SdoAbortError

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

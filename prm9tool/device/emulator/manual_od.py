"""The ``--od manual`` valve: the CANopen object dictionary exactly as the manual lists it.

A real -CA valve implemented from the manual alone answers only the objects of tables 7-13,
7-14 and 7-16 (:mod:`prm9tool.catalogue.manual_od`) and has no store command: table 7-13 lists
no 0x1010/0x1011 and §7.2.2 (figure 7-3, point B) says the valve keeps the parameters once
they are set. So over CANopen this valve

* answers 0x06020000 (no object) / 0x06090011 (no sub-index) for every other address, and its
  sub-index 0 "highest sub-index supported" counts only the listed sub-indices;
* keeps every accepted write of a stored parameter at once (its non-volatile image is written
  with each SDO download, as an auto-saving device does);
* refuses with 0x06040043 (CiA 301 "general parameter incompatibility") a write that would
  leave a combination the catalogue's rules refuse, so it never holds one (decision: the
  manual is silent on how the firmware protects itself; this is the CiA 301 code for it).

The firmware behind it is the same as the full emulated valve's: parameters the manual does
not list keep their stored values and still work inside the valve, they are only not
reachable over CANopen (as on a real valve, where they are not reachable at all).
"""

from __future__ import annotations

import logging
from typing import TYPE_CHECKING

from prm9tool.catalogue.manual_od import MANUAL_OBJECTS, in_manual, manual_highest_sub
from prm9tool.device.emulator.nvimage import is_nonvolatile
from prm9tool.device.emulator.objdict import abort
from prm9tool.device.emulator.odsetup import store_problems
from prm9tool.errors import AbortCode

if TYPE_CHECKING:
    from prm9tool.device.emulator.firmware import Firmware

log = logging.getLogger(__name__)
FULL, MANUAL = "full", "manual"
OD_PROFILES = (FULL, MANUAL)


def check_listed(index: int, subindex: int) -> None:
    """Abort as a valve without the object does when the manual does not list it."""
    if not in_manual(index, subindex):
        code = AbortCode.NO_SUCH_SUBINDEX if index in MANUAL_OBJECTS else AbortCode.NO_SUCH_OBJECT
        raise abort((index, subindex), code)


def read_bytes(fw: Firmware, index: int, subindex: int) -> bytes:
    """An SDO upload on the manual-only valve."""
    check_listed(index, subindex)
    data = fw.od.read_bytes(index, subindex)
    param = fw.od.entry(index, subindex)
    if subindex == 0 and _counts_sub_indices(param.mnemonic):
        return bytes([manual_highest_sub(index)])
    return data


def write_bytes(fw: Firmware, index: int, subindex: int, data: bytes) -> None:
    """An SDO download on the manual-only valve: checked against the rules, then kept."""
    check_listed(index, subindex)
    od = fw.od
    param = od.entry(index, subindex)
    if not is_nonvolatile(param):
        od.write_bytes(index, subindex, data)
        return
    before = od.values.get(param.key)
    image = fw.nonvolatile_values()
    od.write_bytes(index, subindex, data)
    after = fw.nonvolatile_values()
    new_problems = set(store_problems(fw, after)) - set(store_problems(fw, image))
    if new_problems:
        _put_back(fw, param.key, before)
        log.info("write refused (%s): %s", param.mnemonic, "; ".join(sorted(new_problems)))
        raise abort(param.key, AbortCode.PARAMETER_INCOMPATIBLE)
    try:
        fw.nv.replace(after)
    except OSError as exc:
        _put_back(fw, param.key, before)
        log.warning("non-volatile memory not written: %s", exc)
        raise abort(param.key, AbortCode.HARDWARE_ERROR) from exc


def _put_back(fw: Firmware, key: tuple[int, int], value: int | str | None) -> None:
    if value is None:
        fw.od.values.pop(key, None)
    else:
        fw.od.values[key] = value
    fw.setpoint_dirty = fw.config_dirty = True


def _counts_sub_indices(mnemonic: str) -> bool:
    """True for a sub-index 0 that says the highest sub-index (not a count of entries)."""
    return mnemonic.startswith("SUB0_") or mnemonic.endswith("SUBS")

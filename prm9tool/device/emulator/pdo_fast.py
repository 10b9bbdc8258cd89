"""A TPDO's data straight from the compiled loop's state, without the object dictionary's path.

Served valves answer every SYNC with their TPDO1 (status word 0x6041 and an actual value),
and the object dictionary's way to it — an access check, a getter and an encoding per entry,
the getter of the actual value flushing every measuring point of the loop into its mailbox —
was a third of a SYNC's cost in the served valve (docs/PERFORMANCE.md, "issue 30, third
stop"). :func:`sampler` builds, once per mapping, a function that reads the same values the
getters read (:mod:`.odsetup`), in the same order and with the same side effects on the
firmware: the status word first, then for the first actual value what
:meth:`.firmware.Firmware.flush` does to the loop — inputs refreshed if dirty, the compiled
loop's ``prepare`` and ``write_back`` — except copying the 21 measuring points to the mailbox,
which every reader of the mailbox does itself (it flushes first). Only for the compiled kernel
and the objects named in :data:`SLOTS`; any other mapping keeps the object dictionary's path.
``tests/test_emulator_pdo_fast.py`` holds both paths to the same frames.
"""

from __future__ import annotations

import struct
from collections.abc import Callable
from typing import TYPE_CHECKING

from prm9tool.catalogue import CATALOGUE, DataType
from prm9tool.device.emulator.odsetup import clamp_pv, status_flags

if TYPE_CHECKING:
    from prm9tool.device.emulator.firmware import Firmware

Entries = tuple[tuple[int, int, int], ...]
STATUS = CATALOGUE["STATUSWORD"].key  # 0x6041: no flush (its getter reads the state machine)
SLOTS = {  # actual values and the compiled loop's state slot their getters read after a flush
    CATALOGUE["POSACT"].key: "xm",  # 0x6301, position_actual
    CATALOGUE["PRCACT"].key: "pv",  # process_actual
    CATALOGUE["DEMAND"].key: "r",  # demand
}
_FORMAT = {DataType.UNSIGNED16: "H", DataType.INTEGER16: "h"}


def sampler(fw: Firmware, entries: Entries) -> Callable[[], bytes] | None:
    """A function returning ``fw.od.read_mapped(entries)``'s bytes by the fast way, or None
    when this mapping or kernel has none (the caller keeps ``read_mapped``)."""
    if fw.kernel != "compiled" or not entries:
        return None
    from prm9tool.device.emulator.ckernel import S

    od = fw.od
    plan: list[int] = []  # -1: the status word, else a state slot
    fmt = "<"
    for index, sub, bits in entries:
        key = (index, sub)
        param = od.entries.get(key)
        code = None if param is None else _FORMAT.get(param.dtype)
        if param is None or code is None or bits != 16 or key not in (STATUS, *SLOTS):
            return None
        plan.append(-1 if key == STATUS else S[SLOTS[key]])
        fmt += code
    pack = struct.Struct(fmt).pack
    if len(plan) == 2 and plan[0] == -1 and plan[1] >= 0:  # TPDO1 as the valve maps it
        slot = plan[1]

        def status_and_actual() -> bytes:
            word = fw.sm.status_word(status_flags(fw))
            return pack(word, clamp_pv(fw.compiled_state()[slot]))

        return status_and_actual

    def any_order() -> bytes:
        values = []
        state = None
        for slot in plan:
            if slot < 0:
                values.append(fw.sm.status_word(status_flags(fw)))
                continue
            if state is None:
                state = fw.compiled_state()
            values.append(clamp_pv(state[slot]))
        return pack(*values)

    return any_order

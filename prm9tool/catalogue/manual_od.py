"""The CANopen objects the manual lists, and nothing else (manual tables 7-13, 7-14, 7-16).

A -CA valve built from the manual alone answers exactly these addresses over CANopen: the
communication profile of table 7-13 (no store/restore objects 0x1010/0x1011, no RPDO event
timer sub-index 5), the manufacturer objects "of all valves" of table 7-14 and the CiA 408
objects of table 7-16. The parameter catalogue adds objects of this project's own (controller
gains, analog input set-up, switches, type key, setpoint override, …): they are not here.

The emulator's ``--od manual`` valve (:mod:`prm9tool.device.emulator.manual_od`) answers only
these, and the CANopen master is tested against it.
"""

from __future__ import annotations

# how a valve keeps an upload (the upload result, the report, the GUI and the history say it):
# 0x1010 present = store on command (CiA 301); absent, as in table 7-13 = it keeps what is
# written (§7.2.2, figure 7-3 point B); the restart verification reads everything back after
# an NMT reset node
STORED_WITH_1010 = "stored with 0x1010"
KEPT_AS_WRITTEN = "kept by the valve as written (it has no store command)"
VERIFIED_RESTART = "verified after a restart"
# why the restart verification failed (--batch's report, the GUI's history record)
NOT_KEPT_AFTER_RESTART = (
    "after a restart the valve reads back values other than the upload's: it did not keep them"
)


def _record(index: int, highest: int, first: int = 0) -> dict[int, range]:
    return {index: range(first, highest + 1)}


# index → the sub-indices the manual's tables list (sub-index 0 included where they list it)
MANUAL_OBJECTS: dict[int, range] = {
    # table 7-13: communication profile area
    **_record(0x1000, 0),
    **_record(0x1001, 0),
    **_record(0x1003, 8),  # "0..x": the PRM9's history depth (catalogue)
    **_record(0x1005, 0),
    **_record(0x1006, 0),
    **_record(0x1008, 0),
    **_record(0x1009, 0),
    **_record(0x100A, 0),
    **_record(0x1014, 0),
    **_record(0x1017, 0),
    **_record(0x1018, 4),
    **_record(0x1F80, 0),
    **_record(0x1400, 2),
    **_record(0x1401, 2),
    **_record(0x1600, 2),
    **_record(0x1601, 1),
    **_record(0x1A00, 2),
    **_record(0x1A01, 2),
    # table 7-14: manufacturer objects of all valves
    **_record(0x2000, 9),
    **_record(0x2001, 9),
    **_record(0x2002, 0),
    **_record(0x2003, 0),
    **_record(0x2004, 3),
    **_record(0x2005, 4),
    **_record(0x2006, 9),
    **_record(0x2007, 9),
    **_record(0x2008, 0),
    **_record(0x2100, 6),
    # table 7-16: CiA 408 device profile
    **{index: range(1) for index in (0x6040, 0x6041, 0x6042, 0x6043, 0x605F, 0x6330)},
    **{index: range(1) for index in (0x6340, 0x6341, 0x6342, 0x6346, 0x6351, 0x6360)},
    **{
        index: range(2)
        for index in (
            *(0x6300, 0x6301, 0x6310, 0x6332, 0x6333, 0x6335, 0x6336),
            *(0x6343, 0x6344, 0x6345, 0x6350, 0x6352, 0x6353, 0x6361, 0x6362),
            *(0x6380, 0x6381),
        )
    },
}
# TPDO communication records: sub-indices 0, 1, 2 and 5 (table 7-13)
MANUAL_OBJECTS[0x1800] = range(6)
MANUAL_OBJECTS[0x1801] = range(6)
TPDO_SUBS = frozenset({0, 1, 2, 5})


def in_manual(index: int, subindex: int) -> bool:
    """True if the manual's tables list the object at ``index``/``subindex``."""
    subs = MANUAL_OBJECTS.get(index)
    if subs is None or subindex not in subs:
        return False
    return index not in (0x1800, 0x1801) or subindex in TPDO_SUBS


def manual_highest_sub(index: int) -> int:
    """The highest sub-index the manual lists for ``index`` (its sub-index 0 value)."""
    return max(s for s in MANUAL_OBJECTS[index] if in_manual(index, s))

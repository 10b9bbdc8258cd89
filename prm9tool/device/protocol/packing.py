"""Request builders: pack many entries densely into as few reports as the layout allows.

Commands are data: the session, the batch mode, the benchmark and the golden-frame tests all
build their reports here and execute them elsewhere.
"""

from __future__ import annotations

from collections.abc import Sequence

from prm9tool.device.protocol.requests import (
    MAX_READ_ENTRIES,
    MAX_SEGMENTED_LENGTH,
    SEGMENT_WRITE_CHUNK,
    ReadEntries,
    SegmentWrite,
    WriteEntries,
)
from prm9tool.device.protocol.wire import BODY_SIZE

READ_ANSWER_ROOM = BODY_SIZE - 2  # answer body after the result and count bytes
WRITE_ROOM = BODY_SIZE - 1  # request body after the count byte
WRITE_ENTRY_OVERHEAD = 4  # index, subindex, length
READ_ENTRY_OVERHEAD = 1  # length byte in the answer


def pack_reads(items: Sequence[tuple[int, int, int]]) -> list[ReadEntries]:
    """READ requests for ``(index, subindex, expected size)`` items, in order.

    Each request holds at most 20 addresses and only as many entries as their answers fit in
    one report, so the valve answers every entry in one go.
    """
    batches: list[ReadEntries] = []
    current: list[tuple[int, int]] = []
    room = READ_ANSWER_ROOM
    for index, subindex, size in items:
        need = READ_ENTRY_OVERHEAD + size
        if need > READ_ANSWER_ROOM:
            raise ValueError(f"0x{index:04X}/{subindex}: {size} bytes need a segmented read")
        if current and (len(current) == MAX_READ_ENTRIES or need > room):
            batches.append(ReadEntries(tuple(current)))
            current, room = [], READ_ANSWER_ROOM
        current.append((index, subindex))
        room -= need
    if current:
        batches.append(ReadEntries(tuple(current)))
    return batches


def pack_writes(entries: Sequence[tuple[int, int, bytes]]) -> list[WriteEntries]:
    """WRITE requests for ``(index, subindex, encoded value)`` entries, in order."""
    batches: list[WriteEntries] = []
    current: list[tuple[int, int, bytes]] = []
    room = WRITE_ROOM
    for index, subindex, data in entries:
        need = WRITE_ENTRY_OVERHEAD + len(data)
        if need > WRITE_ROOM:
            raise ValueError(f"0x{index:04X}/{subindex}: {len(data)} bytes need a segmented write")
        if current and need > room:
            batches.append(WriteEntries(tuple(current)))
            current, room = [], WRITE_ROOM
        current.append((index, subindex, data))
        room -= need
    if current:
        batches.append(WriteEntries(tuple(current)))
    return batches


def segments(index: int, subindex: int, data: bytes) -> list[SegmentWrite]:
    """SEGMENT_WRITE requests that carry ``data`` (at least one, also for an empty value)."""
    if len(data) > MAX_SEGMENTED_LENGTH:
        raise ValueError(f"value of {len(data)} bytes exceeds {MAX_SEGMENTED_LENGTH}")
    offsets = range(0, max(len(data), 1), SEGMENT_WRITE_CHUNK)
    return [
        SegmentWrite(index, subindex, len(data), o, data[o : o + SEGMENT_WRITE_CHUNK])
        for o in offsets
    ]

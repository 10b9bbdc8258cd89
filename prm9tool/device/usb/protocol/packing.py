"""Request builders: pack many entries densely into as few reports as the layout allows.

Commands are data: the session, the batch mode, the benchmark and the golden-frame tests all
build their reports here and execute them elsewhere.
"""

from __future__ import annotations

from collections.abc import Sequence

from prm9tool.device.usb.protocol.requests import (
    MAX_READ_ENTRIES,
    MAX_RUNS,
    MAX_SEGMENTED_LENGTH,
    SEGMENT_WRITE_CHUNK,
    ReadEntries,
    SegmentWrite,
    WriteEntries,
    runs,
)
from prm9tool.device.usb.protocol.wire import BODY_SIZE

READ_ANSWER_ROOM = BODY_SIZE - 2  # answer body after the result and count bytes
REQUEST_ROOM = BODY_SIZE - 1  # request body after the run count
RUN_HEADER = 4  # index, first subindex, count
READ_ENTRY_OVERHEAD = 1  # length byte in the answer
WRITE_ENTRY_OVERHEAD = 1  # length byte in the request


def _runs_bytes(keys: list[tuple[int, int]], per_entry: list[int]) -> int:
    return RUN_HEADER * len(runs(keys)) + sum(per_entry)


def pack_reads(items: Sequence[tuple[int, int, int]]) -> list[ReadEntries]:
    """READ requests for ``(index, subindex, expected size)`` items, in order.

    Each request holds only as many entries as their answers fit in one report, so the valve
    answers every entry in one go; consecutive subindices share one run header.
    """
    batches: list[ReadEntries] = []
    keys: list[tuple[int, int]] = []
    answer = 0
    for index, subindex, size in items:
        need = READ_ENTRY_OVERHEAD + size
        if need > READ_ANSWER_ROOM:
            raise ValueError(f"0x{index:04X}/{subindex}: {size} bytes need a segmented read")
        trial = [*keys, (index, subindex)]
        if keys and (
            answer + need > READ_ANSWER_ROOM
            or len(runs(trial)) > MAX_RUNS
            or len(trial) > MAX_READ_ENTRIES
        ):
            batches.append(ReadEntries(tuple(keys)))
            keys, answer, trial = [], 0, [(index, subindex)]
        keys, answer = trial, answer + need
    if keys:
        batches.append(ReadEntries(tuple(keys)))
    return batches


def pack_writes(entries: Sequence[tuple[int, int, bytes]]) -> list[WriteEntries]:
    """WRITE requests for ``(index, subindex, encoded value)`` entries, in order."""
    batches: list[WriteEntries] = []
    current: list[tuple[int, int, bytes]] = []
    for index, subindex, data in entries:
        if RUN_HEADER + WRITE_ENTRY_OVERHEAD + len(data) > REQUEST_ROOM:
            raise ValueError(f"0x{index:04X}/{subindex}: {len(data)} bytes need a segmented write")
        trial = [*current, (index, subindex, data)]
        if current and _write_size(trial) > REQUEST_ROOM:
            batches.append(WriteEntries(tuple(current)))
            trial = [(index, subindex, data)]
        current = trial
    if current:
        batches.append(WriteEntries(tuple(current)))
    return batches


def _write_size(entries: list[tuple[int, int, bytes]]) -> int:
    keys = [(index, subindex) for index, subindex, _ in entries]
    return _runs_bytes(keys, [WRITE_ENTRY_OVERHEAD + len(d) for _, _, d in entries])


def segments(index: int, subindex: int, data: bytes) -> list[SegmentWrite]:
    """SEGMENT_WRITE requests that carry ``data`` (at least one, also for an empty value)."""
    if len(data) > MAX_SEGMENTED_LENGTH:
        raise ValueError(f"value of {len(data)} bytes exceeds {MAX_SEGMENTED_LENGTH}")
    offsets = range(0, max(len(data), 1), SEGMENT_WRITE_CHUNK)
    return [
        SegmentWrite(index, subindex, len(data), o, data[o : o + SEGMENT_WRITE_CHUNK])
        for o in offsets
    ]

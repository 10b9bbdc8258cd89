"""Request builders: pack many entries densely into as few reports as the layout allows.

Commands are data: the session, the batch mode, the benchmark and the golden-frame tests all
build their reports here and execute them elsewhere.
"""

from __future__ import annotations

from collections.abc import Sequence
from functools import lru_cache

from prm9tool.device.usb.protocol.requests import (
    MAX_READ_ENTRIES,
    MAX_RUNS,
    MAX_SEGMENTED_LENGTH,
    SEGMENT_WRITE_CHUNK,
    ReadEntries,
    SegmentWrite,
    WriteEntries,
)
from prm9tool.device.usb.protocol.wire import BODY_SIZE

READ_ANSWER_ROOM = BODY_SIZE - 2  # answer body after the result and count bytes
REQUEST_ROOM = BODY_SIZE - 1  # request body after the run count
RUN_HEADER = 4  # index, first subindex, count
READ_ENTRY_OVERHEAD = 1  # length byte in the answer
WRITE_ENTRY_OVERHEAD = 1  # length byte in the request


class _RunCount:
    """The runs of a growing address list, counted as addresses are added (as :func:`runs`
    groups them), so that packing stays linear in the number of entries."""

    def __init__(self) -> None:
        self.count = 0
        self._last = (-1, 0, 0)  # index, first subindex, count of the last run

    def after(self, index: int, subindex: int) -> int:
        """Runs the list would have with ``(index, subindex)`` appended."""
        last_index, first, count = self._last
        extends = last_index == index and first + count == subindex and count < 255
        return self.count if extends else self.count + 1

    def add(self, index: int, subindex: int) -> None:
        """Append ``(index, subindex)``."""
        last_index, first, count = self._last
        if last_index == index and first + count == subindex and count < 255:
            self._last = (index, first, count + 1)
        else:
            self._last = (index, subindex, 1)
            self.count += 1


def pack_reads(items: Sequence[tuple[int, int, int]]) -> list[ReadEntries]:
    """READ requests for ``(index, subindex, expected size)`` items, in order.

    Each request holds only as many entries as their answers fit in one report, so the valve
    answers every entry in one go; consecutive subindices share one run header. An upload
    reads the same list twice (verify, then the stored values): the packing is remembered.
    """
    return list(_pack_reads(tuple(items)))


@lru_cache(maxsize=32)
def _pack_reads(items: tuple[tuple[int, int, int], ...]) -> tuple[ReadEntries, ...]:
    batches: list[ReadEntries] = []
    keys: list[tuple[int, int]] = []
    runs_ = _RunCount()
    answer = 0
    for index, subindex, size in items:
        need = READ_ENTRY_OVERHEAD + size
        if need > READ_ANSWER_ROOM:
            raise ValueError(f"0x{index:04X}/{subindex}: {size} bytes need a segmented read")
        if keys and (
            answer + need > READ_ANSWER_ROOM
            or runs_.after(index, subindex) > MAX_RUNS
            or len(keys) + 1 > MAX_READ_ENTRIES
        ):
            batches.append(ReadEntries(tuple(keys)))
            keys, answer, runs_ = [], 0, _RunCount()
        keys.append((index, subindex))
        runs_.add(index, subindex)
        answer += need
    if keys:
        batches.append(ReadEntries(tuple(keys)))
    return tuple(batches)


def pack_writes(entries: Sequence[tuple[int, int, bytes]]) -> list[WriteEntries]:
    """WRITE requests for ``(index, subindex, encoded value)`` entries, in order."""
    batches: list[WriteEntries] = []
    current: list[tuple[int, int, bytes]] = []
    runs_ = _RunCount()
    data_bytes = 0  # length byte + data of the entries in ``current``
    for index, subindex, data in entries:
        need = WRITE_ENTRY_OVERHEAD + len(data)
        if RUN_HEADER + need > REQUEST_ROOM:
            raise ValueError(f"0x{index:04X}/{subindex}: {len(data)} bytes need a segmented write")
        size = RUN_HEADER * runs_.after(index, subindex) + data_bytes + need
        if current and size > REQUEST_ROOM:
            batches.append(WriteEntries(tuple(current)))
            current, data_bytes, runs_ = [], 0, _RunCount()
        current.append((index, subindex, data))
        runs_.add(index, subindex)
        data_bytes += need
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

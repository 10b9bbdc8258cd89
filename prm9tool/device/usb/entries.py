"""Reading and writing many object-dictionary entries over the protocol, densely packed.

Fixed-size values travel several per report (READ/WRITE); strings travel segmented. Used by
:class:`prm9tool.device.session.ValveSession`; the packing itself lives in the protocol.
"""

from __future__ import annotations

import struct
import threading
from collections.abc import Callable, Mapping, Sequence
from typing import Any

from prm9tool.catalogue import Parameter
from prm9tool.device.records import RefusedError, Steps, Value, check_cancel
from prm9tool.device.usb.protocol import (
    ReadEntries,
    ReadReply,
    SegmentRead,
    SegmentReadReply,
    SegmentWriteReply,
    WriteEntries,
    WriteReply,
    pack_reads,
    pack_writes,
    segments,
)
from prm9tool.errors import ProtocolError, SdoAbortError


class EntryIO:
    """Many-entry reads and writes through ``call(request, expected answer type)``."""

    def __init__(self, call: Callable[..., Any]) -> None:
        self._call = call

    def read(
        self,
        params: Sequence[Parameter],
        steps: Steps | None = None,
        cancel: threading.Event | None = None,
    ) -> dict[str, Value | SdoAbortError]:
        """Values by mnemonic; a refused entry maps to its SdoAbortError."""
        step = steps.step if steps else "read"
        by_key = {p.key: p for p in params}
        results: dict[str, Value | SdoAbortError] = {}
        pending = [(p.index, p.subindex, p.dtype.size) for p in params if not p.is_string]
        for batch in pack_reads(pending):
            addresses = list(batch.addresses)
            while addresses:  # the valve may answer fewer entries than asked (long values)
                check_cancel(cancel, step)
                reply = self._call(ReadEntries(tuple(addresses)), ReadReply)
                if not reply.values or len(reply.values) > len(addresses):
                    raise ProtocolError(
                        f"the valve answered {len(reply.values)} values to {len(addresses)} reads"
                    )
                for key, value in zip(addresses, reply.values, strict=False):
                    results[by_key[key].mnemonic] = decode(by_key[key], value)
                addresses = addresses[len(reply.values) :]
                if steps:
                    steps.advance(len(reply.values))
        for param in (p for p in params if p.is_string):
            check_cancel(cancel, step)
            results[param.mnemonic] = self._read_segmented(param)
            if steps:
                steps.advance(1)
        return results

    def _read_segmented(self, param: Parameter) -> Value | SdoAbortError:
        data = bytearray()
        while True:
            request = SegmentRead(param.index, param.subindex, len(data))
            try:
                reply = self._call(request, SegmentReadReply)
            except SdoAbortError as exc:
                return exc
            if reply.offset != len(data) or (not reply.data and len(data) < reply.total):
                raise ProtocolError(f"{param.mnemonic}: segmented read out of step")
            data += reply.data
            if len(data) >= reply.total:
                return decode(param, bytes(data[: reply.total]))

    def write(
        self,
        params: Sequence[Parameter],
        values: Mapping[str, Value],
        steps: Steps | None = None,
        cancel: threading.Event | None = None,
    ) -> int:
        """Write the values; returns how many were written, raises RefusedError on a refusal."""
        by_key = {p.key: p for p in params}
        encoded = [(p.index, p.subindex, p.dtype.encode(values[p.mnemonic])) for p in params]
        done = 0
        for batch in pack_writes([e for e in encoded if not by_key[e[:2]].is_string]):
            check_cancel(cancel, "write")
            done = self._write_batch(batch, by_key, done)
            if steps:
                steps.advance(len(batch.entries))
        for index, subindex, data in (e for e in encoded if by_key[e[:2]].is_string):
            check_cancel(cancel, "write")
            for piece in segments(index, subindex, data):
                try:
                    self._call(piece, SegmentWriteReply)
                except SdoAbortError as exc:
                    raise RefusedError(by_key[(index, subindex)].mnemonic, exc, done) from exc
            done += 1
            if steps:
                steps.advance(1)
        return done

    def _write_batch(
        self, batch: WriteEntries, by_key: dict[tuple[int, int], Parameter], done: int
    ) -> int:
        try:
            reply = self._call(batch, WriteReply)
        except SdoAbortError as exc:
            param = by_key.get((exc.index, exc.subindex))
            if param is None:
                raise
            position = next(i for i, e in enumerate(batch.entries) if e[:2] == param.key)
            raise RefusedError(param.mnemonic, exc, done + position) from exc
        if reply.count != len(batch.entries):
            raise ProtocolError(f"the valve wrote {reply.count} of {len(batch.entries)} entries")
        return done + reply.count


def decode(param: Parameter, value: bytes | int) -> Value | SdoAbortError:
    """A READ answer entry as a value (or the SdoAbortError of a refused entry)."""
    if isinstance(value, int):
        return SdoAbortError(param.index, param.subindex, value)
    try:
        return param.dtype.decode(value)
    except (struct.error, ValueError) as exc:
        raise ProtocolError(
            f"{param.mnemonic}: the valve sent {len(value)} bytes for a {param.dtype.name} ({exc})"
        ) from exc

"""What a history record holds, and the hash that chains it to the valve's previous record.

Each record's ``hash`` is SHA-256 over the canonical JSON of its content together with the
previous record's hash (``prev_hash``; 64 zeros for a valve's first record). Changing any field
of a record breaks its own hash; deleting or reordering one breaks the next record's
``prev_hash`` or the sequence numbers. No database here: plain data and hashlib.
"""

from __future__ import annotations

import hashlib
import json
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field, fields
from typing import Any

GENESIS = "0" * 64
Raw = int | str

# the fields the hash covers, in this order (docs/history.md)
HASHED = (
    "serial", "seq", "recorded_at", "type_key", "firmware", "link", "device_id",
    "program_version", "os_user", "host", "operation", "outcome", "failed_step",
    "details", "parameters", "prev_hash",
)  # fmt: skip


def canonical(value: object) -> str:
    """Canonical JSON: sorted keys, no spaces, UTF-8 (the same text on every station)."""
    return json.dumps(value, sort_keys=True, separators=(",", ":"), ensure_ascii=False)


@dataclass
class Entry:
    """One operation before it gets its place in the chain (``seq``, hashes)."""

    serial: int
    type_key: str
    firmware: str
    link: str
    device_id: str
    operation: str
    outcome: str
    recorded_at: str
    program_version: str
    os_user: str
    host: str
    failed_step: str | None = None
    details: dict[str, Any] = field(default_factory=dict)
    parameters: Mapping[str, Raw] | None = None

    def to_json(self) -> dict[str, Any]:
        """Everything, as JSON-compatible data (the local queue's line)."""
        data = {f.name: getattr(self, f.name) for f in fields(self)}  # no deep copies
        data["details"] = dict(self.details)
        data["parameters"] = None if self.parameters is None else dict(self.parameters)
        return data

    @classmethod
    def from_json(cls, data: Mapping[str, Any]) -> Entry:
        """The entry a queue line holds."""
        return cls(**dict(data))

    def columns(self, seq: int, prev_hash: str) -> dict[str, Any]:
        """The database row: content as canonical JSON text, ``seq``, both hashes."""
        row = {f.name: getattr(self, f.name) for f in fields(self)}
        row["details"] = canonical(self.details)
        row["parameters"] = None if self.parameters is None else canonical(dict(self.parameters))
        row.update(seq=seq, prev_hash=prev_hash)
        row["hash"] = record_hash(row)
        return row


def record_hash(row: Mapping[str, Any]) -> str:
    """SHA-256 (hex) of the hashed fields of a stored row (details/parameters as stored text)."""
    content = canonical([row[name] for name in HASHED])
    return hashlib.sha256(content.encode("utf-8")).hexdigest()


def other_type(records: Sequence[Mapping[str, Any]], type_key: str | None = None) -> list[int]:
    """The positions of the records whose type key is not the chain's: ``type_key`` (the
    valve's now) or, without one, the newest record's. A valve's type key never changes, so
    such a record is of another valve recorded under the same serial number (emulated valves
    of two runs of the program that both took serial 1001)."""
    if not records:
        return []
    wanted = type_key or str(records[-1]["type_key"])
    return [i for i, record in enumerate(records) if str(record["type_key"]) != wanted]

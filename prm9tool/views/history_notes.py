"""What the user did to a valve online, recorded in its history at once with its meaning.

Online, values taken into the document from a file, from a history record or from an accepted
tuning go to the valve as they are set (active, not stored yet). The history recorded them
only when they were stored, as "online-edits" (or never, when the user did not store them):
now each such act is a record of its own, naming what was done and every value it changed
(raw, from → to). The record holds no parameter set: the valve's stored set is unchanged
until it is stored (Valve → Store, or going offline), which is recorded as before.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

Raw = int | str


def changes(before: Mapping[str, Raw], after: Mapping[str, Raw]) -> dict[str, list[Raw]]:
    """``{mnemonic: [from, to]}`` of the values that differ."""
    return {mn: [before[mn], value] for mn, value in after.items() if before.get(mn) != value}


def record_online_change(
    connection: Any,
    operation: str,
    before: Mapping[str, Raw],
    after: Mapping[str, Raw],
    **details: object,
) -> None:
    """Record ``operation`` (``compare-apply``, ``history-restore``, ``tuning-accepted``) on
    the valve online, with the values it changed and ``details``; nothing offline (no valve
    was changed) or when nothing changed."""
    changed = changes(before, after)
    record = getattr(connection, "record", None)
    if not changed or record is None or not getattr(connection, "is_online", False):
        return
    record(operation, "ok", None, {**details, "changes": changed, "stored": False})

"""A comparison as data: the JSON ``--diff --json`` prints and ``prm9tool.diff`` returns
(docs/compare.md). No Qt."""

from __future__ import annotations

from typing import Any

from prm9tool.compare.model import Comparison, Row

__all__ = ["as_json", "value"]


def value(row: Row, column: int) -> str | None:
    """The row's value on side ``column`` as the file writes it (None: that side lacks it)."""
    return None if row.values[column] is None else row.display(column)


def as_json(comparison: Comparison) -> dict[str, Any]:
    """The comparison as the JSON ``--diff --json`` prints (docs/compare.md)."""
    first, second = comparison.sides
    return {
        "a": {"source": first.label, "type_key": str(first.type_key)},
        "b": {"source": second.label, "type_key": str(second.type_key)},
        "equal": comparison.equal,
        "changed": len(comparison.changed),
        "missing": len(comparison.missing),
        "not_on_valve": [
            {
                "mnemonic": row.mnemonic,
                "not_on": [name for name, lacks in zip("ab", row.absent, strict=True) if lacks],
                "a": value(row, 0),
                "b": value(row, 1),
                "unit": row.parameter.unit,
            }
            for row in comparison.not_on_valve
        ],
        "warnings": [str(w) for w in comparison.warnings()],
        "differences": [
            {
                "mnemonic": row.mnemonic,
                "a": value(row, 0),
                "b": value(row, 1),
                "unit": row.parameter.unit,
            }
            for row in comparison.rows
            if row.differs
        ],
    }

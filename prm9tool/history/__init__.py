"""The history: every operation on a valve's parameter set, in a tamper-evident database.

SQLAlchemy 2 over SQLite (default, in the user data dir) or PostgreSQL (a line of stations),
the schema versioned with Alembic (``migrations/``), a hash chain per valve. No Qt.
"""

from __future__ import annotations

from typing import Any

__all__ = ["decoded", "records"]


def records(serial: int, url: str | None = None) -> list[dict[str, Any]]:
    """Every record of the valve ``serial``, oldest first, as ``--history SERIAL --json``
    lists them (``details`` decoded). ``url``: the database (SQLAlchemy URL; default: the
    setting, else SQLite in the user data dir). Raises HistoryError when it cannot be read."""
    from prm9tool.history.recorder import Recorder

    recorder = Recorder(url)
    try:
        return decoded(recorder.store().records(serial))
    finally:
        recorder.close()


def decoded(rows: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """The store's rows with their ``details`` JSON text decoded (in place; returned)."""
    import json

    for row in rows:
        row["details"] = json.loads(row["details"])
    return rows

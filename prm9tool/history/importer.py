"""Import the backup files prm9tool wrote before the history existed, each exactly once.

Every ``<user data dir>/backups/<serial>/*.prm`` becomes a ``backup`` record of that valve,
dated by the file's modification time; the imported file's path is remembered in the same
transaction, so a second import (or two stations importing at once) adds nothing twice.
The files stay where they are. No Qt.
"""

from __future__ import annotations

import socket
from dataclasses import dataclass, field
from datetime import UTC, datetime
from pathlib import Path
from types import SimpleNamespace
from typing import Any

from sqlalchemy import Connection, func, insert, select

from prm9tool.errors import FileFormatError
from prm9tool.files.prmfile import read_file
from prm9tool.history.recorder import make_entry
from prm9tool.history.schema import ImportedSource
from prm9tool.history.store import HistoryStore
from prm9tool.paths import user_data_dir


@dataclass
class ImportResult:
    """What an import did."""

    imported: list[Path] = field(default_factory=list)
    skipped: int = 0
    problems: list[tuple[Path, str]] = field(default_factory=list)


def import_backups(
    store: HistoryStore, folder: Path | None = None, skip: Path | None = None
) -> ImportResult:
    """Import every backup file under ``folder`` (default: the user data dir's backups);
    ``skip``: a file the caller records itself (the backup just written), left out."""
    root = folder or user_data_dir() / "backups"
    result = ImportResult()
    files = sorted(root.glob("*/*.prm"), key=_age) if root.is_dir() else []
    skipped = None if skip is None else source_name(skip)
    for path in files:
        source = source_name(path)
        if source == skipped or store.imported(source):
            result.skipped += 1
            continue
        try:
            _import_one(store, path, source)
        except _AlreadyImportedError:  # another station or process was quicker
            result.skipped += 1
            continue
        except (FileFormatError, OSError) as exc:
            result.problems.append((path, str(exc)))
            continue
        result.imported.append(path)
    return result


def _age(path: Path) -> tuple[float, str]:
    return (path.stat().st_mtime, path.name)


class _AlreadyImportedError(Exception):
    """The file was imported meanwhile (the transaction is rolled back)."""


def _import_one(store: HistoryStore, path: Path, source: str) -> None:
    contents = read_file(path)
    serial = contents.serial if contents.serial is not None else int(path.parent.name)
    info = SimpleNamespace(
        type_key=str(contents.type_key), serial=serial, firmware=contents.firmware or "",
        device_id="file",
    )  # fmt: skip
    entry = make_entry(info, "backup", "ok", contents.values, {"imported_from": source})
    entry.recorded_at = datetime.fromtimestamp(path.stat().st_mtime, UTC).isoformat(
        timespec="microseconds"
    )

    def mark(conn: Connection, record_id: int) -> Any:
        query = select(func.count()).where(ImportedSource.source == source)
        if conn.execute(query).scalar_one():
            raise _AlreadyImportedError  # rolls the record back with it
        mark_imported(conn, source, record_id)

    store.append(entry, mark)


def source_name(path: Path) -> str:
    """How an imported file is remembered: station and absolute path (stations share one
    database, and their paths may be alike)."""
    return f"{socket.gethostname()}:{path.resolve()}"


def mark_imported(conn: Connection, source: str, record_id: int) -> None:
    """Remember ``source`` as imported into record ``record_id`` (in the caller's transaction;
    a source remembered already keeps its first record)."""
    query = select(func.count()).where(ImportedSource.source == source)
    if not conn.execute(query).scalar_one():
        conn.execute(insert(ImportedSource).values(source=source, record_id=record_id))

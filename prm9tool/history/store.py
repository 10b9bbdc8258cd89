"""The history database: open (and migrate) it, append records to their chain, list, check.

One :class:`HistoryStore` per database URL (``sqlite:///…`` or ``postgresql+psycopg://…``).
Writers never lose a record: on SQLite every write transaction starts with ``BEGIN
IMMEDIATE`` (one writer at a time, the others wait up to 30 s); on PostgreSQL a transaction
takes an advisory lock per valve; and the unique (serial, seq) constraint is the last guard (a
writer that loses a race retries with the new head). Every database failure becomes a
:class:`~prm9tool.errors.HistoryError` that says what is wrong; the database is never
"repaired" or recreated behind the user's back. No Qt.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from sqlalchemy import Connection, bindparam, create_engine, event, func, insert, select, text
from sqlalchemy.engine import Engine, make_url
from sqlalchemy.exc import DBAPIError, IntegrityError, SQLAlchemyError

from prm9tool.errors import HistoryError
from prm9tool.history.chain import GENESIS, Entry, record_hash
from prm9tool.history.schema import ImportedSource, RecordRow

SCHEMA_HEAD = "0001_records"  # the newest migration (tests check it is the scripts' head)
MIGRATIONS = Path(__file__).with_name("migrations")
_SUMMARY = (
    RecordRow.id, RecordRow.serial, RecordRow.seq, RecordRow.recorded_at, RecordRow.type_key,
    RecordRow.firmware, RecordRow.link, RecordRow.device_id, RecordRow.program_version,
    RecordRow.os_user, RecordRow.host, RecordRow.operation, RecordRow.outcome,
    RecordRow.failed_step, RecordRow.details, RecordRow.hash,
)  # fmt: skip


_INSERT = insert(RecordRow)  # one statement, compiled once (recording is on the upload's path)
_HEAD = (
    select(RecordRow.seq, RecordRow.hash)
    .where(RecordRow.serial == bindparam("serial"))
    .order_by(RecordRow.seq.desc())
    .limit(1)
)


@dataclass(frozen=True)
class Broken:
    """A record where a valve's chain breaks, and why."""

    record_id: int
    serial: int
    seq: int
    reason: str

    def __str__(self) -> str:
        return f"record {self.record_id} (valve {self.serial}, #{self.seq}): {self.reason}"


class HistoryStore:
    """A history database, migrated to this program's schema on opening."""

    def __init__(self, url: str) -> None:
        self.url = url
        self.shown_url = shown_url(url)
        self.dialect = make_url(url).get_backend_name()
        self.engine = _engine(url, self.dialect)
        try:
            self._guard(self._migrate)
        except HistoryError:
            self.engine.dispose()
            raise

    def close(self) -> None:
        """Release the database connections."""
        self.engine.dispose()

    def __enter__(self) -> HistoryStore:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    # --- writing --------------------------------------------------------------------------
    def append(
        self, entry: Entry, also: Callable[[Connection, int], None] | None = None
    ) -> dict[str, Any]:
        """Put ``entry`` at the end of its valve's chain; returns the stored row (with id).

        ``also(connection, record_id)`` runs in the same transaction (the import marks its
        source file there). Retries when another writer took the same place meanwhile.
        """
        for _attempt in range(50):
            try:
                return self._guard(lambda: self._append(entry, also))
            except _RacedError:
                time.sleep(0.01)
        raise HistoryError(f"{self.shown_url}: too many writers at once, the record was not added")

    def _append(
        self, entry: Entry, also: Callable[[Connection, int], None] | None
    ) -> dict[str, Any]:
        try:
            with self.engine.begin() as conn:
                if self.dialect == "postgresql":
                    conn.execute(text("SELECT pg_advisory_xact_lock(:k)"), {"k": entry.serial})
                head = conn.execute(_HEAD, {"serial": entry.serial}).first()
                row = entry.columns(head.seq + 1, head.hash) if head else entry.columns(1, GENESIS)
                result = conn.execute(_INSERT, row)
                key = result.inserted_primary_key
                assert key is not None  # an INSERT of one row always has one
                row["id"] = int(key[0])
                if also is not None:
                    also(conn, row["id"])
                return row
        except IntegrityError as exc:
            raise _RacedError from exc

    # --- reading --------------------------------------------------------------------------
    def records(self, serial: int) -> list[dict[str, Any]]:
        """The valve's records, oldest first, without their parameter sets (fast listing)."""
        query = select(*_SUMMARY).where(RecordRow.serial == serial).order_by(RecordRow.seq)
        return self._guard(lambda: self._rows(query))

    def record(self, record_id: int) -> dict[str, Any] | None:
        """One whole record (with ``details`` and ``parameters`` as stored JSON text)."""
        query = select(RecordRow.__table__).where(RecordRow.id == record_id)
        rows = self._guard(lambda: self._rows(query))
        return rows[0] if rows else None

    def serials(self) -> list[int]:
        """Every valve that has records."""
        query = select(RecordRow.serial).distinct().order_by(RecordRow.serial)
        return [row["serial"] for row in self._guard(lambda: self._rows(query))]

    def count(self) -> int:
        """How many records there are (all valves)."""
        query = select(func.count()).select_from(RecordRow)
        return int(self._guard(lambda: self._scalar(query)))

    def imported(self, source: str) -> bool:
        """True when that backup file was imported already."""
        query = select(func.count()).where(ImportedSource.source == source)
        return bool(self._guard(lambda: self._scalar(query)))

    def check(self) -> list[Broken]:
        """Verify every valve's chain; the first broken record of each broken chain."""
        return [b for serial in self.serials() if (b := self.check_valve(serial)) is not None]

    def check_valve(self, serial: int) -> Broken | None:
        """The first record where this valve's chain breaks (None: intact)."""
        query = select(RecordRow.__table__).where(RecordRow.serial == serial)
        rows = self._guard(lambda: self._rows(query.order_by(RecordRow.seq)))
        previous = GENESIS
        for expected, row in enumerate(rows, start=1):
            problem = _problem(row, expected, previous)
            if problem:
                return Broken(row["id"], serial, row["seq"], problem)
            previous = row["hash"]
        return None

    # --- internals ------------------------------------------------------------------------
    def _rows(self, query: Any) -> list[dict[str, Any]]:
        with self.engine.connect() as conn:
            result = conn.execute(query)
            keys = list(result.keys())
            return [dict(zip(keys, row, strict=True)) for row in result]  # 2x Row._mapping

    def _scalar(self, query: Any) -> Any:
        with self.engine.connect() as conn:
            return conn.execute(query).scalar_one()

    def _guard(self, work: Callable[[], Any]) -> Any:
        try:
            return work()
        except _RacedError:
            raise
        except HistoryError:
            raise
        except SQLAlchemyError as exc:
            raise _translated(self.shown_url, exc) from exc

    def _migrate(self) -> None:
        with self.engine.begin() as conn:
            if self.dialect == "postgresql":  # stations starting at once migrate one by one
                conn.execute(text("SELECT pg_advisory_xact_lock(4711000017)"))
            current = _current_revision(conn)
            if current == SCHEMA_HEAD:
                return
            _upgrade(conn, current, self.shown_url)


class _RacedError(Exception):
    """Another writer took the same place in the chain: try again."""


def _problem(row: dict[str, Any], expected: int, previous: str) -> str | None:
    if row["seq"] != expected:
        return f"record #{expected} is missing before it (deleted?)"
    if row["prev_hash"] != previous:
        return "it does not follow the valve's previous record (a record was changed or removed)"
    if record_hash(row) != row["hash"]:
        return "its content was changed after it was written (the hash does not match)"
    return None


def shown_url(url: str) -> str:
    """The database as a message names it: the password hidden, an SQLite file's path as the
    user wrote it (SQLAlchemy's rendering %-escapes it: ``sqlite:///C%3A%5Cusers%5C…``)."""
    parsed = make_url(url)
    if parsed.get_backend_name() == "sqlite" and parsed.database and not parsed.query:
        return f"{parsed.drivername}:///{parsed.database}"
    return parsed.render_as_string(hide_password=True)


def _engine(url: str, dialect: str) -> Engine:
    if dialect != "sqlite":
        return create_engine(url, pool_pre_ping=True, connect_args={"connect_timeout": 5})
    database = make_url(url).database
    if database and database != ":memory:":
        Path(database).parent.mkdir(parents=True, exist_ok=True)
    engine = create_engine(url, connect_args={"timeout": 30})

    @event.listens_for(engine, "connect")
    def _autocommit(dbapi_connection: Any, _record: Any) -> None:
        dbapi_connection.isolation_level = None  # SQLAlchemy emits BEGIN itself (below)
        # write-ahead log: one fsync per record (synchronous=FULL keeps every committed record
        # on power loss), readers never block the writer
        dbapi_connection.execute("PRAGMA journal_mode=WAL")
        dbapi_connection.execute("PRAGMA synchronous=FULL")

    @event.listens_for(engine, "begin")
    def _begin(conn: Connection) -> None:
        conn.exec_driver_sql("BEGIN IMMEDIATE")  # one writer at a time, no upgrade deadlocks

    return engine


def _current_revision(conn: Connection) -> str | None:
    from alembic.runtime.migration import MigrationContext

    return MigrationContext.configure(conn).get_current_revision()


def _upgrade(conn: Connection, current: str | None, shown: str) -> None:
    from alembic import command
    from alembic.config import Config
    from alembic.script import ScriptDirectory

    config = Config()
    config.set_main_option("script_location", str(MIGRATIONS))
    config.attributes["connection"] = conn
    known = {script.revision for script in ScriptDirectory.from_config(config).walk_revisions()}
    if current is not None and current not in known:
        raise HistoryError(
            f"the history database {shown} was written by a newer prm9tool (schema "
            f"{current}; this prm9tool knows up to {SCHEMA_HEAD}): update prm9tool. "
            "The database was not changed.",
            "newer",
        )
    command.upgrade(config, "head")


def _translated(shown: str, exc: SQLAlchemyError) -> HistoryError:
    detail = str(exc.orig) if isinstance(exc, DBAPIError) else str(exc)
    detail = detail.strip().splitlines()[0] if detail.strip() else type(exc).__name__
    lowered = detail.lower()
    if "not a database" in lowered or "malformed" in lowered:
        return HistoryError(
            f"the history database {shown} is damaged ({detail}). prm9tool leaves it as it "
            "is: move it aside (prm9tool then starts a new one) or restore it from a copy",
            "corrupt",
        )
    if "disk is full" in lowered or "no space" in lowered:
        return HistoryError(
            f"the history database {shown} cannot grow: the disk is full ({detail})", "full"
        )
    return HistoryError(f"the history database {shown} cannot be reached: {detail}")

"""The history's tables (SQLAlchemy 2 declarative); the migrations create exactly these."""

from __future__ import annotations

from sqlalchemy import BigInteger, Integer, String, Text, UniqueConstraint
from sqlalchemy.orm import DeclarativeBase, Mapped, mapped_column


class Base(DeclarativeBase):
    """Declarative base of the history tables."""


class RecordRow(Base):
    """One operation on one valve; never updated or deleted (triggers refuse it)."""

    __tablename__ = "records"
    __table_args__ = (UniqueConstraint("serial", "seq", name="uq_records_serial_seq"),)

    id: Mapped[int] = mapped_column(Integer, primary_key=True, autoincrement=True)
    serial: Mapped[int] = mapped_column(BigInteger, nullable=False)
    seq: Mapped[int] = mapped_column(Integer, nullable=False)  # 1, 2, … per valve
    recorded_at: Mapped[str] = mapped_column(String(40), nullable=False)  # ISO 8601, UTC
    type_key: Mapped[str] = mapped_column(String(64), nullable=False)
    firmware: Mapped[str] = mapped_column(String(64), nullable=False)
    link: Mapped[str] = mapped_column(String(32), nullable=False)
    device_id: Mapped[str] = mapped_column(String(255), nullable=False)
    program_version: Mapped[str] = mapped_column(String(32), nullable=False)
    os_user: Mapped[str] = mapped_column(String(128), nullable=False)
    host: Mapped[str] = mapped_column(String(255), nullable=False)
    operation: Mapped[str] = mapped_column(String(32), nullable=False)
    outcome: Mapped[str] = mapped_column(String(32), nullable=False)
    failed_step: Mapped[str | None] = mapped_column(String(32), nullable=True)
    details: Mapped[str] = mapped_column(Text, nullable=False)  # canonical JSON
    parameters: Mapped[str | None] = mapped_column(Text, nullable=True)  # canonical JSON
    prev_hash: Mapped[str] = mapped_column(String(64), nullable=False)
    hash: Mapped[str] = mapped_column(String(64), nullable=False)


class ImportedSource(Base):
    """A backup file already imported into the history (so it is imported once)."""

    __tablename__ = "imported_sources"

    source: Mapped[str] = mapped_column(String(1024), primary_key=True)
    record_id: Mapped[int] = mapped_column(Integer, nullable=False)

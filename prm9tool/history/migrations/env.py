"""Alembic environment: runs on the connection prm9tool hands over (never from alembic.ini)."""

from __future__ import annotations

from alembic import context

from prm9tool.history.schema import Base

connection = context.config.attributes["connection"]
context.configure(connection=connection, target_metadata=Base.metadata)
with context.begin_transaction():
    context.run_migrations()

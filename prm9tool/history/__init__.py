"""The history: every operation on a valve's parameter set, in a tamper-evident database.

SQLAlchemy 2 over SQLite (default, in the user data dir) or PostgreSQL (a line of stations),
the schema versioned with Alembic (``migrations/``), a hash chain per valve. No Qt.
"""

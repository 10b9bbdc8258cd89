"""Which history database to use: ``--history-db``, ``PRM9TOOL_HISTORY_DB``, the setting, or
SQLite in the user data dir (docs/history.md). One answer for the GUI and the command line."""

from __future__ import annotations

import json
import os
from pathlib import Path

from prm9tool.paths import user_data_dir

SETTINGS_FILE = "history.json"  # {"url": "postgresql+psycopg://…", "unreachable": "refuse"}
POLICIES = ("ask", "refuse", "queue")


def settings_path() -> Path:
    """The history setting's file (shared by the GUI and ``--batch`` on one station)."""
    return user_data_dir() / SETTINGS_FILE


def _settings() -> dict[str, str]:
    try:
        data = json.loads(settings_path().read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return {}
    return {k: v for k, v in data.items() if isinstance(v, str)} if isinstance(data, dict) else {}


def default_url() -> str:
    """SQLite in the user data dir: nothing to install, works offline."""
    return f"sqlite:///{user_data_dir() / 'history.sqlite3'}"


def database_url(explicit: str | None = None) -> str:
    """The database URL: ``explicit`` (``--history-db``), then the environment, the setting,
    the default. A bare path means a SQLite file."""
    url = explicit or os.environ.get("PRM9TOOL_HISTORY_DB") or _settings().get("url")
    if not url:
        return default_url()
    return url if "://" in url else f"sqlite:///{Path(url).expanduser().resolve()}"


def unreachable_policy(explicit: str | None = None, default: str = "ask") -> str:
    """What to do when the database cannot be reached before an upload: ``ask`` the user,
    ``refuse`` the upload, or ``queue`` the record locally and upload."""
    policy = explicit or _settings().get("unreachable") or default
    return policy if policy in POLICIES else default


def save_settings(url: str | None, unreachable: str) -> None:
    """Write the setting (None: the default SQLite database)."""
    from prm9tool.files.atomicfile import atomic_write

    data = {"unreachable": unreachable} | ({"url": url} if url else {})
    path = settings_path()
    path.parent.mkdir(parents=True, exist_ok=True)
    atomic_write(path, (json.dumps(data, indent=2) + "\n").encode("utf-8"), backup=False)


def queue_path() -> Path:
    """Records waiting for an unreachable database (one JSON object a line)."""
    return user_data_dir() / "history-queue.jsonl"

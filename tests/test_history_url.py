"""How the history's messages name an SQLite database: its path as the user wrote it.

On Windows the path is ``C:\\Users\\…`` and SQLAlchemy's URL rendering %-escapes the colon,
the backslashes and every letter outside ASCII (``sqlite:///C%3A%5Cusers%5CJi%C5%99%C3%AD…``);
on Linux the same happens to a folder with a colon, a percent sign or a Czech name.
"""

from __future__ import annotations

from prm9tool.history.store import HistoryStore, shown_url


def test_an_sqlite_path_is_shown_as_written(tmp_path):
    folder = tmp_path / "Jiří: 100 %"
    folder.mkdir()
    url = f"sqlite:///{folder / 'h.sqlite3'}"
    with HistoryStore(url) as store:
        assert store.shown_url == url


def test_a_windows_path_is_shown_as_written():
    assert shown_url(r"sqlite:///C:\Users\Jiří\AppData\Local\prm9tool\history.sqlite3") == (
        r"sqlite:///C:\Users\Jiří\AppData\Local\prm9tool\history.sqlite3"
    )


def test_a_server_password_stays_hidden():
    assert shown_url("postgresql+psycopg://ing:secret@db.local/prm9") == (
        "postgresql+psycopg://ing:***@db.local/prm9"
    )

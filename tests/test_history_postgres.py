"""The history on a real PostgreSQL server: chains, tampering, refusal of a newer schema, an
unreachable server, and four --batch processes writing at once.

Skips (with the reason) only where no PostgreSQL can be started; under CI=true it fails instead.
"""

from __future__ import annotations

import itertools
import json
import os
import subprocess
import sys

import pytest
from support.history_support import fill
from support.pg_cluster import NoPostgresError, cluster, new_database

from prm9tool.errors import HistoryError
from prm9tool.history.store import HistoryStore

_names = itertools.count()


@pytest.fixture(scope="module")
def server():
    try:
        with cluster() as url:
            yield url
    except NoPostgresError as exc:
        if os.environ.get("CI", "").lower() == "true":
            pytest.fail(f"CI must run the PostgreSQL tests: {exc}")
        pytest.skip(f"no PostgreSQL server can be started here: {exc}")


@pytest.fixture
def url(server):
    return new_database(server, f"history_{os.getpid()}_{next(_names)}")


def sql(url, *statements):
    import psycopg

    with psycopg.connect(url.replace("postgresql+psycopg", "postgresql"), autocommit=True) as conn:
        for statement in statements:
            conn.execute(statement)


def test_chains_append_only_and_tampering_found(url):
    import psycopg

    with HistoryStore(url) as store:
        fill(store, 4711, 3)
        assert [r["seq"] for r in store.records(4711)] == [1, 2, 3] and store.check() == []
        with pytest.raises(psycopg.errors.RaiseException, match="append-only"):
            sql(url, "UPDATE records SET outcome = 'x'")
        sql(url, "ALTER TABLE records DISABLE TRIGGER records_no_change",
            "UPDATE records SET firmware = 'V9' WHERE seq = 2")  # fmt: skip
        (broken,) = store.check()
    assert broken.seq == 2 and "content was changed" in broken.reason


def test_a_newer_schema_is_refused(url):
    HistoryStore(url).close()
    sql(url, "UPDATE alembic_version SET version_num = '0099_future'")
    with pytest.raises(HistoryError, match="written by a newer prm9tool") as caught:
        HistoryStore(url)
    assert caught.value.kind == "newer"


def test_an_unreachable_server_is_a_clear_error(server):
    dead = server.rsplit(":", 1)[0] + ":1/postgres"
    with pytest.raises(HistoryError, match="cannot be reached") as caught:
        HistoryStore(dead)
    assert caught.value.kind == "unreachable" and "127.0.0.1" in str(caught.value)


def test_four_batch_processes_at_once_lose_and_duplicate_nothing(url, tmp_path):
    from test_batch_cli import E04, tuned_file

    source = tuned_file(tmp_path)
    processes = []
    for number in range(4):  # four stations, each with three valves; serial 4711 on every one
        data = tmp_path / f"station{number}"
        env = dict(os.environ, PRM9TOOL_DATA_DIR=str(data))
        valves = [f"{E04}:4711", f"{E04}:{5000 + number}", f"{E04}:{6000 + number}"]
        command = [sys.executable, "-m", "prm9tool", "--batch", str(source), "--history-db", url,
                   "--report", str(tmp_path / f"r{number}.json")]  # fmt: skip
        for valve in valves:
            command += ["--emulator", valve]
        processes.append(subprocess.Popen(command, env=env, cwd=tmp_path,
                                          stderr=subprocess.PIPE, text=True))  # fmt: skip
    for process in processes:
        _out, err = process.communicate(timeout=180)
        assert process.returncode == 0, err
    for number in range(4):
        report = json.loads((tmp_path / f"r{number}.json").read_text())
        assert {v["history"] for v in report["valves"]} == {"recorded"}
    with HistoryStore(url) as store:
        assert store.count() == 4 * 3 * 2  # a backup and an upload per valve
        assert [r["seq"] for r in store.records(4711)] == list(range(1, 9))
        assert store.check() == []
        assert len({r["hash"] for r in store.records(4711)}) == 8

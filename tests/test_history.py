"""The history database on SQLite: chains, tampering found, bad databases, the local queue."""

from __future__ import annotations

import json
import sqlite3
from pathlib import Path

import pytest
from sqlalchemy import event
from support.history_support import Valve, factory_values, fill

from prm9tool.cli.main import main
from prm9tool.errors import ExitCode, HistoryError
from prm9tool.files.prmfile import read_file
from prm9tool.history.config import database_url
from prm9tool.history.export import export_record
from prm9tool.history.importer import import_backups
from prm9tool.history.recorder import Recorder, make_entry
from prm9tool.history.store import MIGRATIONS, SCHEMA_HEAD, HistoryStore
from prm9tool.paths import user_data_dir


@pytest.fixture(autouse=True)
def _stores_closed(monkeypatch: pytest.MonkeyPatch):
    """Every history a test opened is closed when it ends: Python 3.13 warns about an SQLite
    connection left to the garbage collector (ResourceWarning: unclosed database), which the
    suite's warnings-are-errors turns into an error in whichever test runs next."""
    opened: list[HistoryStore] = []
    original = HistoryStore.__init__

    def opening(self: HistoryStore, url: str) -> None:
        opened.append(self)
        original(self, url)

    monkeypatch.setattr(HistoryStore, "__init__", opening)
    yield
    for store in opened:
        if hasattr(store, "engine"):
            store.close()


def sqlite_url(tmp_path: Path, name: str = "h.sqlite3") -> str:
    return f"sqlite:///{tmp_path / name}"


def raw_sql(url: str, *statements: str) -> None:
    """Change the file behind prm9tool's back (what a tamperer would do)."""
    db = sqlite3.connect(url.removeprefix("sqlite:///"))
    try:
        for statement in statements:
            db.execute(statement)
        db.commit()
    finally:
        db.close()


def test_records_chain_per_valve_and_list_without_parameters(tmp_path):
    store = HistoryStore(sqlite_url(tmp_path))
    fill(store, 4711, 3)
    fill(store, 4712, 2)
    records = store.records(4711)
    assert [r["seq"] for r in records] == [1, 2, 3]
    assert "parameters" not in records[0]
    first, second = (store.record(r["id"]) for r in records[:2])
    assert first["prev_hash"] == "0" * 64 and second["prev_hash"] == first["hash"]
    assert json.loads(second["parameters"])["LIMTA"] == 1001
    assert store.serials() == [4711, 4712] and store.count() == 5 and store.check() == []


def test_the_migration_scripts_head_is_the_schema_the_program_expects():
    from alembic.config import Config
    from alembic.script import ScriptDirectory

    config = Config()
    config.set_main_option("script_location", str(MIGRATIONS))
    assert ScriptDirectory.from_config(config).get_current_head() == SCHEMA_HEAD


def test_records_cannot_be_updated_or_deleted_through_the_database(tmp_path):
    url = sqlite_url(tmp_path)
    fill(HistoryStore(url), 1, 1)
    with pytest.raises(sqlite3.IntegrityError, match="append-only"):
        raw_sql(url, "UPDATE records SET outcome = 'x'")
    with pytest.raises(sqlite3.IntegrityError, match="append-only"):
        raw_sql(url, "DELETE FROM records")


@pytest.mark.parametrize(
    ("tamper", "reason"),
    [
        ("UPDATE records SET parameters = replace(parameters, '1001', '1999') WHERE id = 2",
         "its content was changed"),
        ("DELETE FROM records WHERE id = 2", "record #2 is missing before it"),
        ("UPDATE records SET prev_hash = hash WHERE id = 3", "does not follow"),
    ],
)  # fmt: skip
def test_check_names_the_first_broken_record(tmp_path, capsys, tamper, reason):
    url = sqlite_url(tmp_path)
    fill(HistoryStore(url), 4711, 4)
    fill(HistoryStore(url), 4712, 2)
    raw_sql(url, "DROP TRIGGER records_no_update", "DROP TRIGGER records_no_delete", tamper)
    assert main(["--history-check", "--history-db", url]) == ExitCode.VERIFY_FAILED
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "valve 4711" in err[0] and reason in err[0]
    assert err[0].startswith("prm9tool: broken chain: record ")


def test_check_of_an_intact_history_exits_0(tmp_path, capsys):
    url = sqlite_url(tmp_path)
    fill(HistoryStore(url), 5, 3)
    assert main(["--history-check", "--history-db", url]) == ExitCode.OK
    assert "3 records of 1 valves: every hash chain intact" in capsys.readouterr().out


def test_a_corrupt_database_is_named_left_untouched_and_records_are_queued(tmp_path):
    path = tmp_path / "h.sqlite3"
    path.write_bytes(b"this is not SQLite " * 300)
    before = path.read_bytes()
    recorder = Recorder(f"sqlite:///{path}", tmp_path / "queue.jsonl")
    problem = recorder.problem()
    assert problem is not None and problem.kind == "corrupt"
    assert f"the history database sqlite:///{path} is damaged" in str(problem)
    assert "move it aside" in str(problem)
    assert recorder.record(Valve(9), "upload", "ok", factory_values()) == "queued"
    assert path.read_bytes() == before
    path.rename(tmp_path / "damaged.sqlite3")  # what the message tells the user to do
    assert Recorder(f"sqlite:///{path}", tmp_path / "queue.jsonl").store().count() == 1


def test_a_database_of_a_newer_program_is_refused_and_not_changed(tmp_path, capsys):
    url = sqlite_url(tmp_path)
    with HistoryStore(url) as store:
        fill(store, 1, 1)
    raw_sql(url, "UPDATE alembic_version SET version_num = '0042_from_the_future'")
    before = dump(url)  # the content (SQLite may fold its write-ahead log into the file)
    with pytest.raises(HistoryError, match="written by a newer prm9tool") as caught:
        HistoryStore(url)
    assert caught.value.kind == "newer" and "0042_from_the_future" in str(caught.value)
    assert main(["--history", "1", "--history-db", url]) == ExitCode.HISTORY
    assert "update prm9tool" in capsys.readouterr().err
    assert dump(url) == before


def dump(url: str) -> list[str]:
    db = sqlite3.connect(url.removeprefix("sqlite:///"))
    try:
        return list(db.iterdump())
    finally:
        db.close()


def test_a_full_disk_is_reported_and_the_record_waits_in_the_queue(tmp_path):
    url = sqlite_url(tmp_path)
    store = HistoryStore(url)
    fill(store, 3, 1)
    store.engine.dispose()

    @event.listens_for(store.engine, "connect")
    def _full(dbapi_connection, _record):  # the file may not grow any more
        pages = dbapi_connection.execute("PRAGMA page_count").fetchone()[0]
        dbapi_connection.execute(f"PRAGMA max_page_count = {pages}")

    recorder = Recorder(url, tmp_path / "queue.jsonl")
    recorder._store = store
    values = factory_values()
    big = {"padding": "x" * 20000}
    assert recorder.record(Valve(3), "upload", "ok", values, big) == "queued"
    with pytest.raises(HistoryError, match="the disk is full") as caught:
        store.append(recorder_entry(big))
    assert caught.value.kind == "full"
    assert recorder.queued() == 1
    again = Recorder(url, tmp_path / "queue.jsonl")  # disk space again: the queue is flushed
    assert again.store().count() == 2 and again.queued() == 0 and again.store().check() == []


def recorder_entry(details):
    from prm9tool.history.recorder import make_entry

    return make_entry(Valve(3), "upload", "ok", factory_values(), details)


def test_an_unreachable_queue_folder_too_is_an_error_not_a_silent_loss(tmp_path):
    path = tmp_path / "h.sqlite3"
    path.write_bytes(b"garbage " * 1000)
    blocker = tmp_path / "file"
    blocker.write_text("x")
    recorder = Recorder(f"sqlite:///{path}", blocker / "queue.jsonl")
    with pytest.raises(HistoryError, match="could not be kept in"):
        recorder.record(Valve(1), "store", "ok", None)


def test_backups_are_imported_once_and_exported_back_identical(tmp_path, capsys):
    from prm9tool.files.backup import write_backup

    values = factory_values() | {"LIMTA": 1234}
    backup = write_backup("PRM9-06.3Z11/30-24E04S02-CA", 77, "V1", values)
    assert main(["--history-import"]) == ExitCode.OK  # opening the history imported it already
    assert "0 backup files imported, 1 imported before" in capsys.readouterr().out
    store = HistoryStore(database_url())
    assert import_backups(store).skipped == 1
    store.close()
    (user_data_dir() / "backups" / "77" / "extra.prm").write_bytes(backup.read_bytes())
    assert main(["--history-import"]) == ExitCode.OK
    assert "1 backup files imported, 1 imported before" in capsys.readouterr().out
    assert main(["--history-import"]) == ExitCode.OK
    assert "0 backup files imported, 2 imported before" in capsys.readouterr().out
    store = HistoryStore(database_url())
    record = store.records(77)[0]
    assert record["operation"] == "backup"
    assert str(backup.resolve()) in json.loads(record["details"])["imported_from"]
    assert main(["--history-export", str(record["id"]), "-o", str(tmp_path / "r.prm")]) == 0
    assert read_file(tmp_path / "r.prm").values == read_file(backup).values
    export_record(store.record(record["id"]), tmp_path / "r.csv")
    lines = (tmp_path / "r.csv").read_text(encoding="utf-8").splitlines()
    assert lines[1] == "mnemonic,value,unit,description"
    assert any(line.startswith("LIMTA,1234,mA,") for line in lines)
    assert user_data_dir() in backup.parents


def test_history_lists_a_valve_as_text_and_json(tmp_path, capsys):
    url = sqlite_url(tmp_path)
    fill(HistoryStore(url), 4711, 2)
    assert main(["--history", "4711", "--history-db", url]) == ExitCode.OK
    lines = capsys.readouterr().out.splitlines()
    assert len(lines) == 2 and lines[0].split("\t")[2:5] == [
        "upload",
        "ok",
        "PRM9-06.3Z11/30-24E04S02-CA",
    ]
    assert main(["--history", "4711", "--json", "--history-db", url]) == ExitCode.OK
    data = json.loads(capsys.readouterr().out)
    assert data["serial"] == 4711 and [r["seq"] for r in data["records"]] == [1, 2]
    assert {"os_user", "host", "program_version", "firmware", "link", "device_id"} <= set(
        data["records"][0]
    )


_WRITER = """
import sys
from support.history_support import fill
from prm9tool.history.store import HistoryStore
store = HistoryStore(sys.argv[1])
fill(store, 4711, 40)
fill(store, int(sys.argv[2]), 10)
"""


def test_two_writers_on_one_sqlite_file_lose_and_duplicate_nothing(tmp_path):
    import os
    import subprocess
    import sys

    url = sqlite_url(tmp_path)
    HistoryStore(url).close()  # created once; the writers append at the same time
    env = dict(os.environ, PYTHONPATH=str(Path(__file__).parent))
    writers = [
        subprocess.Popen([sys.executable, "-c", _WRITER, url, str(serial)], env=env)
        for serial in (1, 2)
    ]
    assert [w.wait(timeout=120) for w in writers] == [0, 0]
    store = HistoryStore(url)
    assert [r["seq"] for r in store.records(4711)] == list(range(1, 81))
    assert store.count() == 100 and store.check() == []


def test_batch_upload_records_backup_and_upload_with_outcome(tmp_path):
    from test_batch_cli import E04, run, tuned_file

    source = tuned_file(tmp_path)
    result = run(tmp_path, "--batch", str(source), "--emulator", f"{E04}:31", "--report", "r.json")
    assert result.returncode == 0, result.stderr
    report = json.loads((tmp_path / "r.json").read_text())
    assert report["valves"][0]["history"] == "recorded"
    listing = run(tmp_path, "--history", "31", "--json")
    records = json.loads(listing.stdout)["records"]
    assert [(r["operation"], r["outcome"]) for r in records] == [
        ("backup", "ok"), ("batch-upload", "ok")]  # fmt: skip
    assert records[1]["details"]["file"] == str(source)
    assert records[1]["link"] == "emulator"


def test_batch_refuses_to_upload_when_the_history_is_damaged_unless_told_to_queue(tmp_path):
    from test_batch_cli import E04, run, tuned_file

    source = tuned_file(tmp_path)
    damaged = tmp_path / "damaged.sqlite3"
    damaged.write_bytes(b"not a database " * 100)
    db = ["--history-db", f"sqlite:///{damaged}"]
    refused = run(tmp_path, "--batch", str(source), "--emulator", f"{E04}:32", *db)
    assert refused.returncode == ExitCode.HISTORY
    assert "is damaged" in refused.stderr and "nothing was uploaded" in refused.stderr
    queued = run(tmp_path, "--batch", str(source), "--emulator", f"{E04}:32", *db,
                 "--history-unreachable", "queue")  # fmt: skip
    assert queued.returncode == 0, queued.stderr
    lines = (tmp_path / "data" / "history-queue.jsonl").read_text().splitlines()
    assert [json.loads(line)["operation"] for line in lines] == ["backup", "batch-upload"]
    assert run(tmp_path, "--history", "32").returncode == 0  # the default database is fine


def test_old_backups_become_records_the_first_time_a_history_is_opened(tmp_path):
    from prm9tool.files.backup import write_backup

    write_backup("PRM9-06.3Z11/30-24E04S02-CA", 78, "V1", factory_values())
    recorder = Recorder(sqlite_url(tmp_path), tmp_path / "q.jsonl")
    assert [r["operation"] for r in recorder.store().records(78)] == ["backup"]
    recorder.record(Valve(78), "backup", "ok", factory_values(), {"file": "elsewhere.prm"})
    recorder.close()
    again = Recorder(sqlite_url(tmp_path), tmp_path / "q.jsonl")
    assert again.store().count() == 2  # not imported twice
    assert main(["--history-import", "--history-db", sqlite_url(tmp_path)]) == ExitCode.OK
    assert again.store().count() == 2


def test_a_characterization_is_recorded_with_its_verdict_and_figures(tmp_path, capsys):
    from test_characterize_cli import E02, FAST
    from test_characterize_cli import run as characterize

    from prm9tool.device import emulated_valves

    try:
        code = characterize(tmp_path, FAST, 7201, "--json", str(tmp_path / "r.json"))
    finally:
        emulated_valves.forget_emulated_valves()
    assert code == ExitCode.OK
    capsys.readouterr()
    assert main(["--history", "7201", "--json"]) == ExitCode.OK
    (record,) = json.loads(capsys.readouterr().out)["records"]
    assert (record["operation"], record["outcome"]) == ("characterization", "passed")
    # the valve's device ID and link, not the report's sentence on how it was measured
    assert (record["link"], record["device_id"]) == ("emulator", f"emulator:{E02}:7201")
    figures = {f["name"]: f for f in record["details"]["figures"]}
    assert figures["bode_bandwidth_hz"]["passed"] is True
    assert record["details"]["profile"] == "fast test"


def test_a_gui_characterization_online_is_recorded_and_offline_not(tmp_path):
    from types import SimpleNamespace

    from prm9tool.characterize.rig import RigInfo
    from prm9tool.characterize.run import Characterization
    from prm9tool.service.history import run_with_history

    recorder = Recorder(sqlite_url(tmp_path), tmp_path / "q.jsonl")
    info = RigInfo("PRM9-06.3Z11/30-24E04S02-CA", 4713, "1.0.0", "emulator", 5000.0)
    result = Characterization(info, SimpleNamespace(name="p"), "2026-11-24", factory_values())

    from prm9tool.service.history import HistoryHook

    history = HistoryHook(recorder, lambda problem: None)
    connection = SimpleNamespace(history=history, is_online=False)
    run_with_history(connection, lambda: result)
    assert recorder.store().records(4713) == []
    connection.is_online = True
    assert run_with_history(connection, lambda: result) is result
    (record,) = recorder.store().records(4713)
    assert (record["operation"], record["outcome"]) == ("characterization", "passed")


def test_the_command_line_says_when_a_serial_holds_records_of_another_valve_type(tmp_path, capsys):
    """Issue 34 item 4: --history 1001 listed the E02 of one run and the E04 of the next as
    one valve."""
    url = sqlite_url(tmp_path)
    store = HistoryStore(url)
    e02 = "PRM9-06.3Z11/30-24E02S02-CA"
    store.append(make_entry(Valve(1001, e02), "download", "ok", factory_values(e02)))
    store.append(make_entry(Valve(1001), "download", "ok", factory_values()))
    store.close()
    assert main(["--history", "1001", "--history-db", url]) == ExitCode.OK
    err = capsys.readouterr().err
    assert "valve 1001: record 1 is of another type key than the newest record's (" in err

"""What the history costs: recording one upload, and listing a valve with 10 000 records.

1. An upload over the emulated USB link at the real link speed (one report per millisecond,
   as ``--batch`` runs it) against recording that upload (the whole parameter set, hash
   chained) into an open SQLite history: the target is ≤ 5 % of the upload's time.
2. Listing a valve that has 10 000 records (what Valve → History and ``--history`` read)
   against the bare sqlite3 module fetching the same rows: the target is ≤ 100 ms.
With ``--postgres`` both run on a throw-away PostgreSQL cluster as well (tests/support/pg_cluster.py).

    .venv/bin/python benchmarks/bench_history.py [--uploads 5] [--records 10000] [--postgres]
"""

from __future__ import annotations

import argparse
import os
import sqlite3
import statistics
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

from sqlalchemy import insert

from prm9tool.catalogue.typekey import TypeKey
from prm9tool.files.prmfile import PrmContents
from prm9tool.history.chain import GENESIS
from prm9tool.history.recorder import Recorder, make_entry
from prm9tool.history.schema import RecordRow
from prm9tool.history.store import HistoryStore

TYPE_KEY = "PRM9-06.3Z11/30-24E04S02-CA"


def _median_ms(runs: int, once: Callable[[], object]) -> float:
    once()  # warm-up
    samples = []
    for _ in range(runs):
        start = time.perf_counter()
        once()
        samples.append(time.perf_counter() - start)
    return 1000 * statistics.median(samples)


def upload_against_recording(url: str, uploads: int) -> None:
    """Median upload time over the paced link vs. median time to record it."""
    from prm9tool.device.factory import emulator_entries, open_session

    (entry,) = emulator_entries([f"{TYPE_KEY}:9901"])
    values = PrmContents.factory(TypeKey.parse(TYPE_KEY)).values
    recorder = Recorder(url, Path(tempfile.mkdtemp()) / "queue.jsonl")
    with open_session(entry, paced=False, link_paced=True) as session:
        info = session.info
        upload_ms = _median_ms(uploads, lambda: session.upload(values))
    record_ms = _median_ms(
        max(20, uploads), lambda: recorder.record(info, "upload", "ok", values, {"written": 80})
    )
    print(f"  upload over the paced USB link     {upload_ms:9.1f} ms  (median of {uploads})")
    print(f"  recording it into the history      {record_ms:9.2f} ms")
    print(f"  recording / upload                 {record_ms / upload_ms:9.2%}   (target ≤ 5 %)")
    recorder.close()


def _fill(store: HistoryStore, serial: int, count: int) -> None:
    """``count`` chained records in one transaction (the benchmark's set-up, not measured)."""
    values = PrmContents.factory(TypeKey.parse(TYPE_KEY)).values

    class Valve:
        type_key, firmware, device_id = TYPE_KEY, "V0.35.16", "usb:/dev/hidraw0"

    Valve.serial = serial  # type: ignore[attr-defined]
    rows, previous = [], GENESIS
    for seq in range(1, count + 1):
        row = make_entry(Valve, "upload", "ok", values | {"LIMTA": seq % 2000}).columns(
            seq, previous
        )
        rows.append(row)
        previous = row["hash"]
    with store.engine.begin() as conn:
        conn.execute(insert(RecordRow), rows)


def listing(url: str, count: int) -> None:
    """Median time to list a valve with ``count`` records (and the bare sqlite3 fetch)."""
    store = HistoryStore(url)
    _fill(store, 7777, count)
    _fill(store, 7778, 100)  # another valve beside it
    list_ms = _median_ms(5, lambda: store.records(7777))
    assert len(store.records(7777)) == count
    print(f"  listing {count} records (prm9tool)  {list_ms:9.1f} ms  (target ≤ 100 ms)")
    if url.startswith("sqlite:///"):
        db = sqlite3.connect(url.removeprefix("sqlite:///"))
        query = ("SELECT id, serial, seq, recorded_at, type_key, firmware, link, device_id, "
                 "program_version, os_user, host, operation, outcome, failed_step, details, hash "
                 "FROM records WHERE serial = 7777 ORDER BY seq")  # fmt: skip
        bare_ms = _median_ms(5, lambda: db.execute(query).fetchall())
        db.close()
        print(
            f"  the same rows, bare sqlite3        {bare_ms:9.1f} ms  (ratio {list_ms / bare_ms:.1f}x)"
        )
    store.close()


def main() -> int:
    """Run the benchmark."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--uploads", type=int, default=5)
    parser.add_argument("--records", type=int, default=10_000)
    parser.add_argument("--postgres", action="store_true")
    parser.add_argument("--quick", action="store_true", help="a smoke run: seconds, not figures")
    args = parser.parse_args()
    if args.quick:
        args.uploads, args.records = 1, 100
    folder = Path(tempfile.mkdtemp(prefix="prm9tool-bench-history-"))
    os.environ["PRM9TOOL_DATA_DIR"] = str(folder / "data")
    print("SQLite (the default history):")
    upload_against_recording(f"sqlite:///{folder / 'record.sqlite3'}", args.uploads)
    listing(f"sqlite:///{folder / 'list.sqlite3'}", args.records)
    if args.postgres:
        sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
        from support.pg_cluster import cluster, new_database

        with cluster() as server:
            print("PostgreSQL (throw-away cluster on 127.0.0.1):")
            upload_against_recording(new_database(server, "record"), args.uploads)
            listing(new_database(server, "listing"), args.records)
    return 0


if __name__ == "__main__":
    sys.exit(main())

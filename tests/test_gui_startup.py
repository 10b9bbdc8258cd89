"""Start-up (issue 34, item 22): what the window needs before it shows and before the valve's
values are live, and nothing more (benchmarks/bench_startup.py measures the times)."""

from __future__ import annotations

import os
import subprocess
import sys
import threading

from support.gui_support import E02_CA, go_online

from prm9tool.history import recorder as recorder_module
from prm9tool.history.recorder import Recorder

TIMEOUT = 20_000

# What the window does not need to come up: each costs 0.05–1 s to import.
HEAVY = (
    "scipy",  # tuning and characterization analyses
    "pyqtgraph",  # the oscilloscope and the tuning plots
    "sqlalchemy",  # the history database ...
    "alembic",  # ... and its migrations
    "prm9tool.history.store",
    "prm9tool.device.emulator",  # the emulated valve (opened in the worker, after showing)
    "can",  # python-can, canopen: a CAN bus
    "canopen",
)

CHILD = r"""
import sys
from prm9tool import app
from prm9tool.cli.main import build_parser

args = build_parser().parse_args(sys.argv[1:])
qapp = app.create_application()
window = app.create_window(args)
window.show()
qapp.processEvents()
for name in HEAVY:
    if name in sys.modules:
        print("imported", name)
print("shown", window.isVisible())
"""


def test_the_window_shows_without_importing_a_heavy_module(tmp_path):
    env = dict(os.environ, QT_QPA_PLATFORM="offscreen", XDG_CONFIG_HOME=str(tmp_path / "c"),
               PRM9TOOL_DATA_DIR=str(tmp_path / "data"))  # fmt: skip
    code = f"HEAVY = {HEAVY!r}\n{CHILD}"
    run = subprocess.run(
        [sys.executable, "-c", code, "--emulator", E02_CA],
        env=env, capture_output=True, text=True, timeout=120, check=False,
    )  # fmt: skip
    assert run.returncode == 0, run.stderr
    assert "shown True" in run.stdout, run.stdout + run.stderr
    assert [line for line in run.stdout.splitlines() if line.startswith("imported")] == []


def test_the_valve_values_are_live_while_the_history_database_still_opens(
    qtbot, window, monkeypatch
):
    """The first record opens the database (SQLAlchemy, Alembic, the migration check: ~0.3 s);
    the download that goes online waited for it before the values reached the window."""
    opened = threading.Event()
    release = threading.Event()
    store = Recorder.store

    def slow_store(self: Recorder) -> object:
        opened.set()
        assert release.wait(TIMEOUT / 1000)  # the database opens only when the test says so
        return store(self)

    monkeypatch.setattr(Recorder, "store", slow_store)
    recorder = Recorder()
    window.connection.set_recorder(recorder)
    try:
        go_online(qtbot, window, f"{E02_CA}:4741")
        qtbot.waitUntil(lambda: window.sync.active, timeout=TIMEOUT)
    finally:
        release.set()
    # the record is written after all, and nobody reads the history without it
    records = recorder.store().records(4741)
    assert [r["operation"] for r in records] == ["download"]


def test_a_record_taken_for_later_is_written_before_any_read(tmp_path):
    from types import SimpleNamespace

    url = f"sqlite:///{tmp_path / 'h.db'}"
    info = SimpleNamespace(serial=4742, type_key=E02_CA, firmware="1", device_id="emulator:x")
    writer = Recorder(url, tmp_path / "queue.jsonl")
    writer.add_later(recorder_module.make_entry(info, "download", "ok", {"DTAMP": 1}))
    assert writer.store().records(4742)[0]["operation"] == "download"  # a read writes it first
    assert writer.write_later() == "recorded"
    assert len(writer.store().records(4742)) == 1  # and only once


def test_closing_the_recorder_writes_what_it_took_for_later(tmp_path):
    from types import SimpleNamespace

    url = f"sqlite:///{tmp_path / 'h.db'}"
    info = SimpleNamespace(serial=4743, type_key=E02_CA, firmware="1", device_id="emulator:x")
    writer = Recorder(url, tmp_path / "queue.jsonl")
    writer.add_later(recorder_module.make_entry(info, "download", "ok", {"DTAMP": 1}))
    writer.close()
    assert [r["operation"] for r in Recorder(url).store().records(4743)] == ["download"]

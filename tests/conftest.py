"""Shared test set-up: offscreen Qt, hypothesis profiles, isolated user data."""

from __future__ import annotations

import os

import pytest
from hypothesis import HealthCheck, settings

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")

settings.register_profile(
    "ci", max_examples=2000, deadline=None, suppress_health_check=[HealthCheck.too_slow]
)
settings.register_profile("dev", max_examples=200, deadline=None)
settings.load_profile("ci" if os.environ.get("CI") else "dev")


def pytest_addoption(parser: pytest.Parser) -> None:
    parser.addoption(
        "--busy",
        type=int,
        default=int(os.environ.get("PRM9TOOL_TEST_BUSY", "0") or 0),
        metavar="N",
        help="run the tests on a busy machine: N busy-loop processes run for the whole session"
        " (also PRM9TOOL_TEST_BUSY=N)",
    )


@pytest.fixture(autouse=True, scope="session")
def _busy_machine(request: pytest.FixtureRequest):
    """``--busy N``: N processes that spin for the session, as other work on a shared PC does
    (issue 25 item 17: real-time tests must measure their own pace and adapt)."""
    import subprocess
    import sys

    count = int(request.config.getoption("--busy"))
    spinning = [subprocess.Popen([sys.executable, "-c", "while True: pass"]) for _ in range(count)]
    yield
    for process in spinning:
        process.kill()
        process.wait()


@pytest.fixture(autouse=True)
def _garbage_collected_on_the_main_thread():
    """Python's cycle collector runs on the main (GUI) thread only, after each test, as the
    program does it from a timer (prm9tool.app.collect_garbage_on_the_gui_thread): collected
    in a worker thread, a cycle holding Qt widgets can deadlock the GUI thread."""
    import gc

    gc.disable()
    yield
    gc.unfreeze()  # a test that ran app.run() froze its start-up objects (the program keeps them)
    _collected[0] += 1
    # the young generations after every test; everything every FULL_COLLECT_EVERY tests (a full
    # collection after each of 1500 tests doubled the run: 4 -> 9.6 min)
    gc.collect(2 if _collected[0] % FULL_COLLECT_EVERY == 0 else 1)


FULL_COLLECT_EVERY = 25
_collected = [0]


@pytest.fixture(autouse=True)
def _isolated_user_dirs(tmp_path_factory: pytest.TempPathFactory, monkeypatch: pytest.MonkeyPatch):
    """Keep emulator EEPROM images, backups and QSettings out of the real home directory."""
    base = tmp_path_factory.mktemp("userdata")
    monkeypatch.setenv("PRM9TOOL_DATA_DIR", str(base / "data"))
    monkeypatch.setenv("XDG_CONFIG_HOME", str(base / "config"))
    monkeypatch.setenv("XDG_DATA_HOME", str(base / "share"))
    # Windows (the Windows stage): platformdirs asks Windows for these folders, not the
    # environment's LOCALAPPDATA/APPDATA; its own override variables it honours
    monkeypatch.setenv("WIN_PD_OVERRIDE_APPDATA", str(base / "appdata"))
    monkeypatch.setenv("WIN_PD_OVERRIDE_LOCAL_APPDATA", str(base / "localappdata"))
    return base


@pytest.fixture
def data_dir(tmp_path, monkeypatch: pytest.MonkeyPatch):
    """The user data folder of this test (remembered type keys, backups, EEPROM images)."""
    folder = tmp_path / "data"
    monkeypatch.setenv("PRM9TOOL_DATA_DIR", str(folder))
    return folder


@pytest.fixture
def spools():
    """The spool catalogue, as shipped again after the test (which may load a spools.json)."""
    from prm9tool.catalogue.typekey import SPOOLS

    shipped = dict(SPOOLS)
    yield SPOOLS
    SPOOLS.clear()
    SPOOLS.update(shipped)


@pytest.fixture
def answers(monkeypatch: pytest.MonkeyPatch):
    """Every message box recorded and answered without blocking (``gui_support.Prompts``)."""
    from support.gui_support import record_prompts

    return record_prompts(monkeypatch)


@pytest.fixture
def window(qtbot, tmp_path, answers):
    """The main window offline on an E02 document, isolated settings, prompts recorded.

    A test module that needs another valve or the window online defines its own ``window``.
    """
    from support.gui_support import main_window

    with main_window(qtbot, tmp_path) as win:
        yield win

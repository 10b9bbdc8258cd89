"""docs/api.md runs: every fenced python block, in order, in one namespace, on an emulated
valve; what it prints is checked where the page says what it shows."""

from __future__ import annotations

import contextlib
import io
import re
from pathlib import Path

import pytest

import prm9tool
from prm9tool.cli.parser import build_parser
from prm9tool.device import emulated_valves

PAGE = Path(__file__).resolve().parents[1] / "docs" / "api.md"
BLOCK = re.compile(r"^```python\n(.*?)^```$", re.MULTILINE | re.DOTALL)


@pytest.fixture(autouse=True)
def _fresh_emulators():
    yield
    emulated_valves.forget_emulated_valves()


def blocks() -> list[str]:
    """The page's python blocks."""
    return BLOCK.findall(PAGE.read_text(encoding="utf-8"))


def test_the_page_has_examples_of_every_section():
    text = "\n".join(blocks())
    for call in ("connect(", "upload(", "download(", "capture(", "generator(", "restart(",
                 "characterize(", "history.records(", "diff(", "nmt(", "enable("):  # fmt: skip
        assert call in text


def test_every_python_block_runs(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    scope: dict = {"__name__": "__docs__"}
    out = io.StringIO()
    for number, code in enumerate(blocks(), 1):
        with contextlib.redirect_stdout(out):
            exec(compile(code, f"{PAGE.name} block {number}", "exec"), scope)
    shown = out.getvalue().splitlines()
    assert shown[0] == "PRM9-06.3Z11/30-24E02S02-CA 4711 1.0.0 emulator"
    assert "2400" in shown  # LIMTA's factory value
    assert any("LIMTA: 99999 mA is outside the allowed range" in line for line in shown)
    assert "True 43" in " ".join(shown)  # the upload stored all 43 parameters
    assert any("DEVICE_MODE_ACTIVE" in line for line in shown)
    assert "2000 0.0002" in shown
    assert scope["valve"].closed
    assert isinstance(scope["report"], dict)
    assert scope["result"].stored
    assert "[('LIMTA', 1800, 1700), ('DYNFREQ', 80, 120)]" in shown
    assert any(line.startswith("the file is for PRM9-06.3Z11/30-24E04S02-CA") for line in shown)
    assert any("confirm_hydraulics_off=True" in line for line in shown)
    assert "2400 2400" in shown  # restore_factory() restarted: the factory set is effective
    history = [line.split()[1:] for line in shown[-8:]]
    assert history == [
        [operation, "ok", "python", "API"]
        for operation in (
            "backup",
            "upload",
            "download",
            "store",
            "restore-factory",
            "restore-factory",
            "restart",
        )  # with restart, then only_reset=True
    ] + [["characterization", "passed", "python", "API"]]  # the end-of-line test is recorded


def test_the_help_page_names_only_what_the_api_has():
    from prm9tool.api.valve import Valve

    resources = PAGE.parents[1] / "resources" / "help"
    page = (resources / "scripting_en.html").read_text(encoding="utf-8")
    called = set(re.findall(r"prm9tool\.(\w+)\(", page))
    assert called >= {"connect", "read_prm", "list_devices"}
    assert all(hasattr(prm9tool, name) for name in called)
    methods = set(re.findall(r"valve\.(\w+)", page))
    assert methods >= {"upload", "capture", "info"}
    assert all(hasattr(Valve, name) for name in methods)
    for option in re.findall(r"(--[a-z-]+)", page):
        assert option in build_parser().format_help()
    for language in ("en", "de", "cs"):  # reachable from the main page in every language
        assert 'href="scripting_en.html"' in (resources / f"help_{language}.html").read_text(
            encoding="utf-8"
        )

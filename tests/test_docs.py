"""The repository's docs say what the program does (issue 14, items 13 and 16)."""

from __future__ import annotations

import re
import subprocess
from pathlib import Path

import pytest

from prm9tool import display
from prm9tool.catalogue.typekey import DEFAULT_EMULATOR_TYPE_KEY
from prm9tool.cli.main import build_parser
from prm9tool.device import factory

ROOT = Path(__file__).resolve().parent.parent


def _tracked_texts() -> list[Path]:
    """The repository's text files (git's list; outside a checkout every file but .venv)."""
    suffixes = {".py", ".md", ".html", ".toml", ".ts", ".txt", ".json", ".qrc", ""}
    try:
        listed = subprocess.run(
            ["git", "ls-files"], cwd=ROOT, capture_output=True, text=True, check=True
        ).stdout.split()
    except (OSError, subprocess.CalledProcessError):
        listed = [
            str(p.relative_to(ROOT))
            for p in ROOT.rglob("*")
            if p.is_file() and not {".venv", ".git"} & set(p.relative_to(ROOT).parts)
        ]
    return [ROOT / name for name in listed if Path(name).suffix in suffixes]


def test_one_default_emulator_type_key_everywhere():
    assert factory.DEFAULT_EMULATOR_TYPE == DEFAULT_EMULATOR_TYPE_KEY
    assert factory.parse_emulator_spec("", default_serial=3)[0] == DEFAULT_EMULATOR_TYPE_KEY
    help_text = " ".join(build_parser().format_help().split())
    assert f"without TYPEKEY {DEFAULT_EMULATOR_TYPE_KEY}" in help_text
    batch = (ROOT / "docs" / "batch.md").read_text(encoding="utf-8")
    assert f"without a value `{DEFAULT_EMULATOR_TYPE_KEY}`" in batch
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    assert f"without TYPEKEY it is `{DEFAULT_EMULATOR_TYPE_KEY}`" in readme
    for language in ("en", "de", "cs"):
        page = (ROOT / "resources" / "help" / f"help_{language}.html").read_text(encoding="utf-8")
        keys = set(re.findall(r"PRM9-[0-9][0-9A-Z./-]+", page))
        assert keys == {DEFAULT_EMULATOR_TYPE_KEY}, language


def test_the_repository_cites_the_manual_not_a_spec_it_does_not_hold():
    pattern = re.compile(r"SPEC §|SPEC\.md|SPEC decision|the brief\b")
    cited = [
        f"{path.relative_to(ROOT)}:{number}"
        for path in _tracked_texts()
        if path.is_file() and path.name != "test_docs.py"
        for number, line in enumerate(
            path.read_text(encoding="utf-8", errors="replace").splitlines(), 1
        )
        if pattern.search(line)
    ]
    assert cited == []


def test_the_readme_installs_the_x11_libraries_before_the_first_start():
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    install = readme.index("sudo apt-get install libxcb")
    assert install < readme.index(".venv/bin/prm9tool")
    line = readme[install : readme.index("\n", install)].split()
    assert set(display.X11_LIBRARIES.values()) <= set(line)


@pytest.mark.parametrize("option", ["--new", "--export-eds"])
def test_the_readme_says_dash_output_is_standard_output(option):
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    assert "`-o -` writes to standard output" in readme and f"`{option}`" in readme

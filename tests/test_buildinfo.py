"""Version and build information: ``--version`` and Help → About say which build this is."""

from __future__ import annotations

import platform
import subprocess
import sys
from pathlib import Path

import pytest

from prm9tool import __version__, buildinfo
from prm9tool.cli.main import main

ROOT = Path(__file__).resolve().parent.parent


def test_version_names_version_commit_python_and_qt(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["--version"]) == 0
    line = capsys.readouterr().out.strip()
    assert line.startswith(f"prm9tool {__version__} (commit ")
    assert f"Python {platform.python_version()}" in line
    assert "Qt 6." in line


def test_a_checkout_reports_its_git_commit() -> None:
    if not (ROOT / ".git").exists():
        pytest.skip("not a git checkout")
    head = subprocess.run(
        ["git", "-C", str(ROOT), "rev-parse", "HEAD"], capture_output=True, text=True, check=True
    ).stdout.strip()
    commit = buildinfo.build_info().commit
    assert head.startswith(commit.removesuffix("+dirty"))


def test_a_built_executable_reports_its_stamp(monkeypatch: pytest.MonkeyPatch) -> None:
    stamp = type(sys)("prm9tool._build_stamp")
    stamp.COMMIT, stamp.BUILT = "0123456789", "2026-11-26 05:00 UTC"  # type: ignore[attr-defined]
    monkeypatch.setitem(sys.modules, "prm9tool._build_stamp", stamp)
    monkeypatch.setattr(sys, "frozen", True, raising=False)
    info = buildinfo.build_info()
    assert (info.commit, info.built, info.frozen) == ("0123456789", "2026-11-26 05:00 UTC", True)
    assert info.line("6.11.3").endswith("Qt 6.11.3, single executable)")


def test_outside_a_checkout_the_commit_is_unknown(tmp_path: Path) -> None:
    assert buildinfo._git_commit(tmp_path) == "unknown"


def test_about_lists_the_commit_and_build(qapp: object) -> None:
    from prm9tool.views.help_dialog import versions

    rows = dict(versions())
    assert rows["commit"] == buildinfo.build_info().commit
    assert "built" in rows


def test_about_names_the_build_in_the_program_language(
    qapp: object, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The German About box read "built  unknown (single executable)"."""
    from prm9tool import i18n
    from prm9tool.views import help_dialog

    info = buildinfo.BuildInfo(
        version=__version__, commit="unknown", built="unknown", frozen=True, python="3"
    )
    monkeypatch.setattr(help_dialog, "build_info", lambda: info)
    i18n.set_language("de")
    try:
        rows = dict(help_dialog.versions())
        about = help_dialog.about_html("", "", "")
    finally:
        i18n.set_language("en")
    assert rows["Revision"] == "unbekannt"
    assert rows["Erstellt"] == "unbekannt (eigenständige Programmdatei)"
    assert "unknown" not in about and "single" not in about

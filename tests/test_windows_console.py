"""A Windows console or pipe: standard output in an ANSI code page (cp1252), not UTF-8.

``--new -o -`` writes a file's bytes to standard output; a *.prm file holds e.g. the unit Ω,
which cp1252 cannot encode (it crashed with UnicodeEncodeError on Windows). Runs on Linux with stdout forced to cp1252, and in the Windows stage under Wine
(tools/windows/ci.sh) as Windows itself gives it.
"""

from __future__ import annotations

import io
import os
import subprocess
import sys

import pytest

from prm9tool.cli.main import main

KEY = "PRM9-06.3Z11/30-24E02S02-CA"


def _cp1252_stdout(monkeypatch: pytest.MonkeyPatch) -> io.BytesIO:
    raw = io.BytesIO()
    monkeypatch.setattr(sys, "stdout", io.TextIOWrapper(raw, encoding="cp1252", newline="\r\n"))
    return raw


def test_new_to_a_cp1252_stdout_writes_the_files_bytes(tmp_path, monkeypatch):
    path = tmp_path / "v.prm"
    assert main(["--new", KEY, "-o", str(path)]) == 0
    assert "Ω".encode() in path.read_bytes()  # what cp1252 cannot encode
    raw = _cp1252_stdout(monkeypatch)
    assert main(["--new", KEY, "-o", "-"]) == 0
    assert raw.getvalue() == path.read_bytes()


def test_new_in_a_process_whose_stdout_is_cp1252(tmp_path):
    env = dict(os.environ, PYTHONIOENCODING="cp1252")
    done = subprocess.run(
        [sys.executable, "-m", "prm9tool", "--new", KEY, "-o", "-"],
        capture_output=True, env=env, cwd=tmp_path, timeout=120, check=False,
    )  # fmt: skip
    assert (done.returncode, done.stderr) == (0, b"")
    assert main(["--new", KEY, "-o", str(tmp_path / "v.prm")]) == 0
    assert done.stdout == (tmp_path / "v.prm").read_bytes()

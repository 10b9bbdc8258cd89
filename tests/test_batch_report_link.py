"""``--report`` onto a symbolic link is refused before any valve is touched, and the report is
never written through a link (issue 15, item 20)."""

from __future__ import annotations

import json
import os

import pytest
from test_batch_cli import E04, run, tuned_file

from prm9tool.cli.batch_report import write_report
from prm9tool.files.atomicfile import atomic_write

pytestmark = pytest.mark.skipif(os.name != "posix", reason="symbolic links as on POSIX")


def test_a_report_path_that_is_a_symbolic_link_is_refused_before_any_valve(tmp_path):
    source = tuned_file(tmp_path)
    precious = tmp_path / "precious.txt"
    precious.write_text("not a report\n")
    (tmp_path / "r.json").symlink_to(precious)
    result = run(tmp_path, "--batch", str(source), "--emulator", f"{E04}:21", "--report", "r.json")
    assert result.returncode == 2
    assert (
        "--report r.json: is a symbolic link; give the path of the report itself" in result.stderr
    )
    assert precious.read_text() == "not a report\n"
    assert (tmp_path / "r.json").is_symlink()
    assert not (tmp_path / "data" / "emulator").exists()  # no valve was touched


def test_a_dangling_symbolic_link_is_refused_too(tmp_path):
    source = tuned_file(tmp_path)
    (tmp_path / "r.json").symlink_to(tmp_path / "elsewhere" / "new.json")
    result = run(tmp_path, "--batch", str(source), "--emulator", f"{E04}:22", "--report", "r.json")
    assert result.returncode == 2 and "is a symbolic link" in result.stderr
    assert not (tmp_path / "elsewhere").exists()


def test_a_link_that_appears_during_the_run_is_replaced_not_followed(tmp_path):
    precious = tmp_path / "precious.txt"
    precious.write_text("not a report\n")
    link = tmp_path / "r.json"
    link.symlink_to(precious)
    write_report(str(link), "upload", "tuned.prm", 0, [])
    assert not link.is_symlink() and json.loads(link.read_text())["exit_code"] == 0
    assert precious.read_text() == "not a report\n"


def test_a_parameter_file_saved_through_a_link_still_replaces_the_target(tmp_path):
    target = tmp_path / "real.prm"
    target.write_bytes(b"old\n")
    link = tmp_path / "link.prm"
    link.symlink_to(target)
    atomic_write(link, b"new\n")
    assert link.is_symlink() and target.read_bytes() == b"new\n"
    assert (tmp_path / "real.prm.bak").read_bytes() == b"old\n"

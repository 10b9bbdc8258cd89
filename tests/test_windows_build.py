"""The Windows build's own defects, each seen when prm9tool was first built for Windows
(docs/executable.md, "Windows"): the one file's name, the icon's Pillow, the compiled kernel's
source under mingw-w64, the smoke test on a build without the compiled kernel."""

from __future__ import annotations

import shutil
import subprocess
import sys
import sysconfig
import tomllib
from pathlib import Path

import pytest
from packaging.markers import default_environment
from packaging.requirements import Requirement

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "tools"))

import build_executable  # noqa: E402
import smoke_executable  # noqa: E402


def test_the_one_file_is_named_exe_on_windows(monkeypatch):
    monkeypatch.setattr(sys, "platform", "win32")
    assert build_executable.onefile_target(Path("dist")) == Path("dist") / "prm9tool.exe"
    monkeypatch.setattr(sys, "platform", "linux")
    assert build_executable.onefile_target(Path("dist")) == Path("dist") / "prm9tool"


@pytest.mark.parametrize(
    ("platform", "needed"), [("win32", True), ("darwin", True), ("linux", False)]
)
def test_the_build_extra_brings_pillow_where_the_icon_needs_it(platform, needed):
    extra = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    requirements = [Requirement(r) for r in extra["project"]["optional-dependencies"]["build"]]
    environment = {**default_environment(), "sys_platform": platform, "extra": "build"}
    wanted = {
        r.name.lower() for r in requirements if not r.marker or r.marker.evaluate(environment)
    }
    assert ("pillow" in wanted) == needed
    assert "pyinstaller" in wanted


@pytest.mark.skipif(shutil.which("gcc") is None, reason="needs gcc (CI installs it)")
def test_the_kernel_source_compiles_with_signal_h_included(tmp_path):
    # mingw-w64's headers include <signal.h>, whose signal() clashed with a function of ours
    source = ROOT / "prm9tool" / "device" / "emulator" / "_ckernel.c"
    command = ["gcc", "-fsyntax-only", "-include", "signal.h",
               f"-I{sysconfig.get_paths()['include']}", str(source)]  # fmt: skip
    done = subprocess.run(command, capture_output=True, text=True, check=False, cwd=tmp_path)
    assert done.returncode == 0, done.stderr


@pytest.mark.skipif(sys.platform == "win32", reason="the stand-in program is a shell script")
@pytest.mark.parametrize(("windows", "kernel"), [(True, "python"), (False, None)])
def test_the_smoke_test_accepts_the_python_kernel_on_windows_only(
    tmp_path, monkeypatch, capsys, windows, kernel
):
    exe = tmp_path / "prm9tool"  # a build whose compiled kernel is missing (as it logs it)
    exe.write_text(
        '#!/bin/sh\n[ "$PRM9TOOL_EMULATOR_KERNEL" = compiled ] && exit 2\n'
        "echo 'emulator: compiled control loop unavailable (no module); using the Python one' >&2\n"
        'echo \'{"values": {"LIMTA": 2400}}\'\n',
        encoding="utf-8",
    )
    exe.chmod(0o755)
    monkeypatch.setattr(smoke_executable, "WINDOWS", windows)
    assert smoke_executable._kernel(exe, tmp_path, {"PATH": "/usr/bin:/bin"}) == kernel
    said = capsys.readouterr().out
    assert ("emulator kernel: python" in said) == windows


def test_the_smoke_test_knows_what_the_program_logs_without_its_compiled_kernel(
    monkeypatch, caplog
):
    from prm9tool.device.emulator import kernels

    monkeypatch.setattr(kernels, "compiled_unavailable", lambda: "no module _ckernel")
    with caplog.at_level("WARNING", logger=kernels.log.name):
        assert kernels.choose("")[0] == "python"
    assert smoke_executable.FALLBACK in caplog.text

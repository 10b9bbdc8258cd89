"""``prm9tool --new`` and ``--check`` as a user runs them: a subprocess, exit codes, output."""

from __future__ import annotations

import json
import os
import subprocess
import sys

import pytest

from prm9tool.cli.parser import SHORT_USAGE
from prm9tool.errors import ExitCode
from prm9tool.files.prmfile import read_file

KEY = "PRM9-06.3Z11/30-24E04S02-CA"
COIL_A = "PRM9-06.2Z51/30-24E02S02"


def prm9tool(*args: str, cwd=None, env=None) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "prm9tool", *args],
        capture_output=True,
        text=True,
        cwd=cwd,
        env=env,
        timeout=60,
        check=False,
    )


def test_new_writes_the_factory_defaults_and_check_accepts_them(tmp_path):
    path = tmp_path / "valve.prm"
    new = prm9tool("--new", KEY, "-o", str(path))
    assert (new.returncode, new.stdout) == (ExitCode.OK, "")
    assert new.stderr == f"{path}: factory defaults of {KEY}, 70 parameters\n"
    contents = read_file(path)
    assert str(contents.type_key) == KEY and contents.values["LIMTA"] == 2400
    check = prm9tool("--check", str(path))
    assert (check.returncode, check.stdout) == (ExitCode.OK, "")
    assert check.stderr == f"{path}: valid (0 warnings)\n"


def test_new_factory_defaults_of_a_one_coil_valve_are_clean(tmp_path):
    # One-coil valves default to 0…10 V (table 8-4), so --new prints no warning for them.
    path = tmp_path / "coil_a.prm"
    result = prm9tool("--new", COIL_A, "-o", str(path))
    assert result.returncode == ExitCode.OK
    assert result.stdout == ""
    assert "AINSETP = 6" in path.read_text(encoding="utf-8")
    assert prm9tool("--check", str(path)).returncode == ExitCode.OK


def test_new_to_standard_output(tmp_path):
    result = prm9tool("--new", KEY, "-o", "-")
    assert result.returncode == ExitCode.OK
    assert (
        result.stdout.startswith("# PRM9 valve parameters")
        and "\nchecksum = crc32:" in result.stdout
    )
    assert list(tmp_path.iterdir()) == []


def test_new_with_a_bad_type_key_names_the_wrong_part(tmp_path):
    path = tmp_path / "x.prm"
    result = prm9tool("--new", "PRM9-06.3Z99/30-24E02S02", "-o", str(path))
    assert result.returncode == ExitCode.USAGE
    assert result.stderr.startswith(
        "prm9tool: error: type key 'PRM9-06.3Z99/30-24E02S02': unknown spool '3Z99'"
    )
    assert not path.exists()


def test_new_never_overwrites_an_existing_file(tmp_path):
    path = tmp_path / "precious.prm"
    path.write_text("my work\n", encoding="utf-8")
    result = prm9tool("--new", KEY, "-o", str(path))
    assert result.returncode == ExitCode.USAGE
    assert (
        result.stderr == f"prm9tool: error: {path} already exists; --new never overwrites a file\n"
    )
    assert path.read_text(encoding="utf-8") == "my work\n"


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--new", KEY], "--new needs an output file: -o FILE.prm"),
        # argparse's words: the file tools are one mutually exclusive group (issue 28)
        (
            ["--new", KEY, "-o", "a.prm", "--check", "a.prm"],
            "argument --check: not allowed with argument --new",
        ),
    ],
)
def test_new_usage_errors(tmp_path, args, message):
    result = prm9tool(*args, cwd=tmp_path)
    assert result.returncode == ExitCode.USAGE
    refusal = f"prm9tool: error: {message}" + (
        " (or -o - for standard output)\n" if "-o FILE" in message else "\n"
    )
    # argparse's refusal after one short usage line (not 27); --new's own without a usage
    assert result.stderr in (refusal, f"{SHORT_USAGE}\n{refusal}")
    assert ("not allowed with" in message) == result.stderr.startswith(SHORT_USAGE)
    assert list(tmp_path.iterdir()) == []


def test_check_prints_every_problem_as_file_line_message_and_exits_3(tmp_path):
    path = tmp_path / "valve.prm"
    assert prm9tool("--new", KEY, "-o", str(path)).returncode == 0
    text = path.read_text(encoding="utf-8")
    text = text.replace("LIMTA = 2400", "LIMTA = lots").replace("DTAMP = 15", "DTAMP = 200")
    text = text.replace("NODEID = 10", "NODEID = 10\nNODEIDX = 3")
    path.write_text(text, encoding="utf-8")
    lines = text.split("\n")

    def at(start: str) -> int:
        return next(n for n, line in enumerate(lines, 1) if line.startswith(start))

    result = prm9tool("--check", str(path))
    assert result.returncode == ExitCode.INVALID_FILE
    assert result.stdout.splitlines() == [
        f"{path}:{at('LIMTA')}: LIMTA: 'lots' is not a number",
        f"{path}:{at('DTAMP')}: DTAMP: 200 % is outside the allowed range 0 … 100 %",
        f"{path}:{at('NODEIDX')}: warning: unknown parameter 'NODEIDX': kept and written back "
        "unchanged (did you mean NODEID?)",
        f"{path}:{at('checksum')}: warning: checksum does not match: the file was changed "
        "outside prm9tool (edited by hand?); saving it from prm9tool writes a new checksum",
    ]
    assert result.stderr == f"{path}: NOT valid (2 errors, 2 warnings)\n"


def test_check_accepts_a_file_with_warnings_only(tmp_path):
    path = tmp_path / "edited.prm"
    assert prm9tool("--new", KEY, "-o", str(path)).returncode == 0
    path.write_text(path.read_text().replace("LIMTA = 2400", "LIMTA = 2000"), encoding="utf-8")
    result = prm9tool("--check", str(path))
    assert result.returncode == ExitCode.OK
    assert result.stdout.count("warning: checksum does not match") == 1
    assert result.stderr == f"{path}: valid (1 warning)\n"


@pytest.mark.parametrize(
    ("content", "expected"),
    [
        (None, "{path}:0: cannot read the file: No such file or directory"),
        (
            b"\x89PNG\r\n\x1a\n\x00\x00",
            "{path}:1: byte 0x89 is not UTF-8 text: the file is corrupt",
        ),
        (b"", "{path}:0: the file is empty"),
    ],
)
def test_check_of_a_file_that_is_no_parameter_file_exits_3(tmp_path, content, expected):
    path = tmp_path / "thing.prm"
    if content is not None:
        path.write_bytes(content)
    result = prm9tool("--check", str(path))
    assert result.returncode == ExitCode.INVALID_FILE
    assert result.stdout.splitlines()[0] == expected.format(path=path)


def test_check_speaks_english_whatever_the_system_language(tmp_path):
    """Messages are translated only in the GUI: --check prints them as the docs quote them."""
    path = tmp_path / "valve.prm"
    assert prm9tool("--new", KEY, "-o", str(path)).returncode == 0
    text = path.read_text(encoding="utf-8").replace("LIMTA = 2400", "LIMTA = 2650")
    path.write_text(text, encoding="utf-8")
    line = next(n for n, entry in enumerate(text.split("\n"), 1) if entry.startswith("LIMTA"))
    bad_key = tmp_path / "bad_key.prm"
    bad_key.write_text(text.replace(KEY, "PRM9-06-3Z11/30-24E04S02-CA"), encoding="utf-8")
    german = {**os.environ, "LANG": "de_DE.UTF-8", "LANGUAGE": "de", "LC_ALL": "de_DE.UTF-8"}
    limta = prm9tool("--check", str(path), env=german)
    assert limta.stdout.splitlines()[0] == (
        f"{path}:{line}: LIMTA = 2650 mA is above the nominal coil current CURNORM = 2600 mA"
    )
    key = prm9tool("--check", str(bad_key), env=german)
    assert (
        "type key 'PRM9-06-3Z11/30-24E04S02-CA': expected '.' between the nominal size '06' "
        "and the spool, found '-'"
    ) in key.stdout
    assert limta.returncode == key.returncode == ExitCode.INVALID_FILE


def test_the_file_commands_never_load_the_qt_gui(tmp_path):
    """--new and --check must run on a production line without a display."""
    path = tmp_path / "valve.prm"
    script = (
        "import json, sys\n"
        "from prm9tool.cli.main import main\n"
        f"codes = [main(['--new', {KEY!r}, '-o', {str(path)!r}]), main(['--check', {str(path)!r}])]\n"
        "qt = sorted(m for m in sys.modules if m.startswith('PySide6'))\n"
        "print(json.dumps({'codes': codes, 'qt': qt}))\n"
    )
    result = subprocess.run(
        [sys.executable, "-c", script], capture_output=True, text=True, timeout=60, check=True
    )
    report = json.loads(result.stdout.splitlines()[-1])
    assert report["codes"] == [0, 0]
    assert not [m for m in report["qt"] if m.endswith(("QtGui", "QtWidgets"))]
    assert report["qt"] == []  # our decision: not even QtCore, so no Qt is needed at all

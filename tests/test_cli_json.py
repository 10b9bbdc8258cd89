"""``--json [OUT.json]`` means the same for every command that reports JSON (issue 28): alone it
prints, with a file name it writes that file and prints nothing, as ``--characterize`` does."""

from __future__ import annotations

import json

import pytest

from prm9tool.catalogue.typekey import TypeKey
from prm9tool.cli.main import main
from prm9tool.device import emulated_valves
from prm9tool.errors import ExitCode
from prm9tool.files.prmfile import PrmContents, write_file
from prm9tool.model.document import ParameterDocument

E04 = "PRM9-06.3Z11/30-24E04S02-CA"


@pytest.fixture(autouse=True)
def _fresh_emulators():
    yield
    emulated_valves.forget_emulated_valves()


def _prm(folder, name, **values):
    key = TypeKey.parse(E04)
    path = folder / name
    write_file(PrmContents(key, {**ParameterDocument(key).values, **values}), path, backup=False)
    return path


def _commands(tmp_path):
    a, b = _prm(tmp_path, "a.prm", LIMTA=1500), _prm(tmp_path, "b.prm")
    valve = ["--emulator", f"{E04}:7401"]
    return {
        "--diff": (["--diff", str(a), str(b)], ExitCode.VERIFY_FAILED, "differences"),
        "--get": ([*valve, "--get", "LIMTA"], ExitCode.OK, "values"),
        "--list-devices": (["--list-devices", *valve], ExitCode.OK, None),
        "--history": (["--history", "7401"], ExitCode.OK, "records"),
    }


@pytest.mark.parametrize("command", ["--diff", "--get", "--list-devices", "--history"])
def test_json_with_a_file_name_writes_that_file_and_alone_prints(command, tmp_path, capsys):
    args, code, key = _commands(tmp_path)[command]
    assert main([*args, "--json"]) == code
    printed = json.loads(capsys.readouterr().out)
    out = tmp_path / "out.json"
    assert main([*args, "--json", str(out)]) == code
    assert capsys.readouterr().out == ""
    written = json.loads(out.read_text(encoding="utf-8"))
    assert type(written) is type(printed)
    if key is not None:
        assert key in written and key in printed


def test_a_json_file_that_cannot_be_written_says_so(tmp_path, capsys):
    a, b = _prm(tmp_path, "a.prm", LIMTA=1500), _prm(tmp_path, "b.prm")
    out = tmp_path / "no" / "out.json"
    assert main(["--diff", str(a), str(b), "--json", str(out)]) == ExitCode.USAGE
    assert f"--json {out}: cannot write it" in capsys.readouterr().err

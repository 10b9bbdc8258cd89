"""``--get``/``--set [--store]`` and ``--list-devices --json`` for shell scripts: real
subprocesses with an emulated valve whose EEPROM image persists between them."""

from __future__ import annotations

import json
import os
import subprocess
from pathlib import Path

import pytest
from support.python_process import run_python

from prm9tool.catalogue import CATALOGUE
from prm9tool.cli.main import main
from prm9tool.device import emulated_valves
from prm9tool.errors import AbortCode, ExitCode, SdoAbortError

E02 = "PRM9-06.3Z11/30-24E02S02-CA"
VALVE = f"{E02}:21"


def run(tmp_path: Path, *args: str) -> subprocess.CompletedProcess:
    env = dict(os.environ, PRM9TOOL_DATA_DIR=str(tmp_path / "data"))
    return run_python("-m", "prm9tool", *args, env=env, cwd=tmp_path)


def test_set_store_then_get_in_another_process(tmp_path):
    done = run(tmp_path, "--emulator", VALVE, "--set", "LIMTA=1800", "DYNFREQ=120", "--store")
    assert done.returncode == ExitCode.OK, done.stderr
    assert done.stdout.splitlines() == ["LIMTA\t1800\tmA", "DYNFREQ\t120\tHz"]
    done = run(tmp_path, "--emulator", VALVE, "--get", "LIMTA", "DYNFREQ", "LIMTB", "--json")
    assert done.returncode == ExitCode.OK, done.stderr
    printed = json.loads(done.stdout)
    assert printed["values"] == {"LIMTA": 1800, "DYNFREQ": 120, "LIMTB": 2400}
    assert printed["units"] == {"LIMTA": "mA", "DYNFREQ": "Hz", "LIMTB": "mA"}
    assert printed["device"]["serial"] == 21 and printed["device"]["link"] == "emulator"
    assert printed["stored"] is False


def test_set_without_store_is_forgotten(tmp_path):
    assert run(tmp_path, "--emulator", VALVE, "--set", "LIMTA=1700").returncode == 0
    assert run(tmp_path, "--emulator", VALVE, "--get", "LIMTA").stdout == "LIMTA\t2400\tmA\n"


def test_a_value_out_of_range_writes_nothing(tmp_path):
    done = run(tmp_path, "--emulator", VALVE, "--set", "DYNFREQ=120", "LIMTA=99999", "--store")
    assert done.returncode == ExitCode.USAGE
    # the range the editors show: 0 … CURNORM (2600 mA on this valve), not the catalogue's 4000
    assert "LIMTA: 99999 mA is outside the allowed range 0 … 2600 mA; nothing was written" in (
        done.stderr
    )
    assert done.stdout == ""
    done = run(tmp_path, "--emulator", VALVE, "--get", "DYNFREQ", "--json")
    assert json.loads(done.stdout)["values"]["DYNFREQ"] != 120  # not even the valid first one


def test_a_value_above_the_valves_cap_writes_nothing(tmp_path):
    # LIMTA may not exceed the valve's CURNORM (2600 mA, manual table 7-14)
    done = run(tmp_path, "--emulator", VALVE, "--set", "DYNFREQ=120", "LIMTA=3000", "--store")
    assert done.returncode == ExitCode.USAGE
    assert "LIMTA = 3000 mA is above the nominal coil current CURNORM = 2600 mA" in done.stderr
    assert done.stderr.endswith("nothing was written\n")
    done = run(tmp_path, "--emulator", VALVE, "--get", "LIMTA", "DYNFREQ")
    assert done.stdout == "LIMTA\t2400\tmA\nDYNFREQ\t80\tHz\n"


def test_a_value_the_valve_refuses_is_exit_1_and_nothing_is_stored(monkeypatch, capsys):
    valve = emulated_valves.emulated_valve(E02, 21)  # the one --emulator opens in this process
    key, write = CATALOGUE["DTAMP"].key, valve.write_bytes

    def refuse_dither(index, subindex, data):
        if (index, subindex) == key:
            raise SdoAbortError(index, subindex, AbortCode.CANNOT_STORE_DEVICE_STATE)
        write(index, subindex, data)

    monkeypatch.setattr(valve, "write_bytes", refuse_dither)
    try:
        code = main(["--emulator", VALVE, "--set", "LIMTA=1800", "DTAMP=10", "--store"])
        assert code == ExitCode.VERIFY_FAILED
        assert "--set DTAMP: 0x6361/1: abort 0x08000022" in capsys.readouterr().err
        assert valve.read(*CATALOGUE["LIMTA"].key) == 1800  # written before, a working value
        stored = valve.firmware.nv.values
        assert stored.get("LIMTA", CATALOGUE["LIMTA"].default) == 2400  # nothing stored
    finally:
        emulated_valves.forget_emulated_valves()


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--get", "NOPE"], "NOPE: no such parameter in the catalogue"),
        (["--set", "LIMTA"], "--set LIMTA: write MNEMONIC=VALUE (LIMTA=1800)"),
        (["--set", "FWVER=2"], "--set FWVER: the parameter is read-only"),
    ],
)
def test_bad_mnemonics_and_assignments(tmp_path, args, message):
    done = run(tmp_path, "--emulator", VALVE, *args)
    assert done.returncode == ExitCode.USAGE
    assert message in done.stderr


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--store", "--emulator", VALVE], "--store belongs to --set"),
        (["--get", "LIMTA"], "--get works on one valve: give one --device ID or --emulator"),
        (["--get", "LIMTA", "--emulator", VALVE, "--batch", "x.prm"], "--get and --batch are"),
        (["--get", "LIMTA", "--emulator", VALVE, "--can-interface", "virtual"], "over USB"),
        (["--get", "LIMTA", "--emulator", VALVE, "--emulator", E02], "one valve"),
    ],
)
def test_usage_errors(capsys, args, message):
    assert main(args) == ExitCode.USAGE
    assert message in capsys.readouterr().err


def test_list_devices_json_is_what_list_devices_returns(tmp_path):
    done = run(tmp_path, "--list-devices", "--emulator", VALVE, "--json")
    assert done.returncode == ExitCode.OK, done.stderr
    code = (
        "import json, prm9tool; print(json.dumps([d.to_dict() for d in "
        f"prm9tool.list_devices(emulators=[{VALVE!r}])]))"
    )
    env = dict(os.environ, PRM9TOOL_DATA_DIR=str(tmp_path / "data"))
    listed = run_python("-c", code, env=env, cwd=tmp_path)
    assert json.loads(done.stdout) == json.loads(listed.stdout)
    (entry,) = json.loads(done.stdout)
    assert entry["device_id"] == f"emulator:{VALVE}" and entry["type_key"] == E02

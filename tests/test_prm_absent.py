"""Issue 25 item 19: a parameter is in a *.prm file with a value, or marked absent by the one
documented line (a CANopen download from a valve without the object, -CA keys only); --batch
reports every parameter it did not upload."""

from __future__ import annotations

import json
import re

import pytest

from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.cli.main import main
from prm9tool.device import emulated_valves, factory
from prm9tool.files.prmcheck import NOT_AVAILABLE_HINT
from prm9tool.files.prmfile import PrmContents, check_bytes, check_file

E04 = "PRM9-06.3Z11/30-24E04S02"
E04_CA = E04 + "-CA"


def _file_with(type_key: str, mnemonic: str, line: str) -> bytes:
    text = PrmContents.factory(TypeKey.parse(type_key)).to_text()
    edited, count = re.subn(rf"(?m)^{mnemonic} = .*$", line, text)
    assert count == 1
    return edited.encode()


def _messages(data: bytes) -> list[str]:
    return [f"{p.severity}: {p.message}" for p in check_bytes(data).problems]


def test_an_empty_value_is_an_error_on_a_valve_without_canopen():
    """Was: valid with a warning that the valve lacks the object over CANopen."""
    data = _file_with(E04, "POST1", "POST1 =")
    result = check_bytes(data)
    assert not result.valid
    assert "error: POST1: no value after '='" in _messages(data)


def test_an_empty_value_without_the_marker_is_an_error_and_says_how_to_mark_it():
    data = _file_with(E04_CA, "POST1", "POST1 =")
    assert not check_bytes(data).valid
    assert (
        "error: POST1: no value after '='; only a download over CANopen may leave a value out,"
        " marked with the comment '# not available over CANopen on the valve this was read"
        " from'" in _messages(data)
    )


def test_the_download_line_marks_a_parameter_absent_on_a_canopen_key():
    data = _file_with(E04_CA, "POST1", "POST1 =" + NOT_AVAILABLE_HINT)
    result = check_bytes(data)
    assert result.valid, _messages(data)
    assert result.contents is not None and "POST1" not in result.contents.values
    assert any("POST1 has no value" in m for m in _messages(data))


@pytest.mark.parametrize(
    ("type_key", "mnemonic"),
    [(E04, "POST1"), (E04_CA, "LIMTA")],  # no CANopen; an object of the manual every valve has
)
def test_the_marker_counts_only_where_a_download_could_have_written_it(type_key, mnemonic):
    data = _file_with(type_key, mnemonic, f"{mnemonic} =" + NOT_AVAILABLE_HINT)
    assert not check_bytes(data).valid
    assert any(m.startswith(f"error: {mnemonic}: no value after '='") for m in _messages(data))


def test_batch_reports_every_parameter_it_did_not_write(tmp_path, data_dir, capsys):
    """Was: `--batch` said ok with nothing skipped while the valve kept its old POST1."""
    assert not CATALOGUE["POST1"].address_from_manual
    path = tmp_path / "f.prm"
    path.write_bytes(_file_with(E04_CA, "POST1", "POST1 =" + NOT_AVAILABLE_HINT))
    assert check_file(path).valid
    spec = f"{E04_CA}:7"
    try:
        session = factory.open_session(factory.list_devices([spec])[-1])
        with session:
            session.write("POST1", 3)
        code = main(["--batch", str(path), "--emulator", spec, "--report", str(tmp_path / "r")])
        err = capsys.readouterr().err
        with factory.open_session(factory.list_devices([spec])[-1]) as session:
            kept = session.read("POST1")
    finally:
        emulated_valves.forget_emulated_valves()
    record = json.loads((tmp_path / "r").read_text(encoding="utf-8"))["valves"][0]
    assert code == 0 and record["result"] == "ok"
    assert record["absent_in_file"] == ["POST1"] and "POST1" in record["skipped"]
    assert (
        "marked absent in the file (the valve it was read from lacks them), not uploaded: POST1"
        in err
    )
    assert kept == 3  # the valve keeps what it held

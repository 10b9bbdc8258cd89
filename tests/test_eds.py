"""EDS export (CiA 306) and the generated object-dictionary table of docs/canopen.md."""

from __future__ import annotations

import configparser
import os
from pathlib import Path

import pytest
from eds_utils.core.file_io.read_eds import read_eds

from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.typekey import TypeKey, all_type_keys
from prm9tool.cli.main import main
from prm9tool.files.eds import export_eds, markdown_table, od_objects

E02 = "PRM9-06.3Z11/30-24E02S02-CA"
E04 = "PRM9-06.3Z11/30-24E04S02-CA"
DOC = Path(__file__).resolve().parent.parent / "docs" / "canopen.md"
BEGIN, END = (
    "<!-- BEGIN generated object dictionary -->",
    "<!-- END generated object dictionary -->",
)


def _parse(text: str) -> configparser.RawConfigParser:
    parser = configparser.RawConfigParser()
    parser.optionxform = str  # type: ignore[assignment,method-assign]
    parser.read_string(text)
    return parser


def test_export_writes_a_cia_306_file(tmp_path: Path):
    out = tmp_path / "valve.eds"
    assert main(["--export-eds", E04, "-o", str(out)]) == 0
    raw = out.read_bytes()
    assert raw.isascii() and b"\r\n" in raw
    eds = _parse(raw.decode("ascii"))
    assert eds["DeviceInfo"]["ProductName"] == E04
    assert eds["DeviceInfo"]["BaudRate_10"] == "0"  # table 7-1: 10 kbit/s not supported
    assert eds["MandatoryObjects"]["SupportedObjects"] == "3"
    assert eds["1800sub1"]["DefaultValue"] == "$NODEID+0x180"
    assert eds["1014"]["DefaultValue"] == "$NODEID+0x80"
    assert eds["1A01sub2"]["DefaultValue"] == "0x21000610"  # decision: after linearization
    assert (eds["6345sub1"]["LowLimit"], eds["6345sub1"]["HighLimit"]) == ("0", "16384")
    for sub in (2, 3):  # LIMTA/LIMTB: the valve refuses more than CURNORM (table 7-14)
        assert eds[f"2004sub{sub}"]["HighLimit"] == eds["2004sub1"]["DefaultValue"] == "2600"
    assert eds["6300sub0"]["DefaultValue"] == "1"  # sub-index 0 of a catalogue-only sub 1
    assert eds["6041"]["PDOMapping"] == "1" and eds["6345sub1"]["PDOMapping"] == "0"
    assert eds["2041"]["DefaultValue"] == E04


def test_every_catalogue_entry_of_the_variant_is_in_the_eds():
    variant = TypeKey.parse(E02).variant
    eds = _parse(export_eds(E02))
    for param in CATALOGUE.for_variant(variant):
        objects = {o.index: o for o in od_objects(variant)}
        section = (
            f"{param.index:04X}"
            if objects[param.index].kind.name == "VAR"
            else f"{param.index:04X}sub{param.subindex:X}"
        )
        assert eds[section]["DataType"] == f"0x{param.dtype.value:04X}", param.mnemonic
    # table 7-14: the external sensor objects are objects of all valves, an E02 -CA's too, and
    # table 7-13's PDO2 mappings (0x1601: one entry, 0x1A01: two) point at them on every -CA
    for section in ("2005sub1", "2005sub4", "2006sub9", "2007sub1", "2008", "2100sub1", "2100sub6"):
        assert section in eds, section
    assert (eds["1601sub0"]["DefaultValue"], eds["1601sub1"]["DefaultValue"]) == ("1", "0x21000210")
    assert [eds[f"1A01sub{sub}"]["DefaultValue"] for sub in range(3)] == [
        "2",
        "0x21000110",
        "0x21000610",
    ]


def test_export_to_stdout(capsys: pytest.CaptureFixture[str]):
    assert main(["--export-eds", E02]) == 0
    assert capsys.readouterr().out.startswith("[FileInfo]\n")


def test_dash_output_means_standard_output_as_for_new(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    assert main(["--export-eds", E02, "-o", "-"]) == 0
    assert capsys.readouterr().out.startswith("[FileInfo]\n")
    assert main(["--new", E02, "-o", "-"]) == 0
    assert "checksum = crc32:" in capsys.readouterr().out
    assert list(tmp_path.iterdir()) == []  # no file named '-'


def test_bad_type_key_is_refused_with_a_clear_message(tmp_path, capsys):
    out = tmp_path / "x.eds"
    assert main(["--export-eds", "PRM9-06.9Q99/30-24E02S02-CA", "-o", str(out)]) == 2
    assert "unknown spool '9Q99'" in capsys.readouterr().err
    assert not out.exists()


def test_valve_without_canopen_has_no_eds(tmp_path, capsys):
    assert main(["--export-eds", "PRM9-06.3Z11/30-24E02S02", "-o", str(tmp_path / "x")]) == 2
    assert capsys.readouterr().err == (
        "prm9tool: PRM9-06.3Z11/30-24E02S02 has no CANopen interface: an EDS exists only "
        "for -CA valves (e.g. PRM9-06.3Z11/30-24E02S02-CA)\n"
    )


def test_unwritable_output_is_reported(tmp_path, capsys):
    target = tmp_path / "missing" / "x.eds"
    assert main(["--export-eds", E02, "-o", str(target)]) == 2
    assert f"cannot write {target}" in capsys.readouterr().err
    assert list(tmp_path.iterdir()) == []


def test_docs_object_dictionary_table_is_current():
    """docs/canopen.md carries the table generated from the catalogue.

    Regenerate it with ``PRM9_UPDATE_DOCS=1 pytest tests/test_eds.py``.
    """
    text = DOC.read_text(encoding="utf-8")
    head, rest = text.split(BEGIN + "\n")
    _, tail = rest.split(END)
    current = head + BEGIN + "\n" + markdown_table() + END + tail
    if os.environ.get("PRM9_UPDATE_DOCS"):
        DOC.write_text(current, encoding="utf-8")
        return
    assert text == current, "docs/canopen.md is stale: run PRM9_UPDATE_DOCS=1 pytest " + __file__


def _one_type_key_per_variant() -> list[str]:
    keys: dict[object, str] = {}
    for key in all_type_keys():
        if key.canopen:
            keys.setdefault(key.variant, str(key))
    return sorted(keys.values())


@pytest.mark.parametrize("type_key", _one_type_key_per_variant())
def test_a_third_party_reader_takes_the_eds_and_every_mapping_points_into_it(type_key, tmp_path):
    """eds-utils reads the file as a naive ``key=value`` reader and looks each PDO mapping up."""
    path = tmp_path / "valve.eds"
    path.write_text(export_eds(type_key), encoding="ascii")
    eds, errors = read_eds(str(path))
    assert errors == []
    for line in path.read_text(encoding="ascii").splitlines():
        assert line.count("=") <= 1, line  # "0 = off" in a name breaks naive readers
    parsed = _parse(path.read_text(encoding="ascii"))
    for map_index in (0x1600, 0x1601, 0x1A00, 0x1A01):
        count = int(parsed[f"{map_index:04X}sub0"]["DefaultValue"], 0)
        for sub in range(1, count + 1):
            value = int(parsed[f"{map_index:04X}sub{sub:X}"]["DefaultValue"], 0)
            index, subindex = value >> 16, (value >> 8) & 0xFF
            assert index in eds.indexes, f"0x{map_index:04X}/{sub} maps 0x{index:04X}"
            target = parsed[f"{index:04X}sub{subindex:X}" if subindex else f"{index:04X}"]
            assert target["PDOMapping"] == "1"

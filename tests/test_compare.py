"""The comparison model and ``--diff``: what differs, what one side lacks, choices, exit codes."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from prm9tool.catalogue import CATALOGUE, Access
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.cli.main import main
from prm9tool.compare import Comparison, Side
from prm9tool.errors import ExitCode
from prm9tool.files.prmfile import PrmContents, write_file

E02 = "PRM9-06.3Z11/30-24E02S02"
E04 = "PRM9-06.3Z11/30-24E04S02-CA"


def side(type_key: str, label: str = "x", **changes: int) -> Side:
    contents = PrmContents.factory(TypeKey.parse(type_key))
    contents.values.update(changes)
    return Side(label, contents.type_key, contents.values)


def prm(tmp_path: Path, name: str, type_key: str = E04, **changes: int) -> Path:
    contents = PrmContents.factory(TypeKey.parse(type_key))
    contents.values.update(changes)
    write_file(contents, tmp_path / name)
    return tmp_path / name


def test_changed_rows_carry_both_values_in_display_units_and_the_counts():
    comparison = Comparison((side(E04, LIMTA=1500, DTAMP=1000), side(E04)))
    assert [row.mnemonic for row in comparison.changed] == ["LIMTA", "DTAMP"]
    limta = comparison.row("LIMTA")
    assert limta.display(0) == CATALOGUE["LIMTA"].format_display(1500)
    assert limta.display(1) == CATALOGUE["LIMTA"].format_display(limta.values[1])
    assert comparison.missing == [] and comparison.warnings() == []
    assert not comparison.equal
    assert Comparison((side(E04), side(E04))).equal


def test_other_variant_rows_are_missing_and_a_warning_names_the_type_keys():
    comparison = Comparison((side(E02, "file"), side(E04, "valve")))
    missing = {row.mnemonic for row in comparison.missing}
    e04_only = {
        p.mnemonic
        for p in CATALOGUE.file_parameters(TypeKey.parse(E04).variant)
        if not p.applies(TypeKey.parse(E02).variant)
    }
    assert missing == e04_only and missing
    assert all(row.values[0] is None for row in comparison.missing)
    texts = [str(w) for w in comparison.warnings()]
    assert texts[0] == f"The type keys differ: file is {E02}, valve is {E04}."
    assert f"{len(missing)} parameters that one side lacks are left out" in texts[1]
    with pytest.raises(ValueError, match="lacks this parameter"):
        comparison.choose(next(iter(missing)), 1)


def test_choices_apply_exactly_the_chosen_values_that_differ_on_the_target():
    comparison = Comparison((side(E04, LIMTA=1500, DTAMP=1000, AINSETP=5), side(E04)))
    comparison.choose("LIMTA", 0)  # take the document's value for the valve
    comparison.choose("DTAMP", 1)  # keep the valve's
    assert comparison.to_apply(1) == {"LIMTA": 1500}
    assert comparison.to_apply(0) == {"DTAMP": comparison.row("DTAMP").values[1]}
    comparison.choose("LIMTA", None)
    assert comparison.to_apply(1) == {}
    comparison.choose_all(0)
    assert set(comparison.to_apply(1)) == {"LIMTA", "DTAMP", "AINSETP"}


def test_filters_differences_block_and_access_level():
    comparison = Comparison((side(E04, LIMTA=1500, DTAMP=1000), side(E04)), Side.factory(
        TypeKey.parse(E04)))  # fmt: skip
    assert {r.mnemonic for r in comparison.filtered(differences_only=True)} == {"LIMTA", "DTAMP"}
    only = comparison.filtered(differences_only=True, mnemonics=["LIMTA", "LIMTB"])
    assert [r.mnemonic for r in only] == ["LIMTA"]
    basic = comparison.filtered(access=Access.BASIC)
    assert basic and all(r.parameter.access is Access.BASIC for r in basic)
    assert len(basic) < len(comparison.filtered())
    assert comparison.row("LIMTA").display(-1) == comparison.row("LIMTA").display(1)


def test_diff_two_files_prints_one_line_per_difference_and_exits_1(tmp_path, capsys):
    a = prm(tmp_path, "a.prm", LIMTA=1500)
    b = prm(tmp_path, "b.prm")
    assert main(["--diff", str(a), str(b)]) == ExitCode.VERIFY_FAILED
    limta = CATALOGUE["LIMTA"]
    default = limta.format_display(limta.default)
    assert capsys.readouterr().out == f"LIMTA\t{limta.format_display(1500)}\t{default}\tmA\n"
    assert main(["--diff", str(b), str(b)]) == ExitCode.OK
    assert capsys.readouterr().out == ""


def test_diff_json_names_sources_counts_and_missing_sides(tmp_path, capsys):
    a = prm(tmp_path, "a.prm", type_key=E02)
    b = prm(tmp_path, "b.prm", LIMTA=1500)
    assert main(["--diff", str(a), str(b), "--json"]) == ExitCode.VERIFY_FAILED
    data = json.loads(capsys.readouterr().out)
    assert data["a"] == {"source": str(a), "type_key": E02}
    assert data["equal"] is False and data["changed"] == 1 and data["missing"] > 0
    missing = [d for d in data["differences"] if d["a"] is None]
    assert len(missing) == data["missing"] and all(d["b"] is not None for d in missing)
    limta = CATALOGUE["LIMTA"]
    expected = {"mnemonic": "LIMTA", "a": limta.format_display(limta.default), "b": "1500",
                "unit": "mA"}  # fmt: skip
    assert [d for d in data["differences"] if d["mnemonic"] == "LIMTA"] == [expected]


def test_diff_invalid_file_exits_3_and_names_the_problem(tmp_path, capsys):
    good = prm(tmp_path, "good.prm")
    bad = tmp_path / "bad.prm"
    bad.write_text("format = prm9tool 1\ngarbage\n", encoding="utf-8")
    assert main(["--diff", str(bad), str(good)]) == ExitCode.INVALID_FILE
    err = capsys.readouterr().err
    assert f"{bad} is not a valid parameter file" in err and f"{bad}:2:" in err


def test_diff_with_a_valve_reads_it_and_records_the_download(tmp_path, capsys):
    a = prm(tmp_path, "a.prm", LIMTA=1500)
    assert main(["--diff", str(a), "--emulator", f"{E04}:7101"]) == ExitCode.VERIFY_FAILED
    assert capsys.readouterr().out.startswith("LIMTA\t")
    assert main(["--history", "7101", "--json"]) == ExitCode.OK
    records = json.loads(capsys.readouterr().out)["records"]
    assert [(r["operation"], r["details"]) for r in records] == [
        ("download", {"command": "--diff"})
    ]


def test_diff_with_no_such_valve_exits_4(tmp_path, capsys):
    a = prm(tmp_path, "a.prm")
    assert main(["--diff", str(a), "--device", "999999"]) == ExitCode.NO_DEVICE
    assert "prm9tool:" in capsys.readouterr().err


@pytest.mark.parametrize(
    ("args", "problem"),
    [
        (["--diff", "a.prm"], "add --device ID or --emulator"),
        (["--diff", "a.prm", "b.prm", "--emulator", E04], "leave out --device/--emulator"),
        (["--diff", "a.prm", "b.prm", "c.prm"], "compares two files"),
        (["--diff", "a.prm", "b.prm", "--batch", "x.prm"], "separate commands"),
        (["--json"], "--json [OUT.json] belongs to --diff, --history, --get/--set, --list-devices"),
    ],
)
def test_diff_usage_errors_exit_2(args, problem, capsys):
    assert main(args) == ExitCode.USAGE
    assert problem in capsys.readouterr().err


def test_the_chosen_values_come_from_the_side_chosen_per_row():
    """What two history records give to a document or valve outside the comparison."""
    comparison = Comparison((side(E04, LIMTA=1500), side(E04, DTAMP=1000)))
    comparison.choose("LIMTA", 0)
    comparison.choose("DTAMP", 1)
    assert comparison.chosen() == {"LIMTA": 1500, "DTAMP": 1000}
    comparison.choose("LIMTA", None)
    assert comparison.chosen() == {"DTAMP": 1000}

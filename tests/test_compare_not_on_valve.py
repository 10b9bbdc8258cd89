"""Issue 20 item 4, "missing is not different": a -CA valve without this project's objects
(only what the manual lists) is compared on what both sides have; what the valve lacks is
listed apart as "not on this valve", never as a difference."""

from __future__ import annotations

import json

import pytest
from support.can_link_rig import E04, make_link_rig

from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.cli.main import main
from prm9tool.compare.model import Comparison, Side
from prm9tool.files.prmfile import PrmContents, write_file

KEY = TypeKey.parse(E04)
FACTORY = PrmContents.factory(KEY).values
OURS = sorted(m for m in FACTORY if not CATALOGUE[m].address_from_manual)  # this project's


@pytest.fixture
def real_valve(tmp_path):
    """A -CA valve as the manual lists it: none of this project's objects."""
    rig = make_link_rig("not-on-valve", tmp_path, real_valve=True)
    yield rig
    rig.close()


def _bus(rig) -> list[str]:
    return [
        "--device",
        "can:10",
        "--can-interface",
        "virtual",
        "--can-channel",
        rig.options.channel,
        "--type-key",  # the label's key: a valve as the manual lists it has no 0x2041
        E04,
    ]


def _valve_side(values: dict) -> Side:
    return Side("valve 7", KEY, {m: v for m, v in values.items() if m not in OURS})


def test_what_a_valve_lacks_is_not_a_difference():
    comparison = Comparison((Side("file", KEY, FACTORY), _valve_side(dict(FACTORY))))
    assert OURS and comparison.equal
    assert comparison.changed == [] and comparison.missing == []
    assert [row.mnemonic for row in comparison.not_on_valve] == [
        p.mnemonic for p in CATALOGUE if p.mnemonic in OURS
    ]
    assert comparison.filtered(differences_only=True) == []
    with pytest.raises(ValueError, match="cannot be chosen"):
        comparison.choose(OURS[0], 0)


def test_a_value_both_have_still_differs():
    valve = dict(FACTORY, LIMTA=1500)
    comparison = Comparison((Side("file", KEY, FACTORY), _valve_side(valve)))
    assert not comparison.equal and [row.mnemonic for row in comparison.changed] == ["LIMTA"]


def test_diff_against_the_valves_own_download_is_equal(real_valve, data_dir, tmp_path, capsys):
    """Was: exit 1, every parameter the valve lacks printed as a difference (AINSETP - -)."""
    out = tmp_path / "valve.prm"
    assert main(["--batch", "--download", str(out), *_bus(real_valve)]) == 0
    capsys.readouterr()
    assert main(["--diff", str(out), *_bus(real_valve)]) == 0
    captured = capsys.readouterr()
    assert captured.out == ""
    assert "not compared: " in captured.err and "AINSETP" in captured.err


def test_diff_of_a_full_file_lists_what_the_valve_lacks_apart(
    real_valve, data_dir, tmp_path, capsys
):
    path = tmp_path / "full.prm"
    write_file(PrmContents.factory(KEY), path)
    assert main(["--diff", str(path), *_bus(real_valve), "--json"]) == 0
    report = json.loads(capsys.readouterr().out)
    assert report["equal"] and report["differences"] == []
    lacking = {entry["mnemonic"] for entry in report["not_on_valve"]}
    assert lacking == set(OURS)
    assert all(entry["not_on"] == ["b"] for entry in report["not_on_valve"])
    real_valve.valve.write(*CATALOGUE["LIMTA"].key, 1500)  # one the valve has, changed
    assert main(["--diff", str(path), *_bus(real_valve)]) == 1
    captured = capsys.readouterr()
    assert captured.out.splitlines() == ["LIMTA\t2400\t1500\tmA"]
    assert "not on this valve (valve " in captured.err

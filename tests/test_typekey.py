"""Type keys: parse/format round trips, variants, and messages that name the wrong part."""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from prm9tool.catalogue.typekey import (
    SPOOLS,
    USER_SPOOLS_FILE,
    SpoolSource,
    TypeKey,
    all_type_keys,
    load_user_spools,
)
from prm9tool.catalogue.variant import Coils, Config
from prm9tool.errors import TypeKeyError


def test_manual_example_parses():
    key = TypeKey.parse("PRM9-06.3Z11/30-24E02S02")
    assert (key.size, key.spool, key.flow, key.config, key.canopen) == (
        "06",
        "3Z11",
        "30",
        Config.E02,
        False,
    )
    assert key.coils is Coils.AB
    assert SPOOLS["3Z11"].from_manual and SPOOLS["3Z11"].source is SpoolSource.MANUAL
    assert SPOOLS["2Z51"].source is SpoolSource.ASSUMED


def test_every_key_round_trips():
    for key in all_type_keys():
        assert TypeKey.parse(str(key)) == key


def test_lower_case_and_spaces_are_accepted():
    assert str(TypeKey.parse("  prm9-10.2z51/60-24e04s02-ca ")) == "PRM9-10.2Z51/60-24E04S02-CA"


@pytest.mark.parametrize(
    ("text", "part"),
    [
        ("XRM9-06.3Z11/30-24E02S02", "must start with 'PRM9-'"),
        ("PRM9-08.3Z11/30-24E02S02", "nominal size '08'"),
        ("PRM9-06.9Q99/30-24E02S02", "unknown spool '9Q99'"),
        ("PRM9-10.3Z11/15-24E02S02", "flow '15' l/min does not exist for Dn10"),
        ("PRM9-06.3Z11/30-12E02S02", "supply voltage '12'"),
        ("PRM9-06.3Z11/30-24E05S02", "configuration 'E05'"),
        ("PRM9-06.3Z11/30-24E02S01", "electronics series 'S01'"),
        ("PRM9-06.3Z11/30-24E02S02-XX", "suffix '-XX'"),
        ("PRM9-06.3Z11/30-24E02X02", "electronics series 'X02' must be S02"),
        ("PRM9-06.3Z11/30-24X02S02", "configuration 'X02' must be E02 or E04"),
        ("PRM9-DN06.3Z11/30-24E02S02", "nominal size 'DN06' must be 06 or 10"),
    ],
)
def test_malformed_keys_name_the_wrong_part(text, part):
    with pytest.raises(TypeKeyError, match=re.escape(part)):
        TypeKey.parse(text)


@pytest.mark.parametrize(
    ("text", "message"),
    [
        (
            "PRM9-06-3Z11/30-24E02S02",
            "expected '.' between the nominal size '06' and the spool, found '-'",
        ),
        (
            "PRM9-06.3Z11-30-24E02S02",
            "expected '/' between the spool '3Z11' and the nominal flow, found '-'",
        ),
        (
            "PRM9-06.3Z11/30/24E02S02",
            "expected '-' between the nominal flow '30' and the supply voltage, found '/'",
        ),
        (
            "PRM9-063Z11-30",
            "expected '.' between the nominal size '063' and the spool, found 'Z'",
        ),
        (
            "PRM9-06.3Z11/30",
            "expected '-' between the nominal flow '30' and the supply voltage, "
            "found the end of the key",
        ),
        ("PRM9-06.3Z11/30-24E02S02CA", "expected '-' between the electronics series S02 and 'CA'"),
    ],
)
def test_a_missing_or_wrong_separator_is_named(text, message):
    with pytest.raises(TypeKeyError) as caught:
        TypeKey.parse(text)
    assert str(caught.value) == f"type key {text!r}: {message}"


@pytest.mark.parametrize(
    ("text", "part"),
    [
        ("PRM9-", "nominal size (06 or 10)"),
        ("PRM9-.3Z11/30-24E02S02", "nominal size (06 or 10)"),
        ("PRM9-06./30-24E02S02", "spool"),
        ("PRM9-06.3Z11/-24E02S02", "nominal flow"),
        ("PRM9-06.3Z11/30-E02S02", "supply voltage (24)"),
        ("PRM9-06.3Z11/30-24S02", "configuration (E02 or E04)"),
        ("PRM9-06.3Z11/30-24E02", "electronics series (S02)"),
        ("PRM9-06.3Z11/30-24E02-CA", "electronics series (S02)"),
    ],
)
def test_a_missing_part_is_named(text, part):
    with pytest.raises(TypeKeyError) as caught:
        TypeKey.parse(text)
    assert str(caught.value) == f"type key {text!r}: the {part} is missing"


def _spool_file(folder, entries) -> None:
    folder.mkdir(parents=True, exist_ok=True)
    (folder / USER_SPOOLS_FILE).write_text(json.dumps(entries), encoding="utf-8")


def test_a_user_extends_the_spool_catalogue(tmp_path, spools):
    _spool_file(tmp_path, [{"code": "4z21", "coils": "B", "description": "our own"}])
    assert load_user_spools(tmp_path) == ["4Z21"]
    key = TypeKey.parse("PRM9-06.4Z21/30-24E02S02")
    assert key.coils is Coils.B and spools["4Z21"].source is SpoolSource.USER
    assert TypeKey(key.size, "4Z21", "30", "24", Config.E04, True) in all_type_keys()


def test_without_a_spool_file_nothing_changes(tmp_path, spools):
    assert load_user_spools(tmp_path) == [] and len(spools) == 7


@pytest.mark.parametrize(
    ("entries", "reason"),
    [
        ({"code": "4Z21"}, "expected a list of spools"),
        ([{"code": "4Z21", "coils": "AB"}, {"code": "4Z22", "coils": "C"}], "entry 2: coils 'C'"),
        ([{"code": "4Z-21", "coils": "A"}], "entry 1: code '4Z-21' must be letters and digits"),
        ([{"coils": "A"}], "entry 1: 'code' is missing"),
        ([{"code": "4Z21", "coils": ["A"]}], "entry 1: coils ['A'] must be AB, A or B"),
        ([7], "entry 1: expected an object with code, coils and description"),
        ([{"code": "3Z11", "coils": "A"}], "spool 3Z11 is named in the manual"),
    ],
)
def test_a_wrong_spool_file_names_the_entry_and_adds_nothing(tmp_path, spools, entries, reason):
    _spool_file(tmp_path, entries)
    with pytest.raises(TypeKeyError, match=re.escape(reason)):
        load_user_spools(tmp_path)
    assert "4Z21" not in spools and spools["3Z11"].coils is Coils.AB


def test_the_program_reads_the_spool_file_of_the_user_data_dir(tmp_path):
    data = Path(os.environ["PRM9TOOL_DATA_DIR"])  # conftest: a folder of this test
    _spool_file(data, [{"code": "4Z21", "coils": "A", "description": "our own"}])
    out = tmp_path / "valve.prm"
    result = _prm9tool("--new", "PRM9-06.4Z21/30-24E02S02", "-o", str(out))
    assert (result.returncode, result.stdout) == (0, "")
    assert "AINSETP = 6" in out.read_text(encoding="utf-8")  # one coil: 0…10 V default
    (data / USER_SPOOLS_FILE).write_text("[{", encoding="utf-8")
    result = _prm9tool("--new", "PRM9-06.3Z11/30-24E02S02", "-o", str(tmp_path / "b.prm"))
    assert result.returncode == 0
    assert result.stderr.startswith(f"prm9tool: warning: spool catalogue {data / USER_SPOOLS_FILE}")


def _prm9tool(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "prm9tool", *args],
        capture_output=True,
        text=True,
        timeout=60,
        check=False,
    )

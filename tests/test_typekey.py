"""Type keys: parse/format round trips, variants, and messages that name the wrong part."""

from __future__ import annotations

import re

import pytest

from prm9tool.errors import TypeKeyError
from prm9tool.typekey import SPOOLS, TypeKey, all_type_keys
from prm9tool.variant import Coils, Config


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
    assert SPOOLS["3Z11"].from_manual


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

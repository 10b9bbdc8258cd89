"""Type keys: parse/format round trips, variants, and messages that name the wrong part."""

from __future__ import annotations

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
        ("PRM9-063Z11-30", "expected the form"),
    ],
)
def test_malformed_keys_name_the_wrong_part(text, part):
    with pytest.raises(TypeKeyError, match=part.replace("(", r"\(").replace(")", r"\)")):
        TypeKey.parse(text)

"""Issue 25 item 20: checking a file is linear in its size, whatever its tokens look like, and
a message never repeats a long value. (The time is measured in benchmarks/bench_prm.py; here
a quadratic check shows as a test that does not end.)"""

from __future__ import annotations

import re

from hypothesis import given, settings
from hypothesis import strategies as st

from prm9tool.catalogue.schema import _is_number
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.files.prmfile import MAX_FILE_SIZE, PrmContents, check_bytes
from prm9tool.messages import SHOWN_CHARACTERS, quoted

E04_CA = "PRM9-06.3Z11/30-24E04S02-CA"
BASE = PrmContents.factory(TypeKey.parse(E04_CA)).to_text()
# the number as it was written before (correct, but quadratic when it fails on a long token)
OLD_NUMBER = re.compile(r"[+-]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][+-]?[0-9]+)?")
LONGEST_MESSAGE = 200  # the longest template with a cut value in it


def _with_limta(value: str) -> bytes:
    return re.sub(r"(?m)^LIMTA = .*$", lambda _m: f"LIMTA = {value}", BASE).encode()


@st.composite
def long_tokens(draw) -> str:
    """Runs of one character each (thousands of digits, points, signs, letters) in a row."""
    runs = draw(
        st.lists(
            st.tuples(st.sampled_from("09.eE+-x ,"), st.integers(1, 20_000)), min_size=1, max_size=4
        )
    )
    return "".join(char * count for char, count in runs).strip() or "9"


@settings(max_examples=60)
@given(long_tokens())
def test_a_long_token_is_checked_and_its_message_is_cut(token):
    result = check_bytes(_with_limta(token))
    for problem in result.problems:
        assert len(str(problem.message)) <= LONGEST_MESSAGE, str(problem.message)[:300]
    if not _is_number(token.replace(",", ".") if token.count(",") == 1 else token):
        assert not result.valid


@given(st.text(alphabet="0123456789.eE+-x ", max_size=30))
def test_the_number_rule_is_the_one_it_was(text):
    assert _is_number(text) == (OLD_NUMBER.fullmatch(text) is not None)


def test_the_worst_case_file_under_the_size_limit_is_checked():
    """Nearly 1 MiB of nines ending in a letter: was about 15 min (quadratic), now milliseconds."""
    value = "9" * (MAX_FILE_SIZE - len(BASE) - 100) + "x"
    result = check_bytes(_with_limta(value))
    assert not result.valid
    assert any(str(p.message) == f"LIMTA: {quoted(value)} is not a number" for p in result.problems)
    assert (
        f"({len(value)} characters)" in quoted(value) and len(quoted(value)) < 2 * SHOWN_CHARACTERS
    )

"""Issue 25 item 21: what the header records from a valve reads back exactly. A firmware text
with " # " lost everything after it (read as a comment), blanks at its ends were stripped, and
a control character came back as its escape "\\x0d" instead of itself."""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from prm9tool.catalogue.typekey import TypeKey
from prm9tool.files.backup import write_backup
from prm9tool.files.prmcheck import escape_text, unescape_text
from prm9tool.files.prmfile import PrmContents, check_bytes, read_file

E04_CA = "PRM9-06.3Z11/30-24E04S02-CA"
KEY = TypeKey.parse(E04_CA)
VALUES = PrmContents.factory(KEY).values
texts = st.text(st.characters(exclude_categories=("Cs",)), min_size=1, max_size=40)


def _read_back(firmware: str) -> str | None:
    contents = PrmContents(KEY, dict(VALUES), 1234, firmware)
    result = check_bytes(contents.to_text().encode("utf-8"))
    assert result.valid, [str(p.message) for p in result.problems]
    assert result.contents is not None
    return result.contents.firmware


@pytest.mark.parametrize(
    "firmware", ["V1.2 # beta", " 1.0 ", "1.0\r\nX=1", "#1", "a\\x0d", "\t1\u3000", "C:\\fw"]
)
def test_a_firmware_text_reads_back_exactly(firmware):
    assert _read_back(firmware) == firmware


@given(texts)
def test_any_firmware_text_reads_back_exactly(firmware):
    assert _read_back(firmware) == firmware


@given(texts)
def test_escaping_is_undone_exactly_and_leaves_no_comment_or_line_break(text):
    escaped = escape_text(text)
    assert unescape_text(escaped) == text
    assert "#" not in escaped and "\n" not in escaped and escaped == escaped.strip()


def test_a_backup_keeps_the_firmware_text_of_the_valve(data_dir):
    path = write_backup(E04_CA, 4711, "V0.35 # build 7", VALUES)
    assert read_file(path).firmware == "V0.35 # build 7"
    assert "firmware = V0.35 \\x23 build 7" in path.read_text(encoding="utf-8")


def test_a_backslash_written_by_hand_is_itself():
    assert unescape_text("C:\\fw\\x4") == "C:\\fw\\x4"

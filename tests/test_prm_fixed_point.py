"""*.prm files: load → save → load is a fixed point for every file the reader accepts, and
numbers are ASCII decimal numbers only (issue 15, items 15 and 17)."""

from __future__ import annotations

import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from prm9tool.catalogue.typekey import TypeKey
from prm9tool.files.prmfile import PrmContents, check_bytes, read_bytes

E04_CA = TypeKey.parse("PRM9-06.3Z11/30-24E04S02-CA")
E02 = TypeKey.parse("PRM9-06.3Z11/30-24E02S02")
FACTORY = {key: PrmContents.factory(key).to_text() for key in (E04_CA, E02)}


def _body(text: str) -> list[str]:
    """The lines of a file without its checksum line (a file written by hand has any)."""
    return [line for line in text.split("\n") if line and not line.startswith("checksum")]


def _assert_fixed_point(data: bytes) -> None:
    """If ``data`` reads, saving it and reading that back changes nothing, and saving again
    writes the same text."""
    first = check_bytes(data).contents
    if first is None:
        return
    saved = first.to_text()
    second = read_bytes(saved.encode("utf-8"))
    assert (second.type_key, second.values, second.unknown) == (
        first.type_key,
        first.values,
        first.unknown,
    )
    assert (second.serial, second.firmware) == (first.serial, first.firmware)
    assert second.to_text() == saved
    assert [p for p in second.warnings if p.severity == "error"] == []


# Text a hand-edited value or comment may hold: printable, with the characters the grammar
# gives a meaning to ('#', '=', spaces, tabs) over-represented.
VALUE_TEXT = st.text(
    alphabet=st.one_of(
        st.sampled_from("#= \t,.-+0123456789eE"),
        st.characters(codec="utf-8", exclude_categories=("Cc", "Cs", "Zl", "Zp")),
    ),
    max_size=12,
)
NAMES = st.from_regex(r"[A-Za-z_][A-Za-z0-9_.\-]{0,8}", fullmatch=True)
SPACING = st.sampled_from(["", " ", "  ", "\t"])


@st.composite
def entry_lines(draw: st.DrawFn) -> str:
    """One line a person might add: a comment, a blank line or ``NAME = value  # comment``."""
    kind = draw(st.sampled_from(["comment", "blank", "entry", "entry"]))
    if kind == "comment":
        return draw(SPACING) + "#" + draw(VALUE_TEXT)
    if kind == "blank":
        return draw(SPACING)
    name = draw(st.one_of(NAMES, st.sampled_from(["firmware", "serial", "POSKP", "THRESETP"])))
    line = f"{name}{draw(SPACING)}={draw(SPACING)}{draw(VALUE_TEXT)}"
    if draw(st.booleans()):
        line += draw(st.sampled_from([" ", "  ", "\t"])) + "#" + draw(VALUE_TEXT)
    return line


@st.composite
def edited_files(draw: st.DrawFn) -> bytes:
    """A factory file with lines removed, added and changed, and any checksum line."""
    lines = _body(FACTORY[draw(st.sampled_from([E04_CA, E02]))])
    for _ in range(draw(st.integers(0, 6))):
        at = draw(st.integers(3, len(lines)))  # after the format and type key lines
        lines.insert(at, draw(entry_lines()))
    for _ in range(draw(st.integers(0, 3))):
        at = draw(st.integers(4, len(lines) - 1))
        lines[at] = draw(entry_lines())
    lines.append("checksum = crc32:00000000")
    return "\n".join(lines).encode("utf-8") + b"\n"


def _with(lines: list[str]) -> bytes:
    body = _body(FACTORY[E04_CA])
    return "\n".join([*body[:4], *lines, *body[4:], "checksum = crc32:00000000", ""]).encode()


@given(edited_files())
@example(_with(["FOO=#x"]))
@example(_with(["firmware=#1"]))
@example(_with(["FOO=#x  # a comment", "BAR =#", "BAZ = a#b #c"]))
@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
def test_load_save_load_is_a_fixed_point_for_every_file_the_reader_accepts(data):
    _assert_fixed_point(data)


@pytest.mark.parametrize(
    ("line", "name", "written"),
    [("FOO=#x", "FOO", "FOO =#x"), ("FOO=#", "FOO", "FOO =#"), ("FOO = a#b", "FOO", "FOO = a#b")],
)
def test_a_value_starting_with_a_hash_keeps_its_value_after_saving(line, name, written):
    value = line.partition("=")[2].strip()
    first = read_bytes(_with([line]))
    assert first.unknown == [(name, value)]
    saved = first.to_text()
    assert f"\n{written}\n" in saved
    assert read_bytes(saved.encode()).unknown == [(name, value)]


def test_a_firmware_text_starting_with_a_hash_survives_saving():
    first = read_bytes(_with(["firmware=#1"]))
    assert first.firmware == "#1"
    assert read_bytes(first.to_text().encode()).firmware == "#1"


# --- numbers are ASCII decimal numbers (item 17) -----------------------------------------------
@pytest.mark.parametrize("value", ["２４００", "٢٤٠٠", "2_400", "inf", "nan", "१२"])
def test_a_number_that_is_not_ascii_decimal_is_an_error_on_its_line(value):
    text = FACTORY[E04_CA].replace("LIMTA = 2400", f"LIMTA = {value}")
    result = check_bytes(text.encode())
    line = next(n for n, t in enumerate(text.split("\n"), 1) if t.startswith("LIMTA"))
    errors = [(p.line, str(p.message)) for p in result.errors]
    assert result.contents is None
    assert errors == [(line, f"LIMTA: {value.strip()!r} is not a number")]


@pytest.mark.parametrize(
    ("value", "raw"), [("2400", 2400), ("+2400", 2400), ("2400.0", 2400), ("2.4e3", 2400)]
)
def test_ascii_decimal_numbers_are_read(value, raw):
    text = FACTORY[E04_CA].replace("LIMTA = 2400", f"LIMTA = {value}")
    contents = check_bytes(text.encode()).contents
    assert contents is not None and contents.values["LIMTA"] == raw

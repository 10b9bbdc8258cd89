"""*.prm files: load → save → load is a fixed point for every file the reader accepts, and
numbers are ASCII decimal numbers only (issue 15, items 15 and 17)."""

from __future__ import annotations

import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from prm9tool.catalogue import CATALOGUE
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
# A value as a person may write it: any text, often starting with '#' (issue 15 item 15).
VALUES = st.one_of(VALUE_TEXT, VALUE_TEXT.map(lambda text: "#" + text))
RESERVED = {p.mnemonic for p in CATALOGUE} | {"format", "type_key", "serial", "firmware"}
NAMES = st.from_regex(r"[A-Za-z_][A-Za-z0-9_.\-]{0,8}", fullmatch=True).filter(
    lambda name: name not in RESERVED and name != "checksum"
)
SPACING = st.sampled_from(["", " ", "  ", "\t"])
COMMENT = st.one_of(st.just(""), VALUE_TEXT.map(lambda text: "  #" + text))


@st.composite
def entry_line(draw: st.DrawFn, name: str, value: str) -> str:
    """``name = value`` with any spacing around '=' and an optional inline comment."""
    return f"{name}{draw(SPACING)}={draw(SPACING)}{value}{draw(COMMENT)}"


@st.composite
def spelled(draw: st.DrawFn, text: str) -> str:
    """Another spelling of the number ``text`` that reads as the same value."""
    if not text.lstrip("-").replace(".", "").isdigit():
        return text
    number = text.replace(".", ",") if "." in text and draw(st.booleans()) else text
    return draw(st.sampled_from([number, f"+{number}" if number[0] != "-" else number,
                                 f"{text}0" if "." in text else f"{text}.0", f"{text}e0"]))  # fmt: skip


@st.composite
def edited_files(draw: st.DrawFn) -> bytes:
    """A factory file edited by hand: values respelled, a firmware line, unknown entries,
    comment and blank lines added anywhere, and any checksum."""
    lines = _body(FACTORY[draw(st.sampled_from([E04_CA, E02]))])
    for index in draw(st.lists(st.integers(4, len(lines) - 1), max_size=6)):
        name, _equals, rest = lines[index].partition(" = ")
        value = rest.split("  #")[0]
        lines[index] = draw(entry_line(name, draw(spelled(value))))
    if draw(st.booleans()):
        lines.insert(3, draw(entry_line("firmware", draw(VALUES))))
    for name in draw(st.lists(NAMES, max_size=4, unique=True)):
        lines.insert(draw(st.integers(3, len(lines))), draw(entry_line(name, draw(VALUES))))
    for _ in range(draw(st.integers(0, 4))):
        extra = draw(st.one_of(SPACING, SPACING.map(lambda s: s + "#") | VALUE_TEXT.map(
            lambda text: "#" + text)))  # fmt: skip
        lines.insert(draw(st.integers(2, len(lines))), extra)
    lines.append(draw(st.sampled_from(["checksum = crc32:00000000", "checksum = crc32:1234abcd"])))
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

"""*.prm files: exact round trips, every problem with its line, robustness, atomic saving."""

from __future__ import annotations

import errno
import os
import stat
import sys
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from prm9tool import atomicfile
from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.typekey import TypeKey, all_type_keys
from prm9tool.catalogue.variant import ALL_VARIANTS, Variant
from prm9tool.errors import FileFormatError, FileProblem
from prm9tool.files.prmdocument import load_document, save_document
from prm9tool.files.prmfile import (
    MAX_FILE_SIZE,
    PrmContents,
    check_bytes,
    read_bytes,
    read_file,
    write_file,
)
from prm9tool.messages import Message

E02 = TypeKey.parse("PRM9-06.3Z11/30-24E02S02")
E04_CA = TypeKey.parse("PRM9-06.3Z11/30-24E04S02-CA")
COIL_A = TypeKey.parse("PRM9-06.2Z51/30-24E02S02")


def key_for(variant: Variant) -> TypeKey:
    return next(k for k in all_type_keys() if k.variant == variant)


def factory_text(key: TypeKey) -> str:
    return PrmContents.factory(key).to_text()


def replace_line(text: str, start: str, new: str | None) -> str:
    """Replace (or with None delete) the one line that starts with ``start``."""
    lines = text.split("\n")
    (index,) = [i for i, line in enumerate(lines) if line.startswith(start)]
    if new is None:
        del lines[index]
    else:
        lines[index] = new
    return "\n".join(lines)


def line_of(text: str, start: str) -> int:
    return next(n for n, line in enumerate(text.split("\n"), 1) if line.startswith(start))


def problems_of(text: str | bytes) -> list[FileProblem]:
    return check_bytes(text.encode() if isinstance(text, str) else text).problems


# --- round trips ---------------------------------------------------------------------------
@pytest.mark.parametrize("variant", ALL_VARIANTS, ids=lambda v: v.label)
def test_factory_file_of_every_variant_reads_back_and_rewrites_identically(variant):
    key = key_for(variant)
    text = factory_text(key)
    contents = read_bytes(text.encode())
    assert contents.type_key == key
    assert contents.values == {
        p.mnemonic: p.default_for(variant) for p in CATALOGUE.file_parameters(variant)
    }
    assert contents.to_text() == text
    assert [p for p in contents.warnings if p.severity == "error"] == []


@pytest.mark.parametrize("variant", ALL_VARIANTS, ids=lambda v: v.label)
def test_document_load_save_reproduces_the_file_byte_for_byte(qapp, tmp_path, variant):
    original = tmp_path / "a.prm"
    write_file(PrmContents.factory(key_for(variant)), original)
    doc = load_document(original)
    assert not doc.modified and doc.path == original
    save_document(doc, tmp_path / "b.prm")
    assert (tmp_path / "b.prm").read_bytes() == original.read_bytes()


@given(st.data())
def test_every_value_a_parameter_can_hold_survives_the_file_exactly(data):
    param = data.draw(st.sampled_from(CATALOGUE.file_parameters(E04_CA.variant)))
    if param.choices:
        raw = data.draw(st.sampled_from([code for code, _ in param.choices]))
    else:
        raw = data.draw(st.integers(param.raw_min, param.raw_max))
    assert param.parse_display(param.format_display(raw)) == raw


def test_edited_values_comments_unknown_entries_and_source_survive_a_round_trip(qapp, tmp_path):
    text = factory_text(E04_CA)
    text = replace_line(text, "format =", "# Test rig 3, hydraulic press\nformat = prm9tool 1")
    text = replace_line(
        text, "type_key =", f"type_key = {E04_CA}\nserial = 4711\nfirmware = V0.35.16"
    )
    text = replace_line(text, "LIMTA =", "# reduced for the small pump\nLIMTA = 2000  # was 2400")
    text = replace_line(
        text, "checksum =", "FUTUREPARAM = 17 # from prm9tool 9\n\nchecksum = crc32:00000000"
    )
    path = tmp_path / "edited.prm"
    path.write_text(text, encoding="utf-8")
    doc = load_document(path)
    assert doc.value("LIMTA") == 2000
    assert (doc.source_serial, doc.source_firmware) == (4711, "V0.35.16")
    assert doc.unknown_entries == [("FUTUREPARAM", "17")]
    doc.set_value("DYNFREQ", 100)
    save_document(doc, path)
    saved = path.read_text(encoding="utf-8")
    assert "# Test rig 3, hydraulic press\nformat = prm9tool 1\n" in saved
    assert "# reduced for the small pump\nLIMTA = 2000  # was 2400\n" in saved
    assert "DYNFREQ = 100  # Dither: frequency [Hz]\n" in saved
    assert "\nFUTUREPARAM = 17 # from prm9tool 9\n\nchecksum = crc32:" in saved
    assert "serial = 4711\nfirmware = V0.35.16\n" in saved
    problems = check_bytes(saved.encode()).problems  # new checksum: no "edited" warning
    assert [p.message for p in problems] == [
        "unknown parameter 'FUTUREPARAM': kept and written back unchanged"
    ]


def test_crlf_and_byte_order_mark_from_windows_editors_are_accepted(qapp, tmp_path):
    text = factory_text(E02)
    path = tmp_path / "windows.prm"
    path.write_bytes(b"\xef\xbb\xbf" + text.replace("\n", "\r\n").encode())
    doc = load_document(path)  # same checksum: line ends and BOM are not content
    assert read_file(path).warnings == []
    save_document(doc, path)
    assert path.read_text(encoding="utf-8") == text


# --- every problem, with its line -----------------------------------------------------------
def _one(text: str, severity: str = "error") -> FileProblem:
    found = [p for p in problems_of(text) if p.severity == severity and "checksum" not in p.message]
    assert len(found) == 1, found
    return found[0]


@pytest.mark.parametrize(
    ("replaces", "line", "message"),
    [
        ("LIMTA =", "LIMTA = abc", "LIMTA: 'abc' is not a number"),
        ("LIMTA =", "LIMTA =", "LIMTA: no value after '='"),
        ("LIMTA =", "LIMTA = 5000", "LIMTA: 5000 mA is outside the allowed range 0 … 4000 mA"),
        ("LIMTA =", "LIMTA = -1e400", "LIMTA: '-1e400' is not a number"),
        ("THRESETP =", "THRESETP = 1e308", "THRESETP: '1e308' is far outside the range"),
        ("AINSETP =", "AINSETP = 12", "AINSETP: 12 is not one of the allowed codes 0, 1, 2"),
        ("LIMTA =", "LIMTA = 2700", "LIMTA = 2700 mA is above the nominal coil current CURNORM"),
        ("SETPLINXB =", "SETPLINXB = -40", "SETPLIN linearization points must increase strictly"),
        ("LIMTA =", "LIMTA=2000 junk", "LIMTA: '2000 junk' is not a number"),
        (None, "PWR = 24", "PWR (Supply voltage) is a read-only value, not a setting"),
        (None, "DEVMODE = 1", "DEVMODE (Device mode) is set online only"),
        (None, "LIMTA 2000", "garbled line: expected 'NAME = value', a '#' comment or a blank"),
        ("checksum =", "checksum = crc32:1234", "checksum 'crc32:1234' is damaged"),
    ],
)
def test_a_bad_entry_is_reported_on_its_own_line(replaces, line, message):
    text = factory_text(E02)
    if replaces is None:
        text = replace_line(text, "DYNFREQ =", f"DYNFREQ = 80\n{line}")
    else:
        text = replace_line(text, replaces, line)
    problem = next(p for p in problems_of(text) if p.message.startswith(message))
    assert (problem.line, problem.severity) == (line_of(text, line), "error")


def test_a_parameter_the_type_key_does_not_have_is_an_error():
    text = replace_line(factory_text(E02), "LIMTB =", "LIMTB = 2400\nPRCKP = 2")
    problem = _one(text)
    assert problem.line == line_of(text, "PRCKP")
    assert problem.message == (
        "PRCKP (Process controller: proportional gain Kp) does not exist on E02 two coils valves "
        "(type key PRM9-06.3Z11/30-24E02S02); remove the line or change the type key"
    )


def test_an_e02_ca_file_neither_needs_nor_takes_the_external_sensor_objects():
    """Table 7-14 gives an E02 -CA the objects 0x2005-0x2008 too, but it has no sensor input:
    they are not part of its parameter set, so its file has none and refuses one."""
    e02_ca = TypeKey.parse(f"{E02}-CA")
    factory = factory_text(e02_ca)
    assert "SENS" not in factory and problems_of(factory) == []
    text = replace_line(factory, "LIMTB =", "LIMTB = 2400\nSENSTYPE = 9")
    problem = _one(text)
    assert problem.line == line_of(text, "SENSTYPE")
    assert problem.message == (
        "SENSTYPE (External sensor: signal type) is not a parameter of E02 two coils -CA valves "
        f"(type key {e02_ca}): they have the object but no external sensor input; remove the "
        "line or change the type key"
    )


def test_a_missing_parameter_is_reported_on_the_type_key_line():
    text = replace_line(factory_text(E02), "DTAMP =", None)
    problem = _one(text)
    assert problem.line == line_of(text, "type_key")
    assert (
        problem.message
        == "DTAMP (Dither: amplitude) is missing (required for E02 two coils valves)"
    )


def test_a_duplicate_is_reported_on_the_second_occurrence():
    text = replace_line(factory_text(E02), "DTAMP =", "DTAMP = 15\nDTAMP = 20")
    problem = _one(text)
    first = line_of(text, "DTAMP")
    assert (problem.line, problem.message) == (
        first + 1,
        f"DTAMP is set twice (first on line {first})",
    )


def test_an_unknown_mnemonic_is_a_warning_with_a_suggestion_and_is_kept():
    text = replace_line(factory_text(E02), "DTAMP =", "DTAMP = 15\nDTAMPP = 20")
    problem = _one(text, "warning")
    assert problem.line == line_of(text, "DTAMPP")
    assert problem.message == (
        "unknown parameter 'DTAMPP': kept and written back unchanged (did you mean DTAMP?)"
    )
    contents = read_bytes(text.encode())
    assert contents.unknown == [("DTAMPP", "20")]
    assert "\nDTAMPP = 20\n" in contents.to_text()


def test_a_value_the_valve_cannot_hold_exactly_is_a_warning_naming_the_stored_value():
    text = replace_line(factory_text(E02), "THRESETP =", "THRESETP = 5.001")
    problem = _one(text, "warning")
    assert problem.message == (
        "THRESETP: 5.001 % is stored as 5 %, the nearest value the valve can hold"
    )
    assert read_bytes(text.encode()).values["THRESETP"] == 819


def test_a_setpoint_type_table_8_4_does_not_recommend_is_a_warning():
    assert problems_of(factory_text(COIL_A)) == []  # factory default is a recommended type
    text = replace_line(factory_text(COIL_A), "AINSETP =", "AINSETP = 9")
    problems = problems_of(text)
    assert (
        FileProblem(
            line_of(text, "AINSETP"),
            "AINSETP: ±10 V bipolar is not a recommended setpoint type for E02 coil A valves "
            "(manual table 8-4)",
            "warning",
        )
        in problems
    )
    assert all(p.severity == "warning" for p in problems)


def test_problems_are_messages_a_view_translates_and_a_rule_keeps_its_own():
    text = replace_line(factory_text(COIL_A), "AINSETP =", "AINSETP = 9")
    text = replace_line(text, "LIMTA =", "LIMTA =")
    values = read_bytes(factory_text(COIL_A).encode()).values | {"AINSETP": 9}
    (rule,) = CATALOGUE.check_rules(COIL_A.variant, values)
    recommended, empty, edited = problems_of(text)
    assert recommended.text == rule.text  # the catalogue's message, not a copy of its English
    assert isinstance(empty.text, Message) and empty.message == "LIMTA: no value after '='"
    german = {
        "{0}: no value after '='": "{0}: kein Wert nach '='",
        "{0}:{1}: warning: {2}": "{0}:{1}: Warnung: {2}",
        "{0} coil A{1}": "{0} Spule A{1}",
    }

    def translate(_context: str, source: str) -> str:
        return german.get(source, source)

    line = line_of(text, "LIMTA")
    assert (
        empty.located("f.prm").render(translate, "de") == f"f.prm:{line}: LIMTA: kein Wert nach '='"
    )
    assert (
        recommended.located("f.prm")
        .render(translate, "de")
        .endswith(
            ": Warnung: AINSETP: ±10 V bipolar is not a recommended setpoint type for E02 Spule A "
            "valves (manual table 8-4)"
        )
    )
    assert edited.format("f.prm").startswith(f"f.prm:{edited.line}: warning: checksum does not")


def test_every_problem_of_a_file_is_reported_at_once_in_line_order():
    text = factory_text(E02)
    for start, new in (("LIMTA =", "LIMTA = x"), ("DTAMP =", "DTAMP = 999"), ("POSKP =", None)):
        text = replace_line(text, start, new)
    problems = problems_of(text)
    assert [p.line for p in problems] == sorted(p.line for p in problems)
    assert len([p for p in problems if p.severity == "error"]) == 3
    assert problems[-1].severity == "warning" and "edited by hand" in problems[-1].message


# --- header and integrity -------------------------------------------------------------------
def test_a_hand_edit_is_a_warning_and_the_file_stays_usable():
    text = replace_line(factory_text(E02), "LIMTA =", "LIMTA = 2000")
    assert problems_of(text) == [
        FileProblem(
            line_of(text, "checksum"),
            "checksum does not match: the file was changed outside prm9tool (edited by hand?); "
            "saving it from prm9tool writes a new checksum",
            "warning",
        )
    ]
    assert read_bytes(text.encode()).values["LIMTA"] == 2000


@pytest.mark.parametrize(
    ("data", "line", "message"),
    [
        (b"", 0, "the file is empty"),
        (b"hello\n", 1, "garbled line"),
        (b"[section]\nkey = 1\n", 1, "garbled line"),
        (b"key = 1\n", 1, "expected 'format = prm9tool 1' as the first entry"),
        (b"format = prm9tool 2\n", 1, "format version 2 is newer than this prm9tool reads (1)"),
        (b"format = other 1\n", 1, "format 'other 1' is unknown"),
        (b"format = prm9tool 1\nchecksum = crc32:00000000\n", 1, "no 'type_key = ...' entry"),
    ],
)
def test_a_file_that_is_not_a_prm9tool_file_is_corrupt(data, line, message):
    problem = next(p for p in problems_of(data) if message in p.message)
    assert (problem.line, problem.severity) == (line, "error")


def test_a_bad_type_key_names_the_wrong_part():
    text = replace_line(factory_text(E02), "type_key =", "type_key = PRM9-06.3Z11/30-24E05S02")
    problem = next(p for p in problems_of(text) if "type key" in p.message)
    assert problem.line == line_of(text, "type_key")
    assert "configuration 'E05' must be E02 or E04" in problem.message


@pytest.mark.parametrize("serial", ["0", "-5", "12a", "99999999999", "1" * 5000])
def test_a_bad_serial_number_is_an_error(serial):
    text = replace_line(factory_text(E02), "type_key =", f"type_key = {E02}\nserial = {serial}")
    problem = _one(text)
    assert problem.line == line_of(text, "serial")
    assert "must be a whole number 1 … 4294967295" in problem.message


def test_a_truncated_file_is_corrupt():
    data = factory_text(E02).encode()
    cut = data[: len(data) // 2]
    problems = problems_of(cut)
    last = cut.count(b"\n") + 1
    assert (
        FileProblem(
            last,
            "no 'checksum = ...' line at the end: the file is truncated (a file written by hand must "
            "end with one, e.g. 'checksum = crc32:00000000')",
        )
        in problems
    )


def test_binary_junk_and_bad_encoding_are_reported_on_their_lines():
    text = factory_text(E02)
    data = text.replace("DTAMP = 15", "DTAMP = 1\x005").encode()
    data = data.replace(b"LIMTA = 2400", b"LIMTA = \xff2400")
    problems = problems_of(data)
    assert (
        FileProblem(
            line_of(text, "DTAMP"), "control character U+0000: binary data, the file is corrupt"
        )
        in problems
    )
    assert (
        FileProblem(line_of(text, "LIMTA"), "byte 0xFF is not UTF-8 text: the file is corrupt")
        in problems
    )


def test_text_after_the_checksum_line_is_an_error():
    text = factory_text(E02) + "LIMTA = 2000\n"
    assert problems_of(text) == [
        FileProblem(text.count("\n"), "text after the checksum line, which must be the last line")
    ]


def test_a_huge_file_is_refused_without_parsing(tmp_path):
    path = tmp_path / "huge.prm"
    path.write_bytes(b"#" * (MAX_FILE_SIZE + 1))
    with pytest.raises(FileFormatError, match="too large to be a parameter file"):
        read_file(path)


def test_a_missing_file_is_a_file_format_error_on_line_0(tmp_path):
    with pytest.raises(FileFormatError) as info:
        read_file(tmp_path / "nothing.prm")
    assert info.value.problems == [
        FileProblem(0, "cannot read the file: No such file or directory")
    ]


# --- robustness: any bytes --------------------------------------------------------------------
def _check_never_crashes(data: bytes) -> None:
    lines = data.count(b"\n") + 1
    try:
        contents = read_bytes(data, "fuzz.prm")
    except FileFormatError as exc:
        error: FileFormatError | None = exc
    else:
        error = None
    if error is not None:
        assert error.problems and any(p.severity == "error" for p in error.problems)
        assert all(0 <= p.line <= lines and p.message for p in error.problems)
        assert str(error).startswith("fuzz.prm:")
        return
    again = read_bytes(contents.to_text().encode())  # what was accepted can be saved
    assert (again.type_key, again.values, again.unknown) == (
        contents.type_key,
        contents.values,
        contents.unknown,
    )


VALID_FILES = [
    factory_text(E02).encode(),
    factory_text(COIL_A).encode(),
    replace_line(
        factory_text(E04_CA), "LIMTA =", "# comment\nLIMTA = 2000  # note\nX.Y = 1"
    ).encode(),
]
VALUES = st.one_of(
    st.text(max_size=12),
    st.integers(-70000, 70000).map(str),
    st.floats(allow_nan=True, allow_infinity=True).map(repr),
    st.sampled_from(["", "#", "=", "1,5", "0x10", "nan", "1e309", "±10 V bipolar"]),
)
MUTATIONS = st.tuples(
    st.sampled_from(["delete", "duplicate", "swap", "value", "insert", "truncate", "flip"]),
    st.floats(0, 1, exclude_max=True),
    st.binary(max_size=8),
    VALUES,
)


def _mutate(data: bytes, mutation: tuple[str, float, bytes, str]) -> bytes:
    kind, where, blob, value = mutation
    lines = data.split(b"\n")
    i, pos = int(where * len(lines)), int(where * len(data))
    if kind == "delete":
        del lines[i]
    elif kind == "duplicate":
        lines.insert(i, lines[i])
    elif kind == "swap":
        lines[i], lines[i // 2] = lines[i // 2], lines[i]
    elif kind == "value":
        lines[i] = lines[i].split(b"=")[0] + b"= " + value.encode("utf-8", "surrogatepass")
    elif kind == "insert":
        return data[:pos] + blob + data[pos:]
    elif kind == "truncate":
        return data[:pos]
    else:
        return (
            data[:pos] + bytes([data[pos] ^ (1 << (blob[0] % 8 if blob else 0))]) + data[pos + 1 :]
        )
    return b"\n".join(lines)


# The issue asks for at least 2 000 examples in every CI run, whatever the hypothesis profile.
FUZZ = settings(max_examples=2000, deadline=None, suppress_health_check=[HealthCheck.too_slow])


@FUZZ
@given(st.binary(max_size=3000))
def test_random_bytes_give_a_result_or_a_file_format_error(data):
    _check_never_crashes(data)


@FUZZ
@given(st.sampled_from(VALID_FILES), st.binary(max_size=400))
def test_a_valid_header_followed_by_random_bytes_gives_a_result_or_an_error(base, tail):
    _check_never_crashes(base[: base.index(b"\n\n") + 2] + tail)


@FUZZ
@given(st.sampled_from(VALID_FILES), st.lists(MUTATIONS, min_size=1, max_size=4))
def test_mutated_valid_files_give_a_result_or_a_file_format_error(base, mutations):
    data = base
    for mutation in mutations:
        data = _mutate(data, mutation) if data else data
    _check_never_crashes(data)


# --- saving -----------------------------------------------------------------------------------
def test_saving_keeps_the_previous_file_as_backup(qapp, tmp_path):
    path = tmp_path / "valve.prm"
    doc = load_document(_written(tmp_path / "valve.prm"))
    first = path.read_bytes()
    assert not (tmp_path / "valve.prm.bak").exists()
    doc.set_value("DTAMP", 1000)
    save_document(doc, path)
    assert (tmp_path / "valve.prm.bak").read_bytes() == first
    second = path.read_bytes()
    doc.set_value("DTAMP", 1200)
    save_document(doc, path)
    assert (tmp_path / "valve.prm.bak").read_bytes() == second
    assert not doc.modified and load_document(path).value("DTAMP") == 1200


def _written(path):
    write_file(PrmContents.factory(E02), path)
    return path


@pytest.mark.parametrize("failing_call", [1, 2], ids=["writing the backup", "writing the file"])
def test_a_failure_midway_through_saving_leaves_the_old_file_untouched(
    qapp, tmp_path, monkeypatch, failing_call
):
    path = _written(tmp_path / "valve.prm")
    before = path.read_bytes()
    doc = load_document(path)
    doc.set_value("DTAMP", 1000)
    calls = []

    def write_half_then_fail(stream, data):
        calls.append(data)
        if len(calls) == failing_call:
            stream.write(data[: len(data) // 2])
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
        stream.write(data)

    monkeypatch.setattr(atomicfile, "_write_data", write_half_then_fail)
    with pytest.raises(FileFormatError) as info:
        save_document(doc, path)
    assert info.value.problems == [FileProblem(0, "cannot save the file: No space left on device")]
    assert path.read_bytes() == before
    left = ["valve.prm"] if failing_call == 1 else ["valve.prm", "valve.prm.bak"]
    assert sorted(p.name for p in tmp_path.iterdir()) == left  # no temporary file left
    assert doc.modified and doc.value("DTAMP") == 1000  # nothing lost in the program either


def test_an_interrupt_during_saving_leaves_no_temporary_file(qapp, tmp_path, monkeypatch):
    path = _written(tmp_path / "valve.prm")
    before = path.read_bytes()

    def interrupted(stream, data):
        stream.write(data[:10])
        raise KeyboardInterrupt

    monkeypatch.setattr(atomicfile, "_write_data", interrupted)
    with pytest.raises(KeyboardInterrupt):
        atomicfile.atomic_write(path, b"new", backup=False)
    assert path.read_bytes() == before and [p.name for p in tmp_path.iterdir()] == ["valve.prm"]


@pytest.mark.skipif(sys.platform == "win32", reason="Windows has no mode bits (read-only only)")
def test_saving_keeps_the_permissions_of_the_file(qapp, tmp_path):
    path = _written(tmp_path / "valve.prm")
    path.chmod(0o640)
    save_document(load_document(path), path)
    assert stat.S_IMODE(path.stat().st_mode) == 0o640


def test_a_document_that_would_not_read_back_is_not_written(qapp, tmp_path):
    path = _written(tmp_path / "valve.prm")
    before = path.read_bytes()
    doc = load_document(path)
    doc.unknown_entries.append(("LIMTA", "1"))  # would duplicate a parameter
    with pytest.raises(FileFormatError, match="LIMTA is set twice"):
        save_document(doc, path)
    assert path.read_bytes() == before


def test_load_document_of_a_bad_file_raises_with_every_problem(qapp, tmp_path):
    path = tmp_path / "bad.prm"
    text = replace_line(factory_text(E02), "LIMTA =", "LIMTA = x")
    path.write_text(replace_line(text, "DTAMP =", "DTAMP = 999"), encoding="utf-8")
    with pytest.raises(FileFormatError) as info:
        load_document(path)
    lines = str(info.value).splitlines()
    assert lines[0] == f"{path}:{line_of(text, 'LIMTA')}: LIMTA: 'x' is not a number"
    assert lines[1].startswith(f"{path}:{line_of(text, 'DTAMP')}: DTAMP: 999 % is outside")
    assert lines[2].startswith(f"{path}:{text.count(chr(10))}: warning: checksum does not match")


# --- docs/prm-format.md stays true ------------------------------------------------------------
DOC = Path(__file__).parents[1] / "docs" / "prm-format.md"


def _doc_block(marker: str) -> str:
    text = DOC.read_text(encoding="utf-8")
    start = text.index("```text\n", text.index(f"<!-- generated: {marker} -->")) + len("```text\n")
    return text[start : text.index("```", start)]


def test_the_example_in_the_format_specification_is_what_prm9tool_writes():
    contents = PrmContents.factory(E04_CA)
    contents.serial, contents.firmware = 1234567, "V0.35.16"
    assert _doc_block("example") == contents.to_text()


def test_the_check_output_in_the_format_specification_is_what_prm9tool_reports():
    text = _doc_block("example")
    text = replace_line(text, "THRESETP =", "THRESETP = 5.001  # Setpoint signal: threshold [%]")
    text = replace_line(text, "PRCKP =", "PRCKP = 2x  # Process controller: proportional gain Kp")
    text = replace_line(text, "LIMTA =", "LIMTA = 2700  # bigger solenoid")
    text = replace_line(text, "CANTERM =", "CANTERM = 0\nCOLOR = blue")
    output = "".join(p.format("edited.prm") + "\n" for p in problems_of(text))
    assert _doc_block("check") == output


def test_values_missing_a_parameter_of_the_key_are_refused_in_words_and_nothing_is_written(
    tmp_path,
):
    """Issue 34 item 6: an E02's values under an E04 key (no SENSTYPE …) were a KeyError."""
    e02_values = PrmContents.factory(TypeKey.parse("PRM9-06.3Z11/30-24E02S02-CA")).values
    contents = PrmContents(E04_CA, dict(e02_values))
    path = tmp_path / "out.prm"
    with pytest.raises(FileFormatError) as raised:
        write_file(contents, path)
    assert f"{path}:0: no value for SENSTYPE, SENSINV" in str(raised.value)
    assert f"which every {E04_CA} file holds" in str(raised.value)
    assert not path.exists()

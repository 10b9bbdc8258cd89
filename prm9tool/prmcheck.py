"""The meaning of the entries of a *.prm file: header and values checked against the catalogue.

prmfile.py splits a file into entries; this module decides what they mean and reports every
problem with its line: a missing or unknown format, a bad type key or serial number; unknown
or misplaced mnemonics, values that are not numbers or out of range, missing parameters, and
the catalogue's cross-parameter rules. No Qt.
"""

from __future__ import annotations

import difflib
import math
import re
from dataclasses import dataclass, field

from prm9tool.catalogue import CATALOGUE, Access, Parameter
from prm9tool.errors import FileProblem, TypeKeyError, ValueRangeError
from prm9tool.typekey import TypeKey

FORMAT_NAME = "prm9tool"
FORMAT_VERSION = 1
HEADER_KEYS = frozenset({"format", "type_key", "serial", "firmware"})


@dataclass
class Entry:
    """One ``NAME = value`` line: its number, the value text and the comments around it."""

    line: int
    name: str
    value: str
    comment: str = ""  # "  # ..." after the value, exactly as written
    leading: list[str] = field(default_factory=list)  # comment/blank lines just before


@dataclass
class CheckedEntries:
    """The parameter values of a file (raw), its unknown entries, and every problem found."""

    values: dict[str, int | str] = field(default_factory=dict)
    unknown: list[tuple[str, str]] = field(default_factory=list)
    problems: list[FileProblem] = field(default_factory=list)


class Header:
    """The header entries (format, type key, serial, firmware) and their problems.

    ``readable`` is False when the file does not start with a format line this version of
    prm9tool reads; nothing else in it can then be checked.
    """

    def __init__(self, order: list[Entry], last_line: int) -> None:
        self.problems: list[FileProblem] = []
        self.type_key: TypeKey | None = None
        self.type_key_line = 0
        self.serial: int | None = None
        self.firmware: str | None = None
        self.readable = self._format(order, last_line)
        if not self.readable:
            return
        entries = {entry.name: entry for entry in order}
        if "type_key" not in entries:
            self._error(order[0].line, "no 'type_key = ...' entry: the header is incomplete")
        else:
            self._type_key(entries["type_key"])
        if "serial" in entries:
            self._serial(entries["serial"])
        if "firmware" in entries:
            self._firmware(entries["firmware"])

    def _error(self, line: int, message: str, severity: str = "error") -> None:
        self.problems.append(FileProblem(line, message, severity))

    def _format(self, order: list[Entry], last_line: int) -> bool:
        expected = f"'format = {FORMAT_NAME} {FORMAT_VERSION}'"
        if not order or order[0].name != "format":
            line = order[0].line if order else max(last_line, 1)
            self._error(
                line,
                f"expected {expected} as the first entry: not a prm9tool parameter file, "
                "or its header is damaged",
            )
            return False
        line, value = order[0].line, order[0].value
        match = re.fullmatch(rf"{FORMAT_NAME} ([0-9]{{1,6}})", value)
        if match is None:
            self._error(line, f"format {value!r} is unknown; expected {expected}")
        elif int(match[1]) > FORMAT_VERSION:
            self._error(
                line,
                f"format version {int(match[1])} is newer than this prm9tool reads "
                f"({FORMAT_VERSION}): update prm9tool",
            )
        elif int(match[1]) != FORMAT_VERSION:
            self._error(line, f"format version {int(match[1])} does not exist")
        return not self.problems

    def _type_key(self, entry: Entry) -> None:
        self.type_key_line = entry.line
        try:
            self.type_key = TypeKey.parse(entry.value)
        except TypeKeyError as exc:
            self._error(entry.line, str(exc))

    def _serial(self, entry: Entry) -> None:
        snv = CATALOGUE["SNV"]
        text = entry.value
        digits = len(str(snv.raw_max))
        if (
            not re.fullmatch(f"[0-9]{{1,{digits}}}", text)
            or not snv.raw_min <= int(text) <= snv.raw_max
        ):
            self._error(
                entry.line,
                f"serial {text!r} must be a whole number {snv.raw_min} … {snv.raw_max}",
            )
        else:
            self.serial = int(text)

    def _firmware(self, entry: Entry) -> None:
        if entry.value:
            self.firmware = entry.value
        else:
            self._error(
                entry.line, "firmware is empty; the line is left out when saving", "warning"
            )


def check_entries(
    entries: list[Entry], type_key: TypeKey | None, type_key_line: int
) -> CheckedEntries:
    """Check every parameter entry; without a (valid) type key only variant-free checks run.

    Missing parameters are reported on the type-key line (the type key decides what a file
    must contain); a cross-parameter rule on the line of the first parameter it names.
    """
    result = CheckedEntries()
    lines: dict[str, int] = {}
    for entry in entries:
        if entry.name in HEADER_KEYS:
            continue
        param = CATALOGUE.get(entry.name)
        if param is None:
            result.unknown.append((entry.name, entry.value))
            result.problems.append(FileProblem(entry.line, _unknown(entry.name), "warning"))
            continue
        lines[entry.name] = entry.line
        problem = _misplaced(param, type_key)
        if problem:
            result.problems.append(FileProblem(entry.line, problem))
            continue
        _check_value(param, entry, result)
    if type_key is not None:
        _check_complete(type_key, lines, type_key_line, result)
        for rule in CATALOGUE.check_rules(type_key.variant, result.values):
            line = next((lines[mn] for mn in rule.mnemonics if mn in lines), type_key_line)
            result.problems.append(FileProblem(line, rule.message, rule.severity))
    return result


def _unknown(name: str) -> str:
    message = f"unknown parameter {name!r}: kept and written back unchanged"
    close = difflib.get_close_matches(name.upper(), [p.mnemonic for p in CATALOGUE], 1, 0.8)
    return f"{message} (did you mean {close[0]}?)" if close else message


def _misplaced(param: Parameter, type_key: TypeKey | None) -> str:
    """Why ``param`` may not appear in this file, or an empty string."""
    name = f"{param.mnemonic} ({param.text.en})"
    if not param.in_file:
        if param.access is Access.READ_ONLY:
            return f"{name} is a read-only value, not a setting a parameter file can hold"
        return f"{name} is set online only and does not belong in a parameter file"
    if type_key is not None and not param.applies(type_key.variant):
        return (
            f"{name} does not exist on {type_key.variant.label} valves (type key {type_key}); "
            "remove the line or change the type key"
        )
    return ""


def _check_value(param: Parameter, entry: Entry, result: CheckedEntries) -> None:
    if not entry.value:
        result.problems.append(FileProblem(entry.line, f"{param.mnemonic}: no value after '='"))
        return
    try:
        raw = param.parse_display(entry.value)
        param.check_raw(raw)
    except ValueRangeError as exc:
        result.problems.append(FileProblem(entry.line, str(exc)))
        return
    result.values[param.mnemonic] = raw
    note = _rounding(param, entry.value, raw)
    if note:
        result.problems.append(FileProblem(entry.line, note, "warning"))


def _rounding(param: Parameter, text: str, raw: int | str) -> str:
    """A warning when ``text`` is not exactly a value the valve can hold, else ''."""
    cleaned = text.replace(",", ".") if text.count(",") == 1 else text
    try:
        written = float(cleaned)
    except ValueError:
        return ""  # a choice label such as "±10 V bipolar"
    stored = param.format_display(raw)
    if not math.isfinite(written) or written == float(stored):
        return ""
    unit = f" {param.unit}" if param.unit else ""
    return (
        f"{param.mnemonic}: {text}{unit} is stored as {stored}{unit}, "
        "the nearest value the valve can hold"
    )


def _check_complete(
    type_key: TypeKey, lines: dict[str, int], type_key_line: int, result: CheckedEntries
) -> None:
    for param in CATALOGUE.file_parameters(type_key.variant):
        if param.mnemonic not in lines:
            result.problems.append(
                FileProblem(
                    type_key_line,
                    f"{param.mnemonic} ({param.text.en}) is missing "
                    f"(required for {type_key.variant.label} valves)",
                )
            )

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

from prm9tool.catalogue import CATALOGUE, Access, Parameter, variant_label
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.errors import FileProblem, TypeKeyError, ValueRangeError
from prm9tool.messages import QT_TRANSLATE_NOOP, SHOWN_CHARACTERS, Message, message_of, quoted

# A spelling suggestion for an unknown name compares it with every catalogue mnemonic; a file
# full of unknown names (1 MiB holds 60 000) took 10-19 s. Typos in a real file are a handful.
MAX_SUGGESTIONS = 20
FORMAT_NAME = "prm9tool"
FORMAT_VERSION = 1
HEADER_KEYS = frozenset({"format", "type_key", "serial", "firmware"})

_NO_FORMAT = QT_TRANSLATE_NOOP(
    "Problems",
    "expected {0} as the first entry: not a prm9tool parameter file, or its header is damaged",
)
_UNKNOWN_FORMAT = QT_TRANSLATE_NOOP("Problems", "format {0} is unknown; expected {1}")
_NEWER_FORMAT = QT_TRANSLATE_NOOP(
    "Problems", "format version {0} is newer than this prm9tool reads ({1}): update prm9tool"
)
_NO_SUCH_FORMAT = QT_TRANSLATE_NOOP("Problems", "format version {0} does not exist")
_NO_TYPE_KEY = QT_TRANSLATE_NOOP("Problems", "no 'type_key = ...' entry: the header is incomplete")
_BAD_SERIAL = QT_TRANSLATE_NOOP("Problems", "serial {0} must be a whole number {1} … {2}")
_EMPTY_FIRMWARE = QT_TRANSLATE_NOOP(
    "Problems", "firmware is empty; the line is left out when saving"
)
_UNKNOWN = QT_TRANSLATE_NOOP("Problems", "unknown parameter {0}: kept and written back unchanged")
_UNKNOWN_CLOSE = QT_TRANSLATE_NOOP(
    "Problems", "unknown parameter {0}: kept and written back unchanged (did you mean {1}?)"
)
_READ_ONLY = QT_TRANSLATE_NOOP(
    "Problems", "{0} ({1}) is a read-only value, not a setting a parameter file can hold"
)
_ONLINE_ONLY = QT_TRANSLATE_NOOP(
    "Problems", "{0} ({1}) is set online only and does not belong in a parameter file"
)
_NOT_ON_VARIANT = QT_TRANSLATE_NOOP(
    "Problems",
    "{0} ({1}) does not exist on {2} valves (type key {3}); remove the line or change the type key",
)
_NOT_IN_SET = QT_TRANSLATE_NOOP(
    "Problems",
    "{0} ({1}) is not a parameter of {2} valves (type key {3}): they have the object but no"
    " external sensor input; remove the line or change the type key",
)
_NO_VALUE = QT_TRANSLATE_NOOP("Problems", "{0}: no value after '='")
_ROUNDED = QT_TRANSLATE_NOOP(
    "Problems", "{0}: {1}{2} is stored as {3}{2}, the nearest value the valve can hold"
)
_NOT_AVAILABLE = QT_TRANSLATE_NOOP(
    "Problems",
    "{0} has no value: the valve it was read from does not have it over CANopen; not uploaded",
)
_MISSING = QT_TRANSLATE_NOOP("Problems", "{0} ({1}) is missing (required for {2} valves)")
_NO_VALUE_NOT_MARKED = QT_TRANSLATE_NOOP(
    "Problems",
    "{0}: no value after '='; only a download over CANopen may leave a value out, marked with"
    " the comment '{1}'",
)

# The one way a parameter may stand in a file without a value: a download over CANopen from a
# valve without this project's object writes the line with this comment (docs/prm-format.md).
NOT_AVAILABLE_HINT = "  # not available over CANopen on the valve this was read from"


_MNEMONICS = [p.mnemonic for p in CATALOGUE]

# What a free text of the header (the firmware a valve reports) must not hold as it is: a
# backslash (the escape itself), a control character (a new line would inject an entry), a TAB,
# a "#" (after a blank it starts a comment), and blanks at either end (the reader strips them).
_MUST_ESCAPE = re.compile(r"[\\\x00-\x1f\x7f-\x9f#]|^\s|\s$")
_ESCAPE = re.compile(r"\\(?:x([0-9a-f]{2})|u([0-9a-f]{4})|U([0-9a-f]{8}))")


def escape_text(text: str) -> str:
    """``text`` as a header value that reads back exactly (:func:`unescape_text`): each
    character that would change or end it written as ``\\xNN`` (``\\uNNNN``,
    ``\\UNNNNNNNN`` beyond Latin-1), e.g. ``1.0 \\x23 beta`` for ``1.0 # beta``."""
    return _MUST_ESCAPE.sub(lambda m: "".join(map(_escaped, m.group())), text)


def _escaped(char: str) -> str:
    code = ord(char)
    if code <= 0xFF:
        return f"\\x{code:02x}"
    return f"\\u{code:04x}" if code <= 0xFFFF else f"\\U{code:08x}"


def unescape_text(value: str) -> str:
    """A header value as the text it stands for: ``\\xNN``, ``\\uNNNN``, ``\\UNNNNNNNN``
    (lower-case hex) are that character; any other backslash is itself (a file written by
    hand, or before this escaping)."""
    return _ESCAPE.sub(lambda m: chr(int(next(g for g in m.groups() if g), 16)), value)


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
            self._error(order[0].line, _NO_TYPE_KEY())
        else:
            self._type_key(entries["type_key"])
        if "serial" in entries:
            self._serial(entries["serial"])
        if "firmware" in entries:
            self._firmware(entries["firmware"])

    def _error(self, line: int, message: Message | str, severity: str = "error") -> None:
        self.problems.append(FileProblem(line, message, severity))

    def _format(self, order: list[Entry], last_line: int) -> bool:
        expected = f"'format = {FORMAT_NAME} {FORMAT_VERSION}'"
        if not order or order[0].name != "format":
            line = order[0].line if order else max(last_line, 1)
            self._error(line, _NO_FORMAT(expected))
            return False
        line, value = order[0].line, order[0].value
        match = re.fullmatch(rf"{FORMAT_NAME} ([0-9]{{1,6}})", value)
        if match is None:
            self._error(line, _UNKNOWN_FORMAT(quoted(value), expected))
        elif int(match[1]) > FORMAT_VERSION:
            self._error(line, _NEWER_FORMAT(int(match[1]), FORMAT_VERSION))
        elif int(match[1]) != FORMAT_VERSION:
            self._error(line, _NO_SUCH_FORMAT(int(match[1])))
        return not self.problems

    def _type_key(self, entry: Entry) -> None:
        self.type_key_line = entry.line
        try:
            self.type_key = TypeKey.parse(entry.value)
        except TypeKeyError as exc:
            self._error(entry.line, message_of(exc))

    def _serial(self, entry: Entry) -> None:
        snv = CATALOGUE["SNV"]
        text = entry.value
        digits = len(str(snv.raw_max))
        if (
            not re.fullmatch(f"[0-9]{{1,{digits}}}", text)
            or not snv.raw_min <= int(text) <= snv.raw_max
        ):
            self._error(entry.line, _BAD_SERIAL(quoted(text), snv.raw_min, snv.raw_max))
        else:
            self.serial = int(text)

    def _firmware(self, entry: Entry) -> None:
        if entry.value:
            self.firmware = unescape_text(entry.value)  # exactly what the valve reported
        else:
            self._error(entry.line, _EMPTY_FIRMWARE(), "warning")


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
            suggest = len(result.unknown) < MAX_SUGGESTIONS
            result.unknown.append((entry.name, entry.value))
            result.problems.append(
                FileProblem(entry.line, _unknown(entry.name, suggest), "warning")
            )
            continue
        lines[entry.name] = entry.line
        problem = _misplaced(param, type_key)
        if problem is not None:
            result.problems.append(FileProblem(entry.line, problem))
            continue
        _check_value(param, entry, result, type_key)
    if type_key is not None:
        _check_complete(type_key, lines, type_key_line, result)
        for rule in CATALOGUE.check_rules(type_key.variant, result.values):
            line = next((lines[mn] for mn in rule.mnemonics if mn in lines), type_key_line)
            result.problems.append(FileProblem(line, rule.text, rule.severity))
    return result


def _unknown(name: str, suggest: bool) -> Message:
    close = _close_mnemonic(name.upper()) if suggest else None
    if close is not None:
        return _UNKNOWN_CLOSE(quoted(name), close)
    return _UNKNOWN(quoted(name))


def _close_mnemonic(name: str) -> str | None:
    """The catalogue mnemonic ``name`` is probably a misspelling of, or None.

    Costs a comparison with every mnemonic (about 1 ms), hence only for the first
    ``MAX_SUGGESTIONS`` unknown names of a file.
    """
    close = difflib.get_close_matches(name, _MNEMONICS, 1, 0.8)
    return close[0] if close else None


def _misplaced(param: Parameter, type_key: TypeKey | None) -> Message | None:
    """Why ``param`` may not appear in this file, or None."""
    if not param.in_file:
        if param.access is Access.READ_ONLY:
            return _READ_ONLY(param.mnemonic, param.text)
        return _ONLINE_ONLY(param.mnemonic, param.text)
    if type_key is not None and not param.applies(type_key.variant):
        variant = variant_label(type_key.variant)
        # an object of the valve outside its parameter set: the external sensor on an E02 -CA
        text = _NOT_IN_SET if param.on_device(type_key.variant) else _NOT_ON_VARIANT
        return text(param.mnemonic, param.text, variant, str(type_key))
    return None


def marked_absent(param: Parameter, entry: Entry, type_key: TypeKey | None) -> bool:
    """True for the line a download over CANopen writes for an object the valve lacks: no
    value, the comment :data:`NOT_AVAILABLE_HINT`, a parameter at this project's own address
    (the manual's objects every -CA valve has), and a -CA type key."""
    return (
        not entry.value
        and entry.comment.strip() == NOT_AVAILABLE_HINT.strip()
        and not param.address_from_manual
        and (type_key is None or type_key.canopen)
    )


def _check_value(
    param: Parameter, entry: Entry, result: CheckedEntries, type_key: TypeKey | None
) -> None:
    if marked_absent(param, entry, type_key):
        result.problems.append(FileProblem(entry.line, _NOT_AVAILABLE(param.mnemonic), "warning"))
        return
    if not entry.value:
        marker = NOT_AVAILABLE_HINT.strip()
        can_be_marked = not param.address_from_manual and (type_key is None or type_key.canopen)
        problem = _NO_VALUE_NOT_MARKED(param.mnemonic, marker) if can_be_marked else None
        result.problems.append(FileProblem(entry.line, problem or _NO_VALUE(param.mnemonic)))
        return
    try:
        raw = param.parse_display(entry.value)
        param.check_raw(raw)
    except ValueRangeError as exc:
        result.problems.append(FileProblem(entry.line, message_of(exc)))
        return
    result.values[param.mnemonic] = raw
    note = _rounding(param, entry.value, raw)
    if note is not None:
        result.problems.append(FileProblem(entry.line, note, "warning"))


def _rounding(param: Parameter, text: str, raw: int | str) -> Message | None:
    """A warning when ``text`` is not exactly a value the valve can hold, else None."""
    try:
        written = float(text)
    except ValueError:
        return None  # a choice label such as "±10 V bipolar"
    stored = param.format_display(raw)
    if not math.isfinite(written) or written == float(stored):
        return None
    unit = f" {param.unit}" if param.unit else ""
    shown = text if len(text) <= SHOWN_CHARACTERS else quoted(text)
    return _ROUNDED(param.mnemonic, shown, unit, stored)


def _check_complete(
    type_key: TypeKey, lines: dict[str, int], type_key_line: int, result: CheckedEntries
) -> None:
    for param in CATALOGUE.file_parameters(type_key.variant):
        if param.mnemonic not in lines:
            result.problems.append(
                FileProblem(
                    type_key_line,
                    _MISSING(param.mnemonic, param.text, variant_label(type_key.variant)),
                )
            )

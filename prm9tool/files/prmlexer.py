"""The lines of a *.prm file: bytes split into ``NAME = value  # comment`` entries and the
comment lines before each, with what makes a file corrupt (not UTF-8, control characters,
garbled lines, a name set twice, text after the checksum), and the checksum itself
(docs/prm-format.md). What the entries mean is prmcheck.py's business. No Qt.
"""

from __future__ import annotations

import re
import zlib

from prm9tool.errors import FileProblem
from prm9tool.files.prmcheck import Entry
from prm9tool.messages import QT_TRANSLATE_NOOP, Message, quoted

_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_.\-]*")
_CHECKSUM = re.compile(r"^crc32:[0-9a-f]{8}$")
_BOM = b"\xef\xbb\xbf"
CONTROL_CHARACTERS = re.compile(r"[\x00-\x08\x0a-\x1f\x7f-\x9f]")  # all but TAB: binary data
_NOT_UTF8 = QT_TRANSLATE_NOOP("Problems", "byte 0x{0} is not UTF-8 text: the file is corrupt")
_CONTROL_CHARACTER = QT_TRANSLATE_NOOP(
    "Problems", "control character U+{0}: binary data, the file is corrupt"
)
_AFTER_CHECKSUM = QT_TRANSLATE_NOOP(
    "Problems", "text after the checksum line, which must be the last line"
)
_GARBLED = QT_TRANSLATE_NOOP(
    "Problems", "garbled line: expected 'NAME = value', a '#' comment or a blank line"
)
_TWICE = QT_TRANSLATE_NOOP("Problems", "{0} is set twice (first on line {1})")
_NO_CHECKSUM = QT_TRANSLATE_NOOP(
    "Problems",
    "no 'checksum = ...' line at the end: the file is truncated (a file written by "
    "hand must end with one, e.g. 'checksum = crc32:00000000')",
)
_CHECKSUM_DAMAGED = QT_TRANSLATE_NOOP(
    "Problems", "checksum {0} is damaged (expected crc32: and 8 hex digits)"
)
_CHECKSUM_CHANGED = QT_TRANSLATE_NOOP(
    "Problems",
    "checksum does not match: the file was changed outside prm9tool (edited by hand?); "
    "saving it from prm9tool writes a new checksum",
)


def checksum(lines: list[str]) -> str:
    """The integrity check of the lines before the checksum line (docs/prm-format.md)."""
    crc = 0
    for line in lines:
        crc = zlib.crc32(line.encode("utf-8") + b"\n", crc)
    return f"crc32:{crc:08x}"


class Lexer:
    """Splits the bytes into entries and comment lines; finds what makes a file corrupt."""

    def __init__(self) -> None:
        self.problems: list[FileProblem] = []
        self.entries: dict[str, Entry] = {}
        self.order: list[Entry] = []
        self.pending: list[str] = []  # comment and blank lines waiting for their entry
        self.seen: list[str] = []  # decoded lines before the checksum line
        self.checksum: Entry | None = None
        self.last_line = 0

    def error(self, line: int, message: Message) -> None:
        """Report ``message`` on ``line``."""
        self.problems.append(FileProblem(line, message))

    def run(self, data: bytes) -> None:
        """Split ``data`` (a whole file) into lines, entries and problems."""
        if data.startswith(_BOM):
            data = data[len(_BOM) :]
        raw_lines = data.split(b"\n")
        if raw_lines[-1] == b"":
            raw_lines.pop()
        self.last_line = len(raw_lines)
        for number, raw in enumerate(raw_lines, start=1):
            text = self._decode(number, raw.removesuffix(b"\r"))
            if text is not None:
                self._line(number, text)

    def _decode(self, number: int, raw: bytes) -> str | None:
        try:
            text = raw.decode("utf-8")
        except UnicodeDecodeError as exc:
            self.error(number, _NOT_UTF8(f"{raw[exc.start]:02X}"))
            return None
        bad = CONTROL_CHARACTERS.search(text)
        if bad is not None:
            code = ord(bad.group())
            self.error(number, _CONTROL_CHARACTER(f"{code:04X}"))
            return None
        return text

    def _line(self, number: int, text: str) -> None:
        stripped = text.strip()
        if self.checksum is not None:
            if stripped:
                self.error(number, _AFTER_CHECKSUM())
            return
        entry = _split_entry(number, text) if stripped and stripped[0] != "#" else None
        if entry is None:
            if stripped and stripped[0] != "#":
                self.error(number, _GARBLED())
            self.pending.append(text)
            self.seen.append(text)
            return
        if entry.name != "checksum":
            self.seen.append(text)
        self._entry(entry)

    def _entry(self, entry: Entry) -> None:
        entry.leading, self.pending = self.pending, []
        if entry.name == "checksum":
            self.checksum = entry
            return
        first = self.entries.get(entry.name)
        if first is not None:
            self.error(entry.line, _TWICE(entry.name, first.line))
            return
        self.entries[entry.name] = entry
        self.order.append(entry)


def _split_entry(number: int, text: str) -> Entry | None:
    """``NAME = value  # comment`` as an Entry, or None (linear time, whatever the line)."""
    name, equals, rest = text.partition("=")
    name = name.strip()
    if not equals or not _NAME.fullmatch(name):
        return None
    hash_at = rest.find("#")
    while hash_at > 0 and not rest[hash_at - 1].isspace():
        hash_at = rest.find("#", hash_at + 1)
    if hash_at <= 0:
        return Entry(number, name, rest.strip())
    value_end = len(rest[:hash_at].rstrip())
    return Entry(number, name, rest[:value_end].strip(), rest[value_end:])


def check_integrity(lexer: Lexer) -> list[FileProblem]:
    """The checksum line's problem: missing (truncated file), damaged, or not matching."""
    entry = lexer.checksum
    if entry is None:
        return [FileProblem(lexer.last_line, _NO_CHECKSUM())]
    if not _CHECKSUM.match(entry.value):
        return [FileProblem(entry.line, _CHECKSUM_DAMAGED(quoted(entry.value)))]
    if entry.value != checksum(lexer.seen):
        return [FileProblem(entry.line, _CHECKSUM_CHANGED(), "warning")]
    return []

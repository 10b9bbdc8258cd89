"""*.prm parameter files: read with every problem reported by line, write atomically.

The format is specified in docs/prm-format.md::

    # comments and blank lines anywhere before the checksum
    format = prm9tool 1
    type_key = PRM9-06.3Z11/30-24E04S02-CA
    serial = 1234567                  (optional: the valve the values were read from)
    firmware = V0.35.16               (optional)
    AINSETP = 9  # Setpoint signal: signal type
    ...                               (one MNEMONIC = value per parameter, display units)
    checksum = crc32:0123abcd         (always the last line)

This module uses no Qt, so ``--check`` and ``--new`` run without it; only
:func:`load_document` and :func:`save_document` import the (QtCore) document model.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from pathlib import Path

from prm9tool.catalogue import CATALOGUE, Parameter
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.errors import FileFormatError, FileProblem
from prm9tool.files.atomicfile import atomic_write, remove_stale_temporaries
from prm9tool.files.prmcheck import (
    FORMAT_NAME,
    FORMAT_VERSION,
    NOT_AVAILABLE_HINT,
    Header,
    check_entries,
    escape_text,
)
from prm9tool.files.prmlexer import CONTROL_CHARACTERS, Lexer, check_integrity, checksum
from prm9tool.messages import QT_TRANSLATE_NOOP, Message

MAX_FILE_SIZE = 1 << 20  # a full file is about 4 kB; anything near 1 MiB is not a *.prm file
BANNER = (
    "# PRM9 valve parameters, written by prm9tool (format: docs/prm-format.md).",
    "# One MNEMONIC = value per line, in display units; lines starting with # are comments.",
)


@dataclass
class PrmContents:
    """Everything a *.prm file holds; values are raw (as in the object dictionary)."""

    type_key: TypeKey
    values: dict[str, int | str]
    serial: int | None = None
    firmware: str | None = None
    unknown: list[tuple[str, str]] = field(default_factory=list)
    comments: dict[str, list[str]] = field(default_factory=dict)  # lines before an entry
    inline_comments: dict[str, str] = field(default_factory=dict)  # "  # ..." after a value
    warnings: list[FileProblem] = field(default_factory=list)  # found while reading

    @classmethod
    def factory(cls, type_key: TypeKey) -> PrmContents:
        """The factory defaults of ``type_key`` (what ``--new`` writes)."""
        params = CATALOGUE.file_parameters(type_key.variant)
        return cls(type_key, {p.mnemonic: p.default_for(type_key.variant) for p in params})

    def to_text(self) -> str:
        """The file text: header, parameters in catalogue order, unknown entries, checksum.

        FileFormatError (path ``<parameter set>``) when a value the type key's file must hold
        is missing: a value may be absent only where a -CA valve has no object at this
        project's own address (written empty, marked not available)."""
        missing = self.missing_values()
        if missing:
            raise FileFormatError("<parameter set>", [FileProblem(0, _missing_text(self, missing))])
        lines: list[str] = []
        self._emit(lines, "format", f"{FORMAT_NAME} {FORMAT_VERSION}", list(BANNER))
        self._emit(lines, "type_key", str(self.type_key))
        if self.serial is not None:
            self._emit(lines, "serial", str(self.serial))
        if self.firmware:
            self._emit(lines, "firmware", escape_text(self.firmware))
        for number, param in enumerate(CATALOGUE.file_parameters(self.type_key.variant)):
            raw = self.values.get(param.mnemonic)
            value = "" if raw is None else param.format_display(raw)
            hint = _hint(param) if raw is not None else NOT_AVAILABLE_HINT
            self._emit(lines, param.mnemonic, value, [""] if number == 0 else [], hint)
        for name, value in self.unknown:
            self._emit(lines, name, value)
        lines.extend(self.comments.get("checksum", [""]))
        lines.append(f"checksum = {checksum(lines)}")
        return "\n".join(lines) + "\n"

    def missing_values(self) -> list[str]:
        """The parameters of the type key's file without a value that the file cannot mark
        "not available" (the manual's objects, or any on a key without -CA)."""
        return [
            param.mnemonic
            for param in CATALOGUE.file_parameters(self.type_key.variant)
            if param.mnemonic not in self.values
            and (param.address_from_manual or not self.type_key.canopen)
        ]

    def _emit(
        self,
        lines: list[str],
        name: str,
        value: str,
        leading: list[str] | None = None,
        hint: str = "",
    ) -> None:
        lines.extend(self.comments.get(name, leading or []))
        value = _escape_controls(value)  # values from a device are data, never file structure
        entry = _entry_text(name, value)
        lines.append(entry + self.inline_comments.get(name, hint))


_MISSING = QT_TRANSLATE_NOOP(
    "Problems",
    "no value for {0}, which every {1} file holds: these are not the values of such a valve",
)


def _missing_text(contents: PrmContents, missing: list[str]) -> Message:
    names = ", ".join(missing[:4]) + (f" … ({len(missing)})" if len(missing) > 4 else "")
    return _MISSING(names, str(contents.type_key))


def _escape_controls(value: str) -> str:
    """``value`` with every control character written as ``\\xNN`` (a CR/LF in a firmware text
    would otherwise start a new line, i.e. inject an entry)."""
    return CONTROL_CHARACTERS.sub(lambda m: f"\\x{ord(m.group()):02x}", value)


def _entry_text(name: str, value: str) -> str:
    """``NAME = value``; a value starting with ``#`` follows the ``=`` directly (``FOO =#x``).

    The reader takes ``#`` after whitespace as the start of an inline comment, except right
    after the ``=``: so ``FOO=#x`` holds the value ``#x`` and must not be written ``FOO = #x``
    (an empty value and a comment).
    """
    if not value:
        return f"{name} ="
    if value.startswith("#"):
        return f"{name} ={value}"
    return f"{name} = {value}"


def _hint(param: Parameter) -> str:
    unit = f" [{param.unit}]" if param.unit else ""
    return f"  # {param.text.en}{unit}"


@dataclass
class CheckResult:
    """The outcome of reading a file: every problem, and the contents when there is no error."""

    problems: list[FileProblem]
    contents: PrmContents | None

    @property
    def errors(self) -> list[FileProblem]:
        """The problems that make the file unusable."""
        return [p for p in self.problems if p.severity == "error"]

    @property
    def valid(self) -> bool:
        """True when the file can be used (warnings allowed)."""
        return self.contents is not None


# --- reading ----------------------------------------------------------------------------------
_TOO_LARGE = QT_TRANSLATE_NOOP(
    "Problems", "too large to be a parameter file ({0} bytes, more than {1})"
)
_EMPTY = QT_TRANSLATE_NOOP("Problems", "the file is empty")
_CANNOT_READ = QT_TRANSLATE_NOOP("Problems", "cannot read the file: {0}")
_CANNOT_SAVE = QT_TRANSLATE_NOOP("Problems", "cannot save the file: {0}")


def check_bytes(data: bytes) -> CheckResult:
    """Read a file's bytes and report every problem; never raises."""
    if len(data) > MAX_FILE_SIZE:
        return CheckResult([FileProblem(0, _TOO_LARGE(len(data), MAX_FILE_SIZE))], None)
    lexer = Lexer()
    lexer.run(data)
    if lexer.last_line == 0:
        return CheckResult([FileProblem(0, _EMPTY())], None)
    problems = list(lexer.problems)
    header = Header(lexer.order, lexer.last_line)
    problems.extend(header.problems)
    if not header.readable:  # not a prm9tool file: checking its entries would only add noise
        return CheckResult(sorted(problems, key=lambda p: p.line), None)
    problems.extend(check_integrity(lexer))
    checked = check_entries(lexer.order, header.type_key, header.type_key_line)
    problems.extend(checked.problems)
    problems.sort(key=lambda p: p.line)
    if any(p.severity == "error" for p in problems) or header.type_key is None:
        return CheckResult(problems, None)
    contents = PrmContents(
        header.type_key,
        checked.values,
        header.serial,
        header.firmware,
        checked.unknown,
        {e.name: e.leading for e in [*lexer.order, lexer.checksum] if e is not None},
        {e.name: e.comment for e in lexer.order},
        problems,
    )
    return CheckResult(problems, contents)


def check_file(path: str | os.PathLike[str]) -> CheckResult:
    """Read and check the file at ``path``; never raises (I/O errors become problems)."""
    try:
        with open(path, "rb") as stream:
            data = stream.read(MAX_FILE_SIZE + 1)
    except OSError as exc:
        problem = FileProblem(0, _CANNOT_READ(exc.strerror or str(exc)))
        return CheckResult([problem], None)
    return check_bytes(data)


def read_bytes(data: bytes, path: str = "<bytes>") -> PrmContents:
    """Parse file bytes; raises FileFormatError listing every problem (never anything else)."""
    return _contents_or_raise(check_bytes(data), path)


def read_file(path: str | os.PathLike[str]) -> PrmContents:
    """Read a *.prm file; raises FileFormatError listing every problem (never anything else).

    Removes the temporary files that a killed save of it left (atomicfile)."""
    remove_stale_temporaries(Path(path))
    return _contents_or_raise(check_file(path), os.fspath(path))


def _contents_or_raise(result: CheckResult, path: str) -> PrmContents:
    if result.contents is None:
        raise FileFormatError(path, result.problems)
    return result.contents


# --- writing ----------------------------------------------------------------------------------
def text_for(contents: PrmContents, path: str | os.PathLike[str]) -> str:
    """``contents.to_text()``; its FileFormatError names ``path``."""
    try:
        return contents.to_text()
    except FileFormatError as exc:
        raise FileFormatError(os.fspath(path), exc.problems) from None


def write_file(
    contents: PrmContents, path: str | os.PathLike[str], backup: bool = True
) -> PrmContents:
    """Write ``contents`` atomically (old file kept as ``<name>.bak``); returns what was written.

    The result is the written file read back: its comments are the ones the file now has and
    its ``warnings`` the file's warnings.

    Refuses (FileFormatError, nothing written) to write a file it could not read back, and
    turns I/O errors into FileFormatError (line 0); the old file is then untouched.
    """
    text = text_for(contents, path)
    result = check_bytes(text.encode("utf-8"))
    if result.contents is None:
        raise FileFormatError(os.fspath(path), result.errors)
    try:
        atomic_write(Path(path), text.encode("utf-8"), backup=backup)
    except OSError as exc:
        problem = FileProblem(0, _CANNOT_SAVE(exc.strerror or str(exc)))
        raise FileFormatError(os.fspath(path), [problem]) from exc
    return result.contents

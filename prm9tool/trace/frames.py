"""Reading a trace file's frames with python-can's own readers (``can.io``), with the position of
a line or frame the reader cannot take: ASC (Vector), BLF (Vector binary), TRC (PEAK), candump
``.log``, and python-can's CSV. No Qt."""

from __future__ import annotations

import logging
from collections.abc import Iterator
from pathlib import Path
from typing import IO, TYPE_CHECKING, Any

from prm9tool.errors import FileFormatError, FileProblem

if TYPE_CHECKING:
    import can

TEXT_FORMATS = (".asc", ".trc", ".log", ".csv")
BINARY_FORMATS = (".blf",)
FORMATS = TEXT_FORMATS + BINARY_FORMATS


class TraceFormatError(FileFormatError):
    """A trace file that cannot be read: the path, the line (text formats; 0 for binary ones)
    and what is wrong, with how many frames were read before it."""

    def __init__(self, path: str, line: int, text: str) -> None:
        self.line = line
        super().__init__(path, [FileProblem(line, text)])
        if not line:  # a binary file or the whole file: no line to name
            self.args = (f"{path}: {text}",)


def trace_format(path: str | Path) -> str:
    """The suffix naming the format of ``path``; TraceFormatError for one python-can cannot read."""
    suffix = Path(path).suffix.lower()
    if suffix not in FORMATS:
        known = ", ".join(FORMATS)
        raise TraceFormatError(
            str(path), 0, f"unknown trace format {suffix or '(none)'!r}: use {known}"
        )
    return suffix


class _CountedLines:
    """A text file that counts the lines python-can's reader has taken from it."""

    def __init__(self, file: IO[str]) -> None:
        self._file = file
        self.line = 0

    def __iter__(self) -> _CountedLines:
        return self

    def __next__(self) -> str:
        text = next(self._file)
        self.line += 1
        return text

    def readline(self, *args: Any) -> str:
        text = self._file.readline(*args)
        if text:
            self.line += 1
        return text

    def __getattr__(self, name: str) -> Any:
        return getattr(self._file, name)


def read_frames(path: str | Path) -> Iterator[can.Message]:
    """Every frame of the trace ``path`` in file order; TraceFormatError with the line (or, in a
    binary file, the frame number) where the file stops making sense: where python-can's
    reader raises, where it drops a line it cannot parse (it only logs a warning), and for a
    BLF file shorter than its header says (truncated: python-can would stop silently)."""
    import can

    suffix = trace_format(path)
    reader_class = can.io.player.MESSAGE_READERS[suffix]
    name = str(path)
    try:
        if suffix in TEXT_FORMATS:  # closed in the finally below (a generator's lifetime)
            raw: IO[Any] = open(path, encoding="utf-8", errors="replace")  # noqa: SIM115
        else:
            raw = open(path, "rb")  # noqa: SIM115
    except OSError as exc:
        raise TraceFormatError(name, 0, f"cannot open the trace: {exc.strerror or exc}") from exc
    counted = _CountedLines(raw) if suffix in TEXT_FORMATS else None
    dropped = _DroppedLines(counted)
    count = 0

    def problem(reason: str) -> TraceFormatError:
        line = dropped.line or (counted.line if counted is not None else 0)
        where = f"at line {line}" if counted is not None else f"after frame {count}"
        return TraceFormatError(
            name, line,
            f"not a valid {suffix[1:].upper()} trace {where} ({count} frames read before it): {reason}",
        )  # fmt: skip

    io_log = logging.getLogger("can.io")
    io_log.addHandler(dropped)
    try:
        reader = reader_class(counted if counted is not None else raw)  # type: ignore[arg-type]
        for message in reader:
            if dropped.reason:
                raise problem(dropped.reason)
            count += 1
            yield message
        if dropped.reason:
            raise problem(dropped.reason)
        _check_complete(reader, path, problem)
    except TraceFormatError:
        raise
    except Exception as exc:  # python-can's readers raise what their parsing meets
        raise problem(str(exc) or type(exc).__name__) from exc
    finally:
        io_log.removeHandler(dropped)
        raw.close()


class _DroppedLines(logging.Handler):
    """A line python-can's reader dropped with a warning (TRC: "Failed to parse message")."""

    def __init__(self, counted: _CountedLines | None) -> None:
        super().__init__(logging.WARNING)
        self._counted = counted
        self.reason = ""
        self.line = 0

    def emit(self, record: logging.LogRecord) -> None:
        if not self.reason and "Writer" not in record.getMessage():
            self.reason = record.getMessage()
            self.line = self._counted.line if self._counted is not None else 0


def _check_complete(reader: Any, path: str | Path, problem: Any) -> None:
    """A BLF file shorter than the size its header gives was cut off."""
    expected = getattr(reader, "file_size", 0)
    if isinstance(expected, int) and expected > 0:
        actual = Path(path).stat().st_size
        if actual < expected:
            raise problem(
                f"the file is truncated: its header gives {expected} bytes, it has {actual}"
            )

"""Reading a trace file's frames with python-can's own readers (``can.io``), with the position of
a line or frame the reader cannot take: ASC (Vector), BLF (Vector binary), TRC (PEAK), candump
``.log``, and python-can's CSV. No Qt."""

from __future__ import annotations

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
    binary file, the frame number) where the file stops making sense."""
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
    count = 0
    try:
        reader = reader_class(counted if counted is not None else raw)  # type: ignore[arg-type]
        for message in reader:
            count += 1
            yield message
    except Exception as exc:  # python-can's readers raise what their parsing meets
        line = counted.line if counted is not None else 0
        where = f"line {line}" if counted is not None else f"after frame {count}"
        reason = str(exc) or type(exc).__name__
        raise TraceFormatError(
            name,
            line,
            f"not a valid {suffix[1:].upper()} trace at {where} ({count} frames read before it): {reason}",
        ) from exc
    finally:
        raw.close()

"""What the batch mode reports: one record per valve, progress lines, the JSON report file.

The report schema is documented in docs/batch.md; keep both in step.
"""

from __future__ import annotations

import json
import sys
import threading
import time
from dataclasses import asdict, dataclass, field
from datetime import UTC, datetime
from pathlib import Path
from typing import Any

from prm9tool._version import __version__
from prm9tool.errors import ExitCode
from prm9tool.files.atomicfile import atomic_write

SCHEMA = 1
# Outcome of one valve -> exit code; the run exits with the most serious one.
RESULTS = {
    "ok": ExitCode.OK,
    "dry-run": ExitCode.OK,
    "downloaded": ExitCode.OK,
    "verification-failed": ExitCode.VERIFY_FAILED,
    "store-failed": ExitCode.VERIFY_FAILED,  # refused or unconfirmed store: nothing stored
    "type-mismatch": ExitCode.TYPE_MISMATCH,
    "communication-error": ExitCode.COMMUNICATION,
}
SEVERITY = (ExitCode.COMMUNICATION, ExitCode.TYPE_MISMATCH, ExitCode.VERIFY_FAILED, ExitCode.OK)


@dataclass
class ValveRecord:
    """The outcome for one valve (one entry of the report's ``valves`` list)."""

    device_id: str
    kind: str
    serial: int
    type_key: str
    firmware: str
    result: str = "communication-error"
    parameters_written: int = 0
    verification: str = "not-run"  # "passed" | "failed" | "not-run"
    mismatches: dict[str, dict[str, Any]] = field(default_factory=dict)
    failed_step: str | None = None
    duration_s: float = 0.0
    started: str | None = None  # UTC, ISO 8601 with milliseconds
    finished: str | None = None
    backup: str | None = None
    backup_valid: bool | None = None  # False: the valve held an invalid set (marked in the file)
    output: str | None = None  # --download: the file written
    changes: int | None = None  # --dry-run: parameters that an upload would change
    error: str | None = None
    skipped: list[str] = field(default_factory=list)  # every parameter of the file not uploaded
    absent_in_file: list[str] = field(default_factory=list)  # marked absent: never uploaded
    history: str | None = None  # "recorded", "queued" or why it was not recorded
    store: str | None = None  # how the valve keeps the set ("stored with 0x1010", …; CANopen)
    came_back: str | None = None  # after a communication error: listed again there (not retried)
    current: dict[str, Any] | None = field(default=None, repr=False)  # --dry-run: as read

    @property
    def exit_code(self) -> ExitCode:
        """The exit code this outcome stands for."""
        return RESULTS[self.result]


def overall(records: list[ValveRecord]) -> ExitCode:
    """The exit code of the run: the most serious outcome of any valve."""
    codes = {r.exit_code for r in records}
    return next((code for code in SEVERITY if code in codes), ExitCode.OK)


def write_report(
    path: str, mode: str, source: str | None, exit_code: int, records: list[ValveRecord]
) -> None:
    """Write the JSON report atomically; a symbolic link at ``path`` is replaced, never
    followed (``run`` refuses a link before the run; one that appears meanwhile cannot make
    the report overwrite another file)."""
    report = {
        "prm9tool": __version__,
        "schema": SCHEMA,
        "created": datetime.now(UTC).isoformat(timespec="seconds"),
        "mode": mode,
        "file": source,
        "exit_code": int(exit_code),
        "valves": [_entry(r) for r in records],
    }
    text = json.dumps(report, indent=2, ensure_ascii=False) + "\n"
    atomic_write(Path(path), text.encode("utf-8"), backup=False, follow_symlinks=False)


def _entry(record: ValveRecord) -> dict[str, Any]:
    entry = asdict(record)
    del entry["current"]  # the values read in a dry run go into the history, not the report
    return entry


class ProgressPrinter:
    """Progress lines on stderr, one valve per line prefix, at most every 10 % per valve."""

    def __init__(self) -> None:
        self._lock = threading.Lock()
        self._last: dict[str, tuple[str, int]] = {}

    def say(self, who: str, text: str) -> None:
        """Print one line about valve ``who``."""
        with self._lock:
            sys.stderr.write(f"[{who}] {text}\n")
            sys.stderr.flush()

    def callback(self, who: str) -> Any:
        """A ``progress(done, total, step)`` callback for valve ``who``."""

        def progress(done: int, total: int, step: str) -> None:
            """Print a line when the step changes, every 10 % and at the end."""
            percent = 100 * done // max(total, 1)
            last_step, last_percent = self._last.get(who, ("", -100))
            if step != last_step or percent >= last_percent + 10 or done == total:
                self._last[who] = (step, percent)
                self.say(who, f"{step} {percent:3d} % ({done}/{total})")

        return progress


class Stopwatch:
    """Seconds since creation, and when that was."""

    def __init__(self) -> None:
        self._start = time.monotonic()
        self.started = utc_now()

    def __call__(self) -> float:
        return round(time.monotonic() - self._start, 3)

    def finish(self, record: ValveRecord) -> None:
        """Put this valve's start, end and duration into ``record``."""
        record.started, record.finished, record.duration_s = self.started, utc_now(), self()


def utc_now() -> str:
    """The current time, UTC, ISO 8601 with milliseconds."""
    return datetime.now(UTC).isoformat(timespec="milliseconds")

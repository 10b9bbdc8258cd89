"""The batch mode's history: check the database before uploading, record each valve after.

A production line wants traceability or nothing: by default an upload run whose history
database cannot be reached uploads nothing (exit 7); ``--history-unreachable queue`` (or the
setting) uploads and keeps the records in the local queue until the database is back.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from prm9tool.cli.batch_report import ValveRecord
from prm9tool.errors import ExitCode, FileFormatError
from prm9tool.history.config import unreachable_policy
from prm9tool.history.recorder import Recorder

Raw = int | str


class BatchHistory:
    """Records what the batch run did to each valve (shared by the worker threads), through
    the valve service's history observer (:class:`~prm9tool.service.history.HistoryHook`),
    each record shaped as the batch report's valve record (docs/batch.md)."""

    def __init__(self, recorder: Recorder, source: str | None) -> None:
        from prm9tool.service.history import HistoryHook

        self.recorder, self.source = recorder, source
        # the report's "history" field says what became of each record; nothing else to say
        self.observer = HistoryHook(recorder, lambda _problem: None)

    @classmethod
    def open(cls, args: argparse.Namespace, error: type[Exception]) -> BatchHistory:
        """The run's history; raises ``error(ExitCode.HISTORY, …)`` when the database is away
        and the policy is to refuse."""
        from prm9tool.cli.history import recorder_for

        recorder = recorder_for(args)
        problem = recorder.problem()
        if problem is not None:
            policy = unreachable_policy(getattr(args, "history_unreachable", None), "refuse")
            if policy != "queue":
                raise error(
                    ExitCode.HISTORY,
                    f"{problem}; nothing was uploaded (--history-unreachable queue uploads "
                    f"and keeps the records in {recorder.queue} until the database is back)",
                )
            print(
                f"prm9tool: warning: {problem}; the records are kept in {recorder.queue}",
                file=sys.stderr,
            )
        return cls(recorder, args.batch or args.download)

    @classmethod
    def for_download(cls, args: argparse.Namespace) -> BatchHistory:
        """The history of a ``--batch --download`` (queued when the database is away)."""
        from prm9tool.cli.history import recorder_for

        return cls(recorder_for(args), args.batch or args.download)

    def upload(self, record: ValveRecord, values: Mapping[str, Raw]) -> None:
        """Record one valve's upload (or dry run) with its outcome and failed step."""
        if record.result == "dry-run":
            self._add(record, "download", "ok", record.current, {"command": "--batch --dry-run"})
            return
        from prm9tool.service.history import upload_details

        stored = record.result == "ok"
        mismatches = {m: (d.get("expected"), d.get("actual")) for m, d in record.mismatches.items()}
        # the upload record's fields (service/history.py), then the batch's context
        details: dict[str, Any] = dict(upload_details(
            record.parameters_written, len(values), mismatches, record.error, record.store))  # fmt: skip
        details.update(command="--batch", file=self.source, verification=record.verification)
        parameters = values if stored else None  # not stored: the valve kept its stored set
        self._add(record, "batch-upload", record.result, parameters, details)

    def backup(self, record: ValveRecord, path: Path) -> None:
        """Record the backup file just written (its parameters are the valve's before)."""
        from prm9tool.files.prmfile import read_file

        try:
            values: Mapping[str, Raw] | None = read_file(path).values
        except FileFormatError:
            values = None
        self._add(record, "backup", "ok", values, {"file": str(path)})

    def download(self, record: ValveRecord, values: Mapping[str, Raw]) -> None:
        """Record a ``--batch --download``."""
        self._add(record, "download", "ok", values, {"file": record.output})

    def _add(
        self,
        record: ValveRecord,
        operation: str,
        outcome: str,
        parameters: Mapping[str, Raw] | None,
        details: dict[str, Any],
    ) -> None:
        record.history = self.observer.record(
            record, operation, outcome, parameters, details, record.failed_step
        )

    def close(self) -> None:
        """Close the database connections."""
        self.recorder.close()

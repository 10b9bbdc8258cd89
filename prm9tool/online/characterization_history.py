"""Characterization and end-of-line results into the history (``characterize.run.RESULT_HOOKS``).

A run records one ``characterization`` record of the valve: outcome ``passed``/``failed``, the
parameter set the valve ran with (read at the start of the run) and every figure with its
limit verdict in the details (:func:`~prm9tool.online.recording.characterization_details`, which
a script's :meth:`Valve.characterize <prm9tool.api.valve.Valve.characterize>` records too).
Used by ``--characterize`` and the GUI alike. No Qt.
"""

from __future__ import annotations

from collections.abc import Callable
from types import SimpleNamespace
from typing import TYPE_CHECKING

from prm9tool.characterize.run import RESULT_HOOKS, Characterization
from prm9tool.history.recorder import Recorder
from prm9tool.online.recording import characterization_details

if TYPE_CHECKING:
    from prm9tool.online.connection import ValveConnection


def recording_hook(recorder: Recorder) -> Callable[[Characterization], None]:
    """A result hook that records each run into ``recorder``'s history (never raises)."""

    def record(result: Characterization) -> None:
        info = result.info
        valve = SimpleNamespace(type_key=info.type_key, serial=info.serial, firmware=info.firmware,
                                device_id=info.device_id or info.link)  # fmt: skip
        outcome, details = characterization_details(result)
        recorder.record_safely(valve, "characterization", outcome, result.parameters, details)

    return record


def record_characterizations(recorder: Recorder) -> Callable[[], None]:
    """Register the hook; returns the function that removes it again."""
    hook = recording_hook(recorder)
    RESULT_HOOKS.append(hook)
    return lambda: RESULT_HOOKS.remove(hook) if hook in RESULT_HOOKS else None


def run_with_history(
    connection: ValveConnection | None, run: Callable[[], Characterization]
) -> Characterization:
    """``run()`` (a characterization on the connection's valve, in the GUI's worker) with its
    result recorded into the connection's history; offline (the simulated valve) nothing is
    recorded."""
    hook = getattr(connection, "history", None)
    if hook is None or not getattr(connection, "is_online", False):
        return run()
    forget = record_characterizations(hook.recorder)
    try:
        return run()
    finally:
        forget()

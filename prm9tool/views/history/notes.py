"""What the user did to a valve online, recorded in its history at once with its meaning.

Online, values taken into the document from a file, from a history record or from an accepted
tuning go to the valve as they are set (active, not stored yet). The history recorded them
only when they were stored, as "online-edits" (or never, when the user did not store them):
now each such act is a record of its own, naming what was done and every value it changed
(raw, from → to). The record holds no parameter set: the valve's stored set is unchanged
until it is stored (Valve → Store, or going offline), which is recorded as before.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

Raw = int | str


def changes(before: Mapping[str, Raw], after: Mapping[str, Raw]) -> dict[str, list[Raw]]:
    """``{mnemonic: [from, to]}`` of the values that differ."""
    return {mn: [before[mn], value] for mn, value in after.items() if before.get(mn) != value}


def record_online_change(
    connection: Any,
    operation: str,
    before: Mapping[str, Raw],
    after: Mapping[str, Raw],
    **details: object,
) -> None:
    """Record ``operation`` (``compare-apply``, ``history-restore``, ``tuning-accepted``) on
    the valve online, with the values it changed and ``details``; nothing offline (no valve
    was changed) or when nothing changed."""
    changed = changes(before, after)
    record = getattr(connection, "record", None)
    if not changed or record is None or not getattr(connection, "is_online", False):
        return
    record(operation, "ok", None, {**details, "changes": changed, "stored": False})


def record_run(connection: Any, operation: str, outcome: str, details: dict[str, Any]) -> None:
    """Record a test that moved the valve online (``autotune``, ``frequency-response``, a
    saved test report); nothing offline, where it ran on the simulated valve."""
    record = getattr(connection, "record", None)
    if record is not None and getattr(connection, "is_online", False):
        record(operation, outcome, None, details)


def _number(value: object) -> float | None:
    """A finite figure as JSON takes it (None for NaN, missing or not a number)."""
    if isinstance(value, bool) or not isinstance(value, int | float) or not math.isfinite(value):
        return None
    return round(float(value), 6)


def autotune_details(result: Any) -> tuple[str, dict[str, Any]]:
    """An autotune run's record, the one every door writes (``service/autotune.py``
    ``details``): outcome ``proposed`` or ``targets-missed``, loop, method, rounds, the gains
    before → proposed, both steps, the profile and its verdict."""
    from prm9tool.service.autotune import details

    outcome, record = details(result)
    return outcome, dict(record)


def bode_details(result: Any) -> tuple[str, dict[str, Any]]:
    """A frequency response's outcome (``ok``) and details: the sweep, −3 dB and −90°."""
    response = getattr(result, "response", None)
    details: dict[str, Any] = {
        "amplitude_pct": _number(getattr(result, "amplitude_pct", None)),
        "centre_pct": _number(getattr(result, "centre_pct", None)),
        "bandwidth_hz": _number(response.bandwidth_hz()) if response is not None else None,
        "phase_90_hz": _number(response.phase_90_hz()) if response is not None else None,
        "limited_to_hz": _number(getattr(result, "limited_to_hz", None)),
        "lost_samples": getattr(result, "lost_samples", 0),
    }
    return "ok", details


def record_tuning_run(connection: Any, kind: str, result: Any) -> None:
    """Record an autotune run or a frequency response of the Tuning window (online; the
    test report is recorded by its own hook, ``service/history.py`` ``run_with_history``)."""
    summaries = {"autotune": autotune_details, "bode": bode_details}
    operations = {"autotune": "autotune", "bode": "frequency-response"}
    if kind in summaries:
        outcome, details = summaries[kind](result)
        record_run(connection, operations[kind], outcome, details)


def record_report_saved(connection: Any, result: Any, pdf: str, loop: str) -> None:
    """Record that the test report of ``result`` was saved as ``pdf`` (with its figures, so
    the history names what failed and where the PDF is)."""
    from prm9tool.service.history import characterization_details

    outcome, details = characterization_details(result)
    record_run(connection, "report-saved", outcome, {**details, "pdf": pdf, "loop": loop})

"""The birth certificate (issue 31 item 5): a valve's end-of-line characterization in the
history, which a later signature is compared with (:mod:`prm9tool.characterize.drift`).

It is the first ``characterization`` record of the valve's serial that passed (for the loop
the signature tests), or, when none passed, its first one (decision: the first, because a
birth certificate is what the valve measured when it left the line, not its latest test).
:func:`reference_of` finds it in a serial's records and refuses, saying how to make one, when
there is none (:class:`NoReferenceError`); :func:`plan_for` is the signature that measures
what it measured. What a characterization keeps in its record for that — its test settings
(:func:`tests_of`) and its step and Bode curves, thinned (:func:`curves`) — is made here too.
No Qt.
"""

from __future__ import annotations

import json
import math
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from prm9tool.analysis.profile import DEFAULT, Profile
from prm9tool.characterize.run import Characterization
from prm9tool.characterize.signature import Plan, plan
from prm9tool.errors import Prm9Error
from prm9tool.messages import QT_TRANSLATE_NOOP

CURVE_POINTS = 160  # a step's curve kept in the history: at most this many points
BODE_POINTS = 80  # the frequency response's


class NoReferenceError(Prm9Error):
    """The history holds no characterization of the valve to compare its signature with."""

    summary = QT_TRANSLATE_NOOP("Errors", "The valve has no birth certificate in the history.")


NO_REFERENCE = QT_TRANSLATE_NOOP(
    "Characterize",
    "the history holds no end-of-line test of serial {0} ({1}) to compare with: make its "
    "birth certificate first — run the end-of-line test on this valve (Tuning window → Test "
    "report → Run the end-of-line test, online; or prm9tool --characterize --device ID "
    "--report OUT.pdf) with the history on; nothing was moved",
)


NO_HISTORY = QT_TRANSLATE_NOOP(
    "Characterize",
    "the birth certificate is kept in the history, which is off for this valve: open it with "
    "the history on; nothing was moved",
)


@dataclass(frozen=True)
class ReferenceFigure:
    """One figure of the birth certificate (``above``: only known to lie above ``value``)."""

    value: float
    unit: str
    above: bool = False


@dataclass(frozen=True)
class Reference:
    """The birth certificate: a ``characterization`` record of the valve's history."""

    record_id: int | None
    date: str  # when that run started (ISO 8601)
    outcome: str  # passed / failed
    end_of_line: bool  # the first that passed (else the first characterization)
    loop: str
    profile: str
    figures: dict[str, ReferenceFigure]
    tests: dict[str, float] = field(default_factory=dict)  # its test settings (when recorded)
    curves: dict[str, Any] | None = None  # its step and Bode curves (when recorded)

    @property
    def what(self) -> str:
        """``the end-of-line test on 2026-11-20`` (English; the views say it in theirs)."""
        kind = "the end-of-line test" if self.end_of_line else "the first characterization"
        return f"{kind} on {self.date[:10]}"

    def profile_for_tests(self) -> Profile:
        """The default profile with the birth certificate's test settings (where recorded)."""
        from dataclasses import replace

        part = DEFAULT.for_loop(self.loop)
        known: dict[str, Any] = {
            k: v for k, v in self.tests.items() if hasattr(part, k) and k != "loop"
        }
        return replace(part, **known) if known else part


def _details(record: Mapping[str, Any]) -> dict[str, Any]:
    details = record.get("details") or {}
    if isinstance(details, str):
        try:
            details = json.loads(details)
        except ValueError:
            return {}
    return details if isinstance(details, dict) else {}


def _loop_of(details: Mapping[str, Any]) -> str:
    loop = details.get("loop")
    if loop in ("position", "process"):
        return str(loop)
    names = [str(f.get("name", "")) for f in details.get("figures", []) if isinstance(f, dict)]
    return "process" if any(n.startswith("flow_") for n in names) else "position"


def reference_of(
    records: Iterable[Mapping[str, Any]], serial: int, type_key: str, loop: str = "position"
) -> Reference:
    """The birth certificate among a serial's ``records`` (oldest first, as
    ``HistoryStore.records`` lists them) for ``loop``; NoReferenceError when there is none."""
    candidates = []
    for record in records:
        if record.get("operation") != "characterization":
            continue
        details = _details(record)
        if record.get("type_key") not in (None, type_key):  # the serial of another valve type
            continue
        if _loop_of(details) == loop and details.get("figures"):
            candidates.append((record, details))
    if not candidates:
        raise NoReferenceError(NO_REFERENCE(serial, type_key))
    passed = [c for c in candidates if c[0].get("outcome") == "passed"]
    record, details = (passed or candidates)[0]
    figures = {}
    for f in details.get("figures", []):
        value = f.get("value")
        number = math.nan if value is None else float(value)
        figures[str(f["name"])] = ReferenceFigure(
            number, str(f.get("unit", "")), bool(f.get("above"))
        )
    tests = details.get("tests") if isinstance(details.get("tests"), dict) else {}
    curves = details.get("curves") if isinstance(details.get("curves"), dict) else None
    return Reference(
        record.get("id"),
        str(details.get("started") or record.get("recorded_at") or ""),
        str(record.get("outcome", "")),
        bool(passed),
        loop,
        str(details.get("profile", "")),
        figures,
        {k: float(v) for k, v in (tests or {}).items() if isinstance(v, int | float)},
        curves,
    )


def plan_for(reference: Reference, sample_rate_hz: float | None = None) -> Plan:
    """The signature that measures what the birth certificate measured (its step amplitudes,
    around its −3 dB frequency, its triangle's rate)."""
    steps = []
    for name in reference.figures:
        parts = name.split("_")
        if parts[0] == "step" and len(parts) == 4:  # step_<a>_<figure>_<unit>
            try:
                steps.append(float(parts[1]))
            except ValueError:
                continue
    bandwidth = reference.figures.get("bode_bandwidth_hz")
    hz = bandwidth.value if bandwidth is not None else None
    return plan(reference.profile_for_tests(), reference.loop, tuple(steps), hz, sample_rate_hz)


# --- what a characterization keeps for a later signature ------------------------------------
def _thin(values: np.ndarray, points: int) -> list[float]:
    step = max(1, math.ceil(len(values) / points))
    return [round(float(v), 4) if math.isfinite(v) else None for v in values[::step]]  # type: ignore[misc]


def curves(result: Characterization) -> dict[str, Any]:
    """The steps and the Bode of a run, thinned to a few hundred numbers, for the plot of a
    later signature over its birth certificate (the ``curves`` of a characterization record)."""
    from prm9tool.characterize.frame import LOOPS

    lp = LOOPS[result.loop]
    steps = []
    for step in result.steps:
        ch = step.record.channels
        if lp.actual not in ch or lp.setpoint not in ch:
            continue
        steps.append({
            "amplitude_pct": step.amplitude_pct,
            "t": _thin(step.record.t, CURVE_POINTS),
            "setpoint": _thin(ch[lp.setpoint], CURVE_POINTS),
            "actual": _thin(ch[lp.actual], CURVE_POINTS),
        })  # fmt: skip
    out: dict[str, Any] = {"steps": steps}
    if result.bode is not None:
        r = result.bode.response
        reliable = np.flatnonzero(r.reliable())  # the points its figures were found on
        picks = np.geomspace(1, max(1, len(reliable)), BODE_POINTS).astype(int) - 1
        keep = reliable[np.unique(picks)] if len(reliable) else np.zeros(0, dtype=int)
        out["bode"] = {
            "frequency": _thin(r.frequency[keep], BODE_POINTS),
            "magnitude_db": _thin(r.magnitude_db[keep], BODE_POINTS),
            "phase_deg": _thin(r.phase_deg[keep], BODE_POINTS),
        }
    return out


def tests_of(result: Characterization) -> dict[str, float]:
    """The test settings of a run's loop (the ``tests`` of a characterization record): what a
    later signature needs to measure alike."""
    for_loop = getattr(result.profile, "for_loop", None)
    if for_loop is None:  # a run without a profile of its own (a record made by hand)
        return {}
    part = for_loop(result.loop)
    return {
        "step_duration_s": part.step_duration_s,
        "bode_amplitude_pct": part.bode_amplitude_pct,
        "bode_f_min_hz": part.bode_f_min_hz,
        "bode_f_max_hz": part.bode_f_max_hz,
        "static_period_s": part.static_period_s,
    }

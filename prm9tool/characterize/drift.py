"""The drift report (issue 31 item 5): a valve's field signature against its birth certificate.

The *birth certificate* is the valve's end-of-line characterization in the history
(:mod:`prm9tool.characterize.birth_certificate`: which record it is, and refusing, saying how
to make one, when there is none). :func:`signature` finds it, plays the signature and compares:
:func:`compare` judges each figure of the signature (:mod:`prm9tool.characterize.signature`)
against the same figure of the birth certificate with the profile's ``[drift]`` limits
(:class:`~prm9tool.analysis.profile.DriftLimit`); :class:`DriftReport` is the result every door
shows: the words and figures ("−3 dB frequency 24.1 Hz, was 29.7 Hz at the end-of-line test
on 2026-11-20: −19 %"), the verdict, the JSON (:meth:`DriftReport.to_dict`) and what the
history keeps (:func:`history_details`). No Qt.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

from prm9tool._version import __version__
from prm9tool.analysis.profile import DEFAULT, SMALL_STEP_PCT, DriftLimit, Profile
from prm9tool.characterize.birth_certificate import (
    NO_HISTORY,
    NoReferenceError,
    Reference,
    ReferenceFigure,
    plan_for,
    reference_of,
)
from prm9tool.characterize.rig import Rig
from prm9tool.characterize.run import Characterization, Figure, Progress
from prm9tool.characterize.signature import Plan, run_signature


# --- the comparison -------------------------------------------------------------------------
@dataclass(frozen=True)
class DriftItem:
    """One figure today and at the birth certificate, and whether it drifted beyond its limit
    (None: not judged — no limit, or a figure measured only one of the two times)."""

    name: str
    label: str  # English ("−3 dB frequency"); the views translate from ``name``
    unit: str
    today: float
    reference: float | None  # None: the birth certificate has no such figure (a step down)
    limit: DriftLimit | None
    drifted: bool | None
    today_above: bool = False
    reference_above: bool = False

    @property
    def change(self) -> float:
        """today − birth certificate (NaN when either is missing)."""
        if self.reference is None:
            return math.nan
        return self.today - self.reference

    @property
    def relative_pct(self) -> float:
        """The change in % of the birth certificate's value (NaN: none, or it is 0)."""
        if self.reference is None or not self.reference:
            return math.nan
        return (self.today - self.reference) / abs(self.reference) * 100.0

    def line(self, since: str) -> str:
        """The figure in words (English): ``−3 dB frequency 24.1 Hz, was 29.7 Hz at the
        end-of-line test on 2026-11-20: −19 % (limit ± 15 %): drifted``."""
        now = shown(self.today, self.unit, self.today_above)
        if self.reference is None:
            return f"{self.label} {now} (no figure at {since}: not judged)"
        was = shown(self.reference, self.unit, self.reference_above)
        text = f"{self.label} {now}, was {was} at {since}"
        if math.isfinite(self.change) and not (self.today_above or self.reference_above):
            text += f": {change_text(self)}"
        if self.limit is not None:
            text += f" (limit {self.limit.text(self.unit)})"
        verdict = {True: "drifted", False: "within", None: "not judged"}[self.drifted]
        return f"{text}: {verdict}"


def shown(value: float, unit: str, above: bool = False) -> str:
    """``24.1 Hz``, ``12.3 ms``, ``0.3 %``, ``not reached`` (NaN), ``above 90 Hz``."""
    if math.isnan(value):
        return "not reached"
    text = f"{value * 1000:.3g} ms" if unit == "s" else f"{value:.3g} {unit}".strip()
    return f"above {text}" if above else text


def signed_change(item: DriftItem) -> tuple[str, str]:
    """The change as a signed number (``−19``, ``+0.8``, ``−0.040``, with the minus sign) and
    its kind: ``"%"`` relative (Hz, s), ``"pp"`` (figures in %), ``""`` (the gain). A change
    that rounds to zero is ``+0``, never ``−0.000``."""
    if item.unit == "%":
        number, kind = f"{item.change:+.2g}", "pp"
    elif not item.unit:  # the gain: a ratio already
        number, kind = f"{round(item.change, 3) + 0.0:+.3f}", ""
    else:
        number, kind = f"{round(item.relative_pct) + 0.0:+.0f}", "%"
    return number.replace("-", "−"), kind


def change_text(item: DriftItem) -> str:
    """``−19 %`` for the figures in Hz and s, ``+0.8 pp`` for those in %, ``−0.040`` for
    the gain."""
    number, kind = signed_change(item)
    return f"{number} {kind}".strip()


def _judge(limit: DriftLimit | None, today: Figure, ref: ReferenceFigure) -> bool | None:
    if limit is None:
        return None
    t_nan, r_nan = math.isnan(today.value), math.isnan(ref.value)
    if t_nan and r_nan:
        return None  # measured neither time (a step that settles in neither window)
    if t_nan or r_nan:
        return True  # measured once only: the valve behaves otherwise than it did
    if today.above or ref.above:  # a bound only: drifted when even the bound says so
        if today.above and ref.above:
            return None
        low_ok = limit.passed(ref.value, today.value)
        if today.above:  # today > today.value
            return None if low_ok or today.value < ref.value else True
        return None if low_ok or today.value > ref.value else True
    return not limit.passed(ref.value, today.value)


def compare(today: Characterization, reference: Reference, profile: Profile) -> list[DriftItem]:
    """Each figure of the signature against the birth certificate's (profile's ``[drift]``
    limits for the loop: :func:`limit_of`)."""
    limits = profile.for_loop(today.loop).drift
    items = []
    for f in today.figures:
        ref = reference.figures.get(f.name)
        limit = limit_of(f.name, limits)
        if ref is None:
            items.append(DriftItem(f.name, f.label, f.unit, f.value, None, limit, None, f.above))
            continue
        items.append(
            DriftItem(
                f.name, f.label, f.unit, f.value, ref.value, limit, _judge(limit, f, ref),
                f.above, ref.above,
            )
        )  # fmt: skip
    return items


def limit_of(name: str, limits: Mapping[str, DriftLimit]) -> DriftLimit | None:
    """The drift limit of figure ``name``: its own (``step_5_rise_s``), else its kind's
    (``step_rise_s``; for a step of at least SMALL_STEP_PCT only), else None."""
    if name in limits:
        return limits[name]
    parts = name.split("_")
    if parts[0] != "step" or len(parts) != 4:
        return None
    try:
        small = abs(float(parts[1])) < SMALL_STEP_PCT
    except ValueError:
        return None
    return None if small else limits.get(f"step_{parts[2]}_{parts[3]}")


@dataclass
class DriftReport:
    """The signature, the birth certificate, each figure's drift and the verdict."""

    today: Characterization
    reference: Reference
    items: list[DriftItem]
    plan: Plan

    @property
    def drifted(self) -> list[DriftItem]:
        """The figures beyond their drift limit."""
        return [i for i in self.items if i.drifted]

    @property
    def passed(self) -> bool:
        """No figure drifted beyond its limit."""
        return not self.drifted

    @property
    def verdict(self) -> str:
        """``no drift`` or ``drifted`` (English: the JSON's and the history's outcome)."""
        return "no-drift" if self.passed else "drifted"

    def lines(self) -> list[str]:
        """Every figure in words (English), the drifted first."""
        since = self.reference.what
        order = sorted(self.items, key=lambda i: {True: 0, False: 1, None: 2}[i.drifted])
        return [i.line(since) for i in order]

    def summary(self) -> str:
        """One sentence: the verdict and which figures drifted."""
        info = self.today.info
        head = f"{info.type_key} serial {info.serial}"
        if self.passed:
            return f"{head}: no figure drifted beyond its limit since {self.reference.what}"
        names = ", ".join(i.label for i in self.drifted)
        return f"{head}: DRIFTED since {self.reference.what}: {names}"

    def to_dict(self) -> dict[str, Any]:
        """The JSON report (docs/twin.md "The birth certificate")."""
        info, ref = self.today.info, self.reference
        return {
            "prm9tool": __version__,
            "date": self.today.date,
            "valve": {"type_key": info.type_key, "serial": info.serial, "firmware": info.firmware},
            "link": info.link,
            "sample_rate_hz": info.sample_rate_hz,
            "loop": self.today.loop,
            "profile": self.today.profile.name,
            "verdict": self.verdict,
            "passed": self.passed,
            "acceptance_passed": self.today.passed,  # today's figures against [limits]
            "summary": self.summary(),
            "reference": {
                "record": ref.record_id,
                "date": ref.date,
                "outcome": ref.outcome,
                "end_of_line": ref.end_of_line,
                "profile": ref.profile,
            },
            "motion_s": round(self.plan.motion_s, 2),
            "figures": [_item_dict(i) for i in self.items],
            "lines": self.lines(),
            "notes": [str(n) for n in self.today.notes],
            "wall_s": round(self.today.wall_s, 3),
        }


def _num(value: float | None) -> float | None:
    return None if value is None or not math.isfinite(value) else round(float(value), 6)


def _item_dict(i: DriftItem) -> dict[str, Any]:
    return {
        "name": i.name, "unit": i.unit, "today": _num(i.today), "today_above": i.today_above,
        "reference": _num(i.reference), "reference_above": i.reference_above,
        "change": _num(i.change), "relative_pct": _num(i.relative_pct),
        "limit_relative_pct": i.limit.relative if i.limit else None,
        "limit_absolute": i.limit.absolute if i.limit else None,
        "drifted": i.drifted,
    }  # fmt: skip


def history_details(report: DriftReport) -> dict[str, Any]:
    """What a ``signature`` record keeps: the birth certificate it was compared with, every
    figure with its drift, the drifted ones by name (docs/history.md)."""
    ref = report.reference
    return {
        "started": report.today.date,
        "profile": report.today.profile.name,
        "loop": report.today.loop,
        "reference": {"record": ref.record_id, "date": ref.date, "end_of_line": ref.end_of_line},
        "drifted": [i.name for i in report.drifted],
        "figures": [_item_dict(i) for i in report.items],
    }


# --- the one implementation ------------------------------------------------------------------
Records = Callable[[int], list[dict[str, Any]]]


def loop_of_rig(rig: Rig) -> str:
    """The loop the valve's setpoint drives: ``process`` on an E04 in control mode 4."""
    from prm9tool.catalogue.typekey import TypeKey
    from prm9tool.catalogue.variant import Config

    variant = TypeKey.parse(rig.info.type_key).variant
    if variant.config is Config.E04 and rig.read(["CTRLMODE"]).get("CTRLMODE") == 4:
        return "process"
    return "position"


def signature(
    rig: Rig,
    records: Records | None,
    profile: Profile | None = None,
    progress: Progress | None = None,
) -> DriftReport:
    """Find the birth certificate of the rig's valve in the history (``records(serial)``:
    its records oldest first; None: the history is off), refuse before anything moves when
    there is none, play the signature and compare. Who ran it records the result
    (``service.history``: a ``signature`` record)."""
    if records is None:
        raise NoReferenceError(NO_HISTORY())
    info = rig.info
    loop = loop_of_rig(rig)
    reference = reference_of(records(int(info.serial)), int(info.serial), info.type_key, loop)
    the_plan = plan_for(reference, info.sample_rate_hz)
    chosen = profile or DEFAULT
    today = run_signature(rig, chosen, the_plan, progress)
    return DriftReport(today, reference, compare(today, reference, chosen), the_plan)

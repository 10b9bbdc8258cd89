"""A twin fitted, recorded and proven (issue 31 items 2 and 4): the one sequence behind
``--fit-twin`` (``--device``/``--emulator`` and ``--from RUN.json``) and the Tuning window's
Twin page. The fit itself is :mod:`prm9tool.twin.fitvalve`; this adds the history record and
the twin characterized as the valve was (the side-by-side). No Qt.
"""

from __future__ import annotations

import os
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from prm9tool.errors import Prm9Error

if TYPE_CHECKING:
    from prm9tool.characterize.run import Characterization
    from prm9tool.service.history import HistoryHook
    from prm9tool.twin.fitvalve import ValveTwin
    from prm9tool.twin.proof import Side

Say = Callable[[str], None]


@dataclass(frozen=True)
class ProvenTwin:
    """A twin written and recorded, and the proof: each figure of the valve and of its twin
    (empty when the twin could not be characterized: ``proof_problem`` says why)."""

    twin: ValveTwin
    sides: list[Side] = field(default_factory=list)
    proof_problem: str = ""
    proof_link: str = ""  # the link the twin was characterized over (its run's ``link``)
    proof_notes: list[str] = field(default_factory=list)  # what that link limited (lost …)

    def report(self) -> dict[str, Any]:
        """The fit report (``--fit-twin … --json``) with the side-by-side (``comparison``)."""
        import math

        from prm9tool.twin.fitvalve import fit_report

        def number(value: float) -> float | None:
            return value if math.isfinite(value) else None  # JSON has no nan

        summary = fit_report(self.twin.fit, self.twin.path)
        if self.sides:
            summary["comparison"] = [
                {"figure": s.name, "unit": s.unit, "valve": number(s.valve),
                 "twin": number(s.twin), "ratio": number(s.ratio)}
                for s in self.sides
            ]  # fmt: skip
            summary["comparison_link"] = self.proof_link
            summary["comparison_notes"] = list(self.proof_notes)
        return summary


def fit_proven(
    run: Characterization,
    path: str | os.PathLike[str],
    history: HistoryHook | None,
    say: Say | None = None,
) -> ProvenTwin:
    """Fit the twin of ``run`` (:func:`~prm9tool.twin.fitvalve.twin_of_run`), write it to
    ``path``, record it in ``history`` (a ``twin`` record; None: not recorded) and
    characterize it as the valve was. Prm9Error/OSError when it cannot be fitted or written
    (nothing is recorded then); a twin that cannot be characterized is still kept."""
    from prm9tool.twin.fitvalve import history_details, history_outcome, twin_of_run
    from prm9tool.twin.proof import characterize_twin, side_by_side

    tell = say or (lambda _text: None)
    tell("fitting the twin")
    twin = twin_of_run(run, path)
    if history is not None:
        history.twin_of(run, history_outcome(twin.fit), history_details(twin.fit, twin.path))
    tell("characterizing the twin as the valve was")
    try:
        again = characterize_twin(run, twin.path)
    except (Prm9Error, ValueError) as exc:  # the twin is written; only its proof is missing
        return ProvenTwin(twin, [], str(exc))
    notes = [str(note) for note in again.notes]
    return ProvenTwin(twin, side_by_side(run, again), proof_link=again.info.link, proof_notes=notes)

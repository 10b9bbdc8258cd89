"""Where a reference signal steps: each jump of a square wave or a single step, with the levels
on either side, for the step-response figures (:mod:`prm9tool.scope.measure`). Numpy, no Qt."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

JUMP_SHARE = 0.2  # a reference step moves at least 20 % of the reference's span ...
JUMP_SAMPLES = 3  # ... within at most 3 samples (one edge)


@dataclass(frozen=True)
class Step:
    """One step of a reference: from sample ``start`` (the first one moved) to ``stop``
    (the first one at the new level), and the levels on either side."""

    start: int
    stop: int
    time: float
    before: float
    after: float


def find_steps(t: np.ndarray, reference: np.ndarray) -> list[Step]:
    """Every step of ``reference`` (a square wave has one per half period), in time order.

    A step is a jump of at least 20 % of the reference's span within at most three samples;
    the levels are the medians of the reference between its neighbouring steps. A ramp or a
    sine has no steps.
    """
    if len(reference) < 3:
        return []
    span = float(np.ptp(reference))
    d = np.diff(reference)
    moved = np.flatnonzero(np.abs(d) >= JUMP_SHARE * span) if span > 0 else np.empty(0, int)
    edges: list[tuple[int, int]] = []  # (first moved sample, first sample at the new level)
    for k in moved:
        last = edges[-1] if edges else None
        if last is not None and k + 1 - last[1] < JUMP_SAMPLES and d[k] * d[last[0]] > 0:
            edges[-1] = (last[0], int(k) + 1)
        else:
            edges.append((int(k), int(k) + 1))
    bounds = [0, *(stop for _, stop in edges)]
    ends = [start + 1 for start, _ in edges[1:]] + [len(reference)]
    steps = []
    for n, (start, stop) in enumerate(edges):
        before = float(np.median(reference[bounds[n] : start + 1]))
        after = float(np.median(reference[stop : ends[n]]))
        if abs(after - before) >= JUMP_SHARE * span:
            steps.append(Step(start, stop, float(t[start + 1]), before, after))
    return steps


def find_step(t: np.ndarray, reference: np.ndarray) -> tuple[float, float, float] | None:
    """The first step of a reference signal: ``(time, level before, level after)``."""
    steps = find_steps(t, reference)
    return (steps[0].time, steps[0].before, steps[0].after) if steps else None

"""The trigger engine: which frame of the stream the oscilloscope shows."""

from __future__ import annotations

from dataclasses import dataclass
from enum import StrEnum

import numpy as np

from prm9tool.scope.buffer import RingBuffer


class TriggerMode(StrEnum):
    """How the display follows the stream."""

    ROLL = "roll"  # no trigger: the newest window scrolls by
    AUTO = "auto"  # triggered frames; rolls when no trigger came for a window length
    NORMAL = "normal"  # only triggered frames
    SINGLE = "single"  # one triggered frame, then hold


class Edge(StrEnum):
    """Trigger edge."""

    RISING = "rising"
    FALLING = "falling"


@dataclass(frozen=True)
class TriggerSettings:
    """Trigger set-up; ``level`` in the channel's display units, ``pre`` = share before t = 0."""

    mode: TriggerMode = TriggerMode.ROLL
    channel: int = 0
    level: float = 0.0
    edge: Edge = Edge.RISING
    pre: float = 0.2


@dataclass(frozen=True)
class Frame:
    """What to show: samples ``[start, start + length)``, time 0 at sample ``origin``."""

    start: int
    length: int
    origin: int
    triggered: bool

    @property
    def stop(self) -> int:
        """Index after the last sample of the frame."""
        return self.start + self.length


class TriggerEngine:
    """Finds trigger edges in newly appended samples and decides which frame to show."""

    def __init__(self, settings: TriggerSettings, window: int) -> None:
        if not 0.0 <= settings.pre <= 1.0:
            raise ValueError("the pre-trigger share must lie between 0 and 1")
        self.settings = settings
        self.window = max(1, window)
        self.pre = round(settings.pre * self.window)
        self.rearm()

    def rearm(self, from_index: int = 0) -> None:
        """Forget the shown frame and search for the next edge from ``from_index``."""
        self._scan = from_index
        self._since = from_index  # where the wait for a trigger began (auto timeout)
        self._pending: Frame | None = None
        self._shown: Frame | None = None
        self.done = False

    @property
    def waiting(self) -> bool:
        """True while a triggered mode waits for its (first or next) edge."""
        return self.settings.mode is not TriggerMode.ROLL and self._pending is None

    def update(self, buffer: RingBuffer) -> Frame | None:
        """The frame to draw now, or None while nothing can be shown yet."""
        mode = self.settings.mode
        if mode is TriggerMode.ROLL:
            return Frame(buffer.total - self.window, self.window, 0, False)
        if self.done:
            return self._shown
        if self._pending is None:
            self._search(buffer)
        if self._pending is not None:
            if buffer.total < self._pending.stop:
                return self._pending  # still filling
            self._complete(buffer.total)
            return self._shown
        if mode is TriggerMode.AUTO and buffer.total - self._since > self.window:
            start = buffer.total - self.window
            return Frame(start, self.window, start + self.pre, False)
        return self._shown

    def _complete(self, total: int) -> None:
        self._shown = self._pending
        self._pending = None
        self._since = total
        self.done = self.settings.mode is TriggerMode.SINGLE

    def _search(self, buffer: RingBuffer) -> None:
        begin = max(self._scan, buffer.first + self.pre, buffer.first + 1)
        start, values = buffer.window(begin - 1, buffer.total)
        self._scan = max(begin, buffer.total)
        if len(values) < 2:
            return
        index = find_edge(values[:, self.settings.channel], self.settings.level, self.settings.edge)
        if index is not None:
            at = start + index
            self._pending = Frame(at - self.pre, self.window, at, True)
            self._scan = at - self.pre + self.window  # hold-off: next edge after this frame


def find_edge(x: np.ndarray, level: float, edge: Edge) -> int | None:
    """Index of the first sample at or past ``level`` whose predecessor was not (None if none)."""
    if edge is Edge.RISING:
        hits = (x[:-1] < level) & (x[1:] >= level)
    else:
        hits = (x[:-1] > level) & (x[1:] <= level)
    found = np.flatnonzero(hits)
    return int(found[0]) + 1 if len(found) else None

"""What a trace says, as records: one :class:`Event` per decoded service (an NMT command, a
heartbeat, an SDO transfer with all its frames, a PDO with its values, ...), the incidents a
service engineer looks for, and the summary of a whole trace. Plain frozen dataclasses with
``to_dict()``; no Qt."""

from __future__ import annotations

from dataclasses import dataclass, field
from enum import StrEnum
from typing import Any


class Kind(StrEnum):
    """What kind of service an event is (the trace view filters by it)."""

    NMT = "NMT"
    HEARTBEAT = "heartbeat"
    SYNC = "SYNC"
    TIME = "TIME"
    EMCY = "EMCY"
    SDO = "SDO"
    PDO = "PDO"
    STATE = "state"  # a CiA 408 device-state transition seen in a status word
    LSS = "LSS"
    ERROR_FRAME = "error frame"
    NOT_UNDERSTOOD = "not understood"


@dataclass(frozen=True, slots=True)
class Event:
    """One decoded service: when (s, the trace's time stamps), which node (None: the whole bus),
    what (``text``, in words), the frames behind it (0-based numbers in the trace) and, for
    values (PDO entries, an SDO's object), ``values``: name → display value."""

    time: float
    node: int | None
    kind: Kind
    text: str
    frames: tuple[int, ...]
    values: tuple[tuple[str, float | int | str], ...] = ()

    def to_dict(self) -> dict[str, Any]:
        """The event as JSON-ready data."""
        return {
            "time": self.time,
            "node": self.node,
            "kind": self.kind.value,
            "text": self.text,
            "frames": list(self.frames),
            "values": dict(self.values),
        }


@dataclass(frozen=True, slots=True)
class Incident:
    """What a service engineer looks for in a trace, with the time and the frames behind it."""

    time: float
    node: int | None
    what: str
    frames: tuple[int, ...]

    def to_dict(self) -> dict[str, Any]:
        """The incident as JSON-ready data."""
        return {
            "time": self.time,
            "node": self.node,
            "what": self.what,
            "frames": list(self.frames),
        }


@dataclass(frozen=True)
class SyncFigures:
    """The SYNC producer's period and jitter over the trace (s)."""

    count: int
    mean_period_s: float | None
    min_period_s: float | None
    max_period_s: float | None
    jitter_s: float | None  # the standard deviation of the period

    def to_dict(self) -> dict[str, Any]:
        """The figures as JSON-ready data."""
        return {
            "count": self.count,
            "mean_period_s": self.mean_period_s,
            "min_period_s": self.min_period_s,
            "max_period_s": self.max_period_s,
            "jitter_s": self.jitter_s,
        }


@dataclass(frozen=True)
class Trace:
    """A decoded trace: its events in time order, incidents, SYNC figures and how every frame
    was accounted for."""

    path: str
    frames: int
    events: list[Event]
    incidents: list[Incident]
    sync: SyncFigures
    nodes: dict[int, str] = field(default_factory=dict)  # node heard -> how it is decoded
    start: float = 0.0  # the first frame's time stamp (the trace's own clock)

    @property
    def not_understood(self) -> list[Event]:
        """The frames listed as not understood."""
        return [e for e in self.events if e.kind is Kind.NOT_UNDERSTOOD]

    def counts(self) -> dict[str, int]:
        """How many events of each kind."""
        result: dict[str, int] = {}
        for event in self.events:
            result[event.kind.value] = result.get(event.kind.value, 0) + 1
        return result

    def to_dict(self) -> dict[str, Any]:
        """The whole trace as JSON-ready data."""
        return {
            "path": self.path,
            "frames": self.frames,
            "start": self.start,
            "nodes": {str(node): how for node, how in sorted(self.nodes.items())},
            "counts": self.counts(),
            "sync": self.sync.to_dict(),
            "incidents": [i.to_dict() for i in self.incidents],
            "events": [e.to_dict() for e in self.events],
        }

    def to_pandas(self) -> Any:
        """The events as a pandas DataFrame (ImportError without pandas)."""
        import pandas as pd

        return pd.DataFrame([e.to_dict() for e in self.events])

"""The incidents a service engineer looks for in a decoded trace, each with its time and the
frames behind it: a node that rebooted or stopped answering, a heartbeat or SYNC gap beyond its
limit, an EMCY and what followed, a setpoint that jumped, a valve that left
DEVICE_MODE_ACTIVE, an SDO abort, error frames. No Qt.

Limits: the configured ones seen in the trace (producer heartbeat time 0x1017, communication
cycle period 0x1006) with half a period of tolerance; where none was seen, 1.5 times the
median period the trace shows.
"""

from __future__ import annotations

import itertools
import statistics
from array import array
from collections.abc import Sequence
from dataclasses import dataclass, field

from prm9tool.trace.events import Event, Incident, Kind, SyncFigures

TOLERANCE = 1.5  # a gap beyond 1.5 periods is one (decision, docs/trace.md)
SETPOINT_JUMP = 50.0  # % of full scale from one RPDO to the next (decision, docs/trace.md)
SETPOINTS = ("POSSETP", "PRCSETP")
FOLLOW_S = 1.0  # what followed an EMCY: the node's next state change within this time
HEARTBEAT_TIME, CYCLE_PERIOD = (0x1017, 0), (0x1006, 0)


@dataclass
class _NodeWatch:
    heartbeats: list[tuple[float, int]] = field(default_factory=list)  # time, frame
    seen: bool = False  # any heartbeat before (a boot-up then is a reboot)
    setpoint: float | None = None
    emcy: tuple[Event, int] | None = None  # an EMCY waiting for what follows, its incident


class IncidentFinder:
    """Collects the configured limits while decoding, finds the incidents at the end."""

    def __init__(self) -> None:
        self.heartbeat_ms: dict[int, int] = {}
        self.cycle_us: int | None = None

    def configured(self, node: int, key: tuple[int, int], value: int) -> None:
        """A value written to or read from a node's object."""
        if key == HEARTBEAT_TIME:
            self.heartbeat_ms[node] = value & 0xFFFF
        elif key == CYCLE_PERIOD and value:
            self.cycle_us = value

    def finish(
        self,
        events: Sequence[Event],
        sync: array,
        sync_frames: array,  # type: ignore[type-arg]
    ) -> tuple[list[Incident], SyncFigures]:
        """The incidents of ``events`` (in frame order) and the SYNC figures."""
        found: list[Incident] = []
        watches: dict[int, _NodeWatch] = {}
        in_errors = False
        for event in events:
            node = event.node
            watch = watches.setdefault(node, _NodeWatch()) if node is not None else None
            if event.kind is Kind.ERROR_FRAME:
                if not in_errors:
                    found.append(Incident(event.time, None, event.text, event.frames))
                in_errors = True
                continue
            in_errors = False
            if watch is None:
                continue
            self._event(event, watch, found)
        end = events[-1].time if events else 0.0
        for node, watch in sorted(watches.items()):
            found += self._heartbeat_gaps(node, watch, end)
        figures, gaps = _sync_figures(sync, sync_frames, self.cycle_us)
        found += gaps
        found.sort(key=lambda i: i.time)
        return found, figures

    def _event(self, event: Event, watch: _NodeWatch, found: list[Incident]) -> None:
        node = event.node
        if event.kind is Kind.HEARTBEAT:
            boot = event.text == "boot-up"
            if boot and watch.seen:
                found.append(
                    Incident(event.time, node, f"node {node} rebooted (boot-up)", event.frames)
                )
            watch.seen = True
            watch.heartbeats.append((event.time, event.frames[0]))
            if boot:
                watch.heartbeats.clear()  # a new life: gaps are counted from here
        elif event.kind is Kind.EMCY and dict(event.values).get("code"):
            found.append(Incident(event.time, node, f"node {node}: {event.text}", event.frames))
            watch.emcy = (event, len(found) - 1)
        elif event.kind is Kind.STATE and event.text.startswith("device state"):
            self._state(event, watch, found)
        elif event.kind is Kind.SDO and " aborted: " in event.text:
            found.append(Incident(event.time, node, f"node {node}: {event.text}", event.frames))
        elif event.kind is Kind.PDO:
            self._setpoint(event, watch, found)

    def _state(self, event: Event, watch: _NodeWatch, found: list[Incident]) -> None:
        node = event.node
        if watch.emcy is not None:
            emcy, at = watch.emcy
            watch.emcy = None
            if event.time - emcy.time <= FOLLOW_S:
                old = found[at]
                what = f"{old.what}; then {event.text}"
                found[at] = Incident(old.time, node, what, (*old.frames, *event.frames))
        if event.text.startswith("device state DEVICE_MODE_ACTIVE → "):
            found.append(
                Incident(
                    event.time,
                    node,
                    f"node {node} left DEVICE_MODE_ACTIVE: {event.text}",
                    event.frames,
                )
            )

    def _setpoint(self, event: Event, watch: _NodeWatch, found: list[Incident]) -> None:
        for name, value in event.values:
            if name in SETPOINTS and isinstance(value, float | int):
                before, watch.setpoint = watch.setpoint, float(value)
                if before is not None and abs(value - before) > SETPOINT_JUMP:
                    what = (
                        f"node {event.node}: setpoint {name} jumped {before:.1f} % → {value:.1f} %"
                    )
                    found.append(Incident(event.time, event.node, what, event.frames))

    def _heartbeat_gaps(self, node: int, watch: _NodeWatch, end: float) -> list[Incident]:
        beats = watch.heartbeats
        periods = [b[0] - a[0] for a, b in itertools.pairwise(beats)]
        configured = self.heartbeat_ms.get(node)
        if configured:
            period, source = configured / 1000.0, f"producer heartbeat time {configured} ms"
        elif len(periods) >= 3:
            period, source = statistics.median(periods), "the heartbeat period the trace shows"
        else:
            return []
        limit = period * TOLERANCE
        found = [
            Incident(
                b[0],
                node,
                f"node {node}: heartbeat gap of {b[0] - a[0]:.3f} s (limit {limit:.3f} s: {source})",
                (a[1], b[1]),
            )
            for a, b in itertools.pairwise(beats)
            if b[0] - a[0] > limit
        ]
        if beats and end - beats[-1][0] > limit:
            last_t, last_frame = beats[-1]
            what = f"node {node} stopped answering: no heartbeat after {last_t:.3f} s (limit {limit:.3f} s: {source})"
            found.append(Incident(last_t, node, what, (last_frame,)))
        return found


def _sync_figures(
    sync: array,
    frames: array,
    cycle_us: int | None,  # type: ignore[type-arg]
) -> tuple[SyncFigures, list[Incident]]:
    """The SYNC period and jitter, and the gaps beyond the limit."""
    if len(sync) < 2:
        return SyncFigures(len(sync), None, None, None, None), []
    import numpy as np

    times = np.frombuffer(sync, dtype=np.float64)
    periods = np.diff(times)
    mean = float(periods.mean())
    figures = SyncFigures(
        len(sync), mean, float(periods.min()), float(periods.max()), float(periods.std())
    )
    if cycle_us:
        period, source = cycle_us / 1e6, f"communication cycle period {cycle_us} µs"
    else:
        period, source = float(np.median(periods)), "the SYNC period the trace shows"
    limit = period * TOLERANCE
    found = [
        Incident(
            float(times[i + 1]),
            None,
            f"SYNC gap of {periods[i] * 1000:.2f} ms (limit {limit * 1000:.2f} ms: {source})",
            (),
        )
        for i in np.flatnonzero(periods > limit)[:1000]
    ]
    return figures, found

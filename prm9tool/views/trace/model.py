"""The decoded trace as a table model: one row per event, filtered by node and kind with numpy
index arrays (a million events filter at once, no per-row Python call)."""

from __future__ import annotations

from typing import Any

import numpy as np
from PySide6.QtCore import QAbstractTableModel, QModelIndex, QPersistentModelIndex, Qt

from prm9tool.trace.events import Event, Kind, Trace

ALL = -1  # the filter value "every node" / "every kind"
KINDS = tuple(Kind)
NO_NODE = 0  # the node column of bus-wide events (NMT to all, SYNC, LSS, error frames)

Index = QModelIndex | QPersistentModelIndex


class EventTableModel(QAbstractTableModel):
    """Time (s from the first frame), node, kind, text, frames."""

    def __init__(self, parent: Any = None) -> None:
        super().__init__(parent)
        self._events: list[Event] = []
        self._start = 0.0
        self._nodes = np.zeros(0, dtype=np.int16)
        self._kinds = np.zeros(0, dtype=np.int8)
        self._rows = np.zeros(0, dtype=np.int64)
        self._firsts = np.zeros(0, dtype=np.int64)
        self._headers = [
            self.tr("Time (s)"), self.tr("Node"), self.tr("Kind"), self.tr("What"),
            self.tr("Frames"),
        ]  # fmt: skip

    def set_trace(self, trace: Trace | None) -> None:
        """Show ``trace`` (None: nothing), every row."""
        self.beginResetModel()
        self._events = trace.events if trace is not None else []
        self._start = trace.start if trace is not None else 0.0
        self._nodes = np.fromiter(
            (e.node if e.node is not None else NO_NODE for e in self._events),
            dtype=np.int16,
            count=len(self._events),
        )
        position = {kind: k for k, kind in enumerate(KINDS)}
        self._kinds = np.fromiter(
            (position[e.kind] for e in self._events), dtype=np.int8, count=len(self._events)
        )
        self._firsts = np.fromiter(
            (e.frames[0] if e.frames else -1 for e in self._events),
            dtype=np.int64,
            count=len(self._events),
        )
        self._rows = np.arange(len(self._events))
        self.endResetModel()

    def set_filter(self, node: int = ALL, kind: Kind | None = None) -> None:
        """Show only the events of ``node`` (ALL: every node; NO_NODE: bus-wide events) and
        of ``kind`` (None: every kind)."""
        keep = np.ones(len(self._events), dtype=bool)
        if node != ALL:
            keep &= self._nodes == node
        if kind is not None:
            keep &= self._kinds == KINDS.index(kind)
        self.beginResetModel()
        self._rows = np.flatnonzero(keep)
        self.endResetModel()

    def event_at(self, row: int) -> Event:
        """The event shown in ``row``."""
        return self._events[int(self._rows[row])]

    def row_of_frame(self, frame: int) -> int | None:
        """The row that shows the event of ``frame`` (None: filtered out). Events are in the
        order of their first frames: a binary search, then back over the few events that
        began earlier (an SDO transfer holds frames after its first)."""
        firsts = self._firsts[self._rows]
        left = int(np.searchsorted(firsts, frame, side="left"))
        if left < len(firsts) and firsts[left] == frame:
            return left  # the first event of the frame (a state change before its PDO)
        for candidate in range(left - 1, max(left - 65, -1), -1):
            if frame in self._events[int(self._rows[candidate])].frames:
                return candidate
        return None

    def rowCount(self, parent: Index = QModelIndex()) -> int:  # noqa: B008
        return 0 if parent.isValid() else len(self._rows)

    def columnCount(self, parent: Index = QModelIndex()) -> int:  # noqa: B008
        return 0 if parent.isValid() else len(self._headers)

    def headerData(self, section: int, orientation: Qt.Orientation, role: int = 0) -> Any:
        if role == Qt.ItemDataRole.DisplayRole and orientation == Qt.Orientation.Horizontal:
            return self._headers[section]
        return None

    def data(self, index: Index, role: int = Qt.ItemDataRole.DisplayRole) -> Any:
        if role != Qt.ItemDataRole.DisplayRole or not index.isValid():
            return None
        event = self.event_at(index.row())
        column = index.column()
        if column == 0:
            return f"{event.time - self._start:.6f}"
        if column == 1:
            return "" if event.node is None else str(event.node)
        if column == 2:
            return event.kind.value
        if column == 3:
            return event.text
        return " ".join(map(str, event.frames[:8])) + (" …" if len(event.frames) > 8 else "")


Series = dict[tuple[int, str], tuple[np.ndarray, np.ndarray]]  # (node, name) -> times, values


def pdo_series(trace: Trace) -> Series:
    """Every numeric value the trace's PDOs carry, per (node, name): times (s from the first
    frame) and values in display units."""
    times: dict[tuple[int, str], list[float]] = {}
    values: dict[tuple[int, str], list[float]] = {}
    for event in trace.events:
        if event.kind is not Kind.PDO or event.node is None:
            continue
        for name, value in event.values:
            if isinstance(value, int | float):
                key = (event.node, name)
                times.setdefault(key, []).append(event.time - trace.start)
                values.setdefault(key, []).append(float(value))
    return {key: (np.asarray(times[key]), np.asarray(values[key])) for key in sorted(times)}

"""CAN traces: recording the bus into ASC/BLF/TRC/candump files and decoding a trace with the
valve's object dictionary (docs/trace.md). No Qt.

``read(path)`` decodes a trace into events; ``record(path, options)`` records the bus the
session uses (a context manager).
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import TYPE_CHECKING

from prm9tool.trace.events import Event, Incident, Kind, SyncFigures, Trace
from prm9tool.trace.frames import TraceFormatError

if TYPE_CHECKING:
    from prm9tool.trace.recorder import Recorder

__all__ = [
    "Event",
    "Incident",
    "Kind",
    "SyncFigures",
    "Trace",
    "TraceFormatError",
    "read",
    "record",
]


def read(path: str | Path, eds: Mapping[int | None, str | Path] | None = None) -> Trace:
    """Decode the trace file ``path``: its events, incidents and SYNC figures. ``eds``: EDS
    files of nodes that are no PRM9 (by node; None: every node identified as no PRM9).
    TraceFormatError (with the line) for a file that cannot be read."""
    from prm9tool.trace.decoder import Decoder
    from prm9tool.trace.frames import read_frames

    return Decoder(str(path), eds).feed_all(read_frames(path))


def record(path: str | Path, options: object = None) -> Recorder:
    """A recorder of the bus ``options`` (a ``CanOptions``; default the virtual bus) into the
    trace file ``path``: ``with record("run.asc", options): ...``."""
    from prm9tool.trace.recorder import record as make

    return make(path, options)  # type: ignore[arg-type]

"""What the connection's worker thread reads between jobs, and when: status, live values,
measuring points and the oscilloscope stream. Runs in the worker thread only; no Qt.
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Protocol

from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.signals import MAX_CHANNELS, SIGNAL_OBJECTS, signals_for
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.catalogue.variant import Variant
from prm9tool.errors import Prm9Error, SdoAbortError

if TYPE_CHECKING:
    import numpy as np

    from prm9tool.device.records import DeviceInfo, ValveStatus
    from prm9tool.device.session import ValveSession
    from prm9tool.device.stream import StreamReader, StreamSilentError

log = logging.getLogger(__name__)
WATCH_RATE_HZ = 250  # the slow stream that refreshes the diagram's measuring points
HIDDEN_GROUPS = ("canopen_comm", "profile_types", "service")
STREAM_PERIOD_S = 0.02  # the oscilloscope stream is drained this often
STATUS_PERIOD_S = 0.5  # status and read-only live values
SIGNAL_PERIOD_S = 0.15  # the diagram's measuring points


@dataclass
class PollResult:
    """What one poll read (None / empty: nothing new)."""

    status: ValveStatus | None = None
    live: dict[str, int | str] = field(default_factory=dict)
    signals: dict[str, float] = field(default_factory=dict)
    samples: np.ndarray | None = None  # (n, channels) raw block of the running stream
    samples_lost: int | None = None  # lost samples of the running stream, when the count changed
    stream_silent: StreamSilentError | None = None  # the stream went dead and was stopped


class Identified(Protocol):
    """Anything that names a valve's type key (a DeviceInfo, the views' ValveIdentity)."""

    @property
    def type_key(self) -> str:
        """The type key, e.g. ``PRM9-06.3Z11/30-24E02S02-CA``."""


def variant_of(info: Identified | None) -> Variant | None:
    """The variant of a DeviceInfo's type key (None offline or if it cannot be parsed)."""
    if info is None:
        return None
    try:
        return TypeKey.parse(info.type_key).variant
    except Prm9Error:
        return None


def live_mnemonics(variant: Variant | None) -> list[str]:
    """Read-only numeric values of the parameter list worth polling on ``variant``."""
    if variant is None:
        return ["PWR", "TEMP", "ERROR"]
    return [
        p.mnemonic
        for p in CATALOGUE.parameter_set(variant)
        if not p.in_file and p.dtype.size and p.group not in HIDDEN_GROUPS
    ]


class Poller:
    """Worker-side state of the periodic reads of one session."""

    def __init__(self) -> None:
        self.live: list[str] = []
        self.live_explicit = False
        self.watched: list[str] = []
        self._stream: StreamReader | None = None  # the oscilloscope's (the API's capture's)
        self._last_row: dict[str, float] = {}
        self._watch_chunk: list[str] = []
        self._watch_index = 0
        self._signal_keys: set[str] = set()
        self._readable: set[str] = set()  # measuring points with an object (SIGNAL_OBJECTS)
        self._lost_reported = 0

    @property
    def stream_keys(self) -> list[str]:
        """The measuring points of the oscilloscope's running stream ([] when none runs)."""
        return list(self._stream.keys) if self._stream is not None else []

    def reset(self, info: DeviceInfo) -> None:
        """A session to the valve ``info`` was opened."""
        variant = variant_of(info)
        self._stream, self._watch_chunk, self._last_row = None, [], {}
        self._signal_keys = {s.key for s in signals_for(variant)} if variant else set()
        self._readable = {
            key
            for key, (mnemonic, _factor) in SIGNAL_OBJECTS.items()
            if key in self._signal_keys and variant and CATALOGUE[mnemonic].applies(variant)
        }
        if not self.live_explicit:
            self.live = live_mnemonics(variant)

    def forget_streams(self) -> None:
        """The session closed: no stream runs any more."""
        self._stream, self._watch_chunk = None, []

    # --- the oscilloscope stream -----------------------------------------------------------------
    def start_stream(self, session: ValveSession, keys: list[str], rate_hz: int) -> list[str]:
        """Start the oscilloscope's stream (the watch stream gives way): the stream reader
        of the API's capture, open-ended, drained by :meth:`poll`."""
        from prm9tool.device.stream import StreamReader  # not at the window's start

        self._stop_watch(session)
        self.stop_stream(session)
        reader = StreamReader(session, keys, rate_hz)
        reader.start()
        self._stream, self._last_row = reader, {}
        self._lost_reported = 0
        return self.stream_keys

    def stop_stream(self, session: ValveSession) -> None:
        """Stop the oscilloscope's stream."""
        reader, self._stream = self._stream, None
        if reader is not None:
            reader.stop()

    # --- polling ----------------------------------------------------------------------------------
    def poll(
        self, session: ValveSession, status: bool, signals: bool, stream: bool = True
    ) -> PollResult:
        """Read what is due; communication errors propagate (the link is lost)."""
        result = PollResult()
        if stream and self._stream is not None:
            self._drain(self._stream, result)
        if status:
            result.status = session.status()
            result.live = self._read_live(session)
        if signals and (self.watched or self._watch_chunk):
            result.signals = self._read_signals(session)
        return result

    def _drain(self, reader: StreamReader, result: PollResult) -> None:
        """The oscilloscope's new samples and lost count; a dead stream is stopped and said in
        the capture's words; the session stays open (its requests may still be answered)."""
        from prm9tool.device.stream import StreamSilentError

        try:
            block = reader.read()
        except StreamSilentError as silent:
            self.stop_stream(reader.session)
            result.stream_silent = silent
            return
        if len(block):
            self._last_row.update(latest_values(reader.keys, block))
            result.samples = block
        if reader.lost != self._lost_reported:
            self._lost_reported = result.samples_lost = reader.lost

    def _read_live(self, session: ValveSession) -> dict[str, int | str]:
        """Read the live values; one the valve refuses is dropped from the list, not retried."""
        names = list(self.live)
        if not names:
            return {}
        try:
            return dict(session.read_many(names))
        except SdoAbortError as exc:
            refused = CATALOGUE.by_address(exc.index, exc.subindex)
            log.info("live value refused, no longer polled: %s", exc)
            self.live = [] if refused is None else [n for n in names if n != refused.mnemonic]
            return {}

    def _read_signals(self, session: ValveSession) -> dict[str, float]:
        """Latest values of the watched measuring points.

        The valve reports measuring points in its stream (at most three at once). While the
        oscilloscope streams, its samples serve; a point the valve also holds as an object
        (the actual position, the demand, the control deviation …: SIGNAL_OBJECTS) is read;
        every other watched point is NaN (no value now), never the value it had before the
        oscilloscope took the stream. Otherwise a slow "watch" stream visits the watched points
        three at a time, so each one is refreshed every few polls.
        """
        if self.stream_keys:
            live = {k: self._last_row.get(k, math.nan) for k in self.watched}
            live.update(self._read_objects(session, [k for k in live if math.isnan(live[k])]))
            return live
        # the watch stream is no StreamReader: it takes the newest row of a chunk restarted at
        # each visit; a lost sample or a silent visit only leaves a value for the next visit
        values: dict[str, float] = {}
        if self._watch_chunk:
            block = session.stream_read()
            if len(block):
                values = dict(zip(self._watch_chunk, map(float, block[-1]), strict=True))
        chunk = self._next_watch_chunk()
        if chunk:
            session.stream_start(chunk, WATCH_RATE_HZ)
        elif self._watch_chunk:
            session.stream_stop()
        self._watch_chunk = chunk
        return values

    def _read_objects(self, session: ValveSession, keys: list[str]) -> dict[str, float]:
        """The points among ``keys`` the valve holds as objects, read now; one it refuses is
        not asked for again in this session."""
        wanted = [k for k in keys if k in self._readable]
        if not wanted:
            return {}
        try:
            raw = session.read_many([SIGNAL_OBJECTS[k][0] for k in wanted])
        except SdoAbortError as exc:
            log.info("measuring point by object refused, no longer read: %s", exc)
            self._readable -= set(wanted)
            return {}
        return {k: float(raw[SIGNAL_OBJECTS[k][0]]) * SIGNAL_OBJECTS[k][1] for k in wanted}

    def _next_watch_chunk(self) -> list[str]:
        usable = [k for k in self.watched if k in self._signal_keys]
        if not usable:
            return []
        start = self._watch_index % len(usable)
        self._watch_index = start + MAX_CHANNELS
        return [usable[(start + i) % len(usable)] for i in range(min(MAX_CHANNELS, len(usable)))]

    def _stop_watch(self, session: ValveSession) -> None:
        if self._watch_chunk:
            self._watch_chunk = []
            session.stream_stop()


class Schedule:
    """When the worker's periodic reads are due next (worker thread only).

    The reads run on their own clock, between jobs: a steady flow of jobs (a setpoint
    generator writing every few milliseconds) delays a due read by one job at most.
    """

    def __init__(self) -> None:
        self.next_stream = self.next_status = self.next_signals = 0.0

    def wait_s(self, now: float, streaming: bool) -> float:
        """How long the worker may wait for a job before a read is due."""
        due = min(self.next_status, self.next_signals)
        if streaming:
            due = min(due, self.next_stream)
        return max(0.0, due - now)

    def take_due(self, now: float, streaming: bool) -> tuple[bool, bool, bool]:
        """(stream, status, signals): which reads are due now; they are scheduled again."""
        stream = streaming and now >= self.next_stream
        status, signals = now >= self.next_status, now >= self.next_signals
        if stream:
            self.next_stream = now + STREAM_PERIOD_S
        if status:
            self.next_status = now + STATUS_PERIOD_S
        if signals:
            self.next_signals = now + SIGNAL_PERIOD_S
        return stream, status, signals


def latest_values(keys: list[str], block: Any) -> dict[str, float]:
    """Each channel's newest sample that arrived in ``block`` (a lost one, NaN over CANopen,
    does not blank the live value); channels without any are left out."""
    import numpy as np  # loaded with the stream anyway; not at the program's start

    values: dict[str, float] = {}
    for column, key in enumerate(keys[: block.shape[1]]):
        arrived = np.flatnonzero(np.isfinite(block[:, column]))
        if len(arrived):
            values[key] = float(block[arrived[-1], column])
    return values

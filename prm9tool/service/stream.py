"""The finite capture of measuring points, behind every door: :func:`record` takes ``seconds``
of a stream with the one :class:`~prm9tool.device.stream.StreamReader` (the oscilloscope's in
the GUI's worker is the same reader, open-ended) and, at the default rate, picks the fastest
pace this PC keeps over CANopen and halves it where a recording still lost samples. The API's
``capture`` (``Valve.capture``, :func:`prm9tool.api.measure.capture`) is this with units. No Qt.
"""

from __future__ import annotations

import logging
import time
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from prm9tool.device.stream import StreamReader
from prm9tool.errors import CommunicationError, ValueRangeError

if TYPE_CHECKING:
    from prm9tool.device.session import ValveSession

__all__ = ["Recording", "SamplesLostError", "StreamReader", "link_rate", "record"]

log = logging.getLogger("prm9tool.api")

STREAM_BASE_HZ = 5000  # the valve samples its measuring points every 200 µs (manual §8.7.2)
TRIAL_S = 0.25  # a CANopen pace is tried this long before a capture at the default rate
TRIAL_MIN_HZ = 50  # decision: the halving stops above this (a PC that slow loses at any pace)


class SamplesLostError(CommunicationError):
    """A capture at the default rate lost samples even at the slowest pace it may take."""


@dataclass(frozen=True)
class Recording:
    """Raw samples (n, len(keys)) of a finite capture, its rate and the samples it lost."""

    samples: np.ndarray
    rate_hz: int
    lost: int


def record(
    session: ValveSession, keys: Sequence[str], seconds: float, rate_hz: int | None = None
) -> Recording:
    """``seconds`` of the stream of ``keys``. At the default rate (``rate_hz`` None) nothing
    is lost: over CANopen a recording that lost a sample (the PC got busier than during the
    trial) is taken again at half the pace, and SamplesLostError says so where even the
    slowest pace lost some. With ``rate_hz`` a lost sample is NaN in its place."""
    keys = list(keys)
    if not seconds > 0:
        raise ValueRangeError(f"capture: {seconds} s is not a duration")
    if rate_hz:
        return _record(session, keys, seconds, rate_hz)
    rate = link_rate(session, keys)
    while True:
        taken = _record(session, keys, seconds, rate)
        if not taken.lost or rate >= STREAM_BASE_HZ:  # USB: the valve's own pace, no slower one
            return taken
        slower = _slower(rate)
        if slower is None:
            raise SamplesLostError(
                f"capture: this PC could not keep the SYNC pace: {taken.lost} of "
                f"{len(taken.samples)} samples lost even at {rate} Hz, the slowest default; "
                "pass rate_hz to accept gaps (NaN in their place)"
            )
        log.info("capture: %d samples lost at %d Hz; again at %d Hz", taken.lost, rate, slower)
        rate = slower


def _record(session: ValveSession, keys: list[str], seconds: float, rate: int) -> Recording:
    """The raw samples of ``seconds`` at ``rate`` and how many of them were lost."""
    wanted = max(1, round(seconds * rate))
    poll_s = max(0.001, 10 / rate)  # about one report's worth of samples
    blocks: list[np.ndarray] = []
    lost = 0
    with StreamReader(session, keys, rate) as reader:
        while reader.received < wanted:
            before, got = reader.lost, reader.received
            block = reader.read(expected=wanted)
            if len(block):
                lost += min(reader.lost - before, wanted - got)  # past the end: not ours
                blocks.append(block)
            else:
                time.sleep(poll_s)
    return Recording(np.concatenate(blocks)[:wanted], rate, lost)


def _slower(rate: int) -> int | None:
    """The next pace of the default's halving (None: ``rate`` was its slowest)."""
    divider = 2 * round(STREAM_BASE_HZ / rate)
    slower = STREAM_BASE_HZ // divider
    return None if slower < TRIAL_MIN_HZ else slower


def link_rate(session: ValveSession, keys: list[str]) -> int:
    """The fastest rate the link streams without losing samples: 5000 Hz divided by a whole
    number. Over USB the valve's own 5 kHz; over CANopen the SYNC + TPDO pace of the bus
    (docs/can-link.md) only if this PC keeps it: the tool's SYNC thread skips a tick it
    reaches late, and a loaded PC lost 13-32 % of the samples at 1 kHz. So each pace from the
    bus's, halving, is tried for TRIAL_S and the first that lost nothing is taken (the last
    above TRIAL_MIN_HZ without a trial when none did)."""
    limit = session.info.stream_rate_limit_hz
    if not limit or limit >= STREAM_BASE_HZ:
        return STREAM_BASE_HZ
    divider = int(np.ceil(STREAM_BASE_HZ / limit))
    while True:
        rate = STREAM_BASE_HZ // divider
        slowest = STREAM_BASE_HZ // (2 * divider) < TRIAL_MIN_HZ
        if slowest or _streams_without_loss(session, keys, rate):
            return rate
        divider *= 2


def _streams_without_loss(session: ValveSession, keys: list[str], rate: int) -> bool:
    """True when ``rate`` streamed TRIAL_S without a lost sample (TRIAL_S is shorter than any
    silence bound: a dead stream is the recording's to tell)."""
    with StreamReader(session, keys, rate) as reader:
        until = time.monotonic() + TRIAL_S
        while time.monotonic() < until:
            reader.read()  # drained, not kept
            time.sleep(min(0.02, TRIAL_S / 10))
        reader.read()
        return reader.lost == 0

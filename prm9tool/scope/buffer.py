"""Sample storage of the oscilloscope: the ring buffer, one capture, decimation, autoscale."""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from prm9tool.catalogue.signals import Signal

MAX_RATE_HZ = 5000  # one sample per 200 µs control cycle
RATES_HZ = (5000, 2500, 1000, 500, 250, 100, 50)  # 5 kHz / decimation
WINDOWS_S = (0.05, 0.1, 0.2, 0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 30.0, 60.0)
BUFFER_S = 60.0  # history kept at the full rate (longer at lower rates)


class RingBuffer:
    """Preallocated ``(capacity, channels)`` sample store addressed by absolute sample index.

    Every sample is stored twice (at ``i % capacity`` and ``i % capacity + capacity``) so any
    run of at most ``capacity`` consecutive samples is one numpy view — drawing the last window
    never copies. Storage is channel-major, so each channel of a window is contiguous (fast
    per-channel reductions for decimation, triggers and figures).
    """

    def __init__(self, capacity: int, channels: int) -> None:
        if capacity < 1 or channels < 1:
            raise ValueError("a ring buffer needs at least one sample and one channel")
        self.capacity = capacity
        self.channels = channels
        self._data = np.zeros((channels, 2 * capacity), dtype=np.float64)
        self.total = 0  # absolute index of the next sample

    @property
    def first(self) -> int:
        """Absolute index of the oldest sample still held."""
        return max(0, self.total - self.capacity)

    def clear(self) -> None:
        """Forget every sample (the memory stays allocated)."""
        self.total = 0

    def append(self, block: np.ndarray) -> None:
        """Append an ``(n, channels)`` block; the oldest samples are overwritten when full."""
        if block.ndim != 2 or block.shape[1] != self.channels:
            raise ValueError(f"expected an (n, {self.channels}) block, got {block.shape}")
        skipped = max(0, len(block) - self.capacity)
        block = block[skipped:]
        self.total += skipped
        pos = self.total % self.capacity
        head = min(len(block), self.capacity - pos)
        for dest, part in ((pos, block[:head]), (0, block[head:])):
            self._data[:, dest : dest + len(part)] = part.T
            self._data[:, dest + self.capacity : dest + self.capacity + len(part)] = part.T
        self.total += len(block)

    def window(self, start: int, stop: int) -> tuple[int, np.ndarray]:
        """Samples ``[start, stop)`` clipped to what is held: ``(first index, view)``."""
        start = max(start, self.first)
        stop = min(stop, self.total)
        if stop <= start:
            return start, self._data[:, :0].T
        offset = start % self.capacity
        return start, self._data[:, offset : offset + stop - start].T

    def latest(self, count: int) -> tuple[int, np.ndarray]:
        """The last ``count`` samples (fewer if fewer are held)."""
        return self.window(self.total - count, self.total)


class Capture:
    """One recording: its channels, sample rate and ring buffer (display units)."""

    def __init__(self, signals: Sequence[Signal], rate_hz: int, buffer_s: float = BUFFER_S) -> None:
        if not signals:
            raise ValueError("a capture needs at least one measuring point")
        self.signals = tuple(signals)
        self.rate_hz = rate_hz
        capacity = max(int(buffer_s * MAX_RATE_HZ), int(rate_hz * buffer_s))
        self.buffer = RingBuffer(capacity, len(self.signals))
        self._scales = np.array([s.scale for s in self.signals], dtype=np.float64)

    @property
    def keys(self) -> list[str]:
        """Measuring-point keys in column order."""
        return [s.key for s in self.signals]

    def feed(self, raw: np.ndarray) -> None:
        """Append a raw ``(n, channels)`` block from the stream."""
        self.buffer.append(np.asarray(raw, dtype=np.float64) * self._scales)

    def times(self, start: int, count: int, origin: int = 0) -> np.ndarray:
        """Time axis in seconds of ``count`` samples from ``start``, relative to ``origin``."""
        return (np.arange(count, dtype=np.float64) + (start - origin)) / self.rate_hz

    def span(self, t0: float, t1: float, origin: int = 0) -> tuple[np.ndarray, np.ndarray]:
        """``(times, values)`` of the samples between times ``t0`` and ``t1`` (a copy)."""
        first = origin + math.ceil(t0 * self.rate_hz - 1e-9)
        stop = origin + math.floor(t1 * self.rate_hz + 1e-9) + 1
        start, values = self.buffer.window(first, stop)
        return self.times(start, len(values), origin), values.copy()


def peak_decimate(t: np.ndarray, values: np.ndarray, points: int) -> tuple[np.ndarray, np.ndarray]:
    """At most about ``points`` points per channel keeping every block's minimum and maximum.

    Blocks of ``ds`` samples become two points (min, max) at the block's first time stamp, so
    spikes and the envelope of fast signals survive (the peak method of pyqtgraph). The
    samples of a last, incomplete block are kept as they are. Lost samples (NaN) are left out
    of a block's peaks; a block without any sample stays NaN (a gap in the curve).
    """
    ds = -(-len(t) // max(1, points // 2))
    if ds <= 1:
        return t, values
    full = (len(t) // ds) * ds
    blocks = full // ds
    peaks = np.empty((2 * blocks + len(t) - full, values.shape[1]))
    for c in range(values.shape[1]):
        column = np.ascontiguousarray(values[:full, c]).reshape(blocks, ds)
        # fmin/fmax skip lost samples (NaN) without a warning; a block of only NaN stays a gap
        peaks[0 : 2 * blocks : 2, c] = np.fmin.reduce(column, axis=1)
        peaks[1 : 2 * blocks : 2, c] = np.fmax.reduce(column, axis=1)
    peaks[2 * blocks :] = values[full:]
    return np.concatenate([np.repeat(t[:full:ds], 2), t[full:]]), peaks


BRIDGE_SAMPLES = 4  # decision: a line is drawn across at most this many lost samples


def curve_points(
    t: np.ndarray, y: np.ndarray, bridge: int = BRIDGE_SAMPLES
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The samples of one channel that arrived, and where the curve connects them:
    ``(times, values, connect)``, ``connect[i]`` joining point ``i`` to ``i + 1``.

    A lost sample (NaN) is left out; the line goes on across at most ``bridge`` lost samples
    (a few ms, not visible as such at a scope's zoom) and breaks at a longer gap, which the plot
    then shows as a gap at its time. The spacing is taken from ``t`` itself, so peak-decimated
    times (two points per block) work too.
    """
    ok = np.isfinite(y)
    x, v = t[ok], y[ok]
    connect = np.ones(len(x), dtype=bool)
    if len(x) > 1 and len(t) > 1:
        spacing = (float(t[-1]) - float(t[0])) / (len(t) - 1)
        connect[:-1] = np.diff(x) <= (bridge + 1) * spacing * 1.0001
    return x, v, connect


def axis_ranges(
    bounds: Sequence[tuple[float, float] | None],
    current: Sequence[tuple[float, float]],
    units: Sequence[str],
    share_units: bool,
    force: bool = False,
    auto: Sequence[bool] = (),
) -> list[tuple[float, float] | None]:
    """New value range per autoscaled channel (None: keep the axis as it is).

    ``bounds`` holds each autoscaled channel's data minimum and maximum (None: not autoscaled
    or no data). With ``share_units``, autoscaled channels of the same unit get one common
    range, so a setpoint and its actual value compare directly; an autoscaled channel without
    data (``auto``; NaN, e.g. a point a valve over CANopen has no object for) gets it too, since
    the others are drawn on its axis. Hysteresis: an axis changes only when its data leaves the
    range or fills less than half of it (or when ``force``), so a live axis neither jitters nor
    needs redrawing every frame.
    """
    wanted = list(bounds)
    if share_units:
        for unit in set(units):
            group = [(k, b) for k, b in enumerate(bounds) if b is not None and units[k] == unit]
            if group:
                common = (min(b[0] for _, b in group), max(b[1] for _, b in group))
                for k in range(len(bounds)):
                    no_data = k < len(auto) and auto[k] and bounds[k] is None
                    if units[k] == unit and (bounds[k] is not None or no_data):
                        wanted[k] = common
    result: list[tuple[float, float] | None] = []
    for want, (y0, y1) in zip(wanted, current, strict=True):
        if want is None:
            result.append(None)
            continue
        lo, hi = want
        if force or lo < y0 or hi > y1 or hi - lo < 0.5 * (y1 - y0):
            margin = 0.1 * (hi - lo) if hi > lo else max(abs(hi) * 0.05, 0.5)
            result.append((lo - margin, hi + margin))
        else:
            result.append(None)
    return result

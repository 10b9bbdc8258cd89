"""Oscilloscope model: ring buffer, trigger engine, cursors, step-response figures, CSV, generator.

Pure numpy, no Qt (the widget lives in ``prm9tool/views/scope.py``). Samples arrive from the
valve's stream as raw ``(n, channels)`` blocks; :class:`Capture` converts them to display units
once and appends them to a preallocated :class:`RingBuffer`, so everything downstream (trigger
level, cursors, figures, CSV) works in the units the user sees. Sample ``i`` of a capture lies at
``i / rate`` seconds after the capture started; the stream has no gaps (lost samples are counted
by the session, not hidden here).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from enum import StrEnum
from typing import TextIO

import numpy as np

from prm9tool.catalogue import CATALOGUE
from prm9tool.errors import ValueRangeError
from prm9tool.signals import Signal

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
    samples of a last, incomplete block are kept as they are.
    """
    ds = -(-len(t) // max(1, points // 2))
    if ds <= 1:
        return t, values
    full = (len(t) // ds) * ds
    blocks = full // ds
    peaks = np.empty((2 * blocks + len(t) - full, values.shape[1]))
    for c in range(values.shape[1]):
        column = np.ascontiguousarray(values[:full, c]).reshape(blocks, ds)
        peaks[0 : 2 * blocks : 2, c] = column.min(axis=1)
        peaks[1 : 2 * blocks : 2, c] = column.max(axis=1)
    peaks[2 * blocks :] = values[full:]
    return np.concatenate([np.repeat(t[:full:ds], 2), t[full:]]), peaks


def axis_ranges(
    bounds: Sequence[tuple[float, float] | None],
    current: Sequence[tuple[float, float]],
    units: Sequence[str],
    share_units: bool,
    force: bool = False,
) -> list[tuple[float, float] | None]:
    """New value range per autoscaled channel (None: keep the axis as it is).

    ``bounds`` holds each autoscaled channel's data minimum and maximum (None: not autoscaled
    or no data). With ``share_units``, autoscaled channels of the same unit get one common
    range, so a setpoint and its actual value compare directly. Hysteresis: an axis changes
    only when its data leaves the range or fills less than half of it (or when ``force``), so
    a live axis neither jitters nor needs redrawing every frame.
    """
    wanted = list(bounds)
    if share_units:
        for unit in set(units):
            group = [(k, b) for k, b in enumerate(bounds) if b is not None and units[k] == unit]
            if group:
                common = (min(b[0] for _, b in group), max(b[1] for _, b in group))
                for k, _ in group:
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


# --- trigger ---------------------------------------------------------------------------------
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


# --- cursors ---------------------------------------------------------------------------------
@dataclass(frozen=True)
class CursorReadout:
    """Values of every channel at cursors A and B (NaN outside the data) and their differences."""

    t_a: float
    t_b: float
    a: np.ndarray
    b: np.ndarray

    @property
    def dt(self) -> float:
        """B − A in seconds."""
        return self.t_b - self.t_a

    @property
    def frequency(self) -> float:
        """1 / |Δt| in Hz (NaN when the cursors coincide)."""
        return 1.0 / abs(self.dt) if self.dt else math.nan

    @property
    def delta(self) -> np.ndarray:
        """B − A per channel."""
        return self.b - self.a


def cursor_readout(t: np.ndarray, values: np.ndarray, t_a: float, t_b: float) -> CursorReadout:
    """Linearly interpolated channel values at times ``t_a`` and ``t_b``."""

    def at(when: float) -> np.ndarray:
        if len(t) == 0 or not t[0] <= when <= t[-1]:
            return np.full(values.shape[1], math.nan)
        return np.array([np.interp(when, t, values[:, c]) for c in range(values.shape[1])])

    return CursorReadout(t_a, t_b, at(t_a), at(t_b))


# --- step response ---------------------------------------------------------------------------
@dataclass(frozen=True)
class StepFigures:
    """Step-response figures; times in seconds from the step, values in the signal's units."""

    t_step: float
    initial: float
    final: float
    target: float  # level the reference stepped to (NaN without a reference)
    rise_time: float  # 10 % → 90 % of the step (NaN if not reached)
    overshoot: float  # % of the step beyond the final value
    settling_time: float  # until the response stays within ±band of the final value
    band: float = 0.02

    @property
    def steady_state_error(self) -> float:
        """Target − final value (NaN without a reference)."""
        return self.target - self.final


def find_step(t: np.ndarray, reference: np.ndarray) -> tuple[float, float, float] | None:
    """The largest jump of a reference signal: ``(time, level before, level after)``."""
    if len(reference) < 3:
        return None
    k = int(np.argmax(np.abs(np.diff(reference)))) + 1
    before, after = float(np.median(reference[:k])), float(np.median(reference[k:]))
    if before == after:
        return None
    return float(t[k]), before, after


def step_figures(
    t: np.ndarray,
    y: np.ndarray,
    reference: np.ndarray | None = None,
    band: float = 0.02,
) -> StepFigures | None:
    """Figures of the step response ``y`` (with the ``reference`` that stepped, if recorded).

    Without a reference the step is taken where ``y`` leaves its initial level by more than
    ``band`` of the step. The final value is the mean of the last 10 % of the window. Returns
    None when the window holds no step.
    """
    if len(y) < 10:
        return None
    tail = max(1, len(y) // 10)
    final = float(np.mean(y[-tail:]))
    target = math.nan
    if reference is not None:
        step = find_step(t, reference)
        if step is None:
            return None
        t_step, _, target = step
        before = y[t < t_step]
        initial = float(np.median(before)) if len(before) else float(y[0])
    else:
        initial = float(np.median(y[:tail]))
        t_step = _first_crossing(t, y, initial, final, band, 0.0)
    size = final - initial
    if size == 0 or math.isnan(t_step):
        return None
    after = t >= t_step
    ta, ya = t[after], y[after]
    t10 = _first_crossing(ta, ya, initial, final, 0.1, t_step)
    t90 = _first_crossing(ta, ya, initial, final, 0.9, t_step)
    overshoot = max(0.0, float(np.max((ya - final) / size))) * 100.0
    outside = np.flatnonzero(np.abs(ya - final) > band * abs(size))
    if len(outside) == 0:
        settling = 0.0
    elif outside[-1] == len(ya) - 1:
        settling = math.nan
    else:
        settling = float(ta[outside[-1] + 1]) - t_step
    return StepFigures(t_step, initial, final, target, t90 - t10, overshoot, settling, band)


def _first_crossing(
    t: np.ndarray, y: np.ndarray, initial: float, final: float, share: float, t_from: float
) -> float:
    """Interpolated time at which ``y`` first reaches ``initial + share·(final − initial)``."""
    size = final - initial
    progress = (y - initial) / size if size else np.zeros_like(y)
    hits = np.flatnonzero((progress >= share) & (t >= t_from))
    if len(hits) == 0:
        return math.nan
    k = int(hits[0])
    if k == 0 or progress[k - 1] >= share:
        return float(t[k])
    p0, p1 = progress[k - 1], progress[k]
    return float(t[k - 1] + (t[k] - t[k - 1]) * (share - p0) / (p1 - p0))


# --- CSV -------------------------------------------------------------------------------------
def write_csv(out: TextIO, t: np.ndarray, values: np.ndarray, signals: Sequence[Signal]) -> int:
    """Write ``time [s]`` and one column per signal (``key [unit]``); returns the row count."""
    if values.shape != (len(t), len(signals)):
        raise ValueError("one column per signal and one row per time stamp expected")
    header = ",".join(["time [s]"] + [f"{s.key} [{s.unit}]" for s in signals])
    table = np.column_stack([t, values]) if len(t) else np.empty((0, len(signals) + 1))
    fmt = ["%.6f"] + ["%.6g"] * len(signals)
    np.savetxt(out, table, delimiter=",", fmt=fmt, header=header, comments="")
    return len(t)


# --- setpoint generator ----------------------------------------------------------------------
class Waveform(StrEnum):
    """Generator waveforms."""

    STEP = "step"  # offset for half a period, then offset + amplitude, held
    SQUARE = "square"  # offset and offset + amplitude, alternating every half period
    SINE = "sine"  # offset + amplitude · sin(2π t / period)


def setpoint_limits() -> tuple[float, float]:
    """Lowest and highest setpoint the override accepts, in % (from the catalogue)."""
    param = CATALOGUE["SETPOVR"]
    return param.raw_min * param.scale, param.raw_max * param.scale


@dataclass(frozen=True)
class GeneratorSettings:
    """A setpoint waveform in % of the setpoint range; ``period`` in seconds."""

    waveform: Waveform = Waveform.STEP
    amplitude: float = 10.0
    offset: float = 0.0
    period: float = 1.0

    def extremes(self) -> tuple[float, float]:
        """Lowest and highest value the waveform reaches."""
        if self.waveform is Waveform.SINE:
            return self.offset - abs(self.amplitude), self.offset + abs(self.amplitude)
        ends = (self.offset, self.offset + self.amplitude)
        return min(ends), max(ends)

    def check(self) -> None:
        """Raise ValueRangeError with a user-facing message if the waveform is not allowed."""
        if not self.period > 0:
            raise ValueRangeError("The generator period must be longer than 0 s.")
        low, high = self.extremes()
        lo, hi = setpoint_limits()
        if low < lo or high > hi:
            raise ValueRangeError(
                f"The waveform reaches {low:g} … {high:g} %; "
                f"the setpoint must stay within {lo:g} … {hi:g} %."
            )

    def value_at(self, t: np.ndarray | float) -> np.ndarray:
        """Setpoint in % at time(s) ``t`` seconds after the generator started."""
        phase = np.asarray(t, dtype=np.float64) / self.period
        if self.waveform is Waveform.SINE:
            return self.offset + self.amplitude * np.sin(2 * np.pi * phase)
        if self.waveform is Waveform.SQUARE:
            high = np.mod(phase, 1.0) >= 0.5
        else:
            high = phase >= 0.5
        return self.offset + self.amplitude * high

    def raw_at(self, t: float) -> int:
        """The SETPOVR raw value at time ``t`` (clamped to the object's range)."""
        param = CATALOGUE["SETPOVR"]
        raw = param.to_raw(float(self.value_at(t)))
        assert isinstance(raw, int)
        return min(param.raw_max, max(param.raw_min, raw))

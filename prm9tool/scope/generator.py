"""The setpoint generator's waveform maths (the Qt part drives SETPOVR with it).

Its messages are :class:`~prm9tool.messages.Message` templates (context ``GeneratorSettings``):
English in ``str()``, translated where a view shows them. No Qt, so the emulator and the
tuning procedures import the scope model without PySide6.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import StrEnum

import numpy as np

from prm9tool.catalogue import CATALOGUE
from prm9tool.errors import ValueRangeError
from prm9tool.messages import QT_TRANSLATE_NOOP, Number

EDGE_TOLERANCE_S = 1e-9  # an edge on the cycle grid falls on its cycle despite rounding
_PERIOD = QT_TRANSLATE_NOOP("GeneratorSettings", "The generator period must be longer than 0 s.")
_OUTSIDE = QT_TRANSLATE_NOOP(
    "GeneratorSettings",
    "The waveform reaches {0} … {1} %; the setpoint must stay within {2} … {3} %.",
)


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
            raise ValueRangeError(_PERIOD())
        low, high = self.extremes()
        lo, hi = setpoint_limits()
        if low < lo or high > hi:
            raise ValueRangeError(_OUTSIDE(*(Number(f"{v:.6g}") for v in (low, high, lo, hi))))

    def value_at(self, t: np.ndarray | float) -> np.ndarray:
        """Setpoint in % at time(s) ``t`` seconds after the generator started.

        An edge of the step or square wave belongs to the half period it starts: at
        ``t = k · period / 2`` exactly (to 1 ns, so that sampling on a cycle grid such as
        2500 × 200 µs = 0.5 s is not thrown a cycle late by rounding).
        """
        phase = np.asarray(t, dtype=np.float64) / self.period
        if self.waveform is Waveform.SINE:
            return self.offset + self.amplitude * np.sin(2 * np.pi * phase)
        nudged = phase + EDGE_TOLERANCE_S / self.period
        high = np.mod(nudged, 1.0) >= 0.5 if self.waveform is Waveform.SQUARE else nudged >= 0.5
        return self.offset + self.amplitude * high

    def raw_at(self, t: float) -> int:
        """The SETPOVR raw value at time ``t`` (clamped to the object's range)."""
        return int(self.raw_values(np.asarray([t], dtype=np.float64))[0])

    def raw_values(self, t: np.ndarray) -> np.ndarray:
        """SETPOVR raw values (int64, clamped to the object's range) at the times ``t``."""
        param = CATALOGUE["SETPOVR"]
        raw = np.rint(self.value_at(t) / param.scale).astype(np.int64)
        return np.clip(raw, param.raw_min, param.raw_max)

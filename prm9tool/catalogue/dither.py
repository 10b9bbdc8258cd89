"""What the dither parameters mean in milliamperes and hertz: one rule for the valve and the GUI.

The manual gives the dither amplitude DTAMP only in % (fig. 8-18, table 7-16). Our decision
(docs/emulator.md, "Dither decision"): DTAMP 100 % is a peak dither of 10 % of the nominal coil
current CURNORM, so that the factory 15 % moves the spool "by micrometres" (manual §8.7.2).
The emulated firmware applies this rule and the current-limiter dialog draws it.
"""

from __future__ import annotations

from prm9tool.catalogue import scale

FULL = scale.FULL_SCALE  # DTAMP raw value of 100 %
FULL_SCALE = 0.10  # DTAMP 100 % = a peak dither of 10 % CURNORM (decision)
MAX_HZ = 2500.0  # Nyquist of the 200 µs control loop; higher DYNFREQ settings are clamped


def amplitude_ma(dtamp_raw: float, curnorm_ma: float) -> float:
    """Peak dither current in mA of a DTAMP raw value on a valve of nominal current CURNORM."""
    return dtamp_raw / FULL * curnorm_ma * FULL_SCALE


def frequency_hz(dynfreq: float) -> float:
    """The dither frequency the firmware applies for DYNFREQ (clamped at :data:`MAX_HZ`)."""
    return min(dynfreq, MAX_HZ)

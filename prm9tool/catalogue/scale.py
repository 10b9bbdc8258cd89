"""The valve's normalized internal scale: raw 16384 is 100 % (and a gain factor of 1.0).

Process values (setpoint, position, sensor), gains and the linearization points of the valve
are S16 integers on this scale (manual table 7-14 and 7-16: "16384 = 100 %"); every module that
converts between raw counts and % uses these, so the scale is written once.
"""

from __future__ import annotations

FULL_SCALE = 16384
"""Raw value of 100 % (and of the gain factor 1.0)."""

PERCENT = 100.0 / FULL_SCALE
"""% per raw count."""

GAIN = 1.0 / FULL_SCALE
"""Gain factor per raw count (16384 = 1.0, the manual's sensor-gain convention)."""


def to_percent(raw: float) -> float:
    """``raw`` counts in % of full scale."""
    return raw * PERCENT


def from_percent(percent: float) -> float:
    """``percent`` of full scale in raw counts (not rounded)."""
    return percent * FULL_SCALE / 100.0

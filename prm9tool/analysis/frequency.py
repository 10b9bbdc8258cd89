"""Frequency response from streamed samples: scipy's Welch/CSD/coherence, −3 dB and −90°.

The demand value and the response are sampled in the same firmware cycle, so the estimate
``H = P_uy / P_uu`` (the H1 estimator) holds no link latency. Magnitudes are ratios (the
response over the demand, both in %), phases in degrees.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

import numpy as np
from scipy import signal

MIN_COHERENCE = 0.5  # points below are shown but not used for the −3 dB / −90° figures


@dataclass(frozen=True)
class FrequencyResponse:
    """Magnitude (ratio), phase (degrees, unwrapped) and coherence per frequency (Hz)."""

    frequency: np.ndarray
    magnitude: np.ndarray
    phase_deg: np.ndarray
    coherence: np.ndarray

    @property
    def magnitude_db(self) -> np.ndarray:
        """20·log10 of the magnitude."""
        return 20.0 * np.log10(np.maximum(self.magnitude, 1e-12))

    def reliable(self) -> np.ndarray:
        """Mask of the points whose coherence is at least MIN_COHERENCE."""
        return self.coherence >= MIN_COHERENCE

    def bandwidth_hz(self) -> float:
        """First frequency where the magnitude falls 3 dB below its low-frequency value (NaN)."""
        ok = self.reliable()
        f, db = self.frequency[ok], self.magnitude_db[ok]
        if len(f) < 2:
            return math.nan
        return crossing(f, db, float(db[0]) - 3.0103)

    def phase_90_hz(self) -> float:
        """First frequency where the phase lag reaches 90° (NaN if it never does)."""
        ok = self.reliable()
        return crossing(self.frequency[ok], self.phase_deg[ok], -90.0)


def crossing(f: np.ndarray, values: np.ndarray, level: float) -> float:
    """First frequency where ``values`` falls through ``level``, interpolated in log f."""
    below = np.flatnonzero(values <= level)
    if len(below) == 0 or below[0] == 0:
        return math.nan
    k = int(below[0])
    v0, v1 = float(values[k - 1]), float(values[k])
    share = (v0 - level) / (v0 - v1) if v0 != v1 else 0.0
    lf = math.log(f[k - 1]) + share * (math.log(f[k]) - math.log(f[k - 1]))
    return math.exp(lf)


def frequency_response(
    u: np.ndarray,
    y: np.ndarray,
    fs: float,
    f_min: float,
    f_max: float,
    points: int = 60,
) -> FrequencyResponse:
    """Estimate ``y/u`` on ``points`` log-spaced bands between ``f_min`` and ``f_max``.

    The sweep is one deterministic record, so the spectra are taken over all of it with a
    rectangular window (a tapering window would weigh the sweep's start and end, and with
    them the low and high frequencies, unlike the response's delayed copy of them); the
    spectra are summed over each band before dividing, an H1 estimate per band. Coherence
    comes from Welch averaging over eight Hann segments (:func:`scipy.signal.coherence`).
    """
    u = np.asarray(u, dtype=float)
    y = np.asarray(y, dtype=float)
    if u.shape != y.shape or len(u) < 256:
        raise ValueError("u and y must be equally long records of at least 256 samples")
    whole = {"fs": fs, "nperseg": len(u), "window": "boxcar", "detrend": "constant"}
    f, puu = signal.welch(u, **whole)
    _, puy = signal.csd(u, y, **whole)
    fc, coh = signal.coherence(u, y, fs=fs, nperseg=len(u) // 8)
    edges = np.geomspace(f_min, f_max, points + 1)
    centres, h = [], []
    for lo, hi in itertools.pairwise(edges):
        band = (f >= lo) & (f < hi)
        if not band.any() or puu[band].sum() <= 0:
            continue
        suu = puu[band].sum()
        centres.append(float(np.sum(f[band] * puu[band]) / suu))
        h.append(puy[band].sum() / suu)
    response = np.asarray(h, dtype=complex)
    phase = np.degrees(np.unwrap(np.angle(response)))
    freq = np.asarray(centres)
    return FrequencyResponse(freq, np.abs(response), phase, np.interp(freq, fc, coh))


def log_chirp(duration_s: float, fs: float, f0: float, f1: float) -> np.ndarray:
    """A logarithmic sine sweep ``f0`` → ``f1`` of unit amplitude (scipy.signal.chirp)."""
    t = np.arange(round(duration_s * fs)) / fs
    return np.asarray(signal.chirp(t, f0, duration_s, f1, method="logarithmic", phi=-90.0))


def sine_response(t: np.ndarray, u: np.ndarray, y: np.ndarray, f: float) -> complex:
    """Complex gain ``y/u`` at ``f`` by least squares on sine, cosine and offset (lock-in)."""
    w = 2.0 * math.pi * f
    basis = np.column_stack([np.sin(w * t), np.cos(w * t), np.ones(len(t))])
    cu = np.linalg.lstsq(basis, u, rcond=None)[0]
    cy = np.linalg.lstsq(basis, y, rcond=None)[0]
    return complex(cy[0], cy[1]) / complex(cu[0], cu[1])

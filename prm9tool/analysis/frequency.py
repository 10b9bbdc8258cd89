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

    def bandwidth_above_hz(self) -> float:
        """The highest reliable frequency when the magnitude never fell 3 dB below its
        low-frequency value up to it — the −3 dB frequency is above the sweep's end — else
        NaN (it was found, or too few reliable points to tell)."""
        ok = self.reliable()
        f, db = self.frequency[ok], self.magnitude_db[ok]
        if len(f) < 2 or np.any(db <= float(db[0]) - 3.0103):
            return math.nan
        return float(f[-1])

    def phase_90_above_hz(self) -> float:
        """The highest reliable frequency when the phase lag stayed under 90° up to it (the
        −90° frequency is above the sweep's end), else NaN."""
        ok = self.reliable()
        f, phase = self.frequency[ok], self.phase_deg[ok]
        if len(f) < 2 or np.any(phase <= -90.0):
            return math.nan
        return float(f[-1])


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
    from scipy import signal  # imported when used: see prm9tool.analysis.model

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


FIR_S = 0.1  # decision: the impulse response fitted when samples are missing (10 periods of 100 Hz)
FIT_EQUATIONS = 10  # decision: at least ten arrived samples per coefficient of that fit


def frequency_response_with_gaps(
    u: np.ndarray,
    y: np.ndarray,
    missing: np.ndarray,
    fs: float,
    f_min: float,
    f_max: float,
    points: int = 60,
) -> FrequencyResponse:
    """:func:`frequency_response` of a record whose response lost samples (``missing``, or
    NaN); ``u`` is complete (the demand the tool itself sent).

    The same estimator as for a complete record needs a sample in every period, so each lost
    one is replaced by what the demand predicts through an impulse response of :data:`FIR_S`
    fitted by least squares to the samples that arrived (each arrived sample is the demand's
    last ``FIR_S`` weighted by it: a lost one is just one equation less). Nothing is drawn
    between neighbours, and a long gap is filled as well as a short one; the samples that
    arrived are used as they are.
    """
    return frequency_response(u, filled_response(u, y, missing, fs), fs, f_min, f_max, points)


def filled_response(u: np.ndarray, y: np.ndarray, missing: np.ndarray, fs: float) -> np.ndarray:
    """``y`` with its ``missing`` (or NaN) samples predicted from ``u`` (see
    :func:`frequency_response_with_gaps`)."""
    u = np.asarray(u, dtype=float)
    y = np.asarray(y, dtype=float)
    missing = np.asarray(missing, dtype=bool) | np.isnan(y)
    taps = max(2, round(FIR_S * fs))
    if u.shape != y.shape or len(u) < max(256, 2 * taps):
        raise ValueError("u and y must be equally long records of at least 256 samples")
    present = ~missing
    if present.all():
        return y
    offset_u, offset_y = u.mean(), y[present].mean()
    padded = np.concatenate([np.full(taps - 1, u[0] - offset_u), u - offset_u])  # at rest before
    windows = np.lib.stride_tricks.sliding_window_view(padded, taps)[
        :, ::-1
    ]  # row k: u[k…k-taps+1]
    if present.sum() < FIT_EQUATIONS * taps:
        raise ValueError(
            f"too few response samples arrived ({int(present.sum())} of {len(u)}; the fit "
            f"needs {FIT_EQUATIONS * taps})"
        )
    weights, *_ = np.linalg.lstsq(windows[present], y[present] - offset_y, rcond=None)
    out = y.copy()
    out[missing] = windows[missing] @ weights + offset_y
    return out


def log_chirp(duration_s: float, fs: float, f0: float, f1: float) -> np.ndarray:
    """A logarithmic sine sweep ``f0`` → ``f1`` of unit amplitude (scipy.signal.chirp)."""
    t = np.arange(round(duration_s * fs)) / fs
    from scipy import signal

    return np.asarray(signal.chirp(t, f0, duration_s, f1, method="logarithmic", phi=-90.0))


UPDATES_PER_PERIOD = 4  # decision: a sweep counts up to where its setpoint changed this often


@dataclass(frozen=True)
class SweepUpdates:
    """How far a sweep's setpoint followed its plan: it is usable up to ``usable_hz`` (the
    sweep's end when it was updated often enough throughout); ``first_bad`` is the sample
    where it stopped being so (its length ``usable``), ``hold_s`` the longest hold before."""

    usable_hz: float
    usable: int
    hold_s: float  # the hold that ended it (0 when none did)


def sweep_updates(
    planned: np.ndarray, demand: np.ndarray, fs: float, f0: float, f1: float, quantum: float
) -> SweepUpdates:
    """Where the setpoint a valve received (``demand``, per sample) stopped following the
    logarithmic sweep ``planned`` (``f0`` → ``f1``): at the first value it held while the plan
    moved on by more than ``quantum`` for longer than 1/UPDATES_PER_PERIOD of the sweep's
    period there. A busy PC writes the setpoint late; the valve then gets a staircase whose
    jumps the spool answers nonlinearly (measured on the emulator: a 30 ms hold read the
    −3 dB frequency 18 % high, 50 ms 40 % low), so the figures above that frequency would be
    wrong, not just noisy."""
    n = min(len(planned), len(demand))
    planned, demand = np.asarray(planned[:n], float), np.asarray(demand[:n], float)
    if n < 2:
        return SweepUpdates(f1, n, 0.0)
    starts = np.r_[0, np.flatnonzero(np.diff(demand) != 0) + 1]
    lengths = np.diff(np.r_[starts, n])
    moved = np.maximum.reduceat(planned, starts) - np.minimum.reduceat(planned, starts)
    t = starts / fs
    duration = n / fs
    f = f0 * (f1 / f0) ** (t / duration)  # the sweep's frequency where each hold starts
    bad = np.flatnonzero((moved > quantum) & (lengths / fs * f > 1.0 / UPDATES_PER_PERIOD))
    if not len(bad):
        return SweepUpdates(f1, n, 0.0)
    k = int(bad[0])
    return SweepUpdates(float(f[k]), int(starts[k]), float(lengths[k] / fs))


def sine_response(t: np.ndarray, u: np.ndarray, y: np.ndarray, f: float) -> complex:
    """Complex gain ``y/u`` at ``f`` by least squares on sine, cosine and offset (lock-in)."""
    w = 2.0 * math.pi * f
    basis = np.column_stack([np.sin(w * t), np.cos(w * t), np.ones(len(t))])
    cu = np.linalg.lstsq(basis, u, rcond=None)[0]
    cy = np.linalg.lstsq(basis, y, rcond=None)[0]
    return complex(cy[0], cy[1]) / complex(cu[0], cu[1])

"""Model-based tuning: identify a low-order plant from a recorded step, then choose gains.

The plant is the path from the controller's output ``u`` to the controlled value ``y`` (both
recorded in the same firmware cycle, so the loop being closed does not bias the fit):
``G(s) = K·e^(−θs) / ((τ1·s + 1)(τ2·s + 1)(τ3·s + 1))``, with an extra integrator for a process loop
that moves an actuator. Gains are then chosen by simulating the firmware's discrete PIDT1 with
that plant (the same per-cycle equations, output limits included) against a target overshoot
and settling time; the gains must also hold the overshoot with the plant's gain 50 % higher
and two cycles more dead time.
Nothing here ever drives a real loop: the valve only sees steps at gains found safe this way.

scipy is imported in the functions that use it, here and in the other analysis modules: it
takes over a second to import, and the Tuning window, which imports these modules, opened that
much later (docs/PERFORMANCE.md, "Opening the Tuning window").
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, replace

import numpy as np

from prm9tool.analysis.pid import CYCLE_S, PidGains
from prm9tool.catalogue.scale import FULL_SCALE
from prm9tool.scope.measure import step_figures

_FULL = float(FULL_SCALE)  # 100 %: where the controller output saturates

ROBUST_GAIN = 1.5  # the overshoot target must hold with this much more plant gain
ROBUST_DELAY = 2  # ... and this many more cycles of dead time
MAX_DELAY = 12  # samples of dead time tried
MAX_FIT_ERROR_PCT = (
    20.0  # a fit worse than this (RMS, % of the span) proposes no gains (docs/tuning.md)
)


@dataclass(frozen=True)
class PlantModel:
    """``K·e^(−delay·dt·s) / ((τ1·s + 1)(τ2·s + 1)(τ3·s + 1))`` (× 1/s when ``integrating``)."""

    gain: float
    tau1: float
    tau2: float
    tau3: float
    delay: int  # whole cycles of dead time
    integrating: bool
    fit_error: float  # RMS residual of the fit, in % of the response's span

    @property
    def trustworthy(self) -> bool:
        """True when the fit error is within :data:`MAX_FIT_ERROR_PCT` (and finite)."""
        return math.isfinite(self.fit_error) and self.fit_error <= MAX_FIT_ERROR_PCT

    def poles(self, dt: float = CYCLE_S) -> tuple[float, float, float]:
        """Discrete (ZOH) poles of the three lags at the sample time ``dt``."""
        return tuple(math.exp(-dt / tau) for tau in (self.tau1, self.tau2, self.tau3))  # type: ignore[return-value]

    def worse(self) -> PlantModel:
        """The same plant with ROBUST_GAIN more gain and ROBUST_DELAY more dead time."""
        return replace(self, gain=self.gain * ROBUST_GAIN, delay=self.delay + ROBUST_DELAY)

    def simulate(self, u: np.ndarray, dt: float = CYCLE_S) -> np.ndarray:
        """The model's output for the input record ``u`` (starting at rest)."""
        from scipy import signal

        x = np.concatenate([np.zeros(self.delay), u[: len(u) - self.delay]]) * self.gain
        for a in self.poles(dt):
            x = signal.lfilter([0.0, 1.0 - a], [1.0, -a], x)
        if self.integrating:
            x = signal.lfilter([0.0, dt], [1.0, -1.0], x)
        return np.asarray(x)


def identify(
    records: Sequence[tuple[np.ndarray, np.ndarray]], dt: float, integrating: bool = False
) -> PlantModel:
    """Fit the model to one or more ``(u, y)`` records (deviations from their first sample)."""
    pieces = [(np.asarray(u, float) - u[0], np.asarray(y, float) - y[0]) for u, y in records]
    span = max(float(np.ptp(y)) for _, y in pieces) or 1.0
    best: PlantModel | None = None
    for delay in range(MAX_DELAY + 1):
        model = _fit(pieces, dt, delay, integrating, span)
        if best is None or model.fit_error < best.fit_error:
            best = model
    assert best is not None
    return best


def _fit(
    pieces: list[tuple[np.ndarray, np.ndarray]],
    dt: float,
    delay: int,
    integrating: bool,
    span: float,
) -> PlantModel:
    def residual(p: np.ndarray) -> np.ndarray:
        tau = np.exp(p[1:])
        model = PlantModel(p[0], tau[0], tau[1], tau[2], delay, integrating, 0.0)
        return np.concatenate([model.simulate(u, dt) - y for u, y in pieces]) / span

    u0, y0 = pieces[0]
    gain0 = float(np.ptp(y0) / (np.ptp(u0) or 1.0))
    if integrating:
        gain0 /= len(u0) * dt
    start = np.array([gain0, math.log(3e-3), math.log(1e-3), math.log(3e-4)])
    low, high = math.log(dt / 4.0), math.log(100.0)
    from scipy import optimize

    fit = optimize.least_squares(
        residual, start, bounds=([-np.inf, low, low, low], [np.inf, high, high, high]), max_nfev=200
    )
    rms = float(np.sqrt(np.mean(fit.fun**2))) * 100.0
    p = fit.x
    taus = sorted((float(v) for v in np.exp(p[1:])), reverse=True)
    return PlantModel(float(p[0]), taus[0], taus[1], taus[2], delay, integrating, rms)


@dataclass(frozen=True)
class Targets:
    """What the step response of the tuned loop must meet."""

    overshoot_pct: float = 10.0
    settling_s: float = 0.05


def simulate_loop(
    model: PlantModel,
    gains: PidGains,
    step: float,
    duration_s: float,
    out_lo: float = -_FULL,
    dt: float = CYCLE_S,
) -> np.ndarray:
    """Closed-loop response to a setpoint step of ``step`` counts (the firmware's PIDT1).

    ``dt`` is the firmware's cycle; a slow loop (seconds) may be simulated at a multiple of
    it, with the same continuous gains.
    """
    a1, a2, a3 = model.poles(dt)
    g1, g2, g3 = model.gain * (1.0 - a1), 1.0 - a2, 1.0 - a3
    integrating = model.integrating
    kp, ki = gains.kp, gains.ki * dt
    denom = gains.t1 + dt
    kd, t1 = gains.kd / denom, gains.t1 / denom
    n = round(duration_s / dt)
    delayed = [0.0] * (round(model.delay * CYCLE_S / dt) + 1)
    out = np.empty(n)
    s1 = s2 = s3 = y = integ = deriv = prev = 0.0
    for k in range(n):
        s1 = a1 * s1 + g1 * delayed[k % len(delayed)]
        s2 = a2 * s2 + g2 * s1
        s3 = a3 * s3 + g3 * s2
        y = y + dt * s3 if integrating else s3
        e = step - y
        integ = min(max(integ + ki * e, out_lo), _FULL)
        deriv = t1 * deriv + kd * (e - prev)
        prev = e
        delayed[k % len(delayed)] = min(max(kp * e + integ + deriv, out_lo), _FULL)
        out[k] = y
    return out


def loop_figures(response: np.ndarray, step: float, dt: float = CYCLE_S) -> tuple[float, float]:
    """Overshoot (% of the step) and settling time (s, ±2 %; inf if not settled)."""
    t = np.arange(len(response) + 1) * dt
    y = np.concatenate([[0.0], response])
    reference = np.concatenate([[0.0], np.full(len(response), step)])
    figures = step_figures(t, y, reference)
    if figures is None or not np.isfinite(y).all():
        return math.inf, math.inf
    settle = figures.settling_time
    if not math.isfinite(settle) or abs(figures.final - step) > figures.band * abs(step):
        settle = math.inf  # never settles, or settles beside the setpoint (no integral action)
    return figures.overshoot, settle


@dataclass(frozen=True)
class Design:
    """Chosen gains and the simulated figures that chose them."""

    gains: PidGains
    overshoot_pct: float
    settling_s: float
    meets_targets: bool


def design(
    model: PlantModel,
    targets: Targets,
    step: float,
    t1: float,
    margin: float = 0.7,
    out_lo: float = -_FULL,
) -> Design:
    """Search Kp, Ki and the derivative time for the fastest settling within the overshoot.

    ``margin`` shrinks the overshoot allowed in simulation (the real loop has friction and
    quantization the model lacks). The derivative lag ``t1`` stays as given.
    """
    duration = max(3.0 * targets.settling_s, 0.03)
    dt = CYCLE_S * max(1, round(duration / 0.15))  # at most ~750 steps per simulation
    allowed = targets.overshoot_pct * margin
    robust = model.worse()
    loop_gain = abs(model.gain) or 1.0
    best: Design | None = None
    for kp in np.geomspace(0.02, 20.0, 19) / loop_gain:
        for ki_ratio in (0.0, *np.geomspace(5.0, 1000.0, 12)):
            for td in (0.0, 2e-4, 5e-4, 1e-3):
                gains = PidGains(float(kp), float(kp * ki_ratio), float(kp * td), t1)
                response = simulate_loop(model, gains, step, duration, out_lo, dt)
                over, settle = loop_figures(response, step, dt)
                if over > allowed or (best is not None and settle >= best.settling_s):
                    continue
                worse = simulate_loop(robust, gains, step, duration, out_lo, dt)
                r_over, _ = loop_figures(worse, step, dt)
                if r_over <= targets.overshoot_pct:
                    best = Design(gains, over, settle, settle <= targets.settling_s)
    if best is None:
        raise ValueError("no gains meet the overshoot target on the identified model")
    return best

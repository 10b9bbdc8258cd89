"""Step-response measurement on an emulated valve (used by tests, docs and benchmarks).

    .venv/bin/python -m prm9tool.device.emulator.analysis [TYPE_KEY] [--to VOLTS]

prints the rise time, overshoot and settling time of a factory-default valve.
"""

from __future__ import annotations

import argparse
from dataclasses import dataclass

import numpy as np

from prm9tool.device.emulator.constants import CYCLE_S, FULL
from prm9tool.device.emulator.valve import EmulatedValve
from prm9tool.scope.measure import step_figures

FACTORY_E02 = "PRM9-06.3Z11/30-24E02S02"


@dataclass(frozen=True)
class StepResult:
    """A step response. Times in seconds from the step; percentages of the step or of 100 %.

    The figures are those the oscilloscope shows (:func:`prm9tool.scope.step_figures`, one
    definition for both): ``rise_s`` 10 % → 90 % of the step; ``settling_s`` from the step
    until the signal stays within ±2 % of the step around its final value; ``overshoot_percent``
    beyond the final value, in % of the step. ``steady_ripple_percent``: peak-to-peak over the
    last 20 % of the record, in % of 100 %.
    """

    samples: np.ndarray
    initial: float
    final: float
    rise_s: float
    overshoot_percent: float
    settling_s: float
    steady_ripple_percent: float


def step_response(
    valve: EmulatedValve,
    before: float,
    after: float,
    key: str,
    seconds: float,
    input_name: str = "setpoint",
) -> StepResult:
    """Boot (if needed), settle at ``before``, step the input to ``after``, record ``key``."""
    valve.set_input(input_name, before)
    while valve.status().booting:
        valve.advance(0.1)
    valve.advance(0.5)
    valve.capture_start([key])
    valve.advance(CYCLE_S)  # one sample before the step marks where it happens
    valve.set_input(input_name, after)
    valve.advance(seconds)
    samples = valve.capture_read()[:, 0]
    valve.capture_stop()
    return measure(samples)


def measure(samples: np.ndarray) -> StepResult:
    """Figures of a recorded step; the input stepped between samples 0 and 1."""
    t = np.arange(len(samples)) * CYCLE_S
    reference = np.ones(len(samples))
    reference[0] = 0.0
    figures = step_figures(t, samples, reference)
    if figures is None:
        raise ValueError("the record holds no step response")
    tail = samples[int(len(samples) * 0.8) :]
    return StepResult(
        samples=samples,
        initial=figures.initial,
        final=figures.final,
        rise_s=figures.rise_time,
        overshoot_percent=figures.overshoot,
        settling_s=figures.settling_time,
        steady_ripple_percent=float(np.ptp(tail)) / FULL * 100.0,
    )


def main() -> None:
    """Print the step response of a factory-default valve."""
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("type_key", nargs="?", default=FACTORY_E02)
    parser.add_argument("--from", dest="before", type=float, default=0.0, help="V (default 0)")
    parser.add_argument("--to", dest="after", type=float, default=10.0, help="V (default 10)")
    parser.add_argument("--signal", default="position_actual")
    parser.add_argument("--seconds", type=float, default=0.2)
    args = parser.parse_args()
    result = step_response(
        EmulatedValve(args.type_key), args.before, args.after, args.signal, args.seconds
    )
    print(f"{args.type_key}: {args.signal}, setpoint {args.before:g} V -> {args.after:g} V")  # noqa: T201
    print(  # noqa: T201
        f"rise 10-90 %: {result.rise_s * 1e3:.1f} ms, overshoot: "
        f"{result.overshoot_percent:.1f} %, settling (±2 %): {result.settling_s * 1e3:.1f} ms, "
        f"final: {result.final / FULL * 100:.1f} %, ripple: {result.steady_ripple_percent:.2f} %"
    )


if __name__ == "__main__":
    main()

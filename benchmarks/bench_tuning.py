"""Tuning and characterization on the emulator: valve time, wall time, and what physics needs.

Each procedure runs headless on an emulated PRM9-06 E02 valve stepped as fast as the CPU
allows. For each it prints the valve time the procedure took (the valve's own clock), the wall
time, and the time the physics needs (the excitation's own length: the sweep, the triangle,
the steps' windows). The reference, measured in the same run, is the emulator free-running the
same valve time with a constant setpoint: the ratio wall/reference is the cost of driving the
setpoint cycle by cycle and of the analysis. Goals (issue 16): autotune ≤ 30 s of valve time,
a 1–200 Hz Bode ≤ 20 s of valve time.

    .venv/bin/python benchmarks/bench_tuning.py [--quick]

``--quick`` (a smoke run) runs the critical-gain autotune and a 1 s sweep only.
"""

from __future__ import annotations

import argparse
import time
from collections.abc import Callable

from prm9tool.analysis.model import Targets
from prm9tool.analysis.profile import DEFAULT
from prm9tool.characterize.autotune import model_tune
from prm9tool.characterize.critical_gain import critical_gain_tune
from prm9tool.characterize.procedures import bode_test, static_test
from prm9tool.characterize.rig import EmulatorRig
from prm9tool.characterize.run import characterize
from prm9tool.device.emulator import EmulatedValve

E02 = "PRM9-06.3Z11/30-24E02S02"
TESTS: list[tuple[str, Callable[[EmulatorRig], object], float]] = [
    # name, procedure, seconds of excitation the physics needs
    ("autotune, model-based", lambda rig: model_tune(rig, Targets(10.0, 0.04)), 0.28),
    ("autotune, critical gain", lambda rig: critical_gain_tune(rig), 0.0),
    ("Bode 1-200 Hz, 10 s sweep", lambda rig: bode_test(rig, 10.0, 0.0, 1.0, 200.0, 10.0), 10.0),
    ("static, 20 s triangle", lambda rig: static_test(rig, 20.0), 20.0),
    ("end-of-line (default profile)", lambda rig: characterize(rig, DEFAULT), 30.45),
]


def free_run_s(valve_seconds: float) -> float:
    """Wall time of the emulator free-running ``valve_seconds`` (the reference)."""
    valve = EmulatedValve(E02)
    valve.advance(2.0)
    start = time.perf_counter()
    valve.advance(valve_seconds)
    return time.perf_counter() - start


QUICK_TESTS: list[tuple[str, Callable[[EmulatorRig], object], float]] = [
    ("autotune, critical gain", lambda rig: critical_gain_tune(rig), 0.0),
    ("Bode 1-200 Hz, 1 s sweep", lambda rig: bode_test(rig, 10.0, 0.0, 1.0, 200.0, 1.0), 1.0),
]


def main() -> None:
    """Run every procedure once and print the table."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="a smoke run: seconds, not figures")
    quick = parser.parse_args().quick
    print(
        f"{'procedure':32} {'physics':>8} {'valve':>8} {'wall':>8} {'valve/wall':>10} {'wall/ref':>9}"
    )
    for name, procedure, physics in QUICK_TESTS if quick else TESTS:
        rig = EmulatorRig(EmulatedValve(E02))
        start = time.perf_counter()
        procedure(rig)
        wall = time.perf_counter() - start
        valve_s = rig.valve_seconds
        reference = free_run_s(valve_s)
        physics_text = f"{physics:7.2f}s" if physics else "      —"
        print(
            f"{name:32} {physics_text} {valve_s:7.2f}s {wall:7.2f}s {valve_s / wall:9.1f}x "
            f"{wall / reference:8.1f}x"
        )


if __name__ == "__main__":
    main()

"""Twins of varied emulated valves (issue 31): how well the steps' fit finds what was changed.

Six emulated valves whose plant constants were changed (a slower spool, more friction, a
weaker solenoid, a slower solenoid, more static friction than the fit can represent, an E04
with a slower actuator) are recorded with ``prm9tool.twin.identify.record`` and fitted from the
factory plant. For each it prints the changed constants (true → fitted, determined or not), the
residual before and after, and the 0 → 25 % and 0 → 90 % step figures of the twin against the
valve's (rise time ratio, overshoot difference in percentage points).

    PYTHONPATH=$PWD .venv/bin/python benchmarks/bench_twin.py [--quick]

``--quick`` runs the first two valves only.
"""

from __future__ import annotations

import argparse
import time
from dataclasses import replace
from typing import Any

import numpy as np

from prm9tool.catalogue import CATALOGUE
from prm9tool.characterize.rig import EmulatorRig
from prm9tool.device.emulator import EmulatedValve
from prm9tool.device.emulator.constants import PLANT
from prm9tool.scope import measure_step
from prm9tool.twin.identify import FITTED, Steps, fit, record, simulate

E02 = "PRM9-06.3Z11/30-24E02S02"
E04 = "PRM9-06.3Z11/30-24E04S02"
VALVES: tuple[tuple[str, str, dict[str, Any]], ...] = (  # (name, type key, changed constants)
    ("slower spool", E02, {"spool_mass_kg": 0.12, "damping_n_s_per_m": 100.0}),
    ("more friction", E02, {"coulomb_friction_n": 0.6, "static_friction_n": 0.8}),
    ("weaker solenoid", E02, {"force_n_per_a": 24.0}),
    ("slower solenoid", E02, {"coil_l_h": 0.045, "force_lag_s": 0.005}),
    ("static friction only", E02, {"static_friction_n": 1.2}),
    ("E04, slower actuator", E04, {"actuator_full_speed_s": 1.0, "spool_mass_kg": 0.08}),
)


def _figures(steps: Steps, actual: np.ndarray, start_s: float) -> tuple[float, float]:
    t = np.arange(len(actual)) / steps.rate_hz
    window = (t >= start_s - 0.06) & (t < start_s + 0.12)
    figures = measure_step(t[window], actual[window], steps.stimulus[window]).figures
    if figures is None:
        return float("nan"), float("nan")
    return figures.rise_time, figures.overshoot


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="the first two valves only")
    args = parser.parse_args()
    for name, key, changed in VALVES[: 2 if args.quick else None]:
        truth = replace(PLANT, **changed)
        valve = EmulatedValve(key, plant=truth)
        if key == E04:  # its position loop, as the Tuning window tunes it
            valve.write(*CATALOGUE["CTRLMODE"].key, 2)
        while valve.status().booting:
            valve.advance(0.05)
        steps = record(EmulatorRig(valve))
        free = FITTED + tuple(k for k in changed if k not in FITTED)
        began = time.perf_counter()
        result = fit(steps, free=free)
        wall = time.perf_counter() - began
        twin = simulate(steps, result.plant)
        verdict = "explained" if result.explained else "NOT explained by the plant's structure"
        print(f"{name} ({key[-6:]}): rms {result.start_rms_pct:.3f} % → {result.rms_pct:.3f} %"
              f" ({verdict}), {result.evaluations} evaluations, {wall:.1f} s")  # fmt: skip
        for constant in result.constants:
            if constant.name in changed or not constant.determined:
                true = getattr(truth, constant.name)
                state = "determined" if constant.determined else "NOT determined (kept)"
                print(f"    {constant.name}: true {true:g}, fitted {constant.value:.4g}, {state}")
        for start_s, label in ((0.12, "0 → 25 %"), (1.08, "0 → 90 %")):
            rise_v, over_v = _figures(steps, steps.actual, start_s)
            rise_t, over_t = _figures(steps, twin, start_s)
            print(f"    step {label}: rise twin/valve {rise_t / rise_v:.3f},"
                  f" overshoot {over_t:.2f} − {over_v:.2f} = {over_t - over_v:+.2f} pp")  # fmt: skip


if __name__ == "__main__":
    main()

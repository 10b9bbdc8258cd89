"""Twins of varied emulated valves (issue 31 items 2 and 4): the proof for each.

Nine emulated valves whose plant constants (or, for the dead band, the threshold parameter)
were changed are characterized with the default profile (stepped as fast as the CPU allows),
their twin is fitted from that run (the steps, then the joint residual with windows of the
sweep and of the static triangle; an E04 in control mode 4 from its process-loop steps and
flow test: ``prm9tool.twin.fitvalve.twin_of_run``, as ``--fit-twin`` does), and the twin is characterized again with the same procedure. For each it prints the
changed constants (true → fitted, determined or not), the residuals, and every figure of both
runs side by side: ratios twin/valve, differences in percentage points for the figures in %,
with the issue's targets checked (−3 dB within 5 %, overshoot within 1 pp, dead band and
hysteresis within 0.2 pp).

    PYTHONPATH=$PWD .venv/bin/python benchmarks/bench_twin.py [--quick] [--valve NAME]

``--quick`` runs the first valve only (the smoke mode: tens of seconds).
"""

from __future__ import annotations

import argparse
import math
import tempfile
import time
from dataclasses import replace
from pathlib import Path
from typing import Any

from prm9tool.analysis.profile import DEFAULT
from prm9tool.catalogue import CATALOGUE
from prm9tool.characterize.rig import EmulatorRig
from prm9tool.characterize.run import characterize
from prm9tool.device.emulator import EmulatedValve
from prm9tool.device.emulator.constants import PLANT
from prm9tool.twin.fitvalve import twin_of_run
from prm9tool.twin.proof import characterize_twin, side_by_side

E02 = "PRM9-06.3Z11/30-24E02S02"
E04 = "PRM9-06.3Z11/30-24E04S02"
# (name, type key, changed plant constants, changed parameters (raw))
VALVES: tuple[tuple[str, str, dict[str, Any], dict[str, int]], ...] = (
    ("weaker solenoid", E02, {"force_n_per_a": 24.0}, {}),
    ("slower spool", E02, {"spool_mass_kg": 0.12, "damping_n_s_per_m": 100.0}, {}),
    ("more friction", E02, {"coulomb_friction_n": 0.6, "static_friction_n": 0.8}, {}),
    ("slower solenoid", E02, {"coil_l_h": 0.045, "force_lag_s": 0.005}, {}),
    ("larger dead band (THRESETP 10 %)", E02, {}, {"THRESETP": 1638}),
    ("static friction only", E02, {"static_friction_n": 1.2}, {}),
    ("E04 position loop, slower actuator", E04, {"actuator_full_speed_s": 1.0,
                                                  "spool_mass_kg": 0.08}, {"CTRLMODE": 2}),
    # control mode 4 (the E04's default): the process loop and its actuator
    ("E04 process loop, slower actuator", E04, {"actuator_full_speed_s": 1.0}, {}),
    ("E04 process loop, slower actuator and overlap", E04, {"actuator_full_speed_s": 0.8,
                                                             "spool_overlap": 0.03}, {}),
)  # fmt: skip
TARGETS = {  # figure name suffix: (kind, limit)
    "bode_bandwidth_hz": ("ratio", 0.05),
    "_overshoot_pct": ("pp", 1.0),
    "static_dead_band_pct": ("pp", 0.2),
    "static_hysteresis_pct": ("pp", 0.2),
}


def _verdict(name: str, ratio: float, difference: float) -> str:
    for suffix, (kind, limit) in TARGETS.items():
        if name.endswith(suffix):
            off = abs(ratio - 1.0) if kind == "ratio" else abs(difference)
            if not math.isfinite(off):
                return "  (not measured)"
            return "  ok" if off <= limit else "  MISSED"
    return ""


def run_one(name: str, key: str, changed: dict[str, Any], params: dict[str, int]) -> bool:
    truth = replace(PLANT, **changed)
    valve = EmulatedValve(key, serial=5301, plant=truth)
    for mnemonic, raw in params.items():
        valve.write(*CATALOGUE[mnemonic].key, raw)
    while valve.status().booting:
        valve.advance(0.05)
    run = characterize(EmulatorRig(valve), DEFAULT)
    with tempfile.TemporaryDirectory() as folder:
        began = time.perf_counter()
        twin = twin_of_run(run, Path(folder) / "twin.toml")
        wall = time.perf_counter() - began
        sides = side_by_side(run, characterize_twin(run, twin.path))
    fit = twin.fit
    verdict = "explained" if fit.explained else "NOT explained by the plant's structure"
    parts = ", ".join(f"{k} {v:.3f} %" for k, v in fit.parts_rms_pct.items())
    print(f"\n{name} ({key[-6:]}): steps rms {fit.start_rms_pct:.3f} % → {fit.rms_pct:.3f} %"
          f" ({verdict}); {parts}; {fit.evaluations} evaluations, {wall:.0f} s")  # fmt: skip
    for c in fit.constants:
        true = getattr(truth, c.name)
        state = "determined" if c.determined else f"NOT determined ({c.reason or 'kept'})"
        mark = " *" if c.name in changed else ""
        print(f"    {c.name}{mark}: true {true:g}, fitted {c.value:.4g}, {state}")
    fitted = {c.name for c in fit.constants}
    for constant, true in changed.items():
        if constant not in fitted:
            print(f"    {constant} *: true {true:g}, NOT fitted (the twin keeps "
                  f"{getattr(fit.plant, constant):g}: not in this run's data)")  # fmt: skip
    met = True
    print(f"    {'figure':<28} {'valve':>9} {'twin':>9}  twin/valve")
    for s in sides:
        extra = f"{s.difference:+.2f} pp" if s.unit == "%" else f"{s.ratio:.3f}"
        check = _verdict(s.name, s.ratio, s.difference)
        met &= "MISSED" not in check
        print(f"    {s.label:<28} {s.valve:>9.4g} {s.twin:>9.4g}  {extra} {s.unit}{check}")
    return met


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="the first valve only")
    parser.add_argument("--valve", help="only the valve whose name starts with this")
    args = parser.parse_args()
    chosen = [v for v in VALVES if args.valve is None or v[0].startswith(args.valve)]
    results = {}
    for valve in chosen[: 1 if args.quick else None]:
        results[valve[0]] = run_one(*valve)
        print(flush=True)
    print("\ntargets met:", ", ".join(f"{k}: {'yes' if ok else 'NO'}" for k, ok in results.items()))


if __name__ == "__main__":
    main()

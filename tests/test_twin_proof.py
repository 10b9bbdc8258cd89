"""Issue 31 item 4, the proof: two varied emulated valves are characterized, twinned from that
run and the twin characterized with the same procedure; the twin's figures meet the issue's
targets (−3 dB within 5 %, overshoot within 1 pp, dead band and hysteresis within 0.2 pp)."""

from __future__ import annotations

from dataclasses import replace

import pytest

from prm9tool.characterize.rig import EmulatorRig
from prm9tool.device.emulator import EmulatedValve
from prm9tool.device.emulator.constants import PLANT
from prm9tool.twin.fitvalve import fit_valve
from prm9tool.twin.proof import characterize_twin, side_by_side, table

E02 = "PRM9-06.3Z11/30-24E02S02"
VALVES = {  # two of benchmarks/bench_twin.py's six, which the plant structure represents
    "weaker solenoid, heavier spool": {"force_n_per_a": 24.0, "spool_mass_kg": 0.08},
    "slower solenoid": {"coil_l_h": 0.045, "force_lag_s": 0.005},
}


@pytest.mark.parametrize("changed", VALVES.values(), ids=list(VALVES))
def test_the_twin_reproduces_the_valve_figures_within_the_targets(changed, tmp_path):
    valve = EmulatedValve(E02, serial=5201, plant=replace(PLANT, **changed))
    twin = fit_valve(EmulatorRig(valve), tmp_path / "twin.toml")
    assert twin.fit.explained
    assert twin.run is not None
    sides = {s.name: s for s in side_by_side(twin.run, characterize_twin(twin.run, twin.path))}
    shown = "\n".join(table(list(sides.values())))
    assert sides["bode_bandwidth_hz"].ratio == pytest.approx(1.0, abs=0.05), shown
    overshoots = [s for name, s in sides.items() if name.endswith("_overshoot_pct")]
    assert len(overshoots) == 3, shown  # each step amplitude of the default profile
    for side in overshoots:
        assert abs(side.difference) <= 1.0, shown  # percentage points
    for name in ("static_dead_band_pct", "static_hysteresis_pct"):
        assert abs(sides[name].difference) <= 0.2, shown
    # the factory plant does not meet them: the proof is of the fit, not of a lenient target
    if "force_n_per_a" in changed:
        assert sides["bode_bandwidth_hz"].valve < 0.95 * _factory_bandwidth(tmp_path)


def _factory_bandwidth(tmp_path) -> float:
    from prm9tool.analysis.profile import DEFAULT
    from prm9tool.characterize.run import characterize

    run = characterize(EmulatorRig(EmulatedValve(E02, serial=5202)), DEFAULT)
    return next(f.value for f in run.figures if f.name == "bode_bandwidth_hz")

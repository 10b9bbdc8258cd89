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
from prm9tool.twin.proof import characterize_twin, compared, side_by_side, table

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


def test_the_twin_of_a_canopen_valve_is_commissioned_for_its_proof(tmp_path):
    """A -CA twin waits for its master as the valve did: the proof enables it first (found
    with the manual-only CAN valve, tests/test_twin_can.py: "device state INIT")."""
    from types import SimpleNamespace

    from prm9tool.analysis.profile import parse_profile
    from prm9tool.device.emulator.twinfile import write_twin
    from prm9tool.twin.identify import Fit

    path = tmp_path / "twin.toml"
    plant = replace(PLANT, force_n_per_a=24.0)
    write_twin(path, Fit(plant, (), 0.02, 0.06, 1.4, 20), 5203, E02 + "-CA", "1.0.0", "x", {})
    profile = parse_profile({"test": {"step_amplitudes_pct": [25], "static_period_s": 1}})
    run = SimpleNamespace(profile=profile, info=SimpleNamespace(link="USB"))  # measured by USB
    again = characterize_twin(run, path)
    assert not again.info.link.startswith("CANopen")  # a USB run's twin: the emulator's rig
    figures = {f.name: f.value for f in again.figures}
    assert 0.0 < figures["step_25_rise_s"] < 0.05


def test_the_proof_emulates_the_object_dictionary_the_valve_had():
    """A CAN run that read none of the parameters whose address is this project's decision
    was a valve with only the manual's objects: its twin gets only those; one that read any
    had the full dictionary."""
    from types import SimpleNamespace

    from prm9tool.catalogue import CATALOGUE
    from prm9tool.twin.proof import object_dictionary

    manual = {p.key: 0 for p in CATALOGUE if p.address_from_manual}
    decided = next(p.key for p in CATALOGUE if not p.address_from_manual)
    assert object_dictionary(SimpleNamespace(parameters=manual)) == "manual"
    assert object_dictionary(SimpleNamespace(parameters={**manual, decided: 0})) == "full"


def test_the_table_says_not_reached_and_each_rows_kind_of_comparison():
    """A settling time neither side reached reads "not reached", never nan; the last column
    says per row whether it is a difference in pp (figures in %) or a ratio."""
    import math

    from prm9tool.twin.proof import Side

    header, unreached, overshoot, bandwidth, zero = table(
        [
            Side("step_5_settling_s", "step 5 %: settling time", "s", math.nan, math.nan),
            Side("step_5_overshoot_pct", "step 5 %: overshoot", "%", 2.0, 2.5),
            Side("bode_bandwidth_hz", "−3 dB frequency", "Hz", 40.0, 39.0),
            Side("step_5_delay_s", "step 5 %: delay", "s", 0.0, 0.001),
        ]
    )
    assert "nan" not in "\n".join([header, unreached, overshoot, bandwidth, zero])
    assert header.split()[-4:] == ["twin", "compared", "with", "valve"]
    assert unreached.split()[-6:] == ["not", "reached", "not", "reached", "s", "—"]
    assert overshoot.endswith("%     +0.50 pp (twin − valve)")
    assert bandwidth.endswith("Hz    ×0.975 (twin/valve)")
    assert zero.endswith("s     —")  # no ratio to a valve's 0
    assert compared(Side("o", "o", "%", 1.0, 1.0 - 1e-9)) == "-0.00 pp (twin − valve)"

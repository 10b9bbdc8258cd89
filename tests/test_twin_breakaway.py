"""The break-away friction of a twin (issue 31 item 2): scanned on the sorted positions of the
run's small steps, with the other constants refitted (prm9tool/twin/breakaway.py)."""

from __future__ import annotations

import math
from dataclasses import replace

import pytest

from prm9tool.analysis.profile import parse_profile
from prm9tool.characterize.rig import EmulatorRig
from prm9tool.characterize.run import characterize
from prm9tool.device.emulator import EmulatedValve
from prm9tool.device.emulator.constants import PLANT
from prm9tool.twin.breakaway import _spread
from prm9tool.twin.fitvalve import write_fitted
from prm9tool.twin.recording import from_characterization

E02 = "PRM9-06.3Z11/30-24E02S02"
# the default profile's steps; a short sweep and triangle (only the steps are fitted here)
STEPS = {"test": {"step_amplitudes_pct": [5, 25, 90], "bode_duration_s": 1, "bode_f_min_hz": 5,
                  "bode_f_max_hz": 50, "static_period_s": 4}}  # fmt: skip


def test_a_break_away_friction_off_any_grid_is_found_from_the_steps(tmp_path):
    """1.1337 N (on no grid the scan uses: a value the scan could only land on by chance was
    found at 1.2 N before this one was tried), the sliding friction the factory's 0.3 N: the
    steps' fit alone kept 0.5 N and stood in for it with 0.47 N sliding friction."""
    truth = replace(PLANT, static_friction_n=1.1337)
    valve = EmulatedValve(E02, serial=5305, plant=truth)
    while valve.status().booting:
        valve.advance(0.05)
    run = characterize(EmulatorRig(valve), parse_profile(STEPS))
    steps = from_characterization(run, joint=False)
    fit = write_fitted(tmp_path / "twin.toml", steps, 5305, E02, "", "test")
    static = fit.constant("static_friction_n")
    assert static.determined, static
    assert static.value == pytest.approx(1.1337, rel=0.02)
    assert fit.plant.static_friction_n == static.value
    assert fit.constant("coulomb_friction_n").value == pytest.approx(0.3, rel=0.03)
    assert fit.rms_pct < fit.start_rms_pct / 2


def test_a_loss_that_does_not_pin_the_friction_leaves_it_undetermined():
    """Within one LVDT count of the best up to the scan's end, or a basin wider than ±5 %:
    not determined (the valve with 0.6 N sliding, 0.8 N break-away friction's scan)."""
    flat = {0.5 + 0.05 * k: 0.05 + 0.001 * k for k in range(40)}  # rising slowly from the end
    assert _spread(flat) == math.inf
    wide = {0.5 + 0.05 * k: abs(k - 20) * 0.004 for k in range(40)}  # ±0.75 N about 1.5 N
    assert 0.05 < _spread(wide) < math.inf
    sharp = {0.5 + 0.005 * k: abs(k - 100) * 0.02 for k in range(200)}  # ±0.015 N
    assert _spread(sharp) < 0.05

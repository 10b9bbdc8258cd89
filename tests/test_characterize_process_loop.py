"""Issue 34 items 1 and 2: the end-of-line test of an E04 process loop.

The report gave figures for steps that never arrived (rise and overshoot measured against the
last value of a 150 ms window in which the actuator was still moving), and the default profile
applied the spool's limits and windows to the integrating actuator, so it always failed. The
figures are now measured against the setpoint ("not reached" fails), the report names the loop,
and the profile has a part per loop."""

from __future__ import annotations

import json
import math
import re

import numpy as np
import pytest

from prm9tool.analysis.model import Targets
from prm9tool.analysis.profile import DEFAULT, DEFAULT_PROCESS, ProfileError, parse_profile
from prm9tool.characterize.acceptance import propose
from prm9tool.characterize.rig import EmulatorRig
from prm9tool.characterize.run import characterize, report_data
from prm9tool.device.emulator import EmulatedValve
from prm9tool.scope.measure import step_figures_to_setpoint

E04 = "PRM9-06.3Z11/30-24E04S02"
SHORT = {"process": {"test": {"step_duration_s": 0.15, "step_amplitudes_pct": [90]}}}


def _ramp(final: float, seconds: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    t = np.arange(-0.02, 0.15, 0.001)
    setpoint = np.where(t >= 0, 90.0, 0.0)
    y = np.clip(t / seconds, 0.0, 1.0) * final  # a ramp, still moving when the window ends
    return t, y, setpoint


def test_figures_against_the_setpoint_of_a_step_still_on_its_way():
    t, y, setpoint = _ramp(90.0, 0.24)  # at 56 % of 90 % when the window ends
    f = step_figures_to_setpoint(t, y, setpoint)
    assert f is not None and not f.reached
    assert math.isnan(f.overshoot) and math.isnan(f.settling_time) and math.isnan(f.rise_time)
    assert (
        str(f.not_reached("%")) == "not reached: the response ended at 55.9 % of the setpoint 90 %"
    )


def test_figures_against_the_setpoint_of_a_step_that_arrived():
    t, y, setpoint = _ramp(90.0, 0.05)
    f = step_figures_to_setpoint(t, y, setpoint)
    assert f is not None and f.reached and f.not_reached() is None
    assert f.rise_time == pytest.approx(0.04, abs=0.002)  # 10 → 90 % of the way to 90 %
    assert f.overshoot == 0.0 and f.settling_time == pytest.approx(0.049, abs=0.002)


def test_a_process_step_that_never_reached_its_setpoint_fails_as_not_reached():
    rig = EmulatorRig(EmulatedValve(E04))
    result = characterize(rig, parse_profile(SHORT))  # the old 150 ms window
    assert result.loop == "process"
    by_name = {f.name: f for f in result.figures}
    for key in ("overshoot_pct", "rise_s"):
        f = by_name[f"step_90_{key}"]
        assert math.isnan(f.value) and f.passed is False  # was 4.3 % PASS, 106 ms
        assert str(f.note).startswith("not reached: the response ended at 5")
    assert not result.passed
    report = report_data(result)
    assert report["loop"] == "process"
    json.dumps(report)


def test_the_default_profile_passes_the_e04_process_loop_with_windows_for_the_actuator():
    rig = EmulatorRig(EmulatedValve(E04))
    result = characterize(rig, DEFAULT)
    failed = [(f.name, f.value) for f in result.figures if f.passed is False]
    assert result.passed, failed  # the spool's 30 ms rise and 15 Hz failed every time
    assert all(s.record.t[-1] >= 1.4 for s in result.steps)  # windows of 1.5 s, not 150 ms
    limits = {f.name: f.limit for f in result.figures}
    assert limits["step_90_rise_s"] == DEFAULT_PROCESS.limits["step_rise_s"]
    assert result.bode is not None and result.bode.response.frequency[0] < 0.5  # from 0.2 Hz
    assert limits["bode_bandwidth_hz"] is not None
    assert (
        limits["bode_bandwidth_hz"].minimum == DEFAULT_PROCESS.limits["bode_bandwidth_hz"].minimum
    )


def test_the_autotune_of_the_process_loop_can_pass_the_default_profile():
    rig = EmulatorRig(EmulatedValve(E04))
    proposal = propose(rig, "model", "process", Targets(10.0, 0.5), 20.0, 60.0, DEFAULT)
    assert proposal.passes, str(proposal.verdict())
    assert all(s.record.t[-1] >= 1.4 for s in proposal.after_check.steps)


def test_a_profile_sets_the_process_loop_apart_and_keeps_its_defaults():
    profile = parse_profile(
        {
            "name": "line 3",
            "limits": {"step_rise_s": {"max": 0.02}},
            "process": {"limits": {"step_rise_s": {"max": 0.35}}},
        }
    )
    assert profile.limits["step_rise_s"].maximum == 0.02
    process = profile.for_loop("process")
    assert process.name == "line 3"
    assert process.limits["step_rise_s"].maximum == 0.35
    assert process.step_duration_s == DEFAULT_PROCESS.step_duration_s  # its own default
    assert process.limits["bode_bandwidth_hz"] == DEFAULT_PROCESS.limits["bode_bandwidth_hz"]
    assert profile.for_loop("position") is profile
    assert process.for_loop("process") is process  # a part asked again keeps its own limits
    with pytest.raises(ProfileError, match=r"\[process.test\] has no key 'rise'"):
        parse_profile({"process": {"test": {"rise": 1}}})
    with pytest.raises(ProfileError, match=r"\[process\] holds only"):
        parse_profile({"process": {"name": "x"}})


# --- issue 34 item 9: a sweep on a PC too busy to update the setpoint -----------------------------
class HeldRig(EmulatorRig):
    """An emulated valve behind a PC that writes its setpoint only every ``hold`` samples from
    ``after`` on (a busy PC over USB: one report per round trip of tens of ms)."""

    def __init__(self, hold: int, after: int = 0) -> None:
        super().__init__(EmulatedValve("PRM9-06.3Z11/30-24E02S02"))
        self.hold, self.after = hold, after

    def play(self, setpoint_pct, keys, gaps=False):
        values = np.asarray(setpoint_pct, dtype=float).copy()
        if len(values) > 1000:  # the sweep
            index = np.arange(len(values))
            held = np.where(index >= self.after, (index // self.hold) * self.hold, index)
            values = values[held]
        return super().play(values, keys, gaps)


def test_a_sweep_the_pc_could_not_update_is_cut_where_it_stopped_following(qapp):
    from prm9tool.characterize.procedures import bode_test

    right = bode_test(EmulatorRig(EmulatedValve("PRM9-06.3Z11/30-24E02S02")), 10, 0, 2, 100, 1.5)
    assert 25 < right.response.bandwidth_hz() < 36  # ~31 Hz
    held = bode_test(HeldRig(150), 10, 0, 2, 100, 1.5)  # 30 ms holds: read 36 Hz, 18 % high
    assert re.match(r"sweep usable up to [89]\.\d+ Hz", str(held.note)), str(held.note)
    assert "held the valve's setpoint for 30 ms" in str(held.note)
    assert math.isnan(held.response.bandwidth_hz())  # not a wrong figure ...
    assert held.response.bandwidth_above_hz() <= 9.0  # ... but "above" where it was usable
    assert held.held_s == pytest.approx(0.03)
    with pytest.raises(Exception, match="updated the valve's setpoint too seldom"):
        bode_test(HeldRig(1500), 10, 0, 2, 100, 1.5)  # 0.3 s holds: nothing usable


def test_the_frequency_response_page_says_the_pc_cut_the_sweep(qtbot):
    from prm9tool.characterize.procedures import bode_test
    from prm9tool.model.document import ParameterDocument
    from prm9tool.views.tuning.window import TuningWindow

    w = TuningWindow(ParameterDocument("PRM9-06.3Z11/30-24E02S02"))
    qtbot.addWidget(w)
    w.bode.show_result(bode_test(HeldRig(150), 10, 0, 2, 100, 1.5))
    text = w.bode.result.text()
    assert "The PC held the valve's setpoint for 30 ms at 8" in text, text
    assert "sample rate limited" not in text  # it was not the link's sample rate

"""Simulated step responses of the controller dialogs, run on the emulator's firmware."""

from __future__ import annotations

import math

import numpy as np
import pytest

from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.online.tuning import StepResponse, StepSimulator, simulate_step, simulation_values
from prm9tool.scope import step_figures

E02 = "PRM9-06.3Z11/30-24E02S02"
E04_CA = "PRM9-06.3Z11/30-24E04S02-CA"


def defaults(key: str) -> dict[str, int | str]:
    variant = TypeKey.parse(key).variant
    return {p.mnemonic: p.default_for(variant) for p in CATALOGUE.file_parameters(variant)}


def test_the_position_loop_follows_a_50_percent_step():
    response = simulate_step(E02, defaults(E02), "position")
    assert response.t[0] < 0.0 < response.t[-1]
    before = [a for t, a in zip(response.t, response.actual, strict=True) if t < 0]
    assert max(abs(a) for a in before) < 1.0
    assert response.setpoint[-1] == pytest.approx(50.0, abs=0.5)
    assert response.actual[-1] == pytest.approx(50.0, abs=2.5)
    assert response.values["POSKP"] == defaults(E02)["POSKP"]


def test_lower_gain_answers_more_slowly():
    base = defaults(E02)
    fast = simulate_step(E02, base, "position").figures()
    slow = simulate_step(E02, {**base, "POSKP": int(base["POSKP"]) // 4}, "position").figures()
    assert fast.rise_time_s is not None
    assert slow.rise_time_s is None or slow.rise_time_s > fast.rise_time_s


def test_the_process_loop_of_an_e04_valve():
    response = simulate_step(E04_CA, defaults(E04_CA), "process")  # simulated without CANopen
    assert response.setpoint[-1] == pytest.approx(20.0, abs=0.5)
    assert response.actual[-1] == pytest.approx(20.0, abs=2.0)


def test_the_chain_in_front_of_the_loop_is_made_transparent():
    values = simulation_values({**defaults(E02), "THRESETP": 3000, "RAMPSETPOSUP": 900}, "position")
    assert values["THRESETP"] == 0 and values["RAMPSETPOSUP"] == 0
    assert values["AINSETP"] == 9 and values["CTRLMODE"] == 2
    process = simulation_values({**defaults(E04_CA), "GAINSETPOS": 20000}, "process")
    assert process["GAINSETPOS"] == 20000  # part of the process loop


def test_step_figures():
    t = tuple(i * 0.001 for i in range(-5, 100))
    stepped = tuple(0.0 if x < 0 else 50.0 for x in t)
    ideal = tuple(0.0 if x < 0 else min(50.0, x * 5000.0) for x in t)
    figures = StepResponse("position", {}, t, stepped, ideal, 50.0).figures()
    assert figures.overshoot_pct == 0.0
    assert figures.rise_time_s == pytest.approx(0.008, abs=0.0015)
    assert figures.steady_error_pct == pytest.approx(0.0)
    ringing = tuple(0.0 if x < 0 else 50.0 + 30.0 * math.sin(2 * math.pi * x / 0.02) for x in t)
    figures = StepResponse("position", {}, t, stepped, ringing, 50.0).figures()
    assert figures.overshoot_pct > 50.0
    assert figures.settling_time_s is None
    flat = StepResponse("position", {}, t, stepped, (0.0,) * len(t), 50.0).figures()
    assert (flat.rise_time_s, flat.steady_error_pct) == (None, 100.0)


def test_the_dialog_and_the_scope_measure_a_step_alike():
    t = tuple(i * 0.0002 for i in range(-25, 500))
    setpoint = tuple(0.0 if x < 0 else 50.0 for x in t)
    actual = tuple(0.0 if x < 0 else 48.0 * (1 - math.exp(-x / 0.005)) for x in t)
    figures = StepResponse("position", {}, t, setpoint, actual, 50.0).figures()
    scope = step_figures(np.array(t), np.array(actual), np.array(setpoint))
    assert scope is not None
    assert figures.rise_time_s == pytest.approx(scope.rise_time)
    assert figures.rise_time_s == pytest.approx(0.005 * math.log(9), abs=0.0002)
    assert figures.settling_time_s == pytest.approx(scope.settling_time)
    assert figures.steady_error_pct == pytest.approx(4.0, abs=0.01)  # 2 of 50 % left


def test_the_simulator_runs_off_the_gui_thread_and_the_newest_request_wins(qtbot):
    simulator = StepSimulator(E02, defaults(E02), "position")
    received: list[StepResponse] = []
    simulator.response_ready.connect(received.append)
    for kp in (100, 200, 300, 400):
        simulator.request({"POSKP": kp})
    qtbot.waitUntil(lambda: bool(received) and received[-1].values["POSKP"] == 400, timeout=10000)
    qtbot.waitUntil(lambda: not simulator.busy, timeout=10000)
    assert len(received) <= 2  # a running simulation plus only the newest pending one
    simulator.stop()
    simulator.request({"POSKP": 500})
    assert not simulator.busy


def test_a_refused_parameter_is_reported(qtbot):
    simulator = StepSimulator(E02, {**defaults(E02), "LIMTA": 9999}, "position")
    with qtbot.waitSignal(simulator.failed, timeout=10000) as failed:
        simulator.request({})
    assert failed.args[0]
    simulator.stop()


def test_an_unknown_loop_is_refused():
    with pytest.raises(ValueError, match="unknown loop"):
        StepSimulator(E02, {}, "pressure")


def test_the_dialog_and_the_autotune_give_the_same_figures_for_the_same_gains():
    """Issue 25 item 5: the dialog said 0.9 % / 13.6 ms where the autotune said 0.0 % / 17.2 ms
    for the same gains (another stimulus, a 60 ms window). Now both take the autotune's step."""
    from prm9tool.characterize.autotune import simulate_steps
    from prm9tool.characterize.frame import STEP_PRE_S, STEP_WINDOW_S
    from prm9tool.characterize.rig import EmulatorRig
    from prm9tool.device.emulator import EmulatedValve

    gains = {"POSKP": 44, "POSKI": 1031, "POSKD": 44, "POST1": 20}
    dialog = simulate_step(E02, {**defaults(E02), **gains}, "position")
    _, autotune = simulate_steps(EmulatorRig(EmulatedValve(E02)), "position", gains, 50.0, 0.12)
    assert autotune.figures is not None
    shown = dialog.measured()
    assert shown is not None
    assert shown.overshoot == pytest.approx(autotune.figures.overshoot, abs=1e-9)
    assert shown.settling_time == pytest.approx(autotune.figures.settling_time, abs=1e-9)
    assert shown.rise_time == pytest.approx(autotune.figures.rise_time, abs=1e-9)
    assert dialog.t[0] == pytest.approx(-STEP_PRE_S)
    assert dialog.t[-1] == pytest.approx(STEP_WINDOW_S["position"], abs=0.001)
    assert dialog.summary().startswith("Step 0 → 50 %, window −20 … 120 ms: overshoot ")
    assert str(autotune.caption()) == "Step 0 → 50 %, window −20 … 120 ms"

"""Issue 16's done-means on the emulator: (a) Bode, (b) model autotune, (c) critical gain,
(d) linearization; plus the valve being left as it was after a stop, a fault or a limit.

The references are measured here by driving the emulated valve directly (pure sines, a fine
P-only gain sweep), not through the procedures under test.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from prm9tool.analysis.frequency import sine_response
from prm9tool.analysis.model import Targets
from prm9tool.analysis.static import linearization_values, propose_linearization
from prm9tool.catalogue import CATALOGUE
from prm9tool.characterize.autotune import model_tune
from prm9tool.characterize.critical_gain import critical_gain_tune
from prm9tool.characterize.frame import LimitExceededError
from prm9tool.characterize.procedures import bode_test, static_test, step_test
from prm9tool.characterize.rig import EmulatorRig, Stopped
from prm9tool.characterize.transparent import TRANSPARENT
from prm9tool.device.emulator import EmulatedValve
from prm9tool.scope.measure import step_figures

E02 = "PRM9-06.3Z11/30-24E02S02"
CYCLE = 200e-6


def booted(values: dict[str, int] | None = None) -> EmulatedValve:
    valve = EmulatedValve(E02)
    for mnemonic, raw in (values or {}).items():
        param = CATALOGUE[mnemonic]
        valve.write(param.index, param.subindex, raw)
    while valve.status().booting:
        valve.advance(0.05)
    valve.advance(0.05)
    return valve


def put(valve: EmulatedValve, mnemonic: str, raw: int) -> None:
    param = CATALOGUE[mnemonic]
    valve.write(param.index, param.subindex, raw)


def direct_sine_gain(f: float, amplitude: float = 10.0) -> float:
    """|actual/setpoint| from a pure sine written straight into the override."""
    valve = booted(TRANSPARENT)
    put(valve, "SETPOVRON", 1)
    n = round(8.0 / f / CYCLE)
    valve.capture_start(["position_setpoint", "position_actual"], 1)
    for k in range(n):
        put(valve, "SETPOVR", round(amplitude * 163.84 * math.sin(2 * math.pi * f * k * CYCLE)))
        valve.usb_activity()
        valve.advance(CYCLE)
    data = valve.capture_read()
    t = np.arange(len(data)) * CYCLE
    keep = t >= 3.0 / f  # after the transient
    return abs(sine_response(t[keep], data[keep, 0], data[keep, 1], f))


def test_a_bandwidth_agrees_with_pure_sines():
    rig = EmulatorRig(booted())
    tool = bode_test(rig, 10.0, 0.0, 2.0, 100.0, duration_s=4.0).response.bandwidth_hz()
    low = direct_sine_gain(2.0)
    freqs = [20.0, 25.0, 30.0, 35.0, 40.0, 50.0]
    db = [20 * math.log10(direct_sine_gain(f) / low) for f in freqs]
    k = next(i for i, v in enumerate(db) if v <= -3.0103)
    share = (db[k - 1] + 3.0103) / (db[k - 1] - db[k])
    reference = math.exp(math.log(freqs[k - 1]) + share * math.log(freqs[k] / freqs[k - 1]))
    assert tool == pytest.approx(reference, rel=0.05)


def measured_step(values: dict[str, int], amplitude: float = 50.0) -> tuple[float, float]:
    """Overshoot and settling of a step straight on a valve holding ``values``."""
    valve = booted({**TRANSPARENT, **values})
    put(valve, "SETPOVRON", 1)
    valve.capture_start(["position_setpoint", "position_actual"], 1)
    valve.advance(0.01)
    put(valve, "SETPOVR", round(amplitude * 163.84))
    valve.advance(0.12)
    data = valve.capture_read()
    figures = step_figures(np.arange(len(data)) * CYCLE, data[:, 1], data[:, 0])
    assert figures is not None
    return figures.overshoot, figures.settling_time


@pytest.mark.parametrize("factor", [0.1, 3.0])
def test_b_autotune_of_a_detuned_valve_meets_the_targets(factor):
    default = int(CATALOGUE["POSKP"].default)
    rig = EmulatorRig(booted({"POSKP": round(default * factor)}))
    targets = Targets(overshoot_pct=10.0, settling_s=0.04)
    result = model_tune(rig, targets)
    overshoot, settling = measured_step(result.proposed_values)
    assert overshoot <= targets.overshoot_pct
    assert settling <= targets.settling_s
    assert rig.read(["POSKP"])["POSKP"] == round(default * factor)  # proposal not written


def direct_sweep() -> tuple[float, float]:
    """Smallest Kp (grid 0.05) at which a P-only loop keeps oscillating, and its period while
    its swings are small (grown beyond ±20 %, the coils' current limits slow it down)."""
    for kp_raw in range(300, 700, 5):
        valve = booted({**TRANSPARENT, "POSKP": kp_raw, "POSKI": 0, "POSKD": 0})
        put(valve, "SETPOVRON", 1)
        valve.advance(0.03)
        put(valve, "SETPOVR", round(5.0 * 163.84))
        valve.capture_start(["position_actual"], 1)
        for _ in range(5):
            valve.usb_activity()  # the override's watchdog wants a report within 0.5 s
            valve.advance(0.1)
        y = valve.capture_read()[:, 0] / 163.84
        if np.ptp(y[-500:]) > 10.0:  # still swinging by more than 10 % after 0.4 s
            large = np.flatnonzero(np.abs(y[100:] - 5.0) >= 20.0)
            small = y[100 : 100 + (int(large[0]) if len(large) else len(y))]
            tail = small - small.mean()
            spectrum = np.abs(np.fft.rfft(tail * np.hanning(len(tail)), 1 << 17))
            f = np.fft.rfftfreq(1 << 17, CYCLE)
            return kp_raw * 0.01, 1.0 / f[int(np.argmax(spectrum[1:])) + 1]
    raise AssertionError("no oscillation up to Kp 7")


def test_c_critical_gain_agrees_with_a_direct_sweep():
    kkr, tkr = direct_sweep()
    rig = EmulatorRig(booted())
    result = critical_gain_tune(rig)
    assert result.kkr == pytest.approx(kkr, rel=0.10)
    assert result.tkr == pytest.approx(tkr, rel=0.10)
    assert result.gains.kp == pytest.approx(0.5 * result.kkr)
    assert rig.read(["POSKP", "POSKI", "THRESETP"]) == {"POSKP": 40, "POSKI": 1000, "THRESETP": 819}


BENT = {  # a bent setpoint characteristic, its X points not the proposal's
    "SETPLINON": -1,
    **dict(zip([f"SETPLINX{c}" for c in "ABCDEFGHI"],
               [-16384, -11000, -6000, -2500, 0, 3000, 7000, 12000, 16384], strict=True)),
    **dict(zip([f"SETPLINY{c}" for c in "ABCDEFGHI"],
               [-16384, -7000, -2500, -800, 0, 900, 3500, 8500, 16384], strict=True)),
}  # fmt: skip


def test_d_linearization_reduces_the_linearity_error_five_fold():
    rig = EmulatorRig(booted({**BENT, "THRESETP": 0}))
    before = static_test(rig, period_s=4.0)
    channels = before.record.channels
    lin = propose_linearization(
        channels["setpoint_gain"] * 163.84,
        channels["setpoint_linearized"] * 163.84,
        channels["position_actual"],
        before.demand,
    )
    rig.write(linearization_values(lin))
    after = static_test(rig, period_s=4.0)
    assert before.characteristic.linearity_pct > 10.0
    assert after.characteristic.linearity_pct * 5.0 <= before.characteristic.linearity_pct


def test_a_stop_request_leaves_the_valve_as_it_was():
    rig = EmulatorRig(booted())
    rig.stop.set()
    with pytest.raises(Stopped):
        critical_gain_tune(rig)
    assert rig.read(["POSKP", "POSKI", "THRESETP", "SETPOVRON"]) == {
        "POSKP": 40,
        "POSKI": 1000,
        "THRESETP": 819,
        "SETPOVRON": 0,
    }


def test_a_limit_exceeded_stops_the_step_and_restores():
    rig = EmulatorRig(booted())
    with pytest.raises(LimitExceededError, match="left the allowed band"):
        step_test(rig, 50.0, limit_pct=20.0)
    assert rig.read(["THRESETP", "SETPOVRON"]) == {"THRESETP": 819, "SETPOVRON": 0}


def test_over_a_link_the_figures_agree_with_the_stepped_emulator():
    """SessionRig: the override written at the link's pace, samples from the stream."""
    from prm9tool.characterize.rig import SessionRig
    from prm9tool.device import emulated_valves, factory

    session = factory.open_session(f"emulator:{E02}:61", paced=False)
    try:
        rig = SessionRig(session, "emulator over its USB link")
        linked = bode_test(rig, 10.0, 0.0, 2.0, 100.0, 2.0).response.bandwidth_hz()
        static = static_test(rig, period_s=2.0).characteristic
        assert rig.read(["SETPOVRON", "THRESETP"]) == {"SETPOVRON": 0, "THRESETP": 819}
    finally:
        session.close()
        emulated_valves.forget_emulated_valves()
    stepped = bode_test(EmulatorRig(booted()), 10.0, 0.0, 2.0, 100.0, 2.0).response.bandwidth_hz()
    assert linked == pytest.approx(stepped, rel=0.05)
    assert static.gain == pytest.approx(1.0, abs=0.03)


def test_model_autotune_of_the_e04_process_loop():
    """An integrating plant (the actuator); the deviation's gain and offset stay in the loop."""
    valve = EmulatedValve("PRM9-06.3Z11/30-24E04S02")
    rig = EmulatorRig(valve)
    targets = Targets(overshoot_pct=10.0, settling_s=0.5)
    result = model_tune(rig, targets, loop="process", amplitude_pct=20.0)
    assert result.model.integrating
    assert result.model.gain == pytest.approx(4.0, rel=0.05)  # full stroke in 0.5 s at 100 %
    assert result.meets_targets
    assert rig.read(["PRCKP", "GAINSETPOS"]) == {"PRCKP": 200, "GAINSETPOS": 16384}


def test_an_identification_without_response_or_with_a_bad_fit_is_not_trustworthy():
    """The verdict lives below the views: no response or a fit error above the threshold."""
    from dataclasses import replace

    from prm9tool.analysis.model import MAX_FIT_ERROR_PCT, PlantModel
    from prm9tool.characterize.autotune import doubts
    from prm9tool.characterize.frame import Record
    from prm9tool.characterize.procedures import StepResult

    good = PlantModel(1.0, 0.002, 0.001, 0.0005, 2, False, 3.0)
    flat = StepResult(50.0, Record(np.zeros(3), {}), None)
    assert good.trustworthy
    assert not replace(good, fit_error=MAX_FIT_ERROR_PCT + 25.0).trustworthy
    assert not replace(good, fit_error=float("nan")).trustworthy
    texts = [str(d) for d in doubts(replace(good, fit_error=45.0), flat)]
    assert len(texts) == 2
    assert "did not respond" in texts[0]
    assert "fit error 45 %, at most 20 %" in texts[1]


def test_the_rigs_refusals_are_shown_in_the_program_language(qapp):
    """A refusal stays English on the command line and is translated where a view shows it."""
    from prm9tool import i18n
    from prm9tool.characterize.rig import ValveFaultError
    from prm9tool.translate import error_text

    rig = EmulatorRig(EmulatedValve("PRM9-06.3Z11/30-24E02S02-CA"))
    rig.valve.advance(2.0)  # booted: a -CA valve waits in INIT for its master
    with pytest.raises(ValveFaultError) as refused:
        rig.ensure_active()
    rig.stop.set()
    with pytest.raises(Stopped) as stopped:
        rig.check()
    assert "does not follow its setpoint: device state INIT (a -CA valve" in str(refused.value)
    try:
        i18n.set_language("de")
        assert error_text(refused.value).startswith("das Ventil folgt seinem Sollwert nicht")
        assert error_text(stopped.value).startswith("vom Benutzer abgebrochen")
        i18n.set_language("cs")
        assert error_text(stopped.value).startswith("zastaveno uživatelem")
    finally:
        i18n.set_language("en")


def test_a_loop_the_control_mode_does_not_close_is_refused_before_anything_moves():
    """An E04 as delivered (control mode 4): the Tuning window's "Position controller (spool)"
    autotune stepped the process loop instead and stopped with "position_actual left the
    allowed band 0 ± 60 %"; the position loop needs mode 2, the process loop mode 4."""
    from prm9tool.errors import Prm9Error

    e04 = EmulatedValve("PRM9-06.3Z11/30-24E04S02")
    rig = EmulatorRig(e04)
    before = rig.read(["THRESETP", "SETPOVRON", "POSKP"])
    with pytest.raises(Prm9Error, match=r"control mode 4 \(process loop\)") as refused:
        model_tune(rig, Targets(overshoot_pct=10.0, settling_s=0.04))
    assert "Choose the process loop, or set CTRLMODE to 2" in str(refused.value)
    assert rig.played_s == 0.0 and rig.read(list(before)) == before  # nothing written or moved
    e04 = EmulatedValve("PRM9-06.3Z11/30-24E04S02")
    put(e04, "CTRLMODE", 2)  # before it boots (an active valve refuses a new control mode)
    rig = EmulatorRig(e04)
    with pytest.raises(Prm9Error, match=r"control mode 2 \(spool position\): it has no process"):
        step_test(rig, 20.0, loop="process")
    assert step_test(rig, 20.0, duration_s=0.05).figures is not None  # mode 2: the spool's


def test_leaving_the_band_names_the_signal_in_the_program_language(qapp):
    from prm9tool import i18n
    from prm9tool.translate import error_text

    rig = EmulatorRig(booted())
    with pytest.raises(LimitExceededError) as stopped:
        step_test(rig, 50.0, duration_s=0.05, limit_pct=20.0)
    assert str(stopped.value).startswith("Spool position actual (0x6301) left the allowed band")
    i18n.set_language("de")
    try:
        german = error_text(stopped.value)
    finally:
        i18n.set_language("en")
    assert german.startswith("Schieberlage Ist (0x6301) hat das zulässige Band 0 ± 20 % verlassen")


def test_an_e04_sweep_after_a_large_step_starts_from_rest():
    """`--characterize` of an E04 as delivered stopped at its frequency response with
    "process_actual left the allowed band 0 ± 30 %": the actuator was still at 59 % from the
    90 % step (0.15 s) when the sweep began after 0.05 s at 0 %."""
    from prm9tool.characterize.frame import settle

    rig = EmulatorRig(EmulatedValve("PRM9-06.3Z11/30-24E04S02"))
    step_test(rig, 90.0, duration_s=0.15, loop="process")
    bode = bode_test(rig, 10.0, 0.0, 1.0, 20.0, 2.0, "process")  # raised LimitExceededError
    assert abs(bode.record.channels["process_actual"][0]) < 5.0  # was 59 %
    before = rig.played_s
    settle(rig, "process_actual", 0.0, 0.1)  # already there: one hold, no more
    assert rig.played_s - before == pytest.approx(0.1)


def test_a_single_coil_valve_is_characterized_on_its_one_side():
    """A single-coil valve has no negative signal range and no objects for its ramps
    (RAMPSETNEG*, manual §8.7.2): the transparent chain leaves them out (reading them was an
    SDO abort 0x6333/1), the sweep runs clear of the null and the triangle from 0 to 100 %."""
    from prm9tool.analysis.profile import DEFAULT
    from prm9tool.characterize.frame import chain_changes
    from prm9tool.characterize.run import characterize

    valve = EmulatedValve("PRM9-06.2Z51/30-24E02S02")
    while valve.status().booting:
        valve.advance(0.05)
    rig = EmulatorRig(valve)
    assert not any(k.startswith("RAMPSETNEG") for k in chain_changes(rig))
    run = characterize(rig, DEFAULT)
    assert run.bode is not None and run.static is not None
    sweep = run.bode.record.channels["position_setpoint"]
    assert run.bode.centre_pct > DEFAULT.bode_amplitude_pct and sweep.min() >= 0.0
    assert run.static.demand.min() == pytest.approx(0.0) and run.static.demand.max() > 99.0
    assert {f.name for f in run.figures if f.passed is False} == set()
    assert valve.status().active_errors == ()

"""Issue 31 item 2 (start): the plant constants of a varied emulated valve are identified from
its position-loop steps by least squares, and the twin file keeps them."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from prm9tool.catalogue import CATALOGUE
from prm9tool.characterize.rig import EmulatorRig
from prm9tool.device.emulator import EmulatedValve
from prm9tool.device.emulator.constants import PLANT
from prm9tool.errors import Prm9Error
from prm9tool.scope import measure_step
from prm9tool.twin.emulate import emulated_twin
from prm9tool.twin.identify import FITTED, fit
from prm9tool.twin.recording import record
from prm9tool.twin.replay import simulate
from prm9tool.twin.twinfile import TwinFileError, read_twin, write_twin

E02 = "PRM9-06.3Z11/30-24E02S02"
# a slower spool, a weaker solenoid, more friction (static friction as the factory plant's)
VARIED = replace(PLANT, spool_mass_kg=0.09, force_n_per_a=25.0, coulomb_friction_n=0.45)


@pytest.fixture(scope="module")
def fitted():
    valve = EmulatedValve(E02, serial=3101, plant=VARIED)
    while valve.status().booting:
        valve.advance(0.05)
    steps = record(EmulatorRig(valve))
    return steps, fit(steps)


def test_the_constants_a_varied_valve_changed_are_found(fitted):
    steps, result = fitted
    assert result.start_rms_pct > 1.0  # the factory plant does not explain this valve
    assert result.rms_pct < 0.1  # the twin does, within two LVDT steps (0.061 % each)
    assert result.explained
    for name in ("spool_mass_kg", "force_n_per_a", "coulomb_friction_n"):
        found = result.constant(name)
        assert found.determined, found
        assert found.value == pytest.approx(getattr(VARIED, name), rel=0.05), found
    for name in ("damping_n_s_per_m", "force_lag_s", "coil_l_h"):  # unchanged: stay put
        assert result.constant(name).value == pytest.approx(getattr(PLANT, name), rel=0.10)
    twin = simulate(steps, result.plant)
    assert np.sqrt(np.mean((twin - steps.actual) ** 2)) == pytest.approx(result.rms_pct)


def test_a_constant_the_steps_do_not_see_is_said_to_be_undetermined(fitted):
    steps, _ = fitted
    result = fit(steps, free=("thermal_tau_s",), max_evaluations=5)
    (tau,) = result.constants
    assert not tau.determined  # the housing's thermal time constant: not in 1.6 s of steps
    assert tau.value == PLANT.thermal_tau_s  # kept, not invented


def test_the_twin_file_keeps_the_fit_and_refuses_what_it_cannot_use(fitted, tmp_path):
    _, result = fitted
    path = tmp_path / "valve.toml"
    steps, _ = fitted
    write_twin(path, result, 3101, E02, "1.0.0", "position-loop steps, 5000 Hz", steps.values)
    twin = read_twin(path)
    assert twin.parameters == steps.values
    assert twin.plant == result.plant
    assert (twin.serial, twin.type_key, twin.firmware) == (3101, E02, "1.0.0")
    assert set(twin.fit["constants"]) == set(FITTED)
    assert twin.fit["constants"]["force_n_per_a"]["determined"] is True
    text = path.read_text(encoding="utf-8")
    path.write_text(text.replace("version = 1", "version = 2"), encoding="utf-8")
    with pytest.raises(TwinFileError, match="version 2; this prm9tool reads version 1"):
        read_twin(path)
    path.write_text(text.replace("spool_mass_kg =", "spool_mas_kg ="), encoding="utf-8")
    with pytest.raises(TwinFileError, match=r"\[plant\] has no constant 'spool_mas_kg'"):
        read_twin(path)
    with pytest.raises(TwinFileError, match="cannot read the twin file"):
        read_twin(tmp_path / "missing.toml")
    path.write_text(text.replace("POSKP = ", "POSKPX = "), encoding="utf-8")
    with pytest.raises(TwinFileError, match=r"\[parameters\] has no parameter 'POSKPX'"):
        read_twin(path)


def test_the_emulated_twin_answers_the_steps_as_the_valve_did(fitted, tmp_path):
    """Issue 31 item 3 (start): the twin file makes an emulated valve of that serial, type,
    firmware and parameter set, whose steps match the measured ones."""
    steps, result = fitted
    path = tmp_path / "valve.toml"
    tuned = {**steps.values, "POSKP": 30, "POSKI": 700}  # the twin keeps the valve's own set
    write_twin(path, result, 3101, E02, "1.0.0", "position-loop steps, 5000 Hz", tuned)
    valve = emulated_twin(path)
    assert valve.serial == 3101 and str(valve.type_key) == E02
    assert valve.read(*CATALOGUE["POSKP"].key) == 30
    valve.write(*CATALOGUE["POSKP"].key, steps.values["POSKP"])
    valve.write(*CATALOGUE["POSKI"].key, steps.values["POSKI"])
    while valve.status().booting:
        valve.advance(0.05)
    again = record(EmulatorRig(valve))
    assert np.sqrt(np.mean((again.actual - steps.actual) ** 2)) < 0.1
    t = np.arange(len(steps.actual)) / steps.rate_hz
    window = (t >= 0.06) & (t < 0.24)  # the 0 → 25 % step at 0.12 s
    measured = measure_step(t[window], steps.actual[window], steps.stimulus[window]).figures
    twin = measure_step(t[window], again.actual[window], again.stimulus[window]).figures
    assert measured is not None and twin is not None
    assert twin.overshoot == pytest.approx(measured.overshoot, abs=1.0)  # percentage points
    assert twin.rise_time == pytest.approx(measured.rise_time, rel=0.05)


def test_a_valve_the_fitted_structure_cannot_represent_is_said_not_to_be_explained():
    """Break-away friction far above the sliding one, which the default fit keeps: the fit does
    what it can and says the residual is beyond what the plant's structure explains."""
    valve = EmulatedValve(E02, plant=replace(PLANT, static_friction_n=1.2))
    while valve.status().booting:
        valve.advance(0.05)
    result = fit(record(EmulatorRig(valve)))
    assert result.rms_pct <= result.start_rms_pct
    assert not result.explained


def test_a_characterization_run_is_fitted_from_its_steps(tmp_path):
    """The end-of-line characterization's own steps (any link records them the same way) are
    enough to find a weaker solenoid and a slower spool; from its JSON report and CSV files
    as from the run in memory."""
    import json

    from prm9tool.analysis.profile import parse_profile
    from prm9tool.characterize.run import characterize, report_data, write_csv_files
    from prm9tool.twin.recording import from_characterization
    from prm9tool.twin.report import run_of_report

    truth = replace(PLANT, force_n_per_a=24.0, spool_mass_kg=0.08)
    valve = EmulatedValve(E02, plant=truth)
    profile = parse_profile(
        {
            "test": {
                "step_amplitudes_pct": [25, 90],
                "bode_duration_s": 1,
                "bode_f_min_hz": 5,
                "bode_f_max_hz": 50,
                "static_period_s": 1,
            }
        }
    )
    run = characterize(EmulatorRig(valve), profile)
    recordings = from_characterization(run, joint=False)
    assert len(recordings) == 2  # 0 → 25 %, 0 → 90 %
    # with the static characteristic: the triangle's windows through 0 % going up and down
    windows = [r for r in from_characterization(run) if r.kind == "static"]
    assert windows and all(r.skip > 0 and r.tail > 0 for r in windows)
    result = fit(recordings, free=("spool_mass_kg", "force_n_per_a", "damping_n_s_per_m"))
    assert result.explained, result.rms_pct  # the steps played in the run's order (docs/twin.md)
    assert result.constant("force_n_per_a").value == pytest.approx(24.0, rel=0.05)
    assert result.constant("spool_mass_kg").value == pytest.approx(0.08, rel=0.10)
    report = tmp_path / "run.json"
    files = write_csv_files(run, tmp_path / "run")
    report.write_text(json.dumps(report_data(run, files)), encoding="utf-8")
    again = from_characterization(run_of_report(report), joint=False)  # --fit-twin --from's
    assert len(again) == 2 and again[0].type_key == E02
    assert np.abs(again[1].actual - recordings[1].actual).max() < 1e-3  # CSV's 6 digits
    from_file = fit(again, free=("spool_mass_kg", "force_n_per_a", "damping_n_s_per_m"))
    assert from_file.constant("force_n_per_a").value == pytest.approx(24.0, rel=0.05)


def test_fit_twin_on_the_command_line_from_a_report(tmp_path, capsys):
    """``--fit-twin OUT.toml --from RUN.json``: the report's steps fitted, the twin written."""
    import json

    from prm9tool.analysis.profile import parse_profile
    from prm9tool.characterize.run import characterize, report_data, write_csv_files
    from prm9tool.cli.main import main

    valve = EmulatedValve(E02, serial=3107, plant=replace(PLANT, force_n_per_a=24.0))
    profile = parse_profile(
        {"test": {"step_amplitudes_pct": [25], "bode_duration_s": 1, "bode_f_min_hz": 5,
                  "bode_f_max_hz": 50, "static_period_s": 1}}
    )  # fmt: skip
    run = characterize(EmulatorRig(valve), profile)
    report = tmp_path / "run.json"
    report.write_text(json.dumps(report_data(run, write_csv_files(run, tmp_path / "run"))))
    out = tmp_path / "twin.toml"
    assert main(["--fit-twin", str(out), "--from", str(report), "--json"]) == 0
    summary = json.loads(capsys.readouterr().out)
    assert summary["explained"]
    force = next(c for c in summary["constants"] if c["constant"] == "force_n_per_a")
    assert force["value"] == pytest.approx(24.0, rel=0.05)
    twin = read_twin(out)
    assert twin.serial == 3107 and twin.plant.force_n_per_a == pytest.approx(24.0, rel=0.05)
    assert main(["--fit-twin", str(out)]) == 2  # usage: --from is missing
    assert "--fit-twin OUT.toml needs --from RUN.json" in capsys.readouterr().err
    assert main(["--fit-twin", str(out), "--from", str(tmp_path / "none.json")]) == 3
    assert "cannot read" in capsys.readouterr().err


def test_a_recording_at_a_links_1_khz_is_fitted_as_well(fitted):
    """USB and CAN (SYNC) links sample at 1 kHz: every fifth cycle of the valve's loop."""
    from prm9tool.twin.recording import Steps

    steps, _ = fitted
    slow = Steps(steps.type_key, steps.values, steps.stimulus[::5], steps.actual[4::5], 1000.0)
    result = fit(slow)
    assert result.explained
    assert result.constant("force_n_per_a").value == pytest.approx(25.0, rel=0.05)
    assert result.constant("spool_mass_kg").value == pytest.approx(0.09, rel=0.05)
    with pytest.raises(Prm9Error, match="the rate must divide 5000 Hz"):
        fit(Steps(steps.type_key, steps.values, steps.stimulus, steps.actual, 3000.0))


def test_the_twin_of_an_e04_position_loop_run_runs_its_position_loop():
    """A run keeps no CTRLMODE: the twin of an E04 whose position loop was characterized ran
    the process loop (mode 4, the E04's default) and missed every figure (docs/twin.md)."""
    from prm9tool.analysis.profile import parse_profile
    from prm9tool.characterize.run import characterize
    from prm9tool.twin.recording import from_characterization
    from prm9tool.twin.replay import simulate_all

    valve = EmulatedValve("PRM9-06.3Z11/30-24E04S02", plant=replace(PLANT, spool_mass_kg=0.08))
    valve.write(*CATALOGUE["CTRLMODE"].key, 2)
    profile = parse_profile(
        {
            "test": {
                "step_amplitudes_pct": [25],
                "bode_duration_s": 1,
                "bode_f_min_hz": 5,
                "bode_f_max_hz": 50,
                "static_period_s": 1,
            }
        }
    )
    run = characterize(EmulatorRig(valve), profile)
    assert run.loop == "position"
    (steps,) = from_characterization(run, joint=False)
    assert steps.values["CTRLMODE"] == 2
    (simulated,) = simulate_all([steps], valve.plant)
    assert np.sqrt(np.mean((simulated - steps.actual) ** 2)) < 0.12  # its own plant: explained


def test_each_step_is_replayed_after_the_hold_the_procedure_settled_it_with():
    """With break-away friction the spool sticks and slips at the null, so its rest and the
    integrator's state at a step depend on the hold before it: replayed after 0.1 s instead of
    the procedure's max(0.1 s, window) (0.15 s here), even the valve's own plant left 0.5–0.7 %
    rms on the later steps (docs/twin.md)."""
    from prm9tool.analysis.profile import DEFAULT
    from prm9tool.characterize.run import characterize
    from prm9tool.twin.recording import from_characterization
    from prm9tool.twin.replay import hold_cycles, simulate_all

    truth = replace(PLANT, static_friction_n=1.2)
    run = characterize(EmulatorRig(EmulatedValve(E02, plant=truth)), DEFAULT)
    recordings = from_characterization(run, joint=False)
    assert [hold_cycles(r) for r in recordings] == [750] * 3  # 0.15 s at 5 kHz
    for steps, simulated in zip(recordings, simulate_all(recordings, truth), strict=True):
        assert np.sqrt(np.mean((simulated - steps.actual) ** 2)) < 0.01

"""``--fit-twin OUT.toml --from RUN.json`` (issue 31 item 2): a characterization read back from
its JSON report and CSV files is fitted as the run in memory is — the steps, windows of the
sweep and of the static characteristic — recorded, and its twin characterized as it was."""

from __future__ import annotations

import json
from dataclasses import replace

import pytest

import prm9tool
from prm9tool.analysis.profile import parse_profile
from prm9tool.characterize.rig import EmulatorRig
from prm9tool.characterize.run import characterize, report_data, write_csv_files
from prm9tool.cli.main import main
from prm9tool.device.emulator import EmulatedValve
from prm9tool.device.emulator.constants import PLANT
from prm9tool.device.emulator.twinfile import read_twin
from prm9tool.twin.report import run_of_report

E02 = "PRM9-06.3Z11/30-24E02S02"
SHORT = {"test": {"step_amplitudes_pct": [25], "bode_duration_s": 3, "bode_f_min_hz": 2,
                  "bode_f_max_hz": 100, "static_period_s": 4}}  # fmt: skip


@pytest.fixture(scope="module")
def report(tmp_path_factory):
    """The JSON report and CSV files of a weaker, heavier E02's characterization, and the run."""
    where = tmp_path_factory.mktemp("run")
    plant = replace(PLANT, force_n_per_a=24.0, spool_mass_kg=0.08)
    valve = EmulatedValve(E02, serial=3117, plant=plant, nv_path=where / "3117.json")
    run = characterize(EmulatorRig(valve), parse_profile(SHORT))
    path = where / "run.json"
    path.write_text(json.dumps(report_data(run, write_csv_files(run, where / "run"))))
    return path, run


def test_the_report_reads_back_as_the_run(report):
    path, run = report
    again = run_of_report(path)
    assert again.info.serial == 3117 and again.info.type_key == E02
    assert again.profile.bode_f_max_hz == 100 and again.profile.static_period_s == 4
    assert again.bode is not None and again.static is not None and len(again.steps) == 1
    measured = {f.name: f.value for f in run.figures}
    for f in again.figures:  # measured again from the CSV records: as the run measured them
        assert f.value == pytest.approx(measured[f.name], rel=0.02, abs=0.02), f.name


def test_fit_twin_from_a_report_fits_the_sweep_and_the_static_curve(report, tmp_path, capsys):
    path, _ = report
    out, fit_json = tmp_path / "twin.toml", tmp_path / "fit.json"
    url = f"sqlite:///{tmp_path / 'history.db'}"
    args = ["--fit-twin", str(out), "--from", str(path), "--history-db", url]
    assert main([*args, "--json", str(fit_json)]) == 0, capsys.readouterr().err
    fit = json.loads(fit_json.read_text(encoding="utf-8"))
    assert set(fit["parts_rms_pct"]) == {"step", "sweep", "static"}  # not the steps alone
    assert fit["explained"]
    force = next(c for c in fit["constants"] if c["constant"] == "force_n_per_a")
    assert force["determined"] and force["value"] == pytest.approx(24.0, rel=0.05)
    assert "static_friction_n" in {c["constant"] for c in fit["constants"]}  # the joint fit
    proof = {row["figure"]: row for row in fit["comparison"]}  # the twin characterized too
    assert proof["bode_bandwidth_hz"]["ratio"] == pytest.approx(1.0, abs=0.05)
    assert read_twin(out).serial == 3117
    records = prm9tool.history.records(3117, url)
    assert [r["operation"] for r in records] == ["twin"]  # the run was recorded when measured
    assert records[0]["details"]["twin_file"] == str(out.resolve())


def test_an_older_report_without_the_sweeps_record_fits_what_it_has(report, tmp_path, capsys):
    path, _ = report
    data = json.loads(path.read_text(encoding="utf-8"))
    data["csv"] = [name for name in data["csv"] if not name.endswith("-sweep.csv")]
    older = path.parent / "older.json"
    older.write_text(json.dumps(data), encoding="utf-8")
    out = tmp_path / "twin.toml"
    url = f"sqlite:///{tmp_path / 'history.db'}"
    assert main(["--fit-twin", str(out), "--from", str(older), "--history-db", url, "--json"]) == 0
    fit = json.loads(capsys.readouterr().out)
    assert set(fit["parts_rms_pct"]) == {"step", "static"}


def test_a_report_that_cannot_be_used_is_refused_in_words(report, tmp_path, capsys):
    path, _ = report
    data = json.loads(path.read_text(encoding="utf-8"))
    broken = path.parent / "broken.json"
    step = next(name for name in data["csv"] if "-step-" in name)
    (path.parent / "broken-step-25.csv").write_text("time [s],position_actual\n0,x\n")
    data["csv"] = [str(path.parent / "broken-step-25.csv") if n == step else n for n in data["csv"]]
    broken.write_text(json.dumps(data), encoding="utf-8")
    out = tmp_path / "twin.toml"
    assert main(["--fit-twin", str(out), "--from", str(broken)]) == 3
    assert "broken-step-25.csv: not a table of numbers" in capsys.readouterr().err
    assert not out.exists()


@pytest.fixture(scope="module")
def e04_reports(tmp_path_factory):
    """An E04 in control mode 4 (actuator full stroke 1 s) characterized; its JSON report with
    the flow record (``-flow.csv``) and one without it, and the run."""
    from prm9tool.analysis.profile import DEFAULT

    where = tmp_path_factory.mktemp("e04")
    plant = replace(PLANT, actuator_full_speed_s=1.0)
    valve = EmulatedValve("PRM9-06.3Z11/30-24E04S02", serial=3118, plant=plant)
    run = characterize(EmulatorRig(valve), DEFAULT)
    assert run.loop == "process" and run.flow is not None
    data = report_data(run, write_csv_files(run, where / "run"))
    full, steps_only = where / "run.json", where / "steps-only.json"
    full.write_text(json.dumps(data))
    data["csv"] = [name for name in data["csv"] if not name.endswith("-flow.csv")]
    steps_only.write_text(json.dumps(data))
    return full, steps_only, run


@pytest.mark.timeout(600)  # a default E04 characterization and the fit of its flow record
@pytest.mark.parametrize("with_flow", [True, False], ids=["with-flow-record", "steps-only"])
def test_an_e04_process_run_from_its_report_is_fitted_on_what_it_recorded(
    e04_reports, with_flow, tmp_path, capsys
):
    """An E04's process-loop run read back from its JSON report: fitted on its process-loop
    steps and its flow record (``-flow.csv``, which the reader did not take before), and on
    the steps alone from a report without that file — a process-loop step's CSV has the
    spool demand (position_setpoint) too, which once made it a position-loop step and the
    report "no complete process-loop step to fit". What the records determine is said so
    (the actuator's speed), what they do not is kept with why (the spool's constants)."""
    from prm9tool.twin.actuator import NOT_IN_PROCESS_RUN
    from prm9tool.twin.identify import FITTED

    full, steps_only, run = e04_reports
    report = full if with_flow else steps_only
    again = run_of_report(report)
    if with_flow:  # the flow test read back, its figures measured again
        assert again.flow is not None
        assert again.flow.characteristic.gain_positive == pytest.approx(
            run.flow.characteristic.gain_positive, rel=1e-3
        )
    else:
        assert again.flow is None
    out, fit_json = tmp_path / "twin.toml", tmp_path / "fit.json"
    url = f"sqlite:///{tmp_path / 'history.db'}"
    args = ["--fit-twin", str(out), "--from", str(report), "--history-db", url]
    assert main([*args, "--json", str(fit_json)]) == 0, capsys.readouterr().err
    fit = json.loads(fit_json.read_text(encoding="utf-8"))
    assert set(fit["parts_rms_pct"]) == ({"process", "flow"} if with_flow else {"process"})
    assert fit["explained"]
    constants = {c["constant"]: c for c in fit["constants"]}
    speed = constants["actuator_full_speed_s"]
    assert speed["determined"] and speed["value"] == pytest.approx(1.0, rel=0.02)
    for name in FITTED:
        assert not constants[name]["determined"]
        assert constants[name]["reason"] == NOT_IN_PROCESS_RUN
        assert constants[name]["value"] == getattr(PLANT, name)  # kept, not invented
    assert read_twin(out).plant.actuator_full_speed_s == pytest.approx(1.0, rel=0.02)

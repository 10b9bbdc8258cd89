"""``prm9tool --characterize`` on an emulated valve: reports, exit codes, bad input."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from pypdf import PdfReader

from prm9tool.cli.main import main
from prm9tool.device import emulated_valves
from prm9tool.errors import ExitCode

E02 = "PRM9-06.3Z11/30-24E02S02"
FAST = """name = "fast test"
[test]
step_amplitudes_pct = [5, 25, 90]
step_duration_s = 0.1
bode_f_min_hz = 2
bode_f_max_hz = 100
bode_duration_s = 2
static_period_s = 4
[limits]
step_overshoot_pct = { max = 15 }
bode_bandwidth_hz = { min = 15 }
static_hysteresis_pct = { max = 3 }
"""


@pytest.fixture(autouse=True)
def _fresh_emulators():
    yield
    emulated_valves.forget_emulated_valves()


def run(tmp_path, profile: str, serial: int, *extra: str) -> int:
    (tmp_path / "limits.toml").write_text(profile, encoding="utf-8")
    args = ["--characterize", "--emulator", f"{E02}:{serial}", "--profile",
            str(tmp_path / "limits.toml"), *extra]  # fmt: skip
    return main(args)


def test_a_good_valve_passes_with_pdf_json_and_csv(tmp_path, capsys):
    pdf, js = tmp_path / "out.pdf", tmp_path / "out.json"
    assert run(tmp_path, FAST, 31, "--report", str(pdf), "--json", str(js)) == ExitCode.OK
    report = json.loads(js.read_text(encoding="utf-8"))
    assert report["passed"] is True
    assert report["valve"] == {"type_key": E02, "serial": 31, "firmware": "1.0.0"}
    assert report["link"].startswith("emulator") and report["sample_rate_hz"] == 5000
    names = {f["name"]: f for f in report["figures"]}
    assert names["bode_bandwidth_hz"]["value"] > 15 and names["bode_bandwidth_hz"]["passed"]
    assert names["step_90_overshoot_pct"]["max"] == 15
    assert report["parameters"]["POSKP"] == 40
    assert [Path(p).name for p in report["csv"]] == [
        "out-step-5.csv", "out-step-25.csv", "out-step-90.csv", "out-bode.csv", "out-sweep.csv",
        "out-static.csv"
    ]  # fmt: skip
    assert all(Path(p).exists() for p in report["csv"])
    assert (tmp_path / "out-step-25.csv").read_text(encoding="utf-8").startswith("time [s],")
    text = "".join(page.extract_text() for page in PdfReader(pdf).pages)
    assert E02 in text and "31" in text and "PASS" in text
    assert "PASSED" in capsys.readouterr().out


def test_out_of_limits_exits_8_and_names_the_figure(tmp_path, capsys):
    strict = FAST.replace("{ min = 15 }", "{ min = 500 }")
    js = tmp_path / "out.json"
    assert run(tmp_path, strict, 32, "--json", str(js)) == ExitCode.OUT_OF_LIMITS == 8
    report = json.loads(js.read_text(encoding="utf-8"))
    assert report["passed"] is False
    failed = [f["name"] for f in report["figures"] if f["passed"] is False]
    assert failed == ["bode_bandwidth_hz"]
    assert "out of limits: bode_bandwidth_hz" in capsys.readouterr().err


def test_a_step_that_never_settles_says_what_it_did(tmp_path, capsys):
    """Issue 25 item 6: a failed settling time printed "nan" without a word of why."""
    limited = FAST + "step_settling_s = { max = 0.05 }\n"
    js = tmp_path / "out.json"
    assert run(tmp_path, limited, 33, "--json", str(js)) == ExitCode.OUT_OF_LIMITS
    err = capsys.readouterr().err
    line = next(x for x in err.splitlines() if "out of limits: step_5_settling_s" in x)
    assert "(did not settle within ±2 % of the step: oscillation of ±" in line
    report = json.loads(js.read_text(encoding="utf-8"))
    note = {f["name"]: f["note"] for f in report["figures"]}["step_5_settling_s"]
    assert note is not None and line.endswith(f"({note})")


@pytest.mark.parametrize(
    ("profile", "message"),
    [
        ("[limits]\nbandwidth = { min = 1 }\n", "[limits] has no figure 'bandwidth'"),
        ("[test]\nbode_duration_s = -1\n", "bode_duration_s must be a positive number"),
        ("[limits\n", "not valid TOML"),
    ],
)
def test_a_bad_profile_is_refused_and_nothing_is_written(tmp_path, capsys, profile, message):
    js = tmp_path / "out.json"
    assert run(tmp_path, profile, 33, "--json", str(js)) == ExitCode.USAGE
    assert message in capsys.readouterr().err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["limits.toml"]


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--json", "x.json"], "--json [OUT.json] belongs to --diff, --history"),
        (["--profile", "x.toml"], "--profile belongs to --characterize"),
        (["--characterize", "--emulator", E02, "--json"], "--json OUT.json"),
        (["--characterize", "--emulator", E02, "--batch", "a.prm"], "separate commands"),
    ],
)
def test_usage_errors(args, message, capsys):
    assert main(args) == ExitCode.USAGE
    assert message in capsys.readouterr().err


def test_characterize_needs_an_output_and_one_valve(tmp_path, capsys):
    assert main(["--characterize", "--emulator", E02]) == ExitCode.USAGE
    assert "needs --report OUT.pdf and/or --json OUT.json" in capsys.readouterr().err
    out = str(tmp_path / "o.json")
    assert main(["--characterize", "--json", out]) == ExitCode.USAGE
    assert "tests one valve" in capsys.readouterr().err
    assert (
        main(["--characterize", "--json", str(tmp_path / "no" / "o.json"), "--emulator", E02]) == 2
    )
    assert "there is no folder" in capsys.readouterr().err


def test_a_valve_that_does_not_follow_its_setpoint_is_not_tested(tmp_path, capsys):
    js = tmp_path / "out.json"
    args = ["--characterize", "--emulator", "PRM9-06.3Z11/30-24E04S02-CA:34", "--json", str(js)]
    assert main(args) == ExitCode.OUT_OF_LIMITS
    err = capsys.readouterr().err
    assert "does not follow its setpoint: device state INIT" in err
    assert "waits for its master" in err
    assert not js.exists()


def test_enable_commissions_a_ca_valve_that_waits_for_its_master_and_then_tests_it(
    tmp_path, capsys
):
    # issue 28: the command line had no way to do what the window offers ("Enable it now?")
    js = tmp_path / "out.json"
    (tmp_path / "limits.toml").write_text(FAST, encoding="utf-8")
    args = ["--characterize", "--emulator", "PRM9-06.3Z11/30-24E02S02-CA:35", "--json", str(js),
            "--profile", str(tmp_path / "limits.toml")]  # fmt: skip
    assert main([*args, "--enable"]) == ExitCode.USAGE  # the hydraulics question, as a flag
    err = capsys.readouterr().err
    assert "make sure the hydraulics are safe for it and add --hydraulics-safe" in err
    assert not js.exists()
    assert main([*args, "--enable", "--hydraulics-safe"]) == ExitCode.OK
    assert "enabling the valve: NMT start, control word 08h" in capsys.readouterr().err
    assert json.loads(js.read_text(encoding="utf-8"))["passed"] is True


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--enable", "--emulator", E02], "--enable: enabled, the valve follows its setpoint"),
        (["--hydraulics-safe", "--emulator", E02], "--hydraulics-safe answers the hydraulics"),
        (["--characterize", "--emulator", E02, "--json", "x.json", "--hydraulics-safe"],
         "--hydraulics-safe confirms --enable"),
    ],
)  # fmt: skip
def test_enable_usage_errors(args, message, capsys):
    assert main(args) == ExitCode.USAGE
    assert message in capsys.readouterr().err


def test_the_report_pdf_speaks_display_units_and_names_the_valve_on_every_page(tmp_path):
    """Issue 25 item 9: the report's last page listed raw values (DTAMP 2458 for 15 %), and
    its pages repeated neither type key nor serial number."""
    import unicodedata

    pdf = tmp_path / "out.pdf"
    assert run(tmp_path, FAST, 33, "--report", str(pdf)) == ExitCode.OK
    pages = [
        " ".join(unicodedata.normalize("NFKC", page.extract_text()).split())
        for page in PdfReader(pdf).pages
    ]
    last = pages[-1]
    assert "DTAMP 15 %" in last and "LIMTA 2400 mA" in last and "2458" not in last
    assert "raw values" not in last and "Signature:" in last
    for number, text in enumerate(pages, start=1):
        assert f"{E02} · serial number 33" in text and "PRM9 test report" in text
        assert f"Page {number} of {len(pages)}" in text

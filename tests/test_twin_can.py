"""Issue 31 "done means": a valve on CAN with only the manual's objects is identified, twinned
and compared — ``prm9tool --fit-twin OUT.toml --device can:10`` characterizes it at the bus's
SYNC pace (the setpoint in RPDO1: such a valve has no override), fits the twin from that run
and characterizes the twin as the valve was."""

from __future__ import annotations

import json
from dataclasses import replace

import can
import numpy as np
import pytest
from support.can_link_rig import LinkRig, _wrap_sdo
from support.canopen_rig import BOOT_S, unique_channel
from support.waiting import emulator_lag

import prm9tool
from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.commissioning import ENABLE_SEQUENCE, NmtCommand
from prm9tool.cli.main import main
from prm9tool.device import emulated_valves
from prm9tool.device.canlink.bus import CanOptions
from prm9tool.device.emulator import EmulatedValve
from prm9tool.device.emulator.constants import PLANT
from prm9tool.device.emulator.twinfile import read_twin
from prm9tool.errors import ExitCode

E02_CA = "PRM9-06.3Z11/30-24E02S02-CA"
VARIED = replace(PLANT, force_n_per_a=24.0, spool_mass_kg=0.08)  # weaker and heavier
PROFILE = """name = "short, over CAN"
[test]
step_amplitudes_pct = [25]
step_duration_s = 0.15
bode_amplitude_pct = 10
bode_f_min_hz = 2
bode_f_max_hz = 100
bode_duration_s = 3
static_period_s = 4
"""


@pytest.fixture
def manual_only_valve(request, tmp_path, monkeypatch):
    """A booted -CA valve of the varied plant with only the manual's objects (``od="manual"``),
    node 10 on its own virtual channel, commissioned (NMT start, enabled) and in real time."""
    monkeypatch.setenv("PRM9TOOL_DATA_DIR", str(tmp_path / "data"))
    channel = unique_channel(request.node.name)
    valve = EmulatedValve(E02_CA, 4401, nv_path=tmp_path / "4401.json", od="manual", plant=VARIED)
    bus = can.Bus(interface="virtual", channel=channel)
    rig = LinkRig(valve, valve.connect_can(bus), bus, CanOptions("virtual", channel))
    _wrap_sdo(rig)
    valve.advance(BOOT_S)
    valve.nmt_command(NmtCommand.START)
    word = CATALOGUE["CONTROLWORD"]
    for value in ENABLE_SEQUENCE:
        valve.write(word.index, word.subindex, value)
    valve.start()
    yield rig
    valve.stop()
    rig.close()
    emulated_valves.forget_emulated_valves()


def test_a_manual_only_can_valve_is_identified_twinned_and_compared(
    manual_only_valve, tmp_path, capsys
):
    (tmp_path / "short.toml").write_text(PROFILE, encoding="utf-8")
    out, report = tmp_path / "twin.toml", tmp_path / "fit.json"
    url = f"sqlite:///{tmp_path / 'history.db'}"
    with emulator_lag(manual_only_valve.valve) as lags:
        code = main(["--fit-twin", str(out), "--device", "can:10", "--can-interface", "virtual",
                     "--can-channel", manual_only_valve.options.channel, "--profile",
                     str(tmp_path / "short.toml"), "--type-key", E02_CA, "--history-db", url,
                     "--json", str(report)])  # fmt: skip
    err = capsys.readouterr().err
    behind = float(np.percentile(lags, 90)) if lags else 0.0
    if behind > 0.003:  # the valve is in this process: a loaded PC made it lag real time, so
        # its TPDOs describe the PC's load, not the valve (as tests/test_characterize_links)
        pytest.skip(f"the emulated valve was {behind * 1000:.0f} ms behind real time")
    if code in (ExitCode.COMMUNICATION, ExitCode.OUT_OF_LIMITS) and (
        "nothing was interpolated" in err or "too seldom" in err or "a sweep needs" in err
    ):  # a PC too loaded to keep the bus's pace: the rig refused, said so, touched nothing
        pytest.skip(f"the rig refused the run on this loaded PC: {err.strip()}")
    assert code == ExitCode.OK, err
    twin = read_twin(out)
    assert twin.serial == 4401 and twin.type_key == E02_CA
    fit = json.loads(report.read_text(encoding="utf-8"))
    records = prm9tool.history.records(4401, url)
    assert [r["operation"] for r in records] == ["characterization", "twin"]
    assert "comparison" in fit, err  # the twin characterized too
    proof = {row["figure"]: row for row in fit["comparison"]}
    assert {"bode_bandwidth_hz", "step_25_overshoot_pct", "static_dead_band_pct"} <= set(proof)
    if not fit["explained"]:
        # the valve runs in real time in this process: on a loaded PC its TPDO1 samples come
        # early or late against the SYNC (a sample held twice, one out of order), which no
        # plant explains (0.5 % rms with the valve's own plant on one run); then the fitted
        # constants describe that, and the figures are not judged
        pytest.xfail(f"the run's samples jittered on this loaded PC: {fit['rms_pct']:.2f} % rms")
    force = next(c for c in fit["constants"] if c["constant"] == "force_n_per_a")
    assert force["determined"] and force["value"] == pytest.approx(24.0, rel=0.05), force
    assert proof["step_25_overshoot_pct"]["twin"] == pytest.approx(
        proof["step_25_overshoot_pct"]["valve"], abs=1.0
    )
    bandwidth = proof["bode_bandwidth_hz"]
    if bandwidth["valve"] is not None and bandwidth["twin"] is not None:
        assert bandwidth["ratio"] == pytest.approx(1.0, abs=0.05), bandwidth
    for name in ("static_dead_band_pct", "static_hysteresis_pct"):
        assert abs(proof[name]["twin"] - proof[name]["valve"]) <= 0.2, proof[name]

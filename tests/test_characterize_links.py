"""``prm9tool --characterize --device`` over the links a real valve has: USB (the fake hidapi
in front of a paced emulated valve) and CANopen (an emulated -CA valve on a virtual bus)."""

from __future__ import annotations

import json
import os
import sys
import time

import numpy as np
import pytest
from pypdf import PdfReader
from support.usb_fakes import FakeHid
from support.waiting import emulator_lag

from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.commissioning import ENABLE_SEQUENCE, NmtCommand
from prm9tool.cli.main import main
from prm9tool.device import emulated_valves, factory
from prm9tool.device.emulator import EmulatedValve
from prm9tool.device.usb.transport.hidapi import HidTransport
from prm9tool.errors import ExitCode

E02 = "PRM9-06.3Z11/30-24E02S02"
PATH = b"/dev/hidraw5"
# short tests: the valve runs in real time behind a link
SHORT = """name = "short"
[test]
step_amplitudes_pct = [25]
step_duration_s = 0.1
bode_amplitude_pct = 10
bode_f_min_hz = 2
bode_f_max_hz = 100
bode_duration_s = 1.5
static_period_s = 4
[limits]   # loose: the valve runs in real time on a shared, loaded PC (figures are asserted)
step_overshoot_pct = { max = 25 }
step_rise_s = { max = 0.05 }
bode_bandwidth_hz = { min = 10 }
static_gain = { min = 0.9, max = 1.1 }
static_linearity_pct = { max = 5 }
static_hysteresis_pct = { max = 8 }
"""


def step_s(rig) -> float:
    """A step record of 0.1 s, or of 30 samples at the pace the rig measured on this PC (a
    loaded PC makes the CANopen rig slow down; step figures need samples after the step)."""
    return max(0.1, 30 / rig.info.sample_rate_hz)


@pytest.fixture(autouse=True)
def _fresh_emulators():
    yield
    emulated_valves.forget_emulated_valves()


@pytest.fixture
def usb_valve(monkeypatch):
    fake = FakeHid()
    monkeypatch.setitem(sys.modules, "hid", fake.as_module())
    monkeypatch.setitem(sys.modules, "hidraw", fake.as_module())
    monkeypatch.setattr(HidTransport, "settle_s", 0.0)
    valve = EmulatedValve(E02, 4711)
    fake.add(valve, PATH)
    valve.start()  # the valve's own clock: real time, as on the bench
    yield valve
    valve.stop()


def test_characterize_over_usb_with_a_paced_valve(usb_valve, tmp_path, capsys):
    (tmp_path / "short.toml").write_text(SHORT, encoding="utf-8")
    js = tmp_path / "usb.json"
    args = ["--characterize", "--device", f"usb:{PATH.decode()}", "--profile",
            str(tmp_path / "short.toml"), "--json", str(js)]  # fmt: skip
    code = main(args)
    err = capsys.readouterr().err
    refusals = ("updated the valve's setpoint too seldom", "held the valve's setpoint")
    if any(refusal in err for refusal in refusals):  # refused, with the reason (busy PC)
        assert code != ExitCode.OK and not js.exists()
        return
    report = json.loads(js.read_text(encoding="utf-8"))
    assert report["valve"]["serial"] == 4711
    assert report["link"] == "USB" and report["sample_rate_hz"] == 5000
    figures = {f["name"]: f for f in report["figures"]}
    bandwidth = figures["bode_bandwidth_hz"]
    # issue 34 item 9: a busy PC measured 11.9 Hz (the valve's is ~30 Hz) and passed; the
    # figure is now right, or known only to lie above where the sweep was usable, and said so
    if any("sweep usable up to" in note for note in report["notes"]):
        # known only to lie above where the sweep was usable, or found below that point: then
        # it is the valve's (~30 Hz), not the 11.9 Hz a held setpoint made of it
        if bandwidth["value"] is not None and not bandwidth["above"]:
            assert 15 < bandwidth["value"] < 100, bandwidth
    else:
        assert code == ExitCode.OK, err
        assert 15 < bandwidth["value"] < 100, bandwidth
    figures = {name: f["value"] for name, f in figures.items()}
    assert 0.9 < figures["static_gain"] < 1.1
    assert figures["step_25_overshoot_pct"] < 15
    over = CATALOGUE["SETPOVRON"]
    assert usb_valve.read(over.index, over.subindex) == 0  # the override is off again


@pytest.fixture
def can_valve(tmp_path, monkeypatch, request):
    from support.can_link_rig import make_link_rig

    monkeypatch.setenv("PRM9TOOL_DATA_DIR", str(tmp_path / "data"))
    kind = getattr(request, "param", "")  # "real": without this project's objects (0x2050 …)
    rig = make_link_rig(request.node.name, tmp_path, E02 + "-CA", real_valve=kind == "real")
    word = CATALOGUE["CONTROLWORD"]
    if kind != "not-started":  # RPDO1 (the setpoint) counts only when OPERATIONAL
        rig.valve.nmt_command(NmtCommand.START)
    for value in ENABLE_SEQUENCE:  # the master enables the valve (commissioning, §7.6)
        rig.valve.write(word.index, word.subindex, value)
    rig.valve.start()
    yield rig
    rig.valve.stop()
    rig.close()


def test_characterize_over_canopen_at_the_links_rate(can_valve, tmp_path, capsys):
    (tmp_path / "short.toml").write_text(SHORT, encoding="utf-8")
    js, pdf = tmp_path / "can.json", tmp_path / "can.pdf"
    args = ["--characterize", "--device", "can:10", "--can-interface", "virtual",
            "--can-channel", can_valve.options.channel, "--profile", str(tmp_path / "short.toml"),
            "--json", str(js), "--report", str(pdf)]  # fmt: skip
    with emulator_lag(can_valve.valve) as lags:
        code = main(args)
    err = capsys.readouterr().err
    behind = float(np.percentile(lags, 90)) if lags else 0.0
    if code == ExitCode.OUT_OF_LIMITS and behind > 0.003:  # the valve is in this process
        pytest.skip(f"the emulated valve was {behind * 1000:.0f} ms behind real time: {err}")
    if code == ExitCode.COMMUNICATION:  # a PC too loaded to keep the pace: said, not hidden
        assert "link lost" in err or "updated the valve's setpoint too seldom" in err, err
        # either refusal says the run stopped and nothing of it was made up or kept
        assert "the test was stopped" in err and not js.exists(), err
        assert can_valve.working("SETPOVRON") == 0
        pytest.skip(f"the rig refused the run on this loaded PC: {err.strip()}")
    if "a sweep needs at least" in err:  # the pace this PC keeps is too slow for the profile
        assert "choose a duration of at least" in err and not js.exists(), err
        assert can_valve.working("SETPOVRON") == 0
        pytest.skip(f"the link's pace on this loaded PC is too slow for the sweep: {err.strip()}")
    assert js.exists(), err
    report = json.loads(js.read_text(encoding="utf-8"))
    assert report["link"].startswith("CANopen node 10 (virtual "), report["link"]
    rate = report["sample_rate_hz"]
    assert rate == 1000  # the bus's pace: RPDO1 + SYNC + TPDO1 per ms, never the USB's 5 kHz
    assert "TPDO1 at the tool's SYNC, one sample per 1 ms" in report["link"]
    figures = {f["name"]: f["value"] for f in report["figures"]}
    assert 0.9 < figures["static_gain"] < 1.1
    assert figures["step_25_rise_s"] > 0
    if rate / 10 < 100:  # the sweep asked up to 100 Hz: the link limits it and says so
        assert report["notes"] == [
            f"sweep limited to {rate / 10:g} Hz (of 100 Hz asked) by the link's sample rate "
            f"of {rate:g} Hz"
        ]
        text = " ".join("".join(p.extract_text() for p in PdfReader(pdf).pages).split())
        assert f"Limited by the link sweep limited to {rate / 10:g} Hz" in text
    assert code in (ExitCode.OK, ExitCode.OUT_OF_LIMITS), err
    assert can_valve.working("SETPOVRON") == 0  # the override is off again


def test_the_tuning_windows_rig_over_canopen(can_valve):
    from prm9tool.analysis.model import Targets
    from prm9tool.characterize.autotune import model_tune
    from prm9tool.characterize.canrig import CanRig, LinkTooSlowError, rig_for_session
    from prm9tool.characterize.procedures import step_test
    from prm9tool.device.canlink.session import CanopenSession
    from prm9tool.errors import Prm9Error

    too_slow: LinkTooSlowError | None = None
    with CanopenSession(can_valve.options, 10) as session:
        rig = rig_for_session(session, "USB")  # what the Tuning window's runner does online
        assert isinstance(rig, CanRig) and rig.info.link.startswith("CANopen node 10")
        try:
            step = step_test(rig, 25.0, duration_s=step_s(rig))
        except LinkTooSlowError as exc:  # a PC too loaded to keep the pace: the rig says so
            too_slow = exc
        else:
            assert step.figures is not None
            assert step.figures.final == pytest.approx(25.0, abs=2.0)
            assert np.isnan(step.record.channels["controller_output"]).all()  # no object
        with pytest.raises(Prm9Error) as refused:
            model_tune(rig, Targets(10.0, 0.04))
        if isinstance(refused.value, LinkTooSlowError):  # it plays before it can tell
            too_slow = too_slow or refused.value
        else:
            assert "needs the controller's output" in str(refused.value)
    assert can_valve.working("SETPOVRON") == 0
    assert can_valve.working("POSKP") == CATALOGUE["POSKP"].default
    if too_slow is not None:  # the refusal and the valve's state were checked, not the figures
        assert "the test was stopped" in str(too_slow), too_slow
        pytest.skip(f"the rig refused a test on this loaded PC: {too_slow}")


@pytest.mark.parametrize("can_valve", ["real"], indirect=True)
def test_a_valve_without_the_override_objects_is_characterized_over_rpdo1(can_valve):
    from prm9tool.characterize.canrig import LinkTooSlowError, rig_for_session
    from prm9tool.characterize.procedures import STATIC_MIN_SAMPLES, static_test, step_test
    from prm9tool.device.canlink.rpdo_setpoint import RpdoSetpoint
    from prm9tool.device.canlink.session import CanopenSession
    from prm9tool.errors import Prm9Error

    before = can_valve.working("POSSETP")
    with CanopenSession(can_valve.options, 10, type_key=E02 + "-CA") as session:
        with pytest.raises(Prm9Error, match="not available over CANopen"):
            session.read("SETPOVRON")  # what a real valve lacks: the override
        assert "SETPOVRON" in session.unavailable
        assert isinstance(session.setpoint_link(), RpdoSetpoint)
        rig = rig_for_session(session)
        try:
            step = step_test(
                rig, 25.0, duration_s=step_s(rig)
            )  # the setpoint travels in RPDO1 (0x6300)
            # the triangle's period for the pace this PC keeps (the rig measured it)
            period_s = max(2.0, 1.1 * STATIC_MIN_SAMPLES / rig.info.sample_rate_hz)
            static = static_test(rig, period_s=period_s)
        except LinkTooSlowError as exc:  # a PC too loaded to keep the pace: the rig says so
            too_slow: LinkTooSlowError | None = exc
        else:
            too_slow = None
            assert step.figures is not None
            assert step.figures.final == pytest.approx(25.0, abs=2.0)
            assert 0.9 < static.characteristic.gain < 1.1
        assert "SETPOVR" not in session.unavailable  # never asked for: not even tried
    assert can_valve.working("POSSETP") == before  # the setpoint it had, given back
    if too_slow is not None:  # the link and the valve's state were checked, not the figures
        pytest.skip(f"the rig refused a test on this loaded PC: {too_slow}")


@pytest.mark.parametrize("can_valve", ["not-started"], indirect=True)
def test_a_node_not_operational_is_refused_with_what_to_do_and_nothing_sent(can_valve):
    from support.waiting import wait_for

    from prm9tool.characterize.canrig import rig_for_session
    from prm9tool.characterize.procedures import step_test
    from prm9tool.device.canlink.rpdo_setpoint import RpdoSetpointError
    from prm9tool.device.canlink.session import CanopenSession

    before = can_valve.working("POSSETP")
    with CanopenSession(can_valve.options, 10) as session:
        session.write("HEARTBEAT", 20)
        wait_for(lambda: session.nmt_state == "pre-operational")
        rig = rig_for_session(session)
        with pytest.raises(RpdoSetpointError, match=r"NMT pre-operational.*NMT start"):
            step_test(rig, 25.0, duration_s=step_s(rig))
        session.write("HEARTBEAT", 0)
    assert can_valve.working("POSSETP") == before
    assert can_valve.working("RPDO1TIMER") == 0  # no deadline left armed
    assert can_valve.working("POSKP") == CATALOGUE["POSKP"].default  # parameters as they were


def test_the_sdo_sampler_reads_the_actual_position_not_its_entry_count(can_valve):
    from prm9tool.device.canlink.session import CanopenSession

    with CanopenSession(can_valve.options, 10) as session:
        session.write_many({"SETPOVR": 8192, "SETPOVRON": 1})  # 50 %
        time.sleep(0.1)
        session.stream_start(["position_actual"], 200)
        time.sleep(0.1)
        samples = session.stream_read()
        session.stream_stop()
        session.write("SETPOVRON", 0)
    arrived = samples[~np.isnan(samples[:, 0]), 0]  # a busy PC's late reads are NaN gaps
    assert session.stream_source == "" and len(arrived)
    assert arrived[-1] == pytest.approx(8192, rel=0.03)  # 0x6301/1, not 0x6301/0 (= 1)


def test_the_tuning_window_online_over_canopen(qtbot, can_valve, monkeypatch):
    from PySide6.QtWidgets import QMessageBox

    from prm9tool.model.document import ParameterDocument
    from prm9tool.online.connection import ValveConnection
    from prm9tool.views.tuning.window import TuningWindow

    connection = ValveConnection(
        opener=lambda e: factory.open_session(e, can_link=can_valve.options)
    )
    try:
        with qtbot.waitSignal(connection.online_changed, timeout=10000):
            connection.go_online("can:10")
        w = TuningWindow(ParameterDocument(E02 + "-CA"), connection)
        qtbot.addWidget(w)
        assert "Online" in w.mode.text()
        monkeypatch.setattr(QMessageBox, "question", lambda *a: QMessageBox.StandardButton.Yes)
        w.tabs.setCurrentWidget(w.bode)
        w.bode.duration.setValue(3.0)
        w.bode.f_min.setValue(2.0)
        w.bode.run_button.click()  # asks 2 … 200 Hz
        qtbot.waitUntil(lambda: not w.runner.busy, timeout=30000)
        text = w.bode.result.text()
        # a PC too loaded to keep the pace is said in the status line, never hidden
        status = w.status.text()
        refused = "The link could not keep the test's sample rate." in status or (
            "a sweep needs at least" in status and "choose a duration of at least" in status
        )
        if not refused:
            assert "−3 dB: " in text and ", −90°: " in text, status
            assert (  # by the link's rate, or lower where a busy PC held the setpoint
                "The link's sample rate limited the sweep to" in text
                or "The PC held the valve's setpoint for" in text
            ), text
        if os.environ.get("PRM9TOOL_SCREENSHOTS"):
            w.grab().save(os.path.join(os.environ["PRM9TOOL_SCREENSHOTS"], "tuning_bode_can.png"))
    finally:
        connection.shutdown()
    assert can_valve.working("SETPOVRON") == 0
    if refused:  # said in the window and the valve given back; no figures to check
        pytest.skip(f"the link's pace on this loaded PC refused the sweep: {status}")


def test_a_link_pause_that_lost_the_override_stops_the_test(usb_valve, monkeypatch):
    """In the GUI on a busy PC the end-of-line test's link paused long enough for the firmware
    to drop the override (0.5 s without a report); the valve then followed its own setpoint
    (0 %) and the report showed static gain 0.24, hysteresis 100 % as if measured."""
    import time

    from prm9tool.characterize.procedures import static_test
    from prm9tool.characterize.rig import LinkTooSlowError, SessionRig
    from prm9tool.device import factory

    with factory.open_session(f"usb:{PATH.decode()}") as session:
        rig = SessionRig(session, "USB")
        read = session.stream_read
        calls = {"n": 0}

        def stalling_read():
            calls["n"] += 1
            if calls["n"] == 300:  # in the middle of the triangle
                time.sleep(0.8)
            return read()

        monkeypatch.setattr(session, "stream_read", stalling_read)
        with pytest.raises(LinkTooSlowError, match="paused longer than the valve keeps"):
            static_test(rig, 2.0)
    over = CATALOGUE["SETPOVRON"]
    assert usb_valve.read(over.index, over.subindex) == 0

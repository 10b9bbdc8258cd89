"""Characterization over CANopen at the bus's pace (issue 20 item 5): the setpoint in RPDO1,
the actual position in TPDO1 at a SYNC the tool produces, each sample placed by its SYNC's
number; lost samples are counted and left out, the −3 dB figure stays put, and a response that
has not fallen 3 dB by the sweep's end is "above f_end"."""

from __future__ import annotations

import json
import math
import threading
import time

import numpy as np
import pytest
from scipy import signal

from prm9tool.analysis.frequency import frequency_response, log_chirp
from prm9tool.analysis.profile import DEFAULT
from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.commissioning import ENABLE_SEQUENCE, NmtCommand
from prm9tool.characterize.canrig import CanRig, tick_period_s
from prm9tool.characterize.frame import Record
from prm9tool.characterize.procedures import BodeResult, bode_test
from prm9tool.characterize.rig import EmulatorRig, LinkTooSlowError, RigInfo
from prm9tool.characterize.run import Characterization, figures, report_data
from prm9tool.device.canlink.session import CanopenSession
from prm9tool.device.canlink.sync_clock import SlotSamples, SyncClock
from prm9tool.device.emulator import EmulatedValve

E02 = "PRM9-06.3Z11/30-24E02S02"
TPDO1 = 0x180 + 10


def test_every_answer_is_placed_by_the_number_of_its_sync_and_a_stall_leaves_a_gap():
    period = 0.002
    clock: SyncClock
    started = threading.Event()
    t0 = [0.0]
    stalled: list[int] = []  # the tick at which the PC was held up

    def stall(k: int) -> None:
        if k == 0:
            t0[0] = time.time()
            started.set()
        if k >= 20 and not stalled:  # the PC is busy for 10 periods: no SYNC goes out in time
            stalled.append(k)
            time.sleep(10 * period)

    def valve(_cob_id: int, _data: bytes) -> None:  # answers at once with its own time
        now = time.time()
        slots.put(now, [(now - t0[0]) / period])

    clock = SyncClock(valve, period, stall, limit=100)
    slots = SlotSamples(clock)
    clock.start()
    assert clock.wait_ticks(100, 10.0)
    rows = slots.take(100)[:, 0]
    arrived = ~np.isnan(rows)
    assert clock.skipped >= 5 and (~arrived).sum() == clock.skipped + clock.voided
    assert not arrived[stalled[0] : stalled[0] + 6].any()  # the stall is a gap where it was …
    # … and every sample sits where its time is: the valve's clock agrees with the SYNC count
    # (a busy test machine delays single ticks by up to half a period before they are skipped)
    k = np.flatnonzero(arrived)
    assert np.abs(rows[arrived] - k).max() < 0.75
    assert slots.take(100).shape == (0, 1)  # handed out once


def test_the_tick_period_is_one_ms_where_the_bus_allows():
    assert tick_period_s(500_000) == 0.001  # ≥ 1 kHz at 500 kbit/s
    assert tick_period_s(1_000_000) == 0.001
    assert tick_period_s(125_000) == pytest.approx(0.0035)  # SYNC+RPDO1+TPDO1 ≤ half the bus


@pytest.fixture
def can_valve(tmp_path, monkeypatch, request):
    from support.can_link_rig import make_link_rig

    monkeypatch.setenv("PRM9TOOL_DATA_DIR", str(tmp_path / "data"))
    od = getattr(request, "param", "full")  # "manual": only the objects the manual lists
    rig = make_link_rig(request.node.name, tmp_path, E02 + "-CA", real_valve=True, od=od)
    word = CATALOGUE["CONTROLWORD"]
    rig.valve.nmt_command(NmtCommand.START)  # RPDO1 (the setpoint) counts when OPERATIONAL
    for value in ENABLE_SEQUENCE:
        rig.valve.write(word.index, word.subindex, value)
    rig.valve.start()
    yield rig
    rig.valve.stop()
    rig.close()


def drop_tpdo1(rig, share: float, burst: int) -> list[int]:
    """The valve's TPDO1 frames are lost on their way: ``share`` of them at random and a run
    of ``burst`` every 600 (a receive buffer overrun). Returns the count of frames dropped."""
    send = rig.slave._send
    rng = np.random.default_rng(7)
    count, dropped = [0], [0]

    def lossy(can_id: int, data: bytes) -> None:
        if can_id == TPDO1:
            count[0] += 1
            if rng.random() < share or count[0] % 600 < burst:
                dropped[0] += 1
                return
        send(can_id, data)

    rig.slave._send = lossy
    return dropped


@pytest.mark.parametrize("can_valve", ["full", "manual"], indirect=True)
def test_the_sweep_over_can_runs_at_1_khz_to_100_hz_and_lost_samples_do_not_move_it(can_valve):
    dropped = drop_tpdo1(can_valve, 0.1, 25)
    reference = bode_test(EmulatorRig(EmulatedValve(E02)), 10.0, 0.0, 2.0, 100.0, 3.0)
    lags: list[float] = []  # how far the emulated valve's simulation fell behind real time
    done = threading.Event()

    def watch() -> None:
        while not done.wait(0.002):
            lags.append(can_valve.valve.pacer.lag_s())

    watcher = threading.Thread(target=watch)
    with CanopenSession(can_valve.options, 10, type_key=E02 + "-CA") as session:
        rig = CanRig(session)
        assert rig.info.sample_rate_hz == 1000.0
        assert "TPDO1 at the tool's SYNC, one sample per 1 ms" in rig.info.link
        watcher.start()
        try:
            result = bode_test(rig, 10.0, 0.0, 2.0, 200.0, 3.0)
        except LinkTooSlowError as exc:  # the refusal a PC too loaded for 1 kHz gets
            pytest.skip(f"this PC is too loaded to keep 1 kHz now: {exc}")
        finally:
            done.set()
            watcher.join()
    if result.held_s > 0.0:  # a busy PC held a setpoint: the sweep is used below it only
        assert result.limited_to_hz is not None and result.limited_to_hz < 100.0
        pytest.skip(
            f"this PC held a setpoint {result.held_s * 1000:.0f} ms: the sweep is used up to "
            f"{result.limited_to_hz:.0f} Hz only (issue 34 item 9)"
        )
    assert result.limited_to_hz == 100.0  # 1 kHz / 10 samples per period
    assert len(result.record.t) == 3000 and result.record.t[-1] == pytest.approx(2.999)
    assert result.lost_samples >= 0.1 * 3000 * 0.7  # at least most of what was dropped
    assert result.lost_samples >= min(dropped[0], 3000) * 0.5
    ref_bw = reference.response.bandwidth_hz()
    # the emulated valve runs in this process in batches of 2 ms; when the PC holds it up its
    # simulation falls behind real time and the valve over CAN is not the one measured
    # directly any more (a valve of its own never does): that is said, not measured
    # (benchmarks/bench_tuning_can.py measures how close the figures come)
    behind = float(np.percentile(lags, 90)) if lags else 0.0
    if behind > 0.003:
        pytest.skip(f"the emulated valve was {behind * 1000:.0f} ms behind real time 10 % of it")
    # (a squeezed or stretched time axis would move it by tens of %)
    lag_ms = np.percentile(lags, [50, 90, 99, 100]) * 1000 if lags else []
    assert result.response.bandwidth_hz() == pytest.approx(ref_bw, rel=0.1), (
        f"lag percentiles 50/90/99/100: {lag_ms} ms, lost {result.lost_samples}"
    )
    assert can_valve.working("POSSETP") == 0  # the setpoint it had, given back


def _first_order(fc: float, fs: float, duration: float, f_end: float) -> BodeResult:
    """A fast valve (first order at ``fc``) swept to ``f_end``."""
    u = 10.0 * log_chirp(duration, fs, 1.0, f_end)
    b, a = signal.butter(1, fc, fs=fs)
    y = signal.lfilter(b, a, u)
    response = frequency_response(u, y, fs, 1.0, f_end)
    t = np.arange(len(u)) / fs
    rec = Record(t, {"position_setpoint": u, "position_actual": y})
    return BodeResult(10.0, 0.0, rec, response)


def test_a_response_that_has_not_fallen_3_db_is_above_the_sweeps_end_and_passes_a_minimum():
    fast = _first_order(300.0, 1000.0, 4.0, 100.0)
    assert math.isnan(fast.response.bandwidth_hz())  # not reached …
    assert 80.0 < fast.response.bandwidth_above_hz() <= 100.0  # … up to the sweep's end
    info = RigInfo(E02 + "-CA", 1, "1.0", "CANopen node 10", 1000.0)
    c = Characterization(info, DEFAULT, "2026-11-26", {}, bode=fast)
    c.figures = figures(c)
    bandwidth = next(f for f in c.figures if f.name == "bode_bandwidth_hz")
    assert bandwidth.above and bandwidth.passed is True  # DEFAULT: −3 dB ≥ 15 Hz
    assert bandwidth.text.startswith("above 9") and bandwidth.text.endswith(" Hz")
    figure = next(f for f in report_data(c)["figures"] if f["name"] == "bode_bandwidth_hz")
    assert figure["above"] is True and figure["passed"] is True and figure["value"] > 80
    json.dumps(report_data(c))
    slow = _first_order(30.0, 1000.0, 4.0, 100.0)  # found: a figure, not a bound
    c = Characterization(info, DEFAULT, "2026-11-26", {}, bode=slow)
    found = next(f for f in figures(c) if f.name == "bode_bandwidth_hz")
    assert not found.above and found.value == pytest.approx(30.0, rel=0.05)


def test_above_the_sweeps_end_cannot_confirm_a_maximum_or_a_minimum_beyond_it():
    from prm9tool.analysis.profile import Limit
    from prm9tool.characterize.run import Figure

    above = Figure("bode_bandwidth_hz", "−3 dB", 100.0, "Hz", Limit(15.0, None), above=True)
    assert above.passed is True
    assert Figure("b", "b", 100.0, "Hz", Limit(150.0, None), above=True).passed is False
    assert Figure("b", "b", 100.0, "Hz", Limit(None, 200.0), above=True).passed is False


def test_a_sweep_a_busy_pc_cut_below_the_profiles_minimum_is_refused_not_failed():
    """Issue 34 item 9, met again at a real screen: the Tuning window's end-of-line test of a
    healthy valve said FAIL "−3 dB above 3.43 Hz" (limit ≥ 15 Hz) because a busy PC held the
    setpoint and the sweep was used only up to 3.43 Hz. That decides nothing: refused."""
    from dataclasses import replace

    from prm9tool.characterize.run import refuse_undecided

    info = RigInfo(E02 + "-CA", 1, "1.0", "CANopen node 10", 1000.0)
    cut = replace(_first_order(300.0, 1000.0, 4.0, 3.43), limited_to_hz=3.43, held_s=0.016)
    c = Characterization(info, DEFAULT, "2026-11-26", {}, bode=cut)
    c.figures = figures(c)
    with pytest.raises(LinkTooSlowError, match=r"used only up to 3\.\d+ Hz.*minimum 15 Hz"):
        refuse_undecided(c)
    # the same cut without a hold (the link's own rate limit) stays a verdict
    c = Characterization(info, DEFAULT, "2026-11-26", {}, bode=replace(cut, held_s=0.0))
    c.figures = figures(c)
    refuse_undecided(c)
    assert not c.passed

"""The oscilloscope over CANopen with samples lost (issue 20 item 6, issue 25 item 3): samples
placed by their SYNC count, gaps drawn as gaps, the demand channel is the setpoint the tool
sends (or the step panel says why it has none), and no numpy warnings from empty channels."""

from __future__ import annotations

import threading
import time
from types import SimpleNamespace

import numpy as np
import pytest
from support.scope_fakes import FakeConnection
from support.waiting import wait_for
from test_can_pace import can_valve, drop_tpdo1  # noqa: F401 (the fixture)

from prm9tool.catalogue.signals import BY_KEY
from prm9tool.device.canlink.session import CanopenSession
from prm9tool.device.records import NmtState
from prm9tool.model.document import ParameterDocument
from prm9tool.views.scope.widget import ScopeWidget

E02 = "PRM9-06.3Z11/30-24E02S02"
HALF_S = 0.2  # the square's half period


def rising_edges(values: np.ndarray, level: float) -> np.ndarray:
    """Row numbers where ``values`` (NaN: lost) crosses ``level`` upwards, between the
    samples that arrived."""
    rows = np.flatnonzero(np.isfinite(values))
    above = values[rows] >= level
    return rows[1:][above[1:] & ~above[:-1]]


@pytest.mark.parametrize("can_valve", ["full", "manual"], indirect=True)
def test_a_square_keeps_its_period_with_half_the_tpdo1_frames_lost(can_valve):  # noqa: F811
    dropped = drop_tpdo1(can_valve, 0.45, 40)
    with CanopenSession(can_valve.options, 10, type_key=E02 + "-CA") as session:
        session.write("HEARTBEAT", 20)  # the NMT state the scope needs for PDOs
        wait_for(lambda: session.nmt_state is NmtState.OPERATIONAL)
        link = session.setpoint_link()
        link.begin(0)
        session.stream_start(["position_setpoint", "position_actual"], 1000)
        assert session.stream_source == "pdo"  # TPDO1 at the tool's SYNC, demand from RPDO1
        toggles: list[float] = []
        stop = threading.Event()

        def square() -> None:  # the tool's own setpoint: 0 / 20 %, HALF_S each
            high = False
            while not stop.wait(HALF_S):
                high = not high
                link.set(3277 if high else 0)
                toggles.append(time.perf_counter())

        lags: list[float] = []  # how far the in-process valve's simulation fell behind

        def watch() -> None:
            while not stop.wait(0.002):
                lags.append(can_valve.valve.pacer.lag_s())

        driver, watcher = threading.Thread(target=square), threading.Thread(target=watch)
        driver.start()
        watcher.start()
        time.sleep(7 * HALF_S)
        stop.set()
        driver.join()
        watcher.join()
        time.sleep(0.1)  # the last SYNCs' slots are handed out after their settling time
        blocks = [session.stream_read()]
        lost = session.samples_lost
        session.stream_stop()
        link.end()
    rows = np.concatenate(blocks)
    period = 1.0 / 1000
    demand, actual = rows[:, 0] * BY_KEY["position_setpoint"].scale, rows[:, 1]
    actual = actual * BY_KEY["position_actual"].scale
    assert dropped[0] > 100 and lost >= dropped[0] * 0.9  # (and the ticks a busy PC skipped)
    assert np.isnan(actual).sum() == lost  # each lost sample is a gap at its place
    # the demand is what the tool sent, at the SYNC it went with: its edges are the toggles'
    demand_edges = rising_edges(demand, 10.0) * period
    sent_edges = np.asarray(toggles[0::2]) - toggles[0]
    assert len(demand_edges) == len(sent_edges) >= 3
    assert np.abs((demand_edges - demand_edges[0]) - sent_edges).max() < 0.02
    # the actual position, with half its samples lost, rises a few ms after each demand edge
    # (before: its samples were drawn one after the other and the square shrank to half)
    actual_edges = rising_edges(actual, 10.0) * period
    assert len(actual_edges) == len(demand_edges)
    # (with the samples drawn one after the other, the lag would grow by hundreds of ms per
    # edge; here it is the valve's response plus, at most, a run of lost frames)
    # The emulated valve runs in this process: a PC that holds it up delays its answer by as
    # much as its simulation fell behind (a valve of its own never is): that is allowed for.
    behind = max(lags, default=0.0)
    lag = actual_edges - demand_edges
    # (never before its demand; at the same SYNC when a busy PC skipped the ticks between)
    assert (lag >= 0).all() and (lag < 0.07 + behind).all(), (lag, behind)


@pytest.fixture
def scope(qtbot):
    conn = FakeConnection()
    conn.device = SimpleNamespace(stream_rate_limit_hz=1000.0, stream_gaps=True)
    widget = ScopeWidget(conn, ParameterDocument(E02 + "-CA"))
    qtbot.addWidget(widget)
    widget.resize(1400, 800)
    widget.show()
    return widget, conn


def _lossy_square(seconds: float, lost_share: float) -> np.ndarray:
    """Raw rows at 1 kHz: demand NaN (the valve does not report it), the actual position
    following a 1 s square 0 / 20 % (first order, 10 ms) with ``lost_share`` of its samples
    lost at random and in runs."""
    n = int(seconds * 1000)
    t = np.arange(n) / 1000.0
    phase = t % 1.0
    rising = 1.0 - np.exp(-np.clip(phase - 0.5, 0.0, None) / 0.01)
    falling = np.exp(-phase / 0.01) * (t >= 1.0)
    actual = 3277.0 * np.where(phase >= 0.5, rising, falling)
    rng = np.random.default_rng(3)
    actual[rng.random(n) < lost_share] = np.nan
    for start in range(100, n, 700):
        actual[start : start + 60] = np.nan
    return np.column_stack([np.full(n, np.nan), actual])


def test_the_scope_draws_gaps_at_their_time_and_says_why_the_demand_is_empty(qtbot, scope):
    widget, conn = scope
    widget.controls.rate.setCurrentIndex(widget.controls.rate.findData(1000))
    widget.preselect("position_setpoint")
    widget.preselect("position_actual")
    assert widget.channels.selected() == ["position_setpoint", "position_actual"]
    widget.start()
    block = _lossy_square(3.2, 0.4)
    conn.samples_lost = int(np.isnan(block[:, 1]).sum())
    conn.samples_received.emit(block)
    widget._redraw()  # with numpy warnings as errors: no "All-NaN slice" from the empty demand
    widget.display.freeze()
    curve = widget.plot.curves[1]
    t, y, connect = curve.xData, curve.yData, curve.opts["connect"]
    assert len(t) == np.isfinite(block[:, 1]).sum()  # the samples that arrived, none made up
    breaks = t[:-1][~connect[:-1]]  # the line breaks at every run of lost samples over 4 …
    assert len(breaks) >= 4 and all(np.isnan(block[round(b * 1000) + 1, 1]) for b in breaks)
    edges = t[rising_edges(y, 10.0)]  # … and the square keeps 1 s periods: each rising edge
    late = edges - np.array([0.5, 1.5, 2.5])  # where it is, or after the gap that hid it
    assert (late >= 0).all() and (late < 0.1).all()  # (a gap of 60 ms and more, at random)
    status = widget.status.text()
    assert "Recording at" not in status or "of the 1000 Hz asked for" in status
    steps = widget.step_panel
    steps.reference.setCurrentIndex(steps.reference.findData(0))  # the demand channel
    widget.display.update_readouts()
    assert "the reference channel has no data" in steps.region.text()
    assert "setpoint generator" in steps.region.text()
    steps.reference.setCurrentIndex(steps.reference.findData(-1))  # step on the response
    steps.response.setCurrentIndex(steps.response.findData(1))
    widget.display.update_readouts()
    assert steps.figures["rise"].text() != "—", steps.region.text()
    if shots := __import__("os").environ.get("PRM9TOOL_SCREENSHOTS"):
        widget.grab().save(f"{shots}/scope_can_gaps.png")


def test_the_recording_rate_counts_the_gaps_among_the_rows(qtbot, scope):
    widget, conn = scope
    widget.controls.rate.setCurrentIndex(widget.controls.rate.findData(1000))
    widget.preselect("position_actual")
    widget.start()
    block = _lossy_square(1.0, 0.0)[:, 1:]
    block[::2] = np.nan  # every other sample lost: 500 of 1000 Hz
    conn.samples_lost = 500
    conn.samples_received.emit(block)
    widget._redraw()
    assert "Recording at 500 Hz of the 1000 Hz asked for: 500 samples lost" in (
        widget.status.text()
    )


def test_the_demand_channel_shows_the_sent_setpoint_only_while_the_tool_sends_one():
    from prm9tool.device.canlink.sampler import SdoSampler

    sent: dict[str, float] = {}
    sampler = SdoSampler(
        lambda index, sub: (4096).to_bytes(2, "little"),
        ["position_setpoint", "position_actual", "current_a"],
        200,
        lambda key: sent.get(key, float("nan")),
    )
    try:
        time.sleep(0.05)
        sent["position_setpoint"] = 3277.0
        time.sleep(0.05)
    finally:
        sampler.stop()
    rows = sampler.read()
    arrived = rows[np.isfinite(rows[:, 1])]
    assert np.isnan(arrived[0, 0]) and arrived[-1, 0] == 3277.0  # NaN until the tool sends
    assert (arrived[:, 1] == 4096).all() and np.isnan(rows[:, 2]).all()  # no object: no data


def test_a_lost_sample_does_not_blank_the_live_value():
    from prm9tool.service.polling import latest_values

    block = np.array([[1.0, 5.0, np.nan], [2.0, np.nan, np.nan], [np.nan, np.nan, np.nan]])
    assert latest_values(["a", "b", "c"], block) == {"a": 2.0, "b": 5.0}


def test_the_legend_shows_the_newest_sample_that_arrived():
    from prm9tool.views.scope.display import newest_arrived

    rows = np.array([[1.0, 5.0, np.nan], [2.0, np.nan, np.nan], [np.nan, np.nan, np.nan]])
    shown = newest_arrived(rows)
    assert shown[:2].tolist() == [2.0, 5.0] and np.isnan(shown[2])


def test_the_cursors_read_between_the_samples_that_arrived():
    from prm9tool.scope import cursor_readout

    t = np.arange(5) / 1000.0
    values = np.column_stack([[0.0, np.nan, np.nan, 3.0, 4.0], np.full(5, np.nan)])
    readout = cursor_readout(t, values, 0.0015, 0.004)
    assert readout.a[0] == pytest.approx(1.5) and readout.b[0] == 4.0
    assert np.isnan(readout.a[1])  # no data on that channel: no value, no warning

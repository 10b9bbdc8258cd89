"""The oscilloscope model: ring buffer, triggers, cursors, step figures, CSV, generator maths."""

from __future__ import annotations

import io
import math

import numpy as np
import pytest

from prm9tool.catalogue.signals import BY_KEY
from prm9tool.errors import ValueRangeError
from prm9tool.scope import (
    Capture,
    Edge,
    Frame,
    GeneratorSettings,
    RingBuffer,
    TriggerEngine,
    TriggerMode,
    TriggerSettings,
    Waveform,
    axis_ranges,
    cursor_readout,
    find_edge,
    peak_decimate,
    step_figures,
    write_csv,
)


def _ramp(start: int, count: int, channels: int = 2) -> np.ndarray:
    column = np.arange(start, start + count, dtype=np.float64)
    return np.column_stack([column * (c + 1) for c in range(channels)])


# --- ring buffer -------------------------------------------------------------------------------
def test_ring_buffer_keeps_the_newest_samples_in_order_across_the_wrap():
    buf = RingBuffer(capacity=10, channels=2)
    for start in range(0, 37, 3):
        buf.append(_ramp(start, 3))
    assert buf.total == 39
    assert buf.first == 29
    start, view = buf.latest(10)
    assert start == 29
    np.testing.assert_array_equal(view, _ramp(29, 10))


def test_ring_buffer_window_is_a_view_and_clips_to_what_is_held():
    buf = RingBuffer(capacity=8, channels=1)
    buf.append(_ramp(0, 12, 1))
    start, view = buf.window(0, 100)
    assert (start, len(view)) == (4, 8)
    assert np.shares_memory(view, buf._data)
    assert len(buf.window(20, 30)[1]) == 0


def test_ring_buffer_takes_a_block_longer_than_itself():
    buf = RingBuffer(capacity=5, channels=1)
    buf.append(_ramp(0, 13, 1))
    assert buf.total == 13
    np.testing.assert_array_equal(buf.latest(5)[1][:, 0], np.arange(8, 13))


def test_ring_buffer_refuses_a_block_of_the_wrong_width():
    buf = RingBuffer(capacity=5, channels=3)
    with pytest.raises(ValueError, match=r"\(n, 3\)"):
        buf.append(np.zeros((4, 2)))


def test_capture_converts_raw_values_to_display_units():
    capture = Capture([BY_KEY["position_actual"], BY_KEY["current_a"]], rate_hz=5000)
    capture.feed(np.array([[16384, 800], [-8192, 1200]], dtype=np.int16))
    _, values = capture.buffer.latest(2)
    np.testing.assert_allclose(values, [[100.0, 800.0], [-50.0, 1200.0]])
    np.testing.assert_allclose(capture.times(10, 3), [0.002, 0.0022, 0.0024])
    assert capture.buffer.capacity >= 60 * 5000


# --- trigger -----------------------------------------------------------------------------------
def _square(count: int, period: int, low: float = 0.0, high: float = 1.0) -> np.ndarray:
    phase = np.arange(count) % period
    return np.where(phase >= period // 2, high, low)[:, None]


def _feed(buf: RingBuffer, data: np.ndarray, engine: TriggerEngine, chunk: int = 7):
    frames = []
    for i in range(0, len(data), chunk):
        buf.append(data[i : i + chunk])
        frames.append(engine.update(buf))
    return frames


def test_find_edge_rising_and_falling():
    x = np.array([0.0, 0.2, 0.6, 0.9, 0.4, 0.1])
    assert find_edge(x, 0.5, Edge.RISING) == 2
    assert find_edge(x, 0.5, Edge.FALLING) == 4
    assert find_edge(x, 2.0, Edge.RISING) is None


def test_normal_trigger_frames_start_at_the_edge_minus_the_pre_trigger_share():
    buf = RingBuffer(1000, 1)
    engine = TriggerEngine(TriggerSettings(TriggerMode.NORMAL, level=0.5, pre=0.25), window=40)
    frames = [f for f in _feed(buf, _square(400, 100), engine) if f is not None]
    triggers = sorted({f.origin for f in frames if f.triggered})
    assert triggers == [50, 150, 250, 350]  # every rising edge of the square wave
    assert all(f.start == f.origin - 10 and f.length == 40 for f in frames)


def test_falling_edge_trigger_on_the_chosen_channel():
    data = np.column_stack([np.zeros(300), _square(300, 100)[:, 0]])
    buf = RingBuffer(1000, 2)
    settings = TriggerSettings(TriggerMode.NORMAL, channel=1, level=0.5, edge=Edge.FALLING)
    engine = TriggerEngine(settings, window=20)
    frames = [f for f in _feed(buf, data, engine) if f is not None]
    assert sorted({f.origin for f in frames}) == [100, 200]


def test_normal_trigger_shows_nothing_without_an_edge():
    buf = RingBuffer(1000, 1)
    engine = TriggerEngine(TriggerSettings(TriggerMode.NORMAL, level=5.0), window=20)
    assert set(_feed(buf, _square(300, 50), engine)) == {None}
    assert engine.waiting


def test_single_trigger_holds_the_first_frame():
    buf = RingBuffer(1000, 1)
    engine = TriggerEngine(TriggerSettings(TriggerMode.SINGLE, level=0.5, pre=0.5), window=20)
    frames = _feed(buf, _square(500, 100), engine)
    assert engine.done
    assert frames[-1] == Frame(40, 20, 50, True)
    engine.rearm(buf.total)
    assert not engine.done and engine.update(buf) is None


def test_auto_trigger_rolls_without_edges_and_locks_onto_one():
    buf = RingBuffer(1000, 1)
    engine = TriggerEngine(TriggerSettings(TriggerMode.AUTO, level=0.5, pre=0.5), window=20)
    frames = _feed(buf, np.zeros((100, 1)), engine)
    assert frames[-1] is not None and not frames[-1].triggered
    assert frames[-1].stop == buf.total  # free-running: the newest samples
    frames = _feed(buf, _square(70, 100), engine)  # rising edge at sample 150
    assert frames[-1] is not None and frames[-1].triggered and frames[-1].origin == 150
    frames = _feed(buf, np.ones((40, 1)), engine)  # no edge for a window length: rolls again
    assert frames[-1] is not None and not frames[-1].triggered


def test_roll_mode_shows_the_newest_window():
    buf = RingBuffer(1000, 1)
    engine = TriggerEngine(TriggerSettings(TriggerMode.ROLL), window=30)
    frames = _feed(buf, np.zeros((95, 1)), engine)
    assert frames[-1] == Frame(65, 30, 0, False)


def test_trigger_refuses_a_pre_trigger_share_outside_0_to_1():
    with pytest.raises(ValueError, match="between 0 and 1"):
        TriggerEngine(TriggerSettings(TriggerMode.NORMAL, pre=1.5), window=10)


# --- cursors -----------------------------------------------------------------------------------
def test_cursor_readout_interpolates_values_and_differences():
    t = np.linspace(0.0, 1.0, 11)
    values = np.column_stack([t * 10.0, np.full(11, 3.0)])
    readout = cursor_readout(t, values, 0.25, 0.75)
    np.testing.assert_allclose(readout.a, [2.5, 3.0])
    np.testing.assert_allclose(readout.delta, [5.0, 0.0])
    assert readout.dt == pytest.approx(0.5)
    assert readout.frequency == pytest.approx(2.0)


def test_cursor_outside_the_data_reads_nan():
    t = np.linspace(0.0, 1.0, 11)
    readout = cursor_readout(t, t[:, None], -1.0, 0.5)
    assert math.isnan(readout.a[0]) and readout.b[0] == pytest.approx(0.5)
    assert math.isnan(cursor_readout(t, t[:, None], 0.5, 0.5).frequency)


# --- step response -----------------------------------------------------------------------------
RATE = 5000.0


def _first_order(tau: float, t_step: float = 0.05, duration: float = 0.5):
    t = np.arange(int(duration * RATE)) / RATE
    ref = np.where(t >= t_step, 60.0, 20.0)
    y = 20.0 + 40.0 * np.where(t >= t_step, 1.0 - np.exp(-(t - t_step) / tau), 0.0)
    return t, ref, y


def _second_order(zeta: float, wn: float, t_step: float = 0.05, duration: float = 1.0):
    t = np.arange(int(duration * RATE)) / RATE
    tau = np.maximum(t - t_step, 0.0)
    wd = wn * math.sqrt(1 - zeta**2)
    phi = math.acos(zeta)
    unit = 1 - np.exp(-zeta * wn * tau) * np.sin(wd * tau + phi) / math.sqrt(1 - zeta**2)
    return t, np.where(t >= t_step, 10.0, 0.0), 10.0 * unit


def test_first_order_step_figures():
    tau = 0.01
    t, ref, y = _first_order(tau)
    fig = step_figures(t, y, ref)
    assert fig is not None
    assert fig.t_step == pytest.approx(0.05)
    assert fig.rise_time == pytest.approx(tau * math.log(9), abs=2 / RATE)
    assert fig.overshoot == pytest.approx(0.0, abs=1e-6)
    assert fig.settling_time == pytest.approx(tau * math.log(50), abs=2 / RATE)
    assert fig.steady_state_error == pytest.approx(0.0, abs=1e-3)


def test_second_order_overshoot_matches_theory():
    zeta, wn = 0.5, 60.0
    t, ref, y = _second_order(zeta, wn)
    fig = step_figures(t, y, ref)
    assert fig is not None
    expected = 100 * math.exp(-math.pi * zeta / math.sqrt(1 - zeta**2))
    assert fig.overshoot == pytest.approx(expected, abs=0.2)
    # the 2 % envelope bound: ln(50 / sqrt(1 - zeta²)) / (zeta·wn) is an upper bound
    assert 0 < fig.settling_time <= math.log(50 / math.sqrt(1 - zeta**2)) / (zeta * wn)


def test_steady_state_error_against_the_reference_target():
    t, ref, y = _first_order(0.005)
    fig = step_figures(t, y * 0.95 + 1.0, ref)  # settles at 58 instead of 60
    assert fig is not None
    assert fig.target == pytest.approx(60.0)
    assert fig.steady_state_error == pytest.approx(2.0, abs=0.01)


def test_step_figures_without_a_reference_find_the_step_on_the_response():
    t, _, y = _first_order(0.01)
    fig = step_figures(t, y)
    assert fig is not None
    assert fig.t_step == pytest.approx(0.05, abs=0.001)
    assert fig.rise_time == pytest.approx(0.01 * math.log(9), abs=2 / RATE)
    assert math.isnan(fig.steady_state_error)


def test_unsettled_response_has_no_settling_time_and_flat_data_no_figures():
    t, ref, y = _second_order(0.05, 60.0, duration=0.3)
    fig = step_figures(t, y, ref)
    assert fig is not None and math.isnan(fig.settling_time)
    assert step_figures(t, np.ones_like(t), np.ones_like(t)) is None


def test_a_flat_noisy_response_gives_no_figures():
    t, ref, _ = _first_order(0.01)
    noisy = 20.0 + np.random.default_rng(1).normal(0.0, 0.24, len(t))
    assert step_figures(t, noisy, ref) is None  # the setpoint stepped, the response did not
    assert step_figures(t, noisy) is None


def test_a_response_that_hardly_follows_the_reference_gives_no_figures():
    t, ref, _ = _first_order(0.01)
    creeping = 20.0 + 0.5 * t  # 0.25 of a 40 step: under the 2 % band
    assert step_figures(t, creeping, ref) is None
    assert step_figures(t, creeping, ref, comparable=False) is not None  # other unit: no check


def test_step_figures_stand_0_6_percent_noise():
    tau = 0.01
    t, ref, y = _first_order(tau)
    noisy = y + np.random.default_rng(7).normal(0.0, 0.006 * 40.0, len(t))
    for fig in (step_figures(t, noisy, ref), step_figures(t, noisy)):
        assert fig is not None
        assert fig.initial == pytest.approx(20.0, abs=0.1)
        assert fig.final == pytest.approx(60.0, abs=0.1)
        assert fig.overshoot == 0.0  # the noise peaks are no overshoot
        assert fig.rise_time == pytest.approx(tau * math.log(9), rel=0.05)
        assert fig.settling_time == pytest.approx(tau * math.log(50), rel=0.2)
    zeta, wn = 0.5, 60.0
    t, ref, y = _second_order(zeta, wn)
    noisy = y + np.random.default_rng(3).normal(0.0, 0.006 * 10.0, len(t))
    fig = step_figures(t, noisy, ref)
    assert fig is not None
    assert fig.overshoot == pytest.approx(100 * math.exp(-math.pi * zeta / math.sqrt(0.75)), abs=1)


def test_without_a_reference_the_initial_level_comes_from_before_the_step():
    t, _, y = _first_order(0.01, t_step=0.01)  # a short pre-trigger: the step at 2 %
    fig = step_figures(t, y)
    assert fig is not None
    assert fig.initial == pytest.approx(20.0)
    assert fig.t_step == pytest.approx(0.01, abs=0.001)
    assert fig.rise_time == pytest.approx(0.01 * math.log(9), abs=2 / RATE)


# --- CSV ---------------------------------------------------------------------------------------
def test_csv_has_units_in_the_header_and_one_row_per_sample():
    signals = [BY_KEY["position_actual"], BY_KEY["current_a"], BY_KEY["temperature"]]
    t = np.array([0.0, 0.0002, 0.0004])
    values = np.array([[1.5, 800.0, 41.2], [2.5, 810.0, 41.3], [3.5, 820.0, 41.4]])
    out = io.StringIO()
    assert write_csv(out, t, values, signals) == 3
    lines = out.getvalue().splitlines()
    assert lines[0] == "time [s],position_actual [%],current_a [mA],temperature [°C]"
    assert lines[2] == "0.000200,2.5,810,41.3"
    assert len(lines) == 4


def test_csv_refuses_mismatched_columns():
    with pytest.raises(ValueError, match="one column per signal"):
        write_csv(io.StringIO(), np.zeros(3), np.zeros((3, 2)), [BY_KEY["current_a"]])


# --- generator ---------------------------------------------------------------------------------
def test_generator_waveforms():
    t = np.array([0.0, 0.25, 0.5, 0.75, 1.0, 1.5, 2.25])
    step = GeneratorSettings(Waveform.STEP, amplitude=30, offset=10, period=1.0)
    np.testing.assert_allclose(step.value_at(t), [10, 10, 40, 40, 40, 40, 40])
    square = GeneratorSettings(Waveform.SQUARE, amplitude=30, offset=10, period=1.0)
    np.testing.assert_allclose(square.value_at(t), [10, 10, 40, 40, 10, 40, 10])
    sine = GeneratorSettings(Waveform.SINE, amplitude=20, offset=-5, period=1.0)
    np.testing.assert_allclose(sine.value_at(t), [-5, 15, -5, -25, -5, -5, 15], atol=1e-9)


def test_generator_raw_value_uses_the_catalogue_scale():
    gen = GeneratorSettings(Waveform.STEP, amplitude=50, offset=0, period=1.0)
    assert gen.raw_at(0.0) == 0
    assert gen.raw_at(0.6) == 8192  # 50 % of ±16384


@pytest.mark.parametrize(
    ("settings", "message"),
    [
        (GeneratorSettings(Waveform.SINE, amplitude=60, offset=50), r"reaches -10 … 110 %"),
        (GeneratorSettings(Waveform.STEP, amplitude=-30, offset=-80), r"within -100 … 100 %"),
        (GeneratorSettings(Waveform.SQUARE, period=0.0), "period must be longer"),
    ],
)
def test_generator_refuses_waveforms_outside_the_setpoint_range(settings, message):
    with pytest.raises(ValueRangeError, match=message):
        settings.check()


# --- decimation --------------------------------------------------------------------------------
def test_peak_decimation_keeps_every_blocks_extremes_and_the_tail():
    t = np.arange(1003) / 1000.0
    values = np.column_stack([np.zeros(1003), np.arange(1003.0)])
    values[517, 0] = 9.0  # a one-sample spike
    td, vd = peak_decimate(t, values, points=100)
    assert len(td) == len(vd) <= 110
    assert vd[:, 0].max() == 9.0
    assert vd[0, 1] == 0.0 and vd[1, 1] == 20.0  # blocks of ceil(1003 / 50) = 21: min, max
    np.testing.assert_array_equal(vd[-3:, 1], [1000.0, 1001.0, 1002.0])  # the tail as is
    assert np.all(np.diff(td) >= 0)


def test_peak_decimation_leaves_short_data_alone():
    t = np.arange(10.0)
    values = np.ones((10, 2))
    td, vd = peak_decimate(t, values, points=100)
    assert td is t and vd is values


# --- autoscale ---------------------------------------------------------------------------------
def test_a_shared_axis_whose_channel_has_no_data_takes_the_common_range():
    """Over CANopen the demand value is NaN; the spool's ±20 % was drawn on the demand's axis,
    which kept its ±0.4 labels."""
    current = [(-0.4, 0.4), (-0.4, 0.4)]
    ranges = axis_ranges([None, (-20.0, 20.0)], current, ["%", "%"], True, auto=[True, True])
    assert ranges == [(-24.0, 24.0), (-24.0, 24.0)]
    manual = axis_ranges([None, (-20.0, 20.0)], current, ["%", "%"], True, auto=[False, True])
    assert manual == [None, (-24.0, 24.0)]


def test_axis_ranges_share_a_scale_per_unit_and_leave_manual_axes_alone():
    bounds = [(-30.0, 30.0), (-10.0, 50.0), None]  # channel 3 zoomed by hand
    current = [(0.0, 1.0), (0.0, 1.0), (0.0, 1.0)]
    shared = axis_ranges(bounds, current, ["%", "%", "%"], share_units=True)
    assert shared[0] == shared[1] == pytest.approx((-38.0, 58.0))
    assert shared[2] is None
    separate = axis_ranges(bounds, current, ["%", "%", "%"], share_units=False)
    assert separate[0] == pytest.approx((-36.0, 36.0))
    mixed = axis_ranges(bounds[:2], current[:2], ["%", "mA"], share_units=True)
    assert mixed[1] == pytest.approx((-16.0, 56.0))


def test_axis_ranges_keep_a_range_that_still_fits_the_data():
    current = [(-12.0, 12.0)]
    assert axis_ranges([(-9.0, 9.0)], current, ["%"], share_units=True) == [None]
    assert axis_ranges([(-9.0, 13.0)], current, ["%"], True)[0] is not None  # left the range
    assert axis_ranges([(-2.0, 2.0)], current, ["%"], True)[0] is not None  # fills < half
    assert axis_ranges([(-9.0, 9.0)], current, ["%"], True, force=True)[0] is not None
    assert axis_ranges([(5.0, 5.0)], [(0.0, 1.0)], ["V"], True)[0] == pytest.approx((4.5, 5.5))

"""The setpoint generator's waveform off the GUI thread, on the valve's time base (issue 14
item 11): exact to the emulated valve's 200 µs cycle; over a link timed against the sample
stream, with keepalive writes, and a refused write reported."""

from __future__ import annotations

import threading

import numpy as np
import pytest
from support.waiting import HandClock, wait_for

from prm9tool.catalogue import CATALOGUE
from prm9tool.device import emulated_valves, factory
from prm9tool.device.emulator.constants import CYCLE_S
from prm9tool.device.setpoint import OverrideSetpoint
from prm9tool.errors import AbortCode, SdoAbortError
from prm9tool.scope import GeneratorSettings, Waveform
from prm9tool.service.setpoint_driver import SetpointDriver, StreamClock

E02 = "PRM9-06.3Z11/30-24E02S02"


@pytest.fixture
def session():
    emulated_valves.forget_emulated_valves()
    opened = factory.open_session(f"emulator:{E02}:7201", paced=False)
    opened.transport.valve.advance(2.0)  # booted, running from the analog input
    yield opened
    opened.close()
    emulated_valves.forget_emulated_valves()


def _edges(session, settings: GeneratorSettings, seconds: float):
    """Run ``settings`` for ``seconds`` of valve time; the cycles (counted from the start of
    the waveform) at which the valve's raw setpoint changed level, and its samples."""
    valve = session.transport.valve
    valve.capture_start(["setpoint_raw"], 1)  # one sample per 200 µs cycle
    first = round(valve.time / CYCLE_S)
    driver = SetpointDriver(session, settings, lambda *_: None)
    driver.start()
    start = valve.firmware.program._start - first  # the waveform's cycle 0 in the capture
    for _ in range(round(seconds / 0.1)):
        valve.usb_activity()  # the link's traffic, as the driver's keepalive makes it
        valve.advance(0.1)
    samples = valve.capture_read()[start:, 0]
    driver.stop()
    valve.capture_stop()
    high = samples > 0.5 * (samples.max() + samples.min())
    return np.flatnonzero(np.diff(high.astype(int))) + 1, high


@pytest.mark.parametrize(("period", "half_cycles"), [(1.0, 2500), (0.05, 125)])
def test_square_edges_fall_on_the_valves_cycles(session, period, half_cycles):
    settings = GeneratorSettings(Waveform.SQUARE, 20.0, 0.0, period)
    edges, high = _edges(session, settings, 3.0)
    assert edges[0] == half_cycles  # low for the first half period, from cycle 0
    assert set(np.diff(edges)) == {half_cycles}  # no jitter: every half period is exact
    whole = high[: edges[-1] - edges[-1] % (2 * half_cycles)]
    assert np.count_nonzero(whole) * 2 == len(whole)  # duty exactly 50 %
    assert len(edges) >= int(3.0 / period * 2) - 2


def test_the_override_goes_on_with_the_first_value_and_off_at_stop(session):
    valve = session.transport.valve
    driver = SetpointDriver(session, GeneratorSettings(Waveform.STEP, 20.0, 10.0, 1.0), _never)
    driver.start()
    assert driver.exact  # an emulated valve runs the waveform itself
    assert valve.read(*CATALOGUE["SETPOVRON"].key) == 1
    assert valve.read(*CATALOGUE["SETPOVR"].key) == 1638  # 10 %
    driver.stop()
    assert valve.read(*CATALOGUE["SETPOVRON"].key) == 0
    assert valve.firmware.program is None


def _never(mnemonic: str, exc: Exception) -> None:
    raise AssertionError(f"refused {mnemonic}: {exc}")


class _LinkSession:
    """A session over a link (no emulator behind it) that records its writes."""

    emulator = None

    def __init__(self) -> None:
        self.writes: list[tuple[str, int]] = []
        self.refuse: set[str] = set()
        self.lock = threading.Lock()

    def write(self, mnemonic: str, raw: int) -> None:
        if mnemonic in self.refuse:
            raise SdoAbortError(0x2050, 2, AbortCode.VALUE_TOO_HIGH)
        with self.lock:
            self.writes.append((mnemonic, raw))

    def values(self, mnemonic: str) -> list[int]:
        with self.lock:
            return [raw for name, raw in self.writes if name == mnemonic]

    def setpoint_link(self) -> OverrideSetpoint:
        """As ValveSession's default: the service override SETPOVRON/SETPOVR."""
        return OverrideSetpoint(self)


def test_over_a_link_the_writes_follow_the_stream_time_and_keep_the_override_alive():
    session, clock = _LinkSession(), HandClock()
    driver = SetpointDriver(session, GeneratorSettings(Waveform.SQUARE, 40.0, 10.0, 0.2), _never,
                            clock)  # fmt: skip
    driver.start()
    assert not driver.exact
    assert session.writes[:2] == [("SETPOVR", 1638), ("SETPOVRON", 1)]
    clock.now = 0.1  # the stream says half a period has passed: 50 %
    wait_for(lambda: 8192 in session.values("SETPOVR"))
    wait_for(lambda: session.values("SETPOVR").count(8192) >= 3)  # unchanged: keepalive
    clock.now = 0.2
    wait_for(lambda: session.values("SETPOVR")[-1] == 1638)
    driver.stop()
    assert session.writes[-1] == ("SETPOVRON", 0)


def test_a_refused_write_ends_the_driver_and_is_reported():
    session, clock = _LinkSession(), HandClock()
    refused: list[tuple[str, str]] = []
    driver = SetpointDriver(
        session,
        GeneratorSettings(Waveform.SQUARE, 40.0, 10.0, 0.2),
        lambda name, exc: refused.append((name, str(exc))),
        clock,
    )
    driver.start()
    session.refuse.add("SETPOVR")
    clock.now = 0.1
    wait_for(lambda: refused)
    assert refused[0] == (
        "SETPOVR",
        "0x2050/2: abort 0x06090031 (value of parameter written too high)",
    )
    driver.stop()
    assert session.writes[-1] == ("SETPOVRON", 0)


def test_the_stream_clock_counts_samples():
    clock = StreamClock()
    clock.restart(5000)
    mark = clock.mark()
    clock.samples_arrived(2500)
    assert 0.5 <= clock.seconds_since(mark) < 0.5 + 0.05
    clock.restart(1000)  # another stream: the host's clock again, from the mark
    assert clock.seconds_since(mark) < 0.5

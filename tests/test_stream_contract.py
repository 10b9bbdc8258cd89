"""Capture and the oscilloscope's stream are one operation (issue 28): the API's capture and the
GUI worker's stream read the same valve stream through the same StreamReader, so they give the
same samples, the same count of lost samples and the same words for a stream gone dead (before,
the worker's stream had no silence bound: a dead stream froze the oscilloscope without a word).
"""

from __future__ import annotations

import numpy as np
import pytest
from support.gui_support import E02

import prm9tool
from prm9tool.catalogue.signals import BY_KEY
from prm9tool.device import emulated_valves, factory
from prm9tool.errors import DeviceTimeoutError
from prm9tool.online.connection import ValveConnection
from prm9tool.service.stream import record

TIMEOUT = 15_000
KEY = "position_actual"
RATE_HZ = 1000


def _blocks() -> list[tuple[np.ndarray, int]]:
    """What the valve sends, then silence: 4 blocks of 50 samples, the third with 5 lost (NaN
    rows over CANopen), and the session's count of lost samples rising by them."""
    blocks = []
    for k in range(4):
        block = np.arange(50 * k, 50 * (k + 1), dtype=float).reshape(-1, 1)
        lost = 0
        if k == 2:
            block[10:15] = np.nan
            lost = 5
        blocks.append((block, lost))
    return blocks


def _scripted(session):
    """The open session, its stream replaced by :func:`_blocks` (each start starts it again)."""

    class Scripted(type(session)):  # type: ignore[misc]
        def stream_start(self, keys, rate_hz=5000):
            self._script, self._lost = iter(_blocks()), 0

        def stream_read(self):
            step = next(getattr(self, "_script", iter(())), None)
            if step is None:
                return np.zeros((0, 1))
            block, lost = step
            self._lost += lost
            return block.copy()

        @property
        def samples_lost(self):
            return getattr(self, "_lost", 0)

        def stream_stop(self):
            self._script = iter(())

    session.__class__ = Scripted
    return session


@pytest.fixture
def connection(qtbot):
    conn = ValveConnection(
        opener=lambda entry: _scripted(factory.open_session(entry)),
        lister=lambda emulators, can=None: factory.list_devices(emulators),
    )
    conn.auto_reconnect = False
    yield conn
    conn.shutdown()
    emulated_valves.forget_emulated_valves()


def _api(serial: int, seconds: float):
    with prm9tool.connect(f"emulator:{E02}:{serial}", record_history=False) as valve:
        _scripted(valve.session)
        taken = record(valve.session, [KEY], 0.2, RATE_HZ)  # the capture's own recording
        data = valve.capture([KEY], 0.2, rate_hz=RATE_HZ)
        with pytest.raises(DeviceTimeoutError) as dead:
            valve.capture([KEY], seconds, rate_hz=RATE_HZ)
    return taken, data, str(dead.value)


def _gui(qtbot, connection, serial: int):
    entry = factory.list_devices([f"{E02}:{serial}"])[-1]
    with qtbot.waitSignals([connection.online_changed, connection.device_changed], timeout=TIMEOUT):
        connection.go_online(entry)
    blocks: list[np.ndarray] = []
    lost: list[int] = []
    connection.samples_received.connect(blocks.append)
    connection.samples_lost_changed.connect(lost.append)
    with (
        qtbot.waitSignal(connection.stream_stopped, timeout=TIMEOUT),
        qtbot.waitSignal(connection.failed, timeout=TIMEOUT) as failed,
    ):
        connection.start_stream([KEY], RATE_HZ)
    assert connection.is_online and connection.streaming_keys == []  # stopped, still online
    return np.concatenate(blocks), lost, failed.args[0]


def test_capture_and_the_oscilloscope_stream_give_the_same_samples_loss_and_words(
    qtbot, connection
):
    taken, data, api_dead = _api(7470, seconds=0.3)
    samples, lost, gui_dead = _gui(qtbot, connection, 7471)
    np.testing.assert_array_equal(samples, taken.samples)  # the same 200 raw samples, NaN too
    np.testing.assert_array_equal(data[KEY], taken.samples[:, 0] * BY_KEY[KEY].scale)
    assert taken.lost == 5 and max(lost) == 5  # the session's count, at both doors
    assert int(np.isnan(data[KEY]).sum()) == 5
    words = "the valve sent no samples for 1.0 s (200 received"
    assert api_dead == f"{words} of 300)"  # the capture says how many it wanted
    # the window leads with its translated summary, the same words as the detail
    assert gui_dead == f"The valve stopped sending its measuring points. ({words}))"

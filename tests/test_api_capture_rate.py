"""Issue 34 item 8: a capture over CANopen at its default rate lost 13-32 % of its samples on a
loaded PC, while docs/api.md promised the fastest rate the link streams without loss. The
tool's SYNC thread skips a tick it reaches more than half a period late, so what the bus allows
(1 kHz) is not what a busy PC keeps: the default rate is now the fastest pace a short trial on
this PC streamed without a lost sample."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from prm9tool.api import measure
from prm9tool.service import stream


class PacedLink:
    """A CANopen-like session whose PC keeps ``kept_hz`` at most: faster, it loses samples."""

    def __init__(self, kept_hz: int, limit_hz: float = 1000.0) -> None:
        self.info = SimpleNamespace(stream_rate_limit_hz=limit_hz)
        self.kept_hz = kept_hz
        self.started: list[int] = []
        self.rate = 0

    def stream_start(self, keys, rate_hz):
        self.started.append(rate_hz)
        self.rate = rate_hz

    def stream_read(self):
        return np.zeros((0, 1))

    @property
    def samples_lost(self) -> int:
        return 0 if self.rate <= self.kept_hz else 7

    def stream_stop(self):
        pass


def test_the_default_rate_over_canopen_is_what_this_pc_keeps(monkeypatch):
    monkeypatch.setattr(stream, "TRIAL_S", 0.01)
    busy = PacedLink(kept_hz=300)
    assert stream.link_rate(busy, ["position_actual"]) == 250  # was 1000, losing samples
    assert busy.started == [1000, 500, 250]  # tried from the bus's pace down
    quiet = PacedLink(kept_hz=1000)
    assert stream.link_rate(quiet, ["position_actual"]) == 1000
    hopeless = PacedLink(kept_hz=0)
    assert stream.link_rate(hopeless, ["position_actual"]) == 62  # the slowest, untried
    assert hopeless.started == [1000, 500, 250, 125]
    usb = PacedLink(kept_hz=0, limit_hz=0.0)
    assert stream.link_rate(usb, ["position_actual"]) == 5000 and usb.started == []


class BusierLink(PacedLink):
    """Like PacedLink, but the PC gets busier after the trial: each stream started keeps the
    next of ``kept`` (the last one for the rest); a lost sample is a NaN row."""

    def __init__(self, kept: list[int]) -> None:
        super().__init__(kept_hz=kept[0])
        self.kept = kept
        self.lost = 0
        self.given = 0

    def stream_start(self, keys, rate_hz):
        super().stream_start(keys, rate_hz)
        self.kept_hz = self.kept[min(len(self.started) - 1, len(self.kept) - 1)]
        self.lost = self.given = 0

    def stream_read(self):
        rows = np.ones((max(1, self.rate // 20), 1))
        if self.rate > self.kept_hz:
            rows[::5] = np.nan  # a fifth lost
            self.lost += len(rows[::5])
        self.given += len(rows)
        return rows

    @property
    def samples_lost(self) -> int:
        return self.lost


def test_a_capture_at_the_default_rate_that_lost_samples_is_taken_again_slower(monkeypatch):
    """The trial kept 1 kHz, the capture then lost a fifth of its samples: before, the default
    capture returned them as NaN; now it is taken again at 500 Hz, which lost nothing."""
    monkeypatch.setattr(stream, "TRIAL_S", 0.01)
    monkeypatch.setattr(measure, "_check_keys", lambda session, keys: None)
    link = BusierLink(kept=[1000, 300, 1000])  # trial at 1 kHz ok, capture lost, again ok
    data = measure.capture(link, ["position_actual"], 0.2)
    assert link.started == [1000, 1000, 500]
    assert data.rate_hz == 500 and len(data["t"]) == 100
    assert not np.isnan(data["position_actual"]).any()


def test_a_default_capture_that_loses_at_every_pace_is_refused_with_the_reason(monkeypatch):
    monkeypatch.setattr(stream, "TRIAL_S", 0.01)
    monkeypatch.setattr(measure, "_check_keys", lambda session, keys: None)
    link = BusierLink(kept=[0])
    with pytest.raises(measure.SamplesLostError, match=r"could not keep the SYNC pace.* at 62 Hz"):
        measure.capture(link, ["position_actual"], 0.1)
    assert link.started[-1] == 62


def test_a_capture_at_a_rate_asked_for_keeps_its_gaps_as_nan(monkeypatch):
    monkeypatch.setattr(measure, "_check_keys", lambda session, keys: None)
    link = BusierLink(kept=[0])
    data = measure.capture(link, ["position_actual"], 0.1, rate_hz=1000)
    assert link.started == [1000] and np.isnan(data["position_actual"]).any()

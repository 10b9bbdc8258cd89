"""``prm9tool --characterize --device`` over the links a real valve has: USB (the fake hidapi
in front of a paced emulated valve) and CANopen (an emulated -CA valve on a virtual bus)."""

from __future__ import annotations

import json
import sys

import pytest
from usb_fakes import FakeHid

from prm9tool.catalogue import CATALOGUE
from prm9tool.cli.main import main
from prm9tool.device import factory
from prm9tool.device.emulator import EmulatedValve
from prm9tool.device.transport.hidapi import HidTransport
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
static_period_s = 1.5
[limits]
step_overshoot_pct = { max = 15 }
bode_bandwidth_hz = { min = 15 }
static_linearity_pct = { max = 3 }
"""


@pytest.fixture(autouse=True)
def _fresh_emulators():
    yield
    factory.forget_emulated_valves()


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
    assert main(args) == ExitCode.OK, capsys.readouterr().err
    report = json.loads(js.read_text(encoding="utf-8"))
    assert report["valve"]["serial"] == 4711
    assert report["link"] == "USB" and report["sample_rate_hz"] == 5000
    figures = {f["name"]: f["value"] for f in report["figures"]}
    assert 15 < figures["bode_bandwidth_hz"] < 100
    assert 0.9 < figures["static_gain"] < 1.1
    assert figures["step_25_overshoot_pct"] < 15
    over = CATALOGUE["SETPOVRON"]
    assert usb_valve.read(over.index, over.subindex) == 0  # the override is off again

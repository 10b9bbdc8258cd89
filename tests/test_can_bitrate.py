"""Finding the bus's bit rate by listening only (prm9tool.device.canlink.bitrate, --find-bitrate):
each rate a PRM9 supports is tried in listen-only mode, the one with valid frames wins, nothing
is ever transmitted; an adapter without listen-only, a silent bus and a bus that gives only
error frames each say what to do."""

from __future__ import annotations

import time
from typing import ClassVar

import can
import pytest

from prm9tool.cli.main import main
from prm9tool.device.canlink.bitrate import (
    RATES,
    BitrateNotFoundError,
    NoListenOnlyError,
    find_bitrate,
    open_listen_only,
)
from prm9tool.device.canlink.bus import CanOptions


class AdapterAt(can.BusABC):
    """A listen-only adapter on a bus that runs at ``bus_rate``: at that rate it receives the
    heartbeat of node 10, at any other rate error frames (None: a silent bus)."""

    opened: ClassVar[list[tuple[int, dict[str, object]]]] = []

    def __init__(self, bus_rate: int | None, bitrate: int, **kwargs: object) -> None:
        super().__init__(channel="fake")
        self.bus_rate, self.bitrate = bus_rate, bitrate
        self.opened.append((bitrate, kwargs))

    def send(self, msg: can.Message, timeout: float | None = None) -> None:
        raise AssertionError(f"transmitted {msg} while finding the bit rate")

    def _recv_internal(self, timeout: float | None):  # type: ignore[no-untyped-def]
        time.sleep(0.005)
        if self.bus_rate is None:
            return None, False
        if self.bitrate != self.bus_rate:
            return can.Message(is_error_frame=True), False
        return can.Message(arbitration_id=0x70A, data=[0x05], is_extended_id=False), False


@pytest.fixture(autouse=True)
def _fresh():
    AdapterAt.opened = []


def test_the_rate_with_valid_frames_is_found_fastest_first_without_transmitting():
    said = []
    rate, heard = find_bitrate(
        CanOptions("pcan", "PCAN_USBBUS1"),
        listen_s=0.05,
        opener=lambda _o, r: AdapterAt(250_000, r),
        progress=said.append,
    )
    assert rate == 250_000
    assert [h.bitrate for h in heard] == [1_000_000, 800_000, 500_000, 250_000]
    assert [o[0] for o in AdapterAt.opened] == list(RATES[:4])
    assert heard[0].frames == 0 and heard[0].error_frames > 0
    assert said[-1].describe().startswith("250 kbit/s: ")
    assert "(node 10), 0 error frames" in said[-1].describe()


@pytest.mark.parametrize(
    ("interface", "argument"),
    [
        ("pcan", {"state": can.BusState.PASSIVE}),
        ("kvaser", {"driver_mode": False}),
        ("vector", {"listen_only": True}),
        ("slcan", {"listen_only": True}),
    ],
)
def test_the_adapter_is_opened_in_its_listen_only_mode(monkeypatch, interface, argument):
    opened = {}

    def bus(**kwargs):
        opened.update(kwargs)
        return AdapterAt(None, kwargs["bitrate"])

    monkeypatch.setattr(can, "Bus", bus)
    open_listen_only(CanOptions(interface, "0"), 125_000)
    assert opened == {"interface": interface, "channel": "0", "bitrate": 125_000, **argument}


def test_an_adapter_without_listen_only_is_never_opened_and_the_user_is_told_what_to_try(
    monkeypatch,
):
    monkeypatch.setattr(can, "Bus", lambda **_kw: pytest.fail("opened"))
    with pytest.raises(NoListenOnlyError) as caught:
        find_bitrate(CanOptions("socketcan", "can0"), listen_s=0.01)
    assert str(caught.value) == (
        "prm9tool cannot find the bit rate on socketcan channel can0: the socketcan interface "
        "has no listen-only mode prm9tool can switch on, and it never transmits at a guessed "
        "rate. Try: set the controller to listen-only yourself and try each rate (sudo ip link "
        "set can0 down; sudo ip link set can0 type can bitrate 500000 listen-only on; sudo ip "
        "link set can0 up; candump can0), or read the rate off the valve: its interface switch "
        "sets it at node-ID switch 2…F (2 = 20 k … 8 = 1 M, manual table 7-17); the delivery "
        "state is 500 kbit/s"
    )


def test_a_silent_bus_says_how_to_make_it_talk():
    with pytest.raises(BitrateNotFoundError) as caught:
        find_bitrate(
            CanOptions("pcan", "x"), listen_s=0.02, opener=lambda _o, r: AdapterAt(None, r)
        )
    assert str(caught.value).startswith(
        "nothing was heard on pcan channel x at any rate (1 Mbit/s, 800 kbit/s, 500 kbit/s, "
        "250 kbit/s, 125 kbit/s, 50 kbit/s, 20 kbit/s; 0.02 s each): the bus is silent. Power "
        "a valve up while listening"
    )
    assert len(AdapterAt.opened) == len(RATES)


def test_only_error_frames_point_at_wiring_and_terminators():
    with pytest.raises(BitrateNotFoundError) as caught:
        find_bitrate(
            CanOptions("pcan", "x"), listen_s=0.02, opener=lambda _o, r: AdapterAt(10_000, r)
        )
    assert "no rate gave valid frames on pcan channel x (" in str(caught.value)
    assert "check the wiring and the terminators (120 Ω at both ends)" in str(caught.value)


def test_find_bitrate_on_the_command_line(monkeypatch, capsys):
    monkeypatch.setattr(can, "Bus", lambda **kw: AdapterAt(500_000, kw["bitrate"]))
    monkeypatch.setattr("prm9tool.device.canlink.bitrate.LISTEN_S", 0.05)
    assert main(["--find-bitrate", "--can-interface", "pcan", "--can-channel", "PCAN_USBBUS1"]) == 0
    out = capsys.readouterr().out.splitlines()
    assert out[0].startswith("listening at 1 Mbit/s: 0 frames, ")
    assert out[-1] == "the bus runs at 500000 bit/s: use --can-bitrate 500000"


def test_find_bitrate_command_line_errors(capsys):
    assert main(["--find-bitrate", "--can-interface", "socketcan", "--can-channel", "can0"]) == 6
    assert "cannot find the bit rate on socketcan channel can0" in capsys.readouterr().err
    assert main(["--find-bitrate", "--can-interface", "pcan", "--can-bitrate", "500000"]) == 2
    assert "--find-bitrate listens at every rate" in capsys.readouterr().err

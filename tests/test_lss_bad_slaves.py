"""The LSS master against slaves that misbehave (issue 29), on raw python-can frames beside
emulated valves at node-ID switch 1: scans are bounded and name what would not stop
answering, answers are recognised by their CiA 305 command specifier, and a failed
assignment leaves the valves as they were."""

from __future__ import annotations

import time
from collections.abc import Iterator
from contextlib import contextmanager

import can
import pytest
from support.bad_node import BadLssSlave, LssFault
from support.lss_rig import make_lss_rig

from prm9tool.cli.main import main
from prm9tool.device.canlink.lss import FASTSCAN_FRAMES, LssAddress, LssMasterLink

ADDRESS_4713 = (0xE6, 0x9, 0x10000, 4713)


@pytest.fixture
def rig(request: pytest.FixtureRequest):
    rig = make_lss_rig(request.node.name)
    yield rig
    rig.close()


@contextmanager
def bad_slave(rig, fault: LssFault, address=ADDRESS_4713) -> Iterator[BadLssSlave]:
    bus = can.Bus(interface="virtual", channel=rig.options.channel)
    slave = BadLssSlave(bus, address, fault).start()
    try:
        yield slave
    finally:
        slave.stop()
        bus.shutdown()


def _cli(rig, *args: str) -> int:
    return main([*args, "--can-interface", "virtual", "--can-channel", rig.options.channel])


@pytest.mark.parametrize("command", [["--lss-scan"], ["--lss-assign", "4711=22"]])
def test_a_slave_acknowledging_everything_ends_the_scan_naming_it(rig, capsys, command):
    valve = rig.add(4711)
    with bad_slave(rig, LssFault.ACKNOWLEDGES_ALL) as slave:
        started = time.monotonic()
        code = _cli(rig, *command)
        took = time.monotonic() - started
    err = capsys.readouterr().err
    assert code != 0 and "Traceback" not in err
    assert "a device acknowledges every LSS request" in err and "stopped the scan" in err
    assert "serial 0\t" not in err
    # the master stops at the second round that finds the same address: two Fastscan rounds,
    # the probe and the switch commands (not a frame count of the time it took: took is only
    # reported when it fails)
    assert slave.requests <= 2 * FASTSCAN_FRAMES + 10, (slave.requests, took)
    assert valve.node_id == 0  # the valve beside it kept what it had


def test_a_correct_slave_beside_stray_lss_frames_is_found(rig):
    rig.add(4711)
    with bad_slave(rig, LssFault.STRAY_FRAMES) as stray:
        found = LssMasterLink(rig.shared).scan()
    assert found == [LssAddress(0xE6, 0x9, 0x10000, 4711)]
    assert stray.requests > 0  # it did hear the scan (and sent its stray frames)


def test_a_random_answer_to_inquire_node_id_fails_the_assignment_saying_nothing_changed(
    rig, capsys
):
    with bad_slave(rig, LssFault.RANDOM_INQUIRE) as slave:
        code = _cli(rig, "--lss-assign", "4713=23")
    err = capsys.readouterr().err
    assert code != 0
    assert "UnboundLocalError" not in err and "Traceback" not in err
    assert "serial 4713" in err and "nothing was changed" in err
    assert slave.configured is False  # released (switch state global: waiting)


def test_a_well_behaved_raw_slave_is_found_and_assigned(rig):
    with bad_slave(rig, LssFault.NONE):
        link = LssMasterLink(rig.shared)
        found = link.scan()
        assert found == [LssAddress(*ADDRESS_4713)]
        link.assign(found[0], 23)


def test_a_slow_device_beside_fast_ones_is_found_without_losing_rounds(rig, monkeypatch):
    """A device answering each request 6 ms late beside three that answer at once: its late
    answer to one Fastscan step came after the next request and was taken as that step's
    answer (a wrong bit, the round lost — and every round after it, the step's wait does not
    help), the way a busy PC delays an emulated valve's answer. The master now listens a
    while longer after an answered step, as long as the probe saw the answers spread."""
    rounds = []
    original = LssMasterLink._fastscan
    monkeypatch.setattr(
        LssMasterLink,
        "_fastscan",
        lambda self, *a: rounds.append(original(self, *a)) or rounds[-1],
    )
    for serial in (4711, 4712):
        rig.add(serial)
    bus = can.Bus(interface="virtual", channel=rig.options.channel)
    slow = BadLssSlave(bus, ADDRESS_4713, delay_s=0.006).start()
    try:
        found = LssMasterLink(rig.shared).scan()
    finally:
        slow.stop()
        bus.shutdown()
    assert sorted(a.serial for a in found) == [4711, 4712, 4713]
    lost = [r for r in rounds if r == (True, None)]
    assert not lost, f"{len(lost)} of {len(rounds)} Fastscan rounds lost"


def test_two_raw_slaves_with_one_address_are_named_and_neither_changed(rig, capsys):
    with bad_slave(rig, LssFault.NONE) as first, bad_slave(rig, LssFault.NONE) as second:
        code = _cli(rig, "--lss-assign", "4713=23")
    err = capsys.readouterr().err
    assert code == 2 and "Traceback" not in err
    assert "2 devices answer with the same LSS address" in err
    assert not first.configured and not second.configured

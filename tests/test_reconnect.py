"""The reconnect loop on its own (service/reconnect.py), with fake listings and a fake clock."""

from __future__ import annotations

from dataclasses import dataclass

import pytest

from prm9tool.service.reconnect import (
    MAX_PAUSE_S,
    MIN_PAUSE_S,
    LostValve,
    Outcome,
    Reconnector,
    choose,
    pause_after,
)

USB = LostValve(4711, "usb:1-2:1.0")
CAN = LostValve(4711, "can:5", ("udp_multicast", "239.0.0.1", 250_000))
EMULATED = LostValve(5001, "emulator:PRM9-06.3Z11/30-24E02S01:5001")


@dataclass(frozen=True)
class Entry:
    device_id: str
    serial: int
    kind: str = "usb"


def test_the_same_serial_is_found_on_another_usb_port():
    outcome, entry = choose(USB, [Entry("usb:1-3:1.0", 4711)])
    assert outcome is Outcome.FOUND and entry == Entry("usb:1-3:1.0", 4711)


def test_over_can_the_serial_finds_the_valve_at_a_new_node_id():
    moved = Entry("can:9", 4711, "can")
    outcome, entry = choose(CAN, [Entry("can:3", 17, "can"), moved])
    assert outcome is Outcome.FOUND and entry is moved


def test_the_old_device_id_wins_when_the_serial_is_listed_twice():
    here, there = Entry("can:5", 4711, "can"), Entry("can:9", 4711, "can")
    assert choose(CAN, [there, here]) == (Outcome.FOUND, here)


def test_another_serial_where_the_valve_was_is_another_valve():
    stranger = Entry("can:5", 99, "can")
    assert choose(CAN, [stranger]) == (Outcome.OTHER, stranger)


def test_a_node_of_another_kind_with_the_serial_is_not_the_valve():
    assert choose(CAN, [Entry("can:9", 4711, "not-prm9")]) == (Outcome.WAIT, None)
    assert choose(USB, []) == (Outcome.WAIT, None)


def test_the_listing_asks_for_the_lost_valve_s_own_link():
    assert USB.emulators == [] and USB.can is None
    assert EMULATED.emulators == ["PRM9-06.3Z11/30-24E02S01:5001"] and EMULATED.can is None
    assert CAN.emulators == []
    assert CAN.can == {"interface": "udp_multicast", "channel": "239.0.0.1", "bitrate": 250_000}


@pytest.mark.parametrize(
    ("listing_s", "pause_s"),
    [(0.0, MIN_PAUSE_S), (0.3, 0.6), (5.0, MAX_PAUSE_S)],
)
def test_the_pause_follows_the_listing_time(listing_s, pause_s):
    assert pause_after(listing_s) == pytest.approx(pause_s)


class FakeClock:
    """Time moves only when the lister says a listing took that long."""

    def __init__(self) -> None:
        self.now = 100.0

    def __call__(self) -> float:
        return self.now


def run_with(listings, lost=USB):
    """Run the loop over ``listings`` (lists of entries, or exceptions); returns what it
    reported and what the lister was asked."""
    clock, asked, reported = FakeClock(), [], []
    queue = list(listings)

    def lister(emulators, can):
        asked.append((list(emulators), can))
        clock.now += 0.1  # each listing takes 0.1 s
        item = queue.pop(0)
        if isinstance(item, Exception):
            raise item
        return item

    loop = Reconnector(
        lost,
        lister,
        lambda s: reported.append(("waiting", round(s, 3))),
        lambda e: reported.append(("found", e)),
        lambda e: reported.append(("other", e)),
        clock=clock,
    )
    loop.stop.wait = lambda timeout: reported.append(("pause", round(timeout, 3)))  # type: ignore[method-assign]
    loop.run()
    return reported, asked, loop


def test_the_loop_waits_through_empty_and_failed_listings_until_the_valve_is_back():
    back = Entry("usb:1-2:1.0", 4711)
    reported, asked, loop = run_with([[], OSError("hidapi gone"), [back]])
    assert reported == [
        ("waiting", 0.1),
        ("pause", MIN_PAUSE_S),  # twice 0.1 s
        ("waiting", 0.2),
        ("pause", MIN_PAUSE_S),
        ("found", back),
    ]
    assert asked == [([], None)] * 3 and loop.attempts == 3


def test_the_loop_ends_at_another_valve_and_asks_the_can_bus():
    stranger = Entry("can:5", 12, "can")
    reported, asked, _ = run_with([[stranger]], CAN)
    assert reported == [("other", stranger)]
    assert asked == [([], CAN.can)]


def test_a_stopped_loop_reports_nothing_more():
    def lister(_emulators, _can):
        loop.stop.set()  # the user went online with another valve meanwhile
        return [Entry("usb:1-2:1.0", 4711)]

    reported: list[object] = []
    loop = Reconnector(USB, lister, reported.append, reported.append, reported.append)
    loop.run()
    assert reported == [] and loop.attempts == 1


def test_the_seconds_count_from_the_loss_when_the_loop_starts_again():
    clock = FakeClock()
    loop = Reconnector(USB, lambda *_: [], print, print, print, clock=clock, since=90.0)
    assert loop.elapsed() == pytest.approx(10.0)


def test_after_a_failed_opening_the_loop_pauses_before_it_lists_again():
    clock, reported = FakeClock(), []
    back = Entry("usb:1-2:1.0", 4711)
    loop = Reconnector(USB, lambda *_: [back], print, reported.append, print, clock=clock,
                       first_pause_s=MAX_PAUSE_S)  # fmt: skip
    loop.stop.wait = lambda timeout: reported.append(("pause", timeout))  # type: ignore[method-assign]
    loop.run()
    assert reported == [("pause", MAX_PAUSE_S), back]

"""The LSS frames on their own, without a bus (canlink/lss_exchange.py): an answer is the
frame on 0x7E4 with the asked command specifier, whatever else arrives there; a request the
bus refuses is said in words; one conversation per bus at a time."""

from __future__ import annotations

from types import SimpleNamespace

import pytest

from prm9tool.device.canlink.lss_errors import LssFailedError
from prm9tool.device.canlink.lss_exchange import LSS_REQUEST, LSS_RESPONSE, LssExchange


class FakeNetwork:
    """Answers each request on 0x7E5 with ``replies`` (frames on 0x7E4), in order."""

    def __init__(self, replies: list[bytes], refuse: Exception | None = None):
        self.replies, self.refuse, self.sent, self.listeners = replies, refuse, [], []

    def subscribe(self, can_id, callback):
        assert can_id == LSS_RESPONSE
        self.listeners.append(callback)

    def unsubscribe(self, can_id, callback):
        self.listeners.remove(callback)

    def send_message(self, can_id, data):
        if self.refuse is not None:
            raise self.refuse
        self.sent.append((can_id, bytes(data)))
        for reply in self.replies:
            for callback in list(self.listeners):
                callback(LSS_RESPONSE, bytearray(reply), 0.0)


def _exchange(network: FakeNetwork) -> LssExchange:
    return LssExchange(SimpleNamespace(network=network))  # type: ignore[arg-type]


def test_the_answer_is_the_frame_with_the_asked_command_specifier():
    inquire = bytes([0x5E]).ljust(8, b"\0")
    other, answer = bytes([0x4F]).ljust(8, b"\0"), bytes([0x5E, 12]).ljust(8, b"\0")
    network = FakeNetwork([other, answer])
    assert _exchange(network).ask(inquire, 0x5E, timeout_s=0.0) == answer
    assert network.sent == [(LSS_REQUEST, inquire)] and network.listeners == []


def test_no_answer_with_that_command_specifier_is_none():
    network = FakeNetwork([bytes([0x4F]).ljust(8, b"\0")])  # another service's answer
    assert _exchange(network).ask(bytes([0x5E]).ljust(8, b"\0"), 0x5E, timeout_s=0.0) is None


def test_a_request_the_bus_refuses_is_said_in_words():
    exchange = _exchange(FakeNetwork([], refuse=OSError("adapter unplugged")))
    with pytest.raises(LssFailedError, match=r"refused to send an LSS request.*unplugged"):
        exchange.switch_global(0)


def test_one_lock_per_bus():
    network = FakeNetwork([])
    assert _exchange(network).lock is _exchange(network).lock
    assert _exchange(network).lock is not _exchange(FakeNetwork([])).lock

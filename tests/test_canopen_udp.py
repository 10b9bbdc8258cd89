"""The served valves' udp_multicast datagrams without can.Message (canopen_udp): the bytes
python-can makes, frames a classical node ignores skipped, other buses left to python-can; and
the per-frame work an RPDO each SYNC no longer causes (docs/PERFORMANCE.md, "The PLC rig")."""

from __future__ import annotations

import can
import can.interfaces.udp_multicast.utils as udp
import pytest

from prm9tool.device.emulator import EmulatedValve, canopen_udp
from prm9tool.device.emulator.objdict import ObjectDictionary

E02 = "PRM9-06.3Z11/30-24E02S02-CA"


def _python_can(can_id: int, data: bytes, **flags: bool) -> bytes:
    return udp.pack_message(can.Message(arbitration_id=can_id, data=data, **flags))


@pytest.mark.parametrize("can_id", [0, 0x7F, 0x80, 0xFF, 0x100, 0x181, 0x20A, 0x5FF, 0x7FF])
@pytest.mark.parametrize("size", range(9))
def test_a_sent_datagram_is_the_bytes_python_can_sends(can_id, size):
    data = bytes(range(0xF0, 0xF0 + size))
    headers: dict[int, bytes] = {}
    expected = _python_can(can_id, data, is_extended_id=False)
    assert canopen_udp.datagram(can_id, data, headers) == expected
    assert canopen_udp.datagram(can_id, data, headers) == expected  # from the cached header


def test_a_received_datagram_decodes_to_id_and_data():
    raw = udp.pack_message(
        can.Message(
            arbitration_id=0x20A, data=b"\x0f\x00\x00\x10", is_extended_id=False, timestamp=12.5
        )
    )
    assert canopen_udp.decode(raw) == (0x20A, b"\x0f\x00\x00\x10")


@pytest.mark.parametrize(
    "flags",
    [
        {"is_extended_id": True},
        {"is_remote_frame": True, "is_extended_id": False},
        {"is_error_frame": True, "is_extended_id": False},
        {"is_fd": True, "is_extended_id": False},
    ],
)
def test_frames_a_classical_node_ignores_are_skipped(flags):
    assert canopen_udp.decode(_python_can(0x20A, b"\x01", **flags)) is None


def test_a_datagram_that_is_no_frame_is_named_and_skipped(caplog):
    assert canopen_udp.decode(b"\x93\x01\x02\x03") is None
    assert "no CAN frame" in caplog.text


def test_another_bus_keeps_python_can():
    bus = can.Bus(interface="virtual", channel="prm9tool-udp-test")
    try:
        assert canopen_udp.sender(bus) is None
        assert canopen_udp.receiver(bus) is None
    finally:
        bus.shutdown()


def test_writing_a_value_again_tells_no_one():
    od = ObjectDictionary(EmulatedValve(E02).variant)
    told: list[str] = []
    od.on_change = told.append
    od.write(0x1017, 0, 100)
    od.write(0x1017, 0, 100)  # an RPDO repeating its setpoint: nothing downstream changes
    od.write(0x1017, 0, 200)
    mnemonic = od.entry(0x1017, 0).mnemonic
    assert told == [mnemonic, mnemonic]


def test_an_rpdo_repeating_its_setpoint_leaves_the_loop_inputs_as_they_are():
    """The control word goes to the state machine and a repeated setpoint changes nothing:
    neither rebuilds the loop's inputs (which cost more than the whole frame did)."""
    valve = EmulatedValve(E02)
    valve.advance(2.0)
    fw = valve.firmware
    valve.write_bytes(0x6300, 1, b"\x00\x10")
    fw.flush()
    version = fw.loop.inputs_version
    for _ in range(3):
        valve.write_bytes(0x6040, 0, b"\x0f\x00")
        valve.write_bytes(0x6300, 1, b"\x00\x10")
        fw.flush()
    assert fw.loop.inputs_version == version
    valve.write_bytes(0x6300, 1, b"\x00\x20")  # a new setpoint does
    fw.flush()
    assert fw.loop.inputs_version > version


class _Wrapper:
    """python-can's socket wrapper as :func:`canopen_udp.receiver` uses it, over a socket
    pair: ``recv`` (python-can's ``select`` and read) is counted."""

    timestamp_nanosecond = True
    max_buffer = 4096
    received_ancillary_buffer_size = 64
    received_timestamp_struct = "@ll"

    def __init__(self, sock):
        self._socket = sock
        self.recv_calls: list[float | None] = []

    def recv(self, timeout):
        self.recv_calls.append(timeout)


@pytest.mark.skipif(not hasattr(__import__("socket"), "MSG_DONTWAIT"), reason="POSIX only")
def test_no_wait_asked_and_nothing_queued_returns_without_select(monkeypatch):
    import socket

    mine, _other = socket.socketpair(socket.AF_UNIX, socket.SOCK_DGRAM)
    wrapper = _Wrapper(mine)
    monkeypatch.setattr(canopen_udp, "_socket_wrapper", lambda bus: wrapper)
    receive = canopen_udp.receiver(object())  # type: ignore[arg-type]
    assert receive is not None
    try:
        assert receive(0.0) is None
        assert wrapper.recv_calls == []  # one system call, not a select after it
        assert receive(0.01) is None
        assert wrapper.recv_calls == [0.01]  # a wait asked: python-can's select waits
    finally:
        mine.close()
        _other.close()

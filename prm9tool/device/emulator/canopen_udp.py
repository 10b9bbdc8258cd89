"""python-can's udp_multicast datagrams without ``can.Message`` objects, for the served valves.

A datagram of python-can's ``udp_multicast`` interface is a msgpack map of a message's eleven
fields (``can.interfaces.udp_multicast.utils.pack_message``). Per frame, building a
``can.Message`` (its checks), the dict and the map, and back on reception, cost more than the
emulated valve's own SYNC and RPDO handling (docs/PERFORMANCE.md, "The PLC rig"). Here:

- :func:`sender` sends a classical frame as the bytes ``pack_message`` would make of
  ``can.Message(arbitration_id=…, data=…, is_extended_id=False)``: a header per CAN-ID made
  once, then the data length and the data (bit-identical: tests/test_canopen_udp.py);
- :func:`receiver` takes a datagram off the socket with its kernel time stamp, as the bus
  does, and decodes it with msgpack's C unpacker to ``(can_id, data, timestamp)``, skipping
  frames a classical CAN node ignores (extended, remote, error, CAN FD). A datagram already
  queued is taken without ``select`` first (``MSG_DONTWAIT``, where the socket gives time
  stamps in nanoseconds: Linux): 2.1 against 3.9 µs a datagram, 17 of them a millisecond at
  16 valves.

Both reach python-can's socket wrapper (``bus._multicast``, python-can ≥ 4.4); on any other bus,
or a bus with receive filters, they return None and the caller keeps ``bus.send``/``bus.recv``.
"""

from __future__ import annotations

import contextlib
import logging
import socket
import struct
import sys
from collections.abc import Callable

import can
import msgpack

log = logging.getLogger(__name__)

Frame = tuple[int, bytes, float]  # CAN-ID, data, reception time stamp (s, time.time's epoch)
Send = Callable[[int, bytes], None]
Receive = Callable[[float | None], Frame | None]  # None: nothing arrived within the timeout
_IGNORED = ("is_extended_id", "is_remote_frame", "is_error_frame", "is_fd")
_unpack = msgpack.unpackb


def _pack(value: object) -> bytes:
    return msgpack.packb(value, use_bin_type=True)  # type: ignore[no-any-return]


def _after(key: str, value: object) -> bytes:
    return _pack(key) + _pack(value)


# the fields after "dlc", in pack_message's order: data, then three flags
_DATA_KEY = _pack("data")
_TAIL = _after("is_fd", False) + _after("bitrate_switch", False)
_TAIL += _after("error_state_indicator", False)


def _header(can_id: int) -> bytes:
    """The map's fields up to the value of "dlc" for a classical data frame from this node."""
    head = b"\x8b" + _after("timestamp", 0.0) + _after("arbitration_id", can_id)
    for key, value in (("is_extended_id", False), ("is_remote_frame", False)):
        head += _after(key, value)
    return head + _after("is_error_frame", False) + _after("channel", None) + _pack("dlc")


def datagram(can_id: int, data: bytes, headers: dict[int, bytes] | None = None) -> bytes:
    """What python-can's udp_multicast sends for a classical data frame (0…8 bytes)."""
    head = headers.get(can_id) if headers is not None else None
    if head is None:
        head = _header(can_id)
        if headers is not None:
            headers[can_id] = head
    size = len(data)
    return b"".join((head, bytes((size, *_DATA_KEY, 0xC4, size)), data, _TAIL))


def decode(raw: bytes) -> tuple[int, bytes] | None:
    """``(can_id, data)`` of a datagram, or None for one a classical CAN node ignores
    (extended, remote, error or CAN FD frame) or that is no python-can frame (logged)."""
    try:
        fields = _unpack(raw, raw=False)
        can_id, data = int(fields["arbitration_id"]), bytes(fields["data"])
        ignored = any(fields.get(flag) for flag in _IGNORED)
    except Exception as exc:  # not a python-can datagram: named, not fatal
        log.warning("a datagram on the CAN group that is no CAN frame: %s", exc)
        return None
    if ignored or not 0 <= can_id <= 0x7FF or len(data) > 8:
        return None
    return can_id, data


def _socket_wrapper(bus: can.BusABC) -> object | None:
    try:
        from can.interfaces.udp_multicast import UdpMulticastBus
    except ImportError:  # pragma: no cover - python-can without the interface
        return None
    if not isinstance(bus, UdpMulticastBus):
        return None
    wrapper = getattr(bus, "_multicast", None)
    if not (callable(getattr(wrapper, "send", None)) and callable(getattr(wrapper, "recv", None))):
        return None
    return wrapper


def sender(bus: can.BusABC) -> Send | None:
    """A function sending ``(can_id, data)`` as a classical frame on ``bus``, or None when the
    bus is not python-can's udp_multicast (then ``bus.send`` it is)."""
    wrapper = _socket_wrapper(bus)
    if wrapper is None:
        return None
    send = wrapper.send  # type: ignore[attr-defined]
    headers: dict[int, bytes] = {}

    def send_frame(can_id: int, data: bytes) -> None:
        try:
            send(datagram(can_id, data, headers), None)
        except can.CanError:
            raise
        except OSError as exc:
            raise can.CanOperationError(f"failed to send via socket: {exc}") from exc

    return send_frame


def receiver(bus: can.BusABC) -> Receive | None:
    """A function returning the next classical frame on ``bus`` (None on timeout), or None
    when the bus is not python-can's udp_multicast or filters its frames."""
    wrapper = _socket_wrapper(bus)
    if wrapper is None or getattr(bus, "filters", None):
        return None
    recv = wrapper.recv  # type: ignore[attr-defined]
    take = _queued(wrapper)

    def receive(timeout: float | None) -> Frame | None:
        while True:
            queued = take() if take is not None else None
            if queued is None:
                if take is not None and timeout == 0.0:
                    return None  # nothing queued, and no wait asked: no select after it
                result = recv(timeout)
                if not result:
                    return None
                raw, _, timestamp = result
            else:
                raw, timestamp = queued
            timeout = 0.0  # after a datagram that is no frame for a classical node: the next
            frame = decode(raw)
            if frame is not None:
                return frame[0], frame[1], timestamp

    return receive


def _queued(wrapper: object) -> Callable[[], tuple[bytes, float] | None] | None:
    """A function taking the next datagram already queued at python-can's socket with its
    kernel time stamp (None when none is), as ``wrapper.recv`` would after its ``select``; or
    None where the socket gives no time stamps in nanoseconds (python-can's own path then)."""
    sock = getattr(wrapper, "_socket", None)
    dontwait = getattr(socket, "MSG_DONTWAIT", 0)
    if not (
        isinstance(sock, socket.socket)
        and dontwait
        and getattr(wrapper, "timestamp_nanosecond", False)
    ):
        return None
    try:
        from can.interfaces.udp_multicast.bus import SO_TIMESTAMPNS
    except ImportError:  # pragma: no cover - python-can without the constant
        return None
    size = int(getattr(wrapper, "max_buffer", 0))
    ancillary = int(getattr(wrapper, "received_ancillary_buffer_size", 0))
    stamp = struct.Struct(str(getattr(wrapper, "received_timestamp_struct", "@ll"))).unpack
    if not size or not ancillary:
        return None

    def take() -> tuple[bytes, float] | None:
        try:
            raw, control, _, _ = sock.recvmsg(size, ancillary, dontwait)
        except (BlockingIOError, InterruptedError):
            return None
        except OSError as exc:
            raise can.CanOperationError(f"Failed to receive from IP/UDP socket: {exc}") from exc
        if len(control) != 1 or control[0][:2] != (socket.SOL_SOCKET, SO_TIMESTAMPNS):
            raise can.CanOperationError("received control message type that was not requested")
        seconds, nanoseconds = stamp(control[0][2])
        if nanoseconds >= 1e9:
            raise can.CanOperationError(
                f"Timestamp nanoseconds field was out of range: {nanoseconds}"
            )
        return raw, seconds + nanoseconds * 1.0e-9

    return take


# --- a kernel filter: only the CAN-IDs someone here takes ---------------------------------
SO_ATTACH_FILTER, SO_DETACH_FILTER = 26, 27  # Linux <asm-generic/socket.h>
MAX_FILTERED_IDS = 200  # a BPF jump reaches 255 instructions on: more IDs, no filter
_UDP_HEADER = 8  # a UDP socket's filter sees the datagram from its UDP header on
_ACCEPT, _DROP = 0xFFFFFFFF, 0
_LD_B, _LD_H, _JEQ, _JGE, _JA, _RET = 0x30, 0x28, 0x15, 0x35, 0x05, 0x06
# pack_message's map: 0x8b, "timestamp" (0xa9 + 9), a float64 (0xcb + 8), "arbitration_id"
# (0xae + 14), then the ID: a positive fixint, 0xcc + 1 byte or 0xcd + 2 bytes (big-endian)
_LAYOUT = ((0, 0x8B), (1, 0xA9), (11, 0xCB), (20, 0xAE))
_ID_AT = 35


def id_filter(can_ids: frozenset[int] | set[int]) -> list[tuple[int, int, int, int]]:
    """A classic BPF program for a UDP socket on python-can's udp_multicast group: a datagram
    laid out as ``pack_message`` lays out a classical frame passes only if its CAN-ID is one of
    ``can_ids``; any other datagram passes (decoded and judged as before). Instructions as
    ``(code, jt, jf, k)``."""
    ids = sorted(can_ids)
    program: list[tuple[int, int, int, int]] = []
    for offset, byte in _LAYOUT:  # not laid out so: accept (jump to the last instruction)
        program += [(_LD_B, 0, 0, _UDP_HEADER + offset), (_JEQ, 0, 0xFF, byte)]
    program += [
        (_LD_B, 0, 0, _UDP_HEADER + _ID_AT),
        (_JGE, 1, 0, 0x80),  # a positive fixint is the ID itself
        (_JA, 0, 0, 5),  # -> compare
        (_JEQ, 0, 2, 0xCC),
        (_LD_B, 0, 0, _UDP_HEADER + _ID_AT + 1),
        (_JA, 0, 0, 2),  # -> compare
        (_JEQ, 0, 0xFF, 0xCD),
        (_LD_H, 0, 0, _UDP_HEADER + _ID_AT + 1),
    ]
    for k, can_id in enumerate(ids):  # compare: a taken ID jumps to accept
        program.append((_JEQ, len(ids) - k, 0, can_id))
    program.append((_RET, 0, 0, _DROP))
    program.append((_RET, 0, 0, _ACCEPT))
    last = len(program) - 1
    return [  # 0xFF: "to accept", resolved now that its place is known
        (code, jt, last - i - 1 if jf == 0xFF else jf, k)
        for i, (code, jt, jf, k) in enumerate(program)
    ]


def filter_ids(fd: int, can_ids: frozenset[int] | set[int]) -> bool:
    """Let only datagrams of ``can_ids`` (and any that are not python-can's classical frames)
    reach the socket ``fd`` (:func:`id_filter`); False where the system has no such filter
    (then every datagram arrives, as without it)."""
    import ctypes

    if not sys.platform.startswith("linux"):  # the option numbers are Linux's own
        return False
    try:
        sock = socket.socket(fileno=socket.dup(fd))
    except OSError:
        return False
    try:
        if len(can_ids) > MAX_FILTERED_IDS:
            _detach(sock)
            return False
        program = id_filter(can_ids)
        code = b"".join(struct.pack("HBBI", *instruction) for instruction in program)
        buffer = ctypes.create_string_buffer(code, len(code))
        fprog = struct.pack("HP", len(program), ctypes.addressof(buffer))
        sock.setsockopt(socket.SOL_SOCKET, SO_ATTACH_FILTER, fprog)
        return True
    except OSError as exc:
        log.info("no CAN-ID filter on the CAN socket: %s", exc)
        _detach(sock)
        return False
    finally:
        sock.close()


def _detach(sock: socket.socket) -> None:
    """No filter on the socket (any before is removed: every datagram arrives)."""
    with contextlib.suppress(OSError):  # none was attached
        sock.setsockopt(socket.SOL_SOCKET, SO_DETACH_FILTER, 0)

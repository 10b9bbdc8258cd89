"""The LSS frames on one CAN bus (CiA 305): requests on 0x7E5, answers on 0x7E4 taken by their
command specifier — a frame there with another first byte is no answer (``canopen``'s
LssMaster took the first frame, whatever it was) — and one LSS conversation at a time per bus,
as LSS requests carry no address. The services built on it (Fastscan, selection,
configuration, bit timing) are :class:`prm9tool.device.canlink.lss.LssMasterLink`'s.
"""

from __future__ import annotations

import struct
import threading
import time
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from typing import TYPE_CHECKING

from prm9tool.device.canlink.lss_errors import LssFailedError

if TYPE_CHECKING:
    from prm9tool.device.canlink.bus import CanNetwork

LSS_REQUEST, LSS_RESPONSE = 0x7E5, 0x7E4
ANSWER_S = 0.5  # inquire, configure, store (what canopen's LssMaster waits)
SETTLE_MIN_S = 0.1  # further answers to a request several devices may answer


@dataclass
class Heard:
    """The LSS answers (COB-ID 0x7E4) since :meth:`LssExchange.listen` started."""

    frames: list[tuple[float, bytes]]

    def count(self, cs: int) -> int:
        """How many answers ``cs`` came."""
        return sum(1 for _, data in self.frames if data and data[0] == cs)

    def last(self, cs: int) -> bytes | None:
        """The last answer ``cs`` (None: none came)."""
        return next((data for _, data in reversed(self.frames) if data and data[0] == cs), None)

    def wait(self, cs: int, since: int, timeout_s: float) -> bytes | None:
        """The first answer ``cs`` among the frames from number ``since`` on, waiting up to
        ``timeout_s`` for it (frames with another command specifier are no answer)."""
        deadline = time.monotonic() + timeout_s
        while True:
            found = next((d for _, d in self.frames[since:] if d and d[0] == cs), None)
            if found is not None or time.monotonic() >= deadline:
                return found
            time.sleep(0.001)


_LOCKS: dict[int, threading.Lock] = {}
_LOCKS_LOCK = threading.Lock()


def bus_lock(shared: CanNetwork) -> threading.Lock:
    """One LSS conversation at a time per bus (LSS requests carry no address)."""
    with _LOCKS_LOCK:
        return _LOCKS.setdefault(id(shared.network), threading.Lock())


class LssExchange:
    """Requests and their answers on the bus ``shared``; :attr:`lock` is held for one
    conversation (a scan, an assignment)."""

    def __init__(self, shared: CanNetwork) -> None:
        self._shared = shared
        self.lock = bus_lock(shared)

    def ask(self, request: bytes, cs: int, timeout_s: float = ANSWER_S) -> bytes | None:
        """Send an LSS request, return its answer ``cs`` (None: none came in ``timeout_s``)."""
        with self.listen() as heard:
            self.send(request)
            return heard.wait(cs, 0, timeout_s)

    def activate(self, switch_delay_ms: int) -> None:
        """Activate bit timing (0x15) after ``switch_delay_ms`` (no answer)."""
        self.send(struct.pack("<BH5x", 0x15, switch_delay_ms))

    def switch_global(self, mode: int) -> None:
        """Switch state global (no answer)."""
        self.send(bytes([0x04, mode]).ljust(8, b"\0"))

    def send(self, request: bytes) -> None:
        """One LSS request on 0x7E5; LssFailedError ``lost`` when the bus refuses it."""
        import can

        try:
            self._shared.network.send_message(LSS_REQUEST, request)
        except (can.CanError, OSError, RuntimeError) as exc:  # RuntimeError: bus closed
            raise LssFailedError(
                f"the CAN bus refused to send an LSS request ({exc}); the devices keep what "
                "they had stored",
                "lost",
            ) from None

    @contextmanager
    def listen(self) -> Iterator[Heard]:
        """The answers on 0x7E4 while the block runs (from the bus's receive thread)."""
        heard = Heard([])

        def on_answer(can_id: int, data: bytearray, timestamp: float) -> None:
            heard.frames.append((time.monotonic(), bytes(data)))

        network = self._shared.network
        network.subscribe(LSS_RESPONSE, on_answer)
        try:
            yield heard
        finally:
            network.unsubscribe(LSS_RESPONSE, on_answer)


def settle(heard: Heard, cs: int, sent: float) -> None:
    """Wait for further answers ``cs`` to a request sent at ``sent`` (several devices may
    answer): until none came for ten times the first answer's delay (at least 0.1 s)."""
    times = [t for t, d in heard.frames if d and d[0] == cs]
    quiet = max(10 * (times[0] - sent), SETTLE_MIN_S) if times else SETTLE_MIN_S
    while True:
        times = [t for t, d in heard.frames if d and d[0] == cs]
        last = times[-1] if times else sent
        left = last + quiet - time.monotonic()
        if left <= 0:
            return
        time.sleep(min(left, 0.01))

"""The emulator backend: the same 64-byte reports, handed to an emulated valve's USB firmware.

The link is modelled like USB full speed: at most one report per millisecond in each
direction, an answer at the earliest one frame after its request. The link has its own clock:
``paced=True`` keeps it on the wall clock (each report really takes its frame), ``paced=False``
lets it run as fast as the host asks (tests, tools), so a wait costs no real time. Unless the
valve runs its own real-time thread (the GUI), the transport steps the valve's simulation
deterministically to the link clock. :class:`LinkFaults` injects what real cables do: a link
that dies after report N, and lost, duplicated or late reports.
"""

from __future__ import annotations

import heapq
import time
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from prm9tool.device.emulator.usb_firmware import UsbFirmware
from prm9tool.device.usb.transport.base import Transport
from prm9tool.errors import DeviceDisconnectedError

if TYPE_CHECKING:
    from prm9tool.device.emulator import EmulatedValve

SLOT_S = 0.001  # one USB full-speed frame


@dataclass(frozen=True)
class LinkFaults:
    """Faults of the emulated cable; reports are numbered from 1 in the order they are sent,
    requests and answers alike.

    ``die_after``: the link dies after that many reports (``0``: before the first one).
    ``drop``: reports that are lost. ``duplicate``: reports delivered twice. ``late``: extra
    delay in seconds per report number.
    """

    die_after: int | None = None
    drop: frozenset[int] = frozenset()
    duplicate: frozenset[int] = frozenset()
    late: Mapping[int, float] = field(default_factory=dict)


class EmulatorTransport(Transport):
    """A link to an :class:`EmulatedValve` in this process."""

    def __init__(
        self,
        valve: EmulatedValve,
        *,
        paced: bool = False,
        faults: LinkFaults | None = None,
        timeout_s: float = 0.25,
        retries: int = 3,
    ) -> None:
        super().__init__(timeout_s=timeout_s, retries=retries, name=f"emulator:{valve.serial}")
        self.valve = valve
        self.paced = paced
        self.faults = faults or LinkFaults()
        self.firmware = UsbFirmware.of(valve)
        self.firmware.outbox.clear()
        self._clock = 0.0  # link time: seconds since the transport opened
        self._wall0 = time.monotonic()
        self._stepped_to = 0.0  # link time the valve's simulation has been advanced to
        self._valve_seen = valve.time  # valve time after our last step (detects outside steps)
        self._next_out = 0.0
        self._next_in = 0.0
        self._number = 0
        self._dead = False
        self._inbox: list[tuple[float, int, bytes]] = []

    # --- hooks ---------------------------------------------------------------------------
    def _now(self) -> float:
        if self.paced:
            return time.monotonic() - self._wall0
        self._follow_valve()
        return self._clock

    def _follow_valve(self) -> None:
        """A test or tool stepped the valve itself: the unpaced link clock moves along."""
        moved = self.valve.time - self._valve_seen
        if moved > 0:
            self._clock += moved
            self._stepped_to += moved
        self._valve_seen = self.valve.time

    def _write(self, report: bytes) -> None:
        number = self._take_number()
        if number is None:
            raise DeviceDisconnectedError(f"{self.name}: the USB link is down")
        sent = max(self._now(), self._next_out)
        self._next_out = sent + SLOT_S
        self._wait_until(sent)
        if number in self.faults.drop:
            return
        with self.valve.lock:  # what the firmware sent before this request precedes its answer
            self._collect_stream()
            for _ in range(2 if number in self.faults.duplicate else 1):
                self._queue(sent + SLOT_S, self.firmware.handle(report))

    def _read(self, timeout_s: float) -> bytes | None:
        deadline = self._now() + timeout_s
        while True:
            self._collect_stream()
            if self._inbox and self._inbox[0][0] <= self._now():
                return heapq.heappop(self._inbox)[2]
            if self._dead and not self._inbox:
                raise DeviceDisconnectedError(f"{self.name}: the USB link is down")
            if self._now() >= deadline:
                return None
            target = min(deadline, self._inbox[0][0]) if self._inbox else deadline
            if self.firmware.streaming and not self._inbox:
                target = min(target, self._now() + SLOT_S)
            self._wait_until(target)

    def _close(self) -> None:
        self._inbox.clear()

    # --- the link model ------------------------------------------------------------------
    def _take_number(self) -> int | None:
        if self._dead:
            return None
        self._number += 1
        if self.faults.die_after is not None and self._number > self.faults.die_after:
            self._dead = True
            return None
        return self._number

    def _queue(self, earliest: float, report: bytes) -> None:
        number = self._take_number()
        if number is None or number in self.faults.drop:
            return
        ready = max(earliest, self._next_in)
        self._next_in = ready + SLOT_S
        ready += self.faults.late.get(number, 0.0)
        copies = 2 if number in self.faults.duplicate else 1
        for copy in range(copies):
            heapq.heappush(self._inbox, (ready + copy * SLOT_S, number, report))

    def _collect_stream(self) -> None:
        outbox = self.firmware.outbox
        if not outbox:
            return
        now, valve_now = self._now(), self.valve.time
        while outbox:
            sim_time, report = outbox.popleft()
            self._queue(now - max(0.0, valve_now - sim_time), report)

    def _wait_until(self, moment: float) -> None:
        if self.paced:
            while (remaining := moment - self._now()) > 0:
                time.sleep(remaining)  # one wake-up per wait (the GIL is free meanwhile)
        self._clock = max(self._clock, moment)
        if self.valve.running:  # the valve's own real-time thread moves the simulation
            self._stepped_to = self._clock
        elif self._clock > self._stepped_to:
            self.valve.advance(self._clock - self._stepped_to)
            self._stepped_to = self._clock
            self._valve_seen = self.valve.time

    def unplug(self) -> None:
        """Pull the cable: every report from now on fails, as on a real unplugged valve."""
        self._dead = True
        self._inbox.clear()

    @property
    def reports_on_link(self) -> int:
        """Reports put on the link so far, both directions (the numbering of LinkFaults)."""
        return self._number

    @property
    def link_time(self) -> float:
        """Seconds of link time elapsed (simulated when unpaced)."""
        return self._now()

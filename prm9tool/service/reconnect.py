"""Finding a lost valve again: the reconnect loop of the connection (no Qt, no device layer).

When the link to a valve breaks (a pulled USB cable, a power cycle, a CAN bus-off, a restart
that did not come back), the connection starts a :class:`Reconnector` in a thread of its own.
It lists the valves again and again — on the lost valve's own link: the same USB/emulated
valve, or the same CAN bus — and decides with :func:`choose`:

- the same serial number is listed (over CAN also at another node ID: the serial of 0x1018/4
  says it is the same valve) → ``Found``: the connection opens it and compares, it writes
  nothing by itself;
- another serial number sits where the lost valve was (the same device ID) → ``Other``: a new
  valve, which the user connects to explicitly; the loop ends;
- nothing → it waits and tries again.

The pause between attempts is derived from how long the last listing took (twice that, at
least :data:`MIN_PAUSE_S`, at most :data:`MAX_PAUSE_S`): a slow bus scan is not hammered and a
quick USB enumeration finds a replugged valve within a second. The loop runs until it finds
something or ``stop`` is set (the user goes online or offline himself, the program ends).
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from enum import Enum
from typing import Protocol

MIN_PAUSE_S = 0.2
MAX_PAUSE_S = 1.0
OPENABLE = ("usb", "emulator", "can")  # listed kinds a session can be opened to


class Listed(Protocol):
    """What the loop reads of a listed valve (``DeviceEntry``)."""

    @property
    def device_id(self) -> str:
        """``usb:…``, ``emulator:TYPE:SERIAL`` or ``can:NODE``."""

    @property
    def serial(self) -> int:
        """The valve's serial number (over CAN: 0x1018/4)."""

    @property
    def kind(self) -> str:
        """``usb``, ``emulator``, ``can``, ``not-prm9``, …"""


@dataclass(frozen=True)
class LostValve:
    """Who the lost valve was: its serial number, device ID and (over CAN) its bus
    (interface, channel, bit rate)."""

    serial: int
    device_id: str
    can_bus: tuple[str, str, int | None] | None = None

    @property
    def emulators(self) -> list[str]:
        """The ``--emulator`` spec to list an emulated valve again (``TYPE:SERIAL``)."""
        kind, _, rest = self.device_id.partition(":")
        return [rest] if kind == "emulator" else []

    @property
    def can(self) -> dict[str, object] | None:
        """The CAN bus to scan for a valve lost over CAN (None for USB and emulated valves)."""
        if not self.device_id.startswith("can:") or self.can_bus is None:
            return None
        interface, channel, bitrate = self.can_bus
        return {"interface": interface, "channel": channel, "bitrate": bitrate}


class Outcome(Enum):
    """What one listing says about the lost valve."""

    WAIT = "wait"  # not there (yet)
    FOUND = "found"  # the same serial number: open it
    OTHER = "other"  # another valve where the lost one was


def choose(lost: LostValve, entries: Sequence[Listed]) -> tuple[Outcome, Listed | None]:
    """The lost valve among ``entries``: the same serial number (at its old device ID if it
    is listed twice), else another valve at its old device ID, else nothing."""
    openable = [e for e in entries if e.kind in OPENABLE]
    same = [e for e in openable if e.serial == lost.serial]
    if same:
        same.sort(key=lambda e: e.device_id != lost.device_id)
        return Outcome.FOUND, same[0]
    other = [e for e in entries if e.device_id == lost.device_id]
    if other:
        return Outcome.OTHER, other[0]
    return Outcome.WAIT, None


def pause_after(listing_s: float) -> float:
    """Seconds to wait after a listing that took ``listing_s``."""
    return min(MAX_PAUSE_S, max(MIN_PAUSE_S, 2.0 * listing_s))


Lister = Callable[[Sequence[str], Mapping[str, object] | None], Sequence[Listed]]


class Reconnector:
    """The loop: ``lister(emulators, can)`` until :func:`choose` decides; ``waiting(seconds)``
    after every unsuccessful attempt (seconds since the valve was lost), then ``found(entry)``
    or ``other(entry)``. All three run in the loop's thread."""

    def __init__(
        self,
        lost: LostValve,
        lister: Lister,
        waiting: Callable[[float], None],
        found: Callable[[Listed], None],
        other: Callable[[Listed], None],
        clock: Callable[[], float] = time.monotonic,
        since: float | None = None,
        first_pause_s: float = 0.0,
    ) -> None:
        """``since``: when the valve was lost (``clock`` time; default: now); ``first_pause_s``:
        wait this long before the first listing (after a found valve failed to open)."""
        self.lost = lost
        self.stop = threading.Event()  # set: the loop ends at its next step
        self._lister = lister
        self._waiting, self._found, self._other = waiting, found, other
        self._clock = clock
        self.since = clock() if since is None else since
        self._thread: threading.Thread | None = None
        self.attempts = 0
        self._first_pause_s = first_pause_s

    def elapsed(self) -> float:
        """Seconds since the valve was lost."""
        return self._clock() - self.since

    def start(self) -> None:
        """Run the loop in a thread of its own."""
        self._thread = threading.Thread(target=self.run, name="valve-reconnect", daemon=True)
        self._thread.start()

    def join(self, timeout_s: float) -> None:
        """Stop the loop and wait up to ``timeout_s`` for its thread."""
        self.stop.set()
        if self._thread is not None and self._thread is not threading.current_thread():
            self._thread.join(timeout_s)

    def run(self) -> None:
        """The loop itself (also callable directly, in tests)."""
        if self._first_pause_s:
            self.stop.wait(self._first_pause_s)
        while not self.stop.is_set():
            began = self._clock()
            outcome, entry = self.attempt()
            if self.stop.is_set():
                return
            if outcome is Outcome.FOUND and entry is not None:
                self._found(entry)
                return
            if outcome is Outcome.OTHER and entry is not None:
                self._other(entry)
                return
            self._waiting(self.elapsed())
            self.stop.wait(pause_after(self._clock() - began))

    def attempt(self) -> tuple[Outcome, Listed | None]:
        """One listing and its decision; a listing that fails counts as nothing found (the
        USB stack or the CAN adapter may be gone with the valve)."""
        self.attempts += 1
        try:
            entries = self._lister(self.lost.emulators, self.lost.can)
        except Exception:  # the adapter is away too: try again later
            return Outcome.WAIT, None
        return choose(self.lost, entries)

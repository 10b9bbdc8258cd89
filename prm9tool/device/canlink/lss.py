"""LSS master (CiA 305): finding devices without a node ID and giving them one.

The master sends the CiA 305 requests itself on 0x7E5 and reads the answers on 0x7E4 (the
``canopen`` package's LssMaster took the first frame there as the answer and ran Fastscan
without bounds, see below): switch state global and selective, Fastscan, inquire, configure
node ID and bit timing, activate bit timing, store configuration. A commissioning tool needs
on top: every unconfigured device rather than the first (each one Fastscan finds stays in the
configuration state, so the next Fastscan finds the next), two devices with the same LSS
address detected (both answer the selective switch), every CiA 305 error answer turned into
a sentence, and an assignment that either stores node ID and bit timing together or leaves
the device as it was.

Timing is derived, not guessed: "identify non-configured remote slave" (answered by every
device without a node ID) tells at once whether Fastscan will find anything and how long an
answer takes on this bus; each Fastscan step waits ten times that (at least 50 ms). A step
whose answer came too late makes the scan miss the device (its final check fails, never a
wrong address); the scan then runs again with twice the wait. An answered step waits a little
more (three times the spread of the devices' answers to the probe, at least twice its
latency) before the next request, so that another device's answer to it is not taken as the
next step's (on a virtual bus each device's answer arrives; on a real bus identical answers
merge into one frame, but a slow device's comes late there too).

**Answers by their command specifier, scans bounded.** The master sends the Fastscan, the
selective switch, inquire, configure and store requests itself and takes as the answer only a
frame on 0x7E4 whose first byte is the CiA 305 command specifier of that answer: any other
frame there is no answer (``canopen``'s LssMaster takes the first frame, whatever it is). A
Fastscan round sends at most :data:`FASTSCAN_FRAMES` requests; a scan ends after
:data:`MAX_DEVICES` devices, when a round finds an address found before (a device that
acknowledges every request: each round "finds" it again) or after :data:`SCAN_LIMIT_S`,
saying which. The frames themselves — requests, answers by their command specifier, one
conversation per bus at a time — are :mod:`prm9tool.device.canlink.lss_exchange`.
"""

from __future__ import annotations

import struct
import time
from collections.abc import Callable
from typing import TYPE_CHECKING

from prm9tool.catalogue.canopen_switches import LSS_UNCONFIGURED
from prm9tool.device.canlink.lss_address import LssAddress
from prm9tool.device.canlink.lss_errors import (
    CS_CONFIGURE_BIT_TIMING,
    CS_CONFIGURE_NODE_ID,
    CS_STORE,
    ERRORS,
    SERVICE,
    LssFailedError,
    kbit,
    service_problem,
)
from prm9tool.device.canlink.lss_exchange import ANSWER_S, LssExchange, settle

if TYPE_CHECKING:
    from prm9tool.device.canlink.bus import CanNetwork

CS_SELECTIVE_RESPONSE, CS_IDENTIFY_SLAVE, CS_NON_CONFIGURED_SLAVE = 0x44, 0x4F, 0x50
CS_SELECTIVE = (0x40, 0x41, 0x42, 0x43)  # vendor, product, revision, serial
CS_FASTSCAN, CS_INQUIRE_NODE_ID = 0x51, 0x5E
CS_INQUIRE = (0x5A, 0x5B, 0x5C, 0x5D)  # vendor, product, revision, serial
WAITING, CONFIGURATION = 0, 1
ERROR_NONE = 0
PROBE_WAIT_S = 0.5  # how long "identify non-configured" waits for a first answer (canopen's)
PROBE_MORE_S = 0.02  # and at least this long after it for the other devices' answers
MIN_STEP_S, MAX_STEP_S = 0.05, 0.8
MIN_SETTLE_S = 0.002  # the least wait for further answers to an answered Fastscan step
SCAN_ATTEMPTS = 4
MAX_DEVICES = 127
FASTSCAN_FRAMES = 1 + 4 * 33  # a round: the reset step, 32 bits and a confirmation per part
SCAN_LIMIT_S = 120.0  # a whole scan (127 devices at the slowest step would take far longer)


class LssMasterLink:
    """LSS services on one shared bus, their frames exchanged through the part it holds
    (:class:`~prm9tool.device.canlink.lss_exchange.LssExchange`)."""

    def __init__(self, shared: CanNetwork) -> None:
        self._frames = LssExchange(shared)
        self._lock = self._frames.lock
        self.latency_s: float | None = None  # the first answer to the last probe
        self.spread_s = 0.0  # from its first answer to its last (several devices)

    # --- finding devices ---------------------------------------------------------------
    def scan(self, progress: Callable[[LssAddress], None] | None = None) -> list[LssAddress]:
        """Every device without a node ID, by Fastscan; [] when there is none.

        LssFailedError ``duplicate`` when two devices answer with one address (neither changed).
        """
        with self._lock:
            self._frames.switch_global(WAITING)
            try:
                found = self._fastscan_all(progress)
            finally:
                self._frames.switch_global(WAITING)
            for address in found:
                self._check_unique(address)
            return found

    def _fastscan_all(self, progress: Callable[[LssAddress], None] | None) -> list[LssAddress]:
        found: list[LssAddress] = []
        latency = self._probe()
        if latency is None:
            return found
        step = min(max(10 * latency, MIN_STEP_S), MAX_STEP_S)
        # after an answered step, the later answers of the other devices before the next
        # step (a virtual bus delivers each device's answer; on a real one they merge)
        after = min(max(3 * self.spread_s, 2 * latency, MIN_SETTLE_S), step)
        misses, start = 0, time.monotonic()
        while len(found) < MAX_DEVICES:
            self._check_time(start, found)
            answered, address = self._fastscan(step, after)
            if address is not None:
                if address in found:
                    raise _answers_everything(address, len(found) + 1)
                found.append(address)
                if progress is not None:
                    progress(address)
                continue
            if not answered:
                break  # nobody answered its first step: every device was found
            misses += 1
            if misses >= SCAN_ATTEMPTS:
                for address in found:  # two alike are the likeliest reason: say so
                    self._check_unique(address)
                raise LssFailedError(
                    f"Fastscan did not complete although devices without a node ID answer "
                    f"(tried {misses} times, up to {step * 1000:.0f} ms per step): the bus is "
                    "too busy or a device answers late; try again on a quieter bus",
                    "none",
                )
            step = min(2 * step, MAX_STEP_S)
            after = min(2 * after, step)
        return found

    def _check_time(self, start: float, found: list[LssAddress]) -> None:
        if time.monotonic() - start > SCAN_LIMIT_S:
            raise LssFailedError(
                f"the LSS scan did not end within its bound of {SCAN_LIMIT_S:g} s "
                f"({len(found)} devices found): devices keep answering Fastscan; prm9tool "
                "stopped it. Search again with fewer devices on the bus",
                "endless",
            )

    def _fastscan(self, step: float, after: float) -> tuple[bool, LssAddress | None]:
        """One Fastscan round (CiA 305): (whether its first step was answered, the address
        found or None). At most :data:`FASTSCAN_FRAMES` requests. An answered step waits
        ``after`` more: an answer of another device to it, come after the next request, was
        taken as that one's answer — a wrong bit, the round lost (seen under load with three
        devices on a virtual bus: every round of four failed)."""
        with self._frames.listen() as heard:

            def ask(number: int, bit: int, sub: int, following: int) -> bool:
                since = len(heard.frames)
                request = struct.pack("<BIBBB", CS_FASTSCAN, number, bit, sub, following)
                self._frames.send(request)
                if heard.wait(CS_IDENTIFY_SLAVE, since, step) is None:
                    return False
                time.sleep(after)
                return True

            if not ask(0, 0x80, 0, 0):
                return False, None
            parts = [0, 0, 0, 0]
            for sub in range(4):
                for bit in range(31, -1, -1):
                    if not ask(parts[sub], bit, sub, sub):
                        parts[sub] |= 1 << bit
                if not ask(parts[sub], 0, sub, (sub + 1) & 3):
                    return True, None
        return True, LssAddress(*parts)

    def _probe(self) -> float | None:
        """Seconds until the first device without a node ID answered (None: none did)."""
        with self._frames.listen() as heard:
            start = time.monotonic()
            self._frames.send(bytes([0x4C]).ljust(8, b"\0"))  # identify non-configured remote slave
            deadline = start + PROBE_WAIT_S
            while time.monotonic() < deadline and not heard.count(CS_NON_CONFIGURED_SLAVE):
                time.sleep(0.002)
            if heard.count(CS_NON_CONFIGURED_SLAVE):  # the other devices' answers, for spread_s
                first = time.monotonic() - start
                time.sleep(min(max(20 * first, PROBE_MORE_S), PROBE_WAIT_S))
            answers = [t for t, data in heard.frames if data and data[0] == CS_NON_CONFIGURED_SLAVE]
        self.latency_s = answers[0] - start if answers else None
        self.spread_s = answers[-1] - answers[0] if answers else 0.0
        return self.latency_s

    def _check_unique(self, address: LssAddress) -> None:
        """Select ``address`` alone; LssFailedError ``duplicate`` if two devices answer."""
        try:
            self._select(address)
        finally:
            self._frames.switch_global(WAITING)

    def _select(self, address: LssAddress) -> None:
        """Switch state selective to ``address``: exactly one device must answer."""
        with self._frames.listen() as heard:
            since = len(heard.frames)
            for cs, part in zip(CS_SELECTIVE, address.as_tuple(), strict=True):
                self._frames.send(struct.pack("<BI3x", cs, part))
            start = time.monotonic()
            if heard.wait(CS_SELECTIVE_RESPONSE, since, ANSWER_S) is None:
                raise LssFailedError(
                    f"no device answers to the LSS address {address.describe()}: it left the "
                    "bus or does not take part in LSS (search the bus)",
                    "unanswered",
                )
            settle(heard, CS_SELECTIVE_RESPONSE, start)
            count = heard.count(CS_SELECTIVE_RESPONSE)
        if count > 1:
            raise LssFailedError(
                f"{count} devices answer with the same LSS address ({address.describe()}): LSS "
                "cannot tell them apart and prm9tool changed neither. Take all but one off the "
                "bus (or set one's node-ID switch to a fixed node ID), assign that one, then "
                "the next",
                "duplicate",
            )

    # --- configuring -------------------------------------------------------------------
    def assign(self, address: LssAddress, node_id: int, bit_timing: int | None = None) -> None:
        """Give ``address`` node ID ``node_id`` (and a CiA 305 table-0 bit timing), stored.

        The node ID and bit timing are stored together or not at all: when a service is
        refused or the device stops answering before the store is acknowledged, the master
        puts the pending node ID back (where the device still answers) and releases it, so
        the device keeps what it had. A device without a node ID boots with the new one when
        released (CiA 305); a configured one takes it at its next NMT reset communication.
        """
        if not 1 <= node_id <= 127:
            raise LssFailedError(f"node ID {node_id} is outside 1…127", "refused")
        with self._lock:
            self._frames.switch_global(WAITING)
            try:
                self._select(address)
            except LssFailedError:
                self._frames.switch_global(WAITING)  # two alike: release both
                raise
            try:
                before = self._inquire_node_id(address)  # nothing changed yet if it fails
                try:
                    self._configure(address, CS_CONFIGURE_NODE_ID, node_id)
                    if bit_timing is not None:
                        self._configure(address, CS_CONFIGURE_BIT_TIMING, bit_timing)
                    self._configure(address, CS_STORE)
                except LssFailedError:
                    self._undo(before)
                    raise
            finally:
                self._frames.switch_global(WAITING)

    def activate_bit_timing(self, switch_delay_ms: int) -> None:
        """Every configured device switches to its pending bit timing (no answer; CiA 305:
        silent for ``switch_delay_ms``, switch, silent for it once more)."""
        with self._lock:
            self._frames.switch_global(CONFIGURATION)
            self._frames.activate(switch_delay_ms)
            self._frames.switch_global(WAITING)
            time.sleep(2 * switch_delay_ms / 1000)  # CiA 305: they are silent until then

    def change_bus_bit_timing(self, index: int, switch_delay_ms: int) -> int:
        """Every device that takes part in LSS goes to the CiA 305 table-0 bit timing
        ``index``: configure (all must accept), store (all must confirm), activate after
        ``switch_delay_ms``. Returns how many devices switch; LssFailedError when none answers
        or one refuses (then nothing is activated: no device changes its rate now)."""
        rate = kbit(index)
        with self._lock, self._frames.listen() as heard:
            self._frames.switch_global(CONFIGURATION)
            try:
                for cs, request in (
                    (CS_CONFIGURE_BIT_TIMING, bytes([CS_CONFIGURE_BIT_TIMING, 0, index])),
                    (CS_STORE, bytes([CS_STORE])),
                ):
                    since, sent = len(heard.frames), time.monotonic()
                    self._frames.send(request.ljust(8, b"\0"))  # every answer is judged below
                    heard.wait(cs, since, ANSWER_S)  # the first, then any further ones
                    settle(heard, cs, sent)
                    answers = [d for _, d in heard.frames if len(d) >= 2 and d[0] == cs]
                    if not answers:
                        raise LssFailedError(
                            f"no device answers LSS on this bus ({SERVICE[cs]} {rate}): none "
                            "has its node-ID switch at 1; nothing was changed",
                            "none",
                        )
                    refused = [d for d in answers if d[1] != ERROR_NONE]
                    if refused:
                        reason = ERRORS[cs].get(refused[0][1], f"error {refused[0][1]}")
                        stored = (
                            ""
                            if cs == CS_CONFIGURE_BIT_TIMING
                            else (
                                f"; the other {len(answers) - len(refused)} stored it and take it "
                                "at their next power-up"
                            )
                        )
                        raise LssFailedError(
                            f"{len(refused)} of {len(answers)} devices refused {SERVICE[cs]} "
                            f"{rate}: {reason}; no device switched now{stored}",
                            "refused",
                        )
                self._frames.activate(switch_delay_ms)
            finally:
                self._frames.switch_global(WAITING)
            time.sleep(2 * switch_delay_ms / 1000)  # CiA 305: they are silent until then
        return len(answers)

    def _inquire_node_id(self, address: LssAddress) -> int:
        answer = self._frames.ask(bytes([CS_INQUIRE_NODE_ID]) + bytes(7), CS_INQUIRE_NODE_ID)
        if answer is None:
            raise LssFailedError(
                f"serial {address.serial}: no answer to inquire node ID: the device left the "
                "bus during configuration; nothing was changed",
                "lost",
            )
        node_id = answer[1] if len(answer) > 1 else -1
        if not (1 <= node_id <= 127 or node_id == LSS_UNCONFIGURED):
            raise LssFailedError(
                f"serial {address.serial}: inquire node ID answered {node_id}, which is no node "
                "ID (1…127, 255 unconfigured); nothing was changed",
                "refused",
            )
        return node_id

    def _configure(self, address: LssAddress, cs: int, value: int = 0) -> None:
        """One configure/store service; LssFailedError with the CiA 305 error in words."""
        # configure bit timing: table selector 0 (CiA 305 table 0), then the table index
        request = bytes([cs, 0, value]) if cs == CS_CONFIGURE_BIT_TIMING else bytes([cs, value])
        answer = self._frames.ask(request.ljust(8, b"\0"), cs)
        if answer is None or len(answer) < 3 or answer[1] != ERROR_NONE:
            raise service_problem(
                address, cs, value, answer if answer and len(answer) >= 3 else None
            )

    def _undo(self, before: int) -> None:
        """Put the pending node ID back (best effort: the device may be gone)."""
        node_id = before if 1 <= before <= 127 else LSS_UNCONFIGURED
        self._frames.ask(
            bytes([CS_CONFIGURE_NODE_ID, node_id]).ljust(8, b"\0"), CS_CONFIGURE_NODE_ID
        )


def _answers_everything(address: LssAddress, rounds: int) -> LssFailedError:
    return LssFailedError(
        f"Fastscan round {rounds} found {address.describe()} once more: a device acknowledges "
        "every LSS request (it answers for every bit), so Fastscan cannot find the devices "
        "beside it; prm9tool stopped the scan. Take that device off the bus and search again",
        "endless",
    )

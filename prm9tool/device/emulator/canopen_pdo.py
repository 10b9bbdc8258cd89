"""The PRM9's four PDO channels (manual §7.2.5-7.2.6, table 7-13): fixed mapping, CiA 301 timing.

A channel reads its communication parameters (COB-ID, transmission type, event timer) from the
valve's object dictionary and its mapping from the catalogue; RPDO1/TPDO1 entry 2 follow the
control mode 0x6043. The event timer (sub 5) paces a TPDO and is the reception deadline of an
RPDO (CiA 301). Time is counted in whole milliseconds of simulated time.
"""

from __future__ import annotations

import functools
import logging
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Protocol

from prm9tool.catalogue import CATALOGUE, Parameter
from prm9tool.catalogue.pdo import mapping_for_control_mode
from prm9tool.errors import SdoAbortError

log = logging.getLogger(__name__)

COB_INVALID = 0x80000000  # bit 31: PDO does not exist / is not valid
CAN_ID_MASK = 0x7FF
SYNC_TYPES = range(241)  # 0 acyclic synchronous, 1-240 every n-th SYNC
EVENT_TYPES = (254, 255)
CHANGE_INHIBIT_MS = 10  # decision: event timer 0 -> on change, at most every 10 ms
CONTROL_MODE = CATALOGUE["CTRLMODE"].key  # 0x6043


Entries = tuple[tuple[int, int, int], ...]  # (index, subindex, bits) of each mapped object


class Dictionary(Protocol):
    """The part of the emulated valve a PDO channel needs."""

    def read(self, index: int, subindex: int) -> int | str: ...
    def read_bytes(self, index: int, subindex: int) -> bytes: ...
    def write_bytes(self, index: int, subindex: int, data: bytes) -> None: ...
    def read_mapped(self, entries: Entries) -> bytes: ...
    def write_mapped(self, entries: Entries, data: bytes) -> list[SdoAbortError]: ...
    def pdo_sampler(self, entries: Entries) -> Callable[[], bytes] | None: ...
    def control_mode(self) -> int: ...


@functools.cache
def _mapping_parameters(map_index: int) -> tuple[Parameter, ...]:
    """The catalogue's entries of a mapping object (fixed: computed once, not per frame)."""
    entries = [p for p in CATALOGUE if p.index == map_index and p.subindex > 0]
    return tuple(sorted(entries, key=lambda p: p.subindex))


def mapping(valve: Dictionary, map_index: int) -> Entries:
    """The ``(index, subindex, bits)`` entries of a mapping object in the current control mode.

    As many as its sub-index 0 says: none on a PDO that maps nothing (CiA 301).
    """
    return _entries(map_index, int(valve.read(*CONTROL_MODE)), int(valve.read(map_index, 0)))


@functools.cache
def _entries(map_index: int, mode: int, count: int) -> Entries:
    """The entries for a control mode and count (fixed: computed once, not per frame)."""
    result = []
    for param in _mapping_parameters(map_index)[:count]:
        value = mapping_for_control_mode(param, mode)
        result.append((value >> 16, (value >> 8) & 0xFF, value & 0xFF))
    return tuple(result)


@functools.cache
def mapped_size(entries: Entries) -> int:
    """The bytes a PDO mapping these entries carries."""
    return sum(bits // 8 for _, _, bits in entries)


@dataclass
class PdoChannel:
    """One RPDO or TPDO: configuration cache plus its run-time counters."""

    number: int
    transmit: bool
    cob_id: int = COB_INVALID
    trans_type: int = 255
    event_timer: int = 0
    sync_count: int = 0
    next_due_ms: int = 0
    last_sent_ms: int = -(10**9)
    last_data: bytes | None = None
    pending: bytes | None = field(default=None, repr=False)  # RPDO data waiting for SYNC
    # RPDO: the next frame is due by then (None = not armed), on the time base of
    # :class:`.canopen_watch.TimingWatches` (wall clock when paced, else simulated)
    deadline_ms: float | None = None
    map_count: int = 0  # the mapping's sub-index 0 (read-only: read with the parameters)

    @property
    def comm_index(self) -> int:
        """0x1400.. for RPDOs, 0x1800.. for TPDOs."""
        return (0x1800 if self.transmit else 0x1400) + self.number - 1

    @property
    def map_index(self) -> int:
        """0x1600.. for RPDOs, 0x1A00.. for TPDOs."""
        return (0x1A00 if self.transmit else 0x1600) + self.number - 1

    @property
    def valid(self) -> bool:
        """True unless bit 31 of the COB-ID marks the PDO invalid."""
        return not self.cob_id & COB_INVALID

    @property
    def can_id(self) -> int:
        """The 11-bit CAN identifier."""
        return self.cob_id & CAN_ID_MASK

    def load(self, valve: Dictionary, now_ms: int) -> None:
        """Refresh the configuration from the object dictionary (a new event timer restarts)."""
        self.cob_id = int(valve.read(self.comm_index, 1))
        self.map_count = int(valve.read(self.map_index, 0))
        self.trans_type = int(valve.read(self.comm_index, 2))
        timer = int(valve.read(self.comm_index, 5))
        if timer != self.event_timer:
            self.event_timer = timer
            self.next_due_ms = now_ms + timer
            self.deadline_ms = None  # CiA 301: an RPDO deadline is armed by the next reception

    def restart(self, now_ms: int) -> None:
        """Reset the counters (entering OPERATIONAL, configuration changed)."""
        self.sync_count = 0
        self.next_due_ms = now_ms + self.event_timer
        self.last_data = None
        self.pending = None
        self.deadline_ms = None


def channel_mapping(valve: Dictionary, channel: PdoChannel) -> Entries:
    """:func:`mapping` of a loaded channel: its count as loaded (read-only, so it changes only
    with a power-up, which loads the channel again), the control mode read now."""
    if not channel.map_count:
        return ()
    return _entries(channel.map_index, valve.control_mode(), channel.map_count)


class TpdoLogic:
    """When a TPDO is due and what it carries."""

    def __init__(self, channel: PdoChannel, valve: Dictionary, fast: bool = True) -> None:
        """``fast``: the mapped data through ``valve.pdo_sampler`` where the mapping has one
        (:mod:`.pdo_fast`; False: always ``read_mapped``, the reference path)."""
        self.channel = channel
        self._valve = valve
        self._fast = fast
        self._sampled: Entries = ()  # the mapping _sample was made for
        self._sample: Callable[[], bytes] | None = None

    def data(self) -> bytes | None:
        """The mapped bytes, or None when the PDO maps nothing (CiA 301: mapping disabled)."""
        entries = channel_mapping(self._valve, self.channel)
        if not entries:
            return None  # a TPDO that maps nothing is never sent
        if entries is not self._sampled and self._fast:  # _entries hands out one tuple each
            self._sampled, self._sample = entries, self._valve.pdo_sampler(entries)
        if self._sample is not None:
            return self._sample()
        return self._valve.read_mapped(entries)

    def on_sync(self) -> bytes | None:
        """Data to send on a SYNC (transmission types 0-240), or None."""
        channel = self.channel
        if not channel.valid or channel.trans_type not in SYNC_TYPES:
            return None
        if channel.trans_type == 0:
            data = self.data()
            return data if data is not None and data != channel.last_data else None
        channel.sync_count += 1
        if channel.sync_count < channel.trans_type:
            return None
        channel.sync_count = 0
        return self.data()

    def count_sync(self) -> None:
        """A SYNC this TPDO does not answer (the serving PC got to it too late): the every-
        n-th count goes on as :meth:`on_sync` counts, nothing is sampled or sent."""
        channel = self.channel
        if channel.valid and channel.trans_type in SYNC_TYPES and channel.trans_type:
            channel.sync_count += 1
            if channel.sync_count >= channel.trans_type:
                channel.sync_count = 0

    def on_tick(self, now_ms: int) -> bytes | None:
        """Data to send at ``now_ms`` (event timer, or change of data when the timer is 0)."""
        channel = self.channel
        if not channel.valid or channel.trans_type not in EVENT_TYPES:
            return None
        if channel.event_timer:
            if now_ms < channel.next_due_ms:
                return None
            channel.next_due_ms = now_ms + channel.event_timer
            return self.data()
        if now_ms - channel.last_sent_ms < CHANGE_INHIBIT_MS:
            return None
        data = self.data()
        return data if data is not None and data != channel.last_data else None

    def sent(self, data: bytes, now_ms: int) -> None:
        """Record a transmission (for change detection)."""
        self.channel.last_data = data
        self.channel.last_sent_ms = now_ms
        if self.channel.event_timer:
            self.channel.next_due_ms = now_ms + self.channel.event_timer


class RpdoLogic:
    """Applying received RPDO data to the object dictionary."""

    def __init__(
        self,
        channel: PdoChannel,
        valve: Dictionary,
        length_error: Callable[[], None],
        length_ok: Callable[[], None] = lambda: None,
    ) -> None:
        self.channel = channel
        self._valve = valve
        self._length_error = length_error
        self._length_ok = length_ok

    def received(self, data: bytes) -> bool:
        """A frame on the RPDO's COB-ID arrived (NMT OPERATIONAL); ignored when the RPDO maps
        nothing (CiA 301: mapping disabled). True when it was taken (the deadline watch then
        expects the next one, :meth:`.canopen_watch.TimingWatches.rpdo_received`)."""
        if not self.channel.map_count:
            return False
        if self.channel.trans_type in SYNC_TYPES:
            self.channel.pending = data
        else:
            self.apply(data)
        return True

    def on_sync(self) -> None:
        """Synchronous RPDOs take effect at the SYNC after reception."""
        if self.channel.pending is not None:
            data, self.channel.pending = self.channel.pending, None
            self.apply(data)

    def apply(self, data: bytes, entries: Entries | None = None) -> None:
        """Write the mapped objects; a too short frame is refused (CiA 301 EMCY 0x8210)."""
        if entries is None:
            entries = channel_mapping(self._valve, self.channel)
        if len(data) < mapped_size(entries):
            self._length_error()
            return
        self._length_ok()
        for exc in self._valve.write_mapped(entries, data):
            log.info("RPDO%d: %s", self.channel.number, exc)

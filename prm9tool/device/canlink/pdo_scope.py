"""The oscilloscope over the valve's fixed PDO mapping (manual table 7-13).

TPDO1 carries the status word and, as entry 2, the actual position 0x6301 (control mode 2) or
the process actual value 0x6381 (mode 4). While the node is OPERATIONAL, the scope sets TPDO1 to
transmission type 1 (sent after every SYNC, table 7-12), produces SYNC at the chosen period
(down to 1 ms, or what keeps the scope under half of a slower bus) and takes each TPDO1 as one
sample; stopping stops the SYNC and puts the transmission type back. Samples are placed by the
number of the SYNC they answer (:mod:`prm9tool.device.canlink.sync_clock`): the stream has one
row per SYNC period, and a SYNC without its TPDO1 (or one a busy PC could not send) is a NaN
row — a gap in the curve at its time, counted as lost — so a 1 s square wave keeps its 1 s
period whatever is lost. The demand channel (``position_setpoint``/``process_setpoint``), which
the valve does not report, is the setpoint this tool sends in RPDO1 at each SYNC (the setpoint
generator's; NaN while the tool sends none), and a channel without an object is NaN. Measuring
points with an object other than TPDO1's, or a node that is not OPERATIONAL, are sampled by SDO
(prm9tool.device.canlink.sampler).
"""

from __future__ import annotations

import contextlib
import time
from collections.abc import Sequence

import numpy as np

from prm9tool.catalogue.signals import SIGNAL_OBJECTS, signal_at_index
from prm9tool.device.canlink.bus import CanNetwork
from prm9tool.device.canlink.sampler import DEMAND_KEYS, Demand
from prm9tool.device.canlink.sdo import SdoChannel
from prm9tool.device.canlink.sync_clock import SlotSamples, SyncClock
from prm9tool.device.records import NmtState
from prm9tool.errors import CanBusOffError, DeviceDisconnectedError, Prm9Error

MIN_PERIOD_S = 0.001
SYNC_AND_TPDO1_BITS = (47 + 3) + (47 + 32 + 3)  # SYNC (no data) + TPDO1 (4 bytes) on the wire
MAX_BUS_LOAD = 0.5  # decision: the scope takes at most half the bus, SDO and others need room
SYNCHRONOUS_EVERY_SYNC = 1  # TPDO transmission type 1 (manual table 7-12)
SETTLE_S = 0.05  # a SYNC's slot is handed out this long after it (its TPDO1 has arrived)


class NotPdoMappedError(Prm9Error):
    """These measuring points are not all in TPDO1, or TPDO1 cannot be used now."""


def min_period_s(bitrate: int | None) -> float:
    """The shortest SYNC period the bus allows: 1 ms, or longer where SYNC + TPDO1 would take
    more than half of a slow bus (125 kbit/s: 2.1 ms)."""
    if not bitrate:
        return MIN_PERIOD_S
    return max(MIN_PERIOD_S, SYNC_AND_TPDO1_BITS / bitrate / MAX_BUS_LOAD)


class PdoSampler:
    """Samples TPDO1's entry 2 at a tool-produced SYNC period (same interface as SdoSampler)."""

    def __init__(
        self,
        shared: CanNetwork,
        sdo: SdoChannel,
        keys: Sequence[str],
        rate_hz: float,
        demand: Demand | None = None,
    ) -> None:
        node = int(sdo.node.id or 0)
        if shared.node_seen(node).nmt_state is not NmtState.OPERATIONAL:
            raise NotPdoMappedError(f"node {node} is not OPERATIONAL: no PDOs")
        mapped = signal_at_index(sdo.read_u32(0x1A00, 2) >> 16)  # entry 2: 0x6301 or 0x6381
        read_by_sdo = [k for k in keys if k != mapped and k in SIGNAL_OBJECTS]
        if mapped not in keys or read_by_sdo:
            raise NotPdoMappedError(f"TPDO1 carries {mapped}, not {', '.join(keys)}")
        cob_id = sdo.read_u32(0x1800, 1)
        if cob_id & 0x8000_0000:
            raise NotPdoMappedError("TPDO1 is switched off (0x1800/1 bit 31)")
        if shared.sync_owner is not None:
            raise NotPdoMappedError("another scope produces the SYNC on this bus")
        self.keys = tuple(keys)
        self.period_s = max(1.0 / rate_hz, min_period_s(shared.options.bitrate))
        self._shared, self._sdo, self._cob_id = shared, sdo, cob_id & 0x7FF
        self._column = self.keys.index(mapped)
        self._demand = demand
        self._demands: dict[int, list[float]] = {}  # tick -> the other columns at its SYNC
        self._clock = SyncClock(shared.network.send_message, self.period_s, self._at_sync)
        self._slots = SlotSamples(self._clock)
        self._settle = max(2, round(SETTLE_S / self.period_s))
        self._gaps = 0  # NaN rows handed out
        self._old_type = sdo.upload(0x1800, 2)
        sdo.download(0x1800, 2, bytes([SYNCHRONOUS_EVERY_SYNC]))
        shared.sync_owner = self
        shared.network.subscribe(self._cob_id, self._on_tpdo)
        self._started = time.monotonic()
        self._clock.start()

    @property
    def samples(self) -> int:
        """TPDO1 frames received and placed so far."""
        return self._slots.received

    @property
    def achieved_hz(self) -> float:
        """TPDO1 frames received per second since the start."""
        elapsed = time.monotonic() - self._started
        return self.samples / elapsed if elapsed > 0 else 0.0

    @property
    def lost(self) -> int:
        """SYNC periods handed out without a sample (NaN rows) so far."""
        return self._gaps

    def read(self) -> np.ndarray:
        """One row per SYNC period up to one settling time ago, shape (n, len(keys)); a
        period without its TPDO1 is NaN in TPDO1's column. Raises the bus's error that stopped
        the SYNC."""
        refusal = self._clock.error
        if refusal is not None:
            if self._shared.is_bus_off(refusal):
                raise CanBusOffError(f"the CAN adapter is bus-off: no SYNC ({refusal})")
            raise DeviceDisconnectedError(f"the CAN bus refused the SYNC ({refusal})")
        first = self._slots.given
        mapped = self._slots.take(self._clock.ticks - self._settle)
        self._gaps += int(np.isnan(mapped[:, 0]).sum())
        rows = np.full((len(mapped), len(self.keys)), np.nan)
        for i in range(len(mapped)):
            others = self._demands.pop(first + i, None)
            if others is not None:
                rows[i] = others
        rows[:, self._column] = mapped[:, 0]
        return rows

    def _at_sync(self, tick: int) -> None:
        """Just before SYNC ``tick``: the demand this tool sends now (the other columns)."""
        demand = self._demand
        self._demands[tick] = [
            demand(key) if demand is not None and key in DEMAND_KEYS else float("nan")
            for key in self.keys
        ]

    def stop(self) -> None:
        """Stop the SYNC, stop listening, put TPDO1's transmission type back."""
        self._clock.stop()
        self._shared.network.unsubscribe(self._cob_id, self._on_tpdo)
        self._shared.sync_owner = None
        with contextlib.suppress(Prm9Error):  # a lost link: type 1 stays until the next reset
            self._sdo.download(0x1800, 2, self._old_type)

    def _on_tpdo(self, _can_id: int, data: bytearray, timestamp: float) -> None:
        if len(data) < 4:
            return
        self._slots.put(timestamp, [float(int.from_bytes(bytes(data[2:4]), "little", signed=True))])

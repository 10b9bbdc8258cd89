"""The valve under test over the CANopen link: the setpoint in RPDO1, the response in TPDO1.

The CANopen link has no stream of measuring points sampled in one firmware cycle. The rig runs
the test at the bus's pace instead, as a PLC would: the tool produces SYNC every sample period
(:class:`~prm9tool.device.canlink.sync_clock.SyncClock`, 1 ms where the bit rate allows: SYNC,
RPDO1 and TPDO1 take at most half the bus) and sends each sample's setpoint in RPDO1 just before
its SYNC (``session.setpoint_link()``: control word + 0x6300/0x6380, manual §7.6, table 7-13 —
what a real valve has, not this project's override objects). The valve answers every SYNC with
TPDO1 (transmission type 1 while the test runs, table 7-12), whose entry 2 is the actual position
0x6301 (control mode 2) or the process actual value 0x6381 (mode 4). Frames on one bus are
delivered in order and the valve handles them in that order, so sample ``k`` pairs the setpoint
of tick ``k`` with the response to SYNC ``k``, and its time is ``k`` periods: the SYNC count,
not the PC clock. Measuring points without an object in TPDO1 (the controller's output, the
setpoint chain's stages) give NaN, never a made-up value.

A busy PC loses samples: a tick its thread reaches too late sends nothing (the valve keeps the
setpoint it has, which is what the demand column then holds), a TPDO1 that comes too late for
its SYNC is dropped. Lost responses are bridged by a straight line between their neighbours for
the analysis and counted (:attr:`CanRig.lost`, the report's note); more than 5 % lost, or a gap
longer than :data:`MAX_GAP_S`, make the play fail rather than guess (:class:`LinkTooSlowError`).

A valve whose TPDO1 is switched off or maps neither object is sampled by SDO instead: each
period the setpoint frame, then an SDO read of the response (the period chosen from measured
round trips, at least 2 ms), as before SYNC sampling existed.

The link is taken at the first :meth:`CanRig.play` and held until :meth:`CanRig.release`
(which the procedures call at the end, on Stop, on a fault and on a refusal): a keeper thread
repeats the last frame between plays so the valve's RPDO reception deadline does not fire while
a procedure computes; :meth:`~prm9tool.device.setpoint.SetpointLink.end` sends the setpoint the
valve had before, and TPDO1's transmission type is put back. A refusal (node not OPERATIONAL,
not enabled, RPDO1 off) is the link's error, which says what to do.
"""

from __future__ import annotations

import math
import threading
import time
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING

import numpy as np

from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.signals import signal_at_index, signal_object
from prm9tool.characterize.rig import (
    LATE_SHARE,
    LinkTooSlowError,
    Rig,
    RigInfo,
    ValveFaultError,
    bridgeable,
    bridged,
    counts,
    longest_run,
)
from prm9tool.device.canlink.pdo_scope import MAX_BUS_LOAD
from prm9tool.device.canlink.pdo_scope import MIN_PERIOD_S as MIN_SYNC_PERIOD_S
from prm9tool.device.canlink.sampler import DEMAND_KEYS  # the demand the master wrote
from prm9tool.device.canlink.sync_clock import SlotSamples, SyncClock
from prm9tool.errors import CommunicationError, Prm9Error

__all__ = ["CanRig", "LinkTooSlowError", "rig_for_session"]

if TYPE_CHECKING:
    from prm9tool.device.canlink.session import CanopenSession
    from prm9tool.device.records import ValveStatus
    from prm9tool.device.session import ValveSession
    from prm9tool.device.setpoint import SetpointLink

LATE_PERIODS = 2.0  # a sample this many periods behind its time is late
GAPS_SHARE = 0.75  # a play whose analysis takes gaps (the sweep) may lose up to this share
SETTLE_S = 0.1  # the last SYNC's TPDO1 is awaited this long at most
TICK_BITS = (47 + 3) + 2 * (47 + 32 + 3)  # SYNC + RPDO1 + TPDO1 (4 bytes each) on the wire
SYNCHRONOUS_EVERY_SYNC = 1  # TPDO transmission type 1 (table 7-12)
TRIAL_LATE_SHARE = 0.01  # the pace is kept when at most this share of the trial is late
PROBES = 20  # SDO round trips measured to choose the period
MIN_PERIOD_S = 0.002  # decision: below this a loaded PC cannot keep the period by sleeping
MAX_PERIOD_S = 0.05  # the slowest pace tried (20 Hz)
TRIAL = 200  # samples of the trial run at the chosen pace
CHECK_S = 0.2  # a stop request is looked at this often during a play


class CanRig(Rig):
    """A -CA valve over an open :class:`CanopenSession` (see the module docstring)."""

    def __init__(
        self,
        session: CanopenSession,
        period_s: float | None = None,
        clock: type[SyncClock] | None = None,
    ) -> None:
        """``period_s``: the sample period (None: the bus's pace, or measured for SDO
        polling); ``clock``: the SYNC producer's class (None: :class:`SyncClock`; an emulated
        valve stepped by SYNC needs its master's, :mod:`prm9tool.twin.syncstep`)."""
        super().__init__()
        self.session = session
        self._clock = clock
        self._link: SetpointLink | None = None  # taken at the first play, until release()
        self._lock = threading.Lock()  # one frame at a time, in order (set vs. keep-alive)
        self._sent = 0.0  # perf_counter of the last frame
        self._quit = threading.Event()
        self._keeper: threading.Thread | None = None
        self._keeper_error: Exception | None = None
        self._tpdo1 = self._tpdo1_response()  # (COB-ID, key) or None: SDO polling
        self._old_type: bytes | None = None  # TPDO1's transmission type while a test holds it
        options = session.options
        if self._tpdo1 is not None:
            self.period_s = period_s if period_s is not None else tick_period_s(options.bitrate)
            how = "TPDO1 at the tool's SYNC"
        else:
            self.period_s = period_s if period_s is not None else self._measure_period()
            how = "SDO polling"
        info = session.info
        self.info = RigInfo(
            info.type_key,
            info.serial,
            info.firmware,
            f"CANopen node {session.node_id} ({options.interface} {options.channel}), "
            f"{how}, one sample per {self.period_s * 1000:g} ms",
            1.0 / self.period_s,
            info.device_id,
        )
        self.late = 0  # samples of the last play taken late (SDO) or lost (SYNC)
        self.lost = 0  # samples lost in every play so far (bridged for the analysis)
        self.samples = 0  # samples of every play so far

    def _tpdo1_response(self) -> tuple[int, str] | None:
        """TPDO1's COB-ID and the response its entry 2 carries, when it is on and maps one."""
        sdo = self.session.sdo
        try:
            cob_id = sdo.read_u32(0x1800, 1)
            key = signal_at_index(sdo.read_u32(0x1A00, 2) >> 16)  # 0x6301 or 0x6381
        except Prm9Error:  # no such object: the SDO way
            return None
        if cob_id & 0x8000_0000 or key is None:
            return None
        return cob_id & 0x7FF, key

    def _measure_period(self) -> float:
        """Twice the 90th percentile of measured read round trips, rounded up to 0.5 ms
        (≥ 2 ms); then tried for TRIAL samples at that pace (other threads and processes take
        their share of the PC too) and doubled while too many come late. The setpoint frame
        of a sample needs no answer, so only the read is measured (the valve is not moved)."""
        sdo = self.session.sdo
        obj = CATALOGUE["POSACT"]

        def tick() -> None:
            sdo.upload(obj.index, obj.subindex)

        trips = []
        for _ in range(PROBES):
            start = time.perf_counter()
            tick()
            trips.append(time.perf_counter() - start)
        slow = float(np.percentile(trips, 90))
        period = max(MIN_PERIOD_S, math.ceil(slow * 2.0 / 0.0005) * 0.0005)
        while period < MAX_PERIOD_S:
            late, due = 0, time.perf_counter()
            for _ in range(TRIAL):
                wait = due - time.perf_counter()
                if wait > 0:
                    time.sleep(wait)
                elif -wait > LATE_PERIODS * period:
                    late += 1
                tick()
                due += period
            if late <= TRIAL_LATE_SHARE * TRIAL:
                break
            period *= 2.0
        return period

    def read(self, mnemonics: Sequence[str]) -> dict[str, int]:
        """Raw values by SDO."""
        return {k: int(v) for k, v in self.session.read_many(list(mnemonics)).items()}

    def write(self, values: Mapping[str, int]) -> None:
        """Write by SDO (in the given order)."""
        self.session.write_many(dict(values))

    def play(self, setpoint_pct: np.ndarray, keys: Sequence[str], gaps: bool = False) -> np.ndarray:
        """One setpoint frame and one response per sample period (see the module docstring);
        ``gaps``: lost samples are refused only beyond :data:`GAPS_SHARE`."""
        values = [counts(float(v)) for v in setpoint_pct]
        self._take(values[0])
        self.last_missing = np.zeros(len(values), dtype=bool)
        if self._tpdo1 is not None:
            rows = self._play_sync(values, keys, gaps)
        else:
            rows = self._play_sdo(values, keys)
        status = self.session.status()
        if status.error_code:
            raise ValveFaultError(
                f"the valve reported error {status.error_code:#06x}: {status.error_text}"
            )
        self.last_demand = rows_demand(rows, keys, values) / 163.84
        return rows

    def _play_sync(self, values: list[int], keys: Sequence[str], gaps: bool) -> np.ndarray:
        """Setpoint ``k`` in RPDO1, then SYNC ``k``; TPDO1 placed by the SYNC it answers."""
        assert self._tpdo1 is not None
        cob_id, mapped = self._tpdo1
        n = len(values)
        sent = np.zeros(n, dtype=bool)

        def before_sync(k: int) -> None:
            self._send(values[k])
            sent[k] = True

        make = self._clock or SyncClock
        clock = make(self.session.send_frame, self.period_s, before_sync, limit=n)
        slots = SlotSamples(clock)

        def on_tpdo(_can_id: int, data: bytearray, timestamp: float) -> None:
            if len(data) >= 4:
                slots.put(timestamp, [float(int.from_bytes(data[2:4], "little", signed=True))])

        self.session.listen(cob_id, on_tpdo)
        try:
            clock.start()
            played = self.played_s
            while not clock.wait_ticks(n, CHECK_S):
                self.check()
                self._raise_keeper_error()
                self.played_s = played + clock.ticks * self.period_s
            self.played_s = played + n * self.period_s
            slots.wait_for(n - 1, max(SETTLE_S, 20 * self.period_s))
        finally:
            clock.stop()
            self.session.unlisten(cob_id, on_tpdo)
        if clock.error is not None:
            raise CommunicationError(f"the CAN bus refused the SYNC ({clock.error})")
        response = slots.take(n)[:, 0]
        demand = held(np.asarray(values, dtype=float), sent, values[0])
        if mapped not in keys:  # the response was not asked for (settling at a start value)
            response[:] = np.nan
            return self._columns(keys, mapped, demand, response)
        missing = np.isnan(response)
        lost = int(missing.sum())
        self.late, self.lost, self.samples = lost, self.lost + lost, self.samples + n
        self.last_missing = missing
        gap = longest_run(missing)
        if lost > GAPS_SHARE * n if gaps else not bridgeable(missing, 1.0 / self.period_s):
            raise LinkTooSlowError(
                f"the CANopen link lost {lost} of {n} samples (the longest gap "
                f"{gap * self.period_s * 1000:g} ms) at one sample per "
                f"{self.period_s * 1000:g} ms; the test was stopped, nothing was interpolated"
            )
        return self._columns(keys, mapped, demand, bridged(response))

    @staticmethod
    def _columns(
        keys: Sequence[str], mapped: str, demand: np.ndarray, response: np.ndarray
    ) -> np.ndarray:
        rows = np.full((len(demand), len(keys)), np.nan)
        for column, key in enumerate(keys):
            if key in DEMAND_KEYS:
                rows[:, column] = demand
            elif key == mapped:
                rows[:, column] = response
        return rows

    def _play_sdo(self, values: list[int], keys: Sequence[str]) -> np.ndarray:
        """One setpoint frame and one SDO reading per sample period."""
        sdo = self.session.sdo
        checks = max(1, round(CHECK_S / self.period_s))
        rows = np.full((len(values), len(keys)), np.nan)
        objects = [signal_object(key) for key in keys]  # the catalogue's measuring-point objects
        late = 0
        due = time.perf_counter()
        for i, value in enumerate(values):
            if i % checks == 0:
                self.check()
                self.played_s += checks * self.period_s if i else 0.0
                self._raise_keeper_error()
            wait = due - time.perf_counter()
            if wait > 0:
                time.sleep(wait)
            elif -wait > LATE_PERIODS * self.period_s:
                late += 1
            self._send(value)
            # Frames on the bus are ordered: the SDO request below follows the RPDO frame, so
            # the valve answers it after it has taken this sample's setpoint.
            for column, key in enumerate(keys):
                if key in DEMAND_KEYS:
                    rows[i, column] = value
                elif (found := objects[column]) is not None:  # 0x6301, 0x6381 …
                    obj, factor = found
                    raw = int(obj.dtype.decode(sdo.upload(obj.index, obj.subindex)))
                    rows[i, column] = raw * factor
            due += self.period_s
        self.late, self.samples = late, self.samples + len(values)
        if late > LATE_SHARE * len(values):
            raise LinkTooSlowError(
                f"the CANopen link did not keep one sample per {self.period_s * 1000:g} ms "
                f"({late} of {len(values)} samples late); the test was stopped, nothing was "
                "interpolated"
            )
        return rows

    def _take(self, first: int) -> None:
        """Take the setpoint over (once until :meth:`release`) and start the keeper."""
        if self._link is not None:
            return
        link = self.session.setpoint_link()
        link.begin(first)  # a refusal says what to do; nothing runs then
        self._link, self._sent = link, time.perf_counter()
        if self._tpdo1 is not None:  # TPDO1 after every SYNC while the test holds the valve
            sdo = self.session.sdo
            self._old_type = sdo.upload(0x1800, 2)
            sdo.download(0x1800, 2, bytes([SYNCHRONOUS_EVERY_SYNC]))
        self._quit.clear()
        self._keeper_error = None
        self._keeper = threading.Thread(target=self._keep, name="canrig-keeper", daemon=True)
        self._keeper.start()

    def _send(self, value: int) -> None:
        assert self._link is not None
        with self._lock:
            self._link.set(value)
            self._sent = time.perf_counter()

    def _keep(self) -> None:
        """The last frame again when none was sent for the link's keep-alive interval."""
        link = self._link
        assert link is not None
        while not self._quit.wait(link.keepalive_s / 2):
            with self._lock:
                if time.perf_counter() - self._sent < link.keepalive_s:
                    continue
                try:
                    link.keep_alive()
                except Prm9Error as exc:  # raised in the procedure's thread at its next check
                    self._keeper_error = exc
                    return
                self._sent = time.perf_counter()

    def _raise_keeper_error(self) -> None:
        if self._keeper_error is not None:
            raise self._keeper_error

    def release(self) -> None:
        """Stop the keeper and give the setpoint back (the value the valve had before)."""
        self._quit.set()
        if self._keeper is not None:
            self._keeper.join()
            self._keeper = None
        link, self._link = self._link, None
        if link is not None:
            with self._lock:
                link.end()
        old_type, self._old_type = self._old_type, None
        if old_type is not None:
            self.session.sdo.download(0x1800, 2, old_type)

    def status(self) -> ValveStatus:
        """Status by SDO."""
        return self.session.status()


def tick_period_s(bitrate: int | None) -> float:
    """The sample period at the bus's pace: 1 ms, or longer where SYNC, RPDO1 and TPDO1 would
    take more than half of a slower bus (250 kbit/s: 1.7 ms, 125 kbit/s: 3.5 ms)."""
    if not bitrate:
        return MIN_SYNC_PERIOD_S
    return max(MIN_SYNC_PERIOD_S, math.ceil(TICK_BITS / bitrate / MAX_BUS_LOAD * 1e4) / 1e4)


def held(values: np.ndarray, sent: np.ndarray, before: float) -> np.ndarray:
    """What the valve had at each tick: the tick's value where it was sent, else the last one
    sent before it (``before`` ahead of the first)."""
    index = np.where(sent, np.arange(len(values)), -1)
    index = np.maximum.accumulate(index)
    return np.where(index >= 0, values[np.maximum(index, 0)], before)


def rows_demand(rows: np.ndarray, keys: Sequence[str], values: list[int]) -> np.ndarray:
    """The demand column of ``rows`` (counts), or the stimulus when none was recorded."""
    for column, key in enumerate(keys):
        if key in DEMAND_KEYS:
            return np.asarray(rows[:, column], dtype=float)
    return np.asarray(values, dtype=float)


def rig_for_session(session: ValveSession, link: str = "USB") -> Rig:
    """The rig for an open session: :class:`CanRig` over CANopen, else a
    :class:`~prm9tool.characterize.rig.SessionRig` streaming at 5 kHz (``link`` names it)."""
    from prm9tool.characterize.rig import SessionRig
    from prm9tool.device.canlink.session import CanopenSession

    if isinstance(session, CanopenSession):
        return CanRig(session)
    return SessionRig(session, link)

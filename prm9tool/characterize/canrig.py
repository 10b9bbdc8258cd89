"""The valve under test over the CANopen link: the stimulus and the samples by SDO.

The CANopen link has no stream of measuring points sampled in one firmware cycle. The rig
therefore runs its own loop on the master: each sample period it sends the setpoint through the
session's setpoint link (``session.setpoint_link()``: RPDO1, control word + 0x6300/0x6380,
manual §7.6 and table 7-13 — what a real valve has, not this project's override objects) and
then reads the response's object by SDO (actual position 0x6301, process actual value 0x6381).
CAN frames on one bus are delivered in order and the valve handles them in that order, so the
SDO read sent after the RPDO frame is answered by a valve that has taken the setpoint: the
demand of a sample is known exactly without an object for it, and the phase between them is
accurate to one SDO round trip. Measuring points without an object on the link (the
controller's output, the setpoint chain's stages) give NaN, never a made-up value.

The link is taken at the first :meth:`CanRig.play` and held until :meth:`CanRig.release`
(which the procedures call at the end, on Stop, on a fault and on a refusal): a keeper thread
repeats the last frame between plays so the valve's RPDO reception deadline does not fire while
a procedure computes; :meth:`~prm9tool.device.setpoint.SetpointLink.end` sends the setpoint the
valve had before. A refusal (node not OPERATIONAL, not enabled, RPDO1 off) is the link's error,
which says what to do.

The sample period is chosen from the SDO round trips measured when the rig is made (at least
2 ms) and a trial run at that pace (doubled while more than 1 % of the trial comes late); more
than 5 % of a test's samples taken over two periods late make the play fail rather than be
stretched or interpolated (:class:`LinkTooSlowError`). The TPDO1 scope
(:mod:`prm9tool.device.canlink.pdo_scope`) is not used: its samples carry no demand value.
"""

from __future__ import annotations

import math
import threading
import time
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING

import numpy as np

from prm9tool.catalogue import CATALOGUE
from prm9tool.characterize.rig import Rig, RigInfo, ValveFaultError, counts
from prm9tool.errors import CommunicationError, Prm9Error
from prm9tool.messages import QT_TRANSLATE_NOOP

if TYPE_CHECKING:
    from prm9tool.device.canlink.session import CanopenSession
    from prm9tool.device.records import ValveStatus
    from prm9tool.device.session import ValveSession
    from prm9tool.device.setpoint import SetpointLink

DEMAND_KEYS = ("position_setpoint", "process_setpoint")  # the demand the master wrote
RESPONSE_OBJECTS = {"position_actual": "POSACT", "process_actual": "PRCACT"}  # 0x6301/0x6381
LATE_PERIODS = 2.0  # a sample this many periods behind its time is late
LATE_SHARE = 0.05  # at most this share of a test's samples may be late
TRIAL_LATE_SHARE = 0.01  # the pace is kept when at most this share of the trial is late
PROBES = 20  # SDO round trips measured to choose the period
MIN_PERIOD_S = 0.002  # decision: below this a loaded PC cannot keep the period by sleeping
MAX_PERIOD_S = 0.05  # the slowest pace tried (20 Hz)
TRIAL = 200  # samples of the trial run at the chosen pace
CHECK_S = 0.2  # a stop request is looked at this often during a play


class LinkTooSlowError(CommunicationError):
    """The link could not keep the sample period; the test was stopped (nothing interpolated)."""

    summary = QT_TRANSLATE_NOOP("Errors", "The link could not keep the test's sample rate.")


class CanRig(Rig):
    """A -CA valve over an open :class:`CanopenSession` (see the module docstring)."""

    def __init__(self, session: CanopenSession, period_s: float | None = None) -> None:
        super().__init__()
        self.session = session
        self._link: SetpointLink | None = None  # taken at the first play, until release()
        self._lock = threading.Lock()  # one frame at a time, in order (set vs. keep-alive)
        self._sent = 0.0  # perf_counter of the last frame
        self._quit = threading.Event()
        self._keeper: threading.Thread | None = None
        self._keeper_error: Exception | None = None
        self.period_s = period_s if period_s is not None else self._measure_period()
        options = session.options
        info = session.info
        self.info = RigInfo(
            info.type_key,
            info.serial,
            info.firmware,
            f"CANopen node {session.node_id} ({options.interface} {options.channel}), "
            f"SDO polling, one sample per {self.period_s * 1000:g} ms",
            1.0 / self.period_s,
        )
        self.late = 0  # samples of the last play taken late (LATE_PERIODS)

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

    def play(self, setpoint_pct: np.ndarray, keys: Sequence[str]) -> np.ndarray:
        """One setpoint frame and one reading per sample period (see the module docstring)."""
        sdo = self.session.sdo
        checks = max(1, round(CHECK_S / self.period_s))
        values = [counts(float(v)) for v in setpoint_pct]
        self._take(values[0])
        rows = np.full((len(values), len(keys)), np.nan)
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
                elif key in RESPONSE_OBJECTS:
                    obj = CATALOGUE[RESPONSE_OBJECTS[key]]
                    rows[i, column] = int(obj.dtype.decode(sdo.upload(obj.index, obj.subindex)))
            due += self.period_s
        self.late = late
        if late > LATE_SHARE * len(values):
            raise LinkTooSlowError(
                f"the CANopen link did not keep one sample per {self.period_s * 1000:g} ms "
                f"({late} of {len(values)} samples late); the test was stopped, nothing was "
                "interpolated"
            )
        status = self.session.status()
        if status.error_code:
            raise ValveFaultError(
                f"the valve reported error {status.error_code:#06x}: {status.error_text}"
            )
        self.last_demand = np.asarray(values, dtype=float) / 163.84
        return rows

    def _take(self, first: int) -> None:
        """Take the setpoint over (once until :meth:`release`) and start the keeper."""
        if self._link is not None:
            return
        link = self.session.setpoint_link()
        link.begin(first)  # a refusal says what to do; nothing runs then
        self._link, self._sent = link, time.perf_counter()
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

    def status(self) -> ValveStatus:
        """Status by SDO."""
        return self.session.status()


def rig_for_session(session: ValveSession, link: str = "USB") -> Rig:
    """The rig for an open session: :class:`CanRig` over CANopen, else a
    :class:`~prm9tool.characterize.rig.SessionRig` streaming at 5 kHz (``link`` names it)."""
    from prm9tool.characterize.rig import SessionRig
    from prm9tool.device.canlink.session import CanopenSession

    if isinstance(session, CanopenSession):
        return CanRig(session)
    return SessionRig(session, link)

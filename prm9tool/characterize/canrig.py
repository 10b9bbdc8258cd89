"""The valve under test over the CANopen link: the stimulus and the samples by SDO.

The CANopen link has no stream of measuring points sampled in one firmware cycle. The rig
therefore runs its own loop on the master: each sample period it writes the override value
(SETPOVR, only when it changes) and then reads the response's object (actual position 0x6301,
process actual value 0x6381) — the demand of a sample is the value whose write the valve had
confirmed before the response was read, so it is known exactly without an object for it, and
the phase between them is accurate to one SDO round trip. Measuring points without an object
on the link (the controller's output, the setpoint chain's stages) give NaN, never a made-up
value.

The sample period is chosen from the SDO round trips measured when the rig is made (at least
2 ms) and a trial run at that pace (doubled while more than 1 % of the trial comes late); more
than 5 % of a test's samples taken over two periods late make the play fail rather than be
stretched
or interpolated (:class:`LinkTooSlowError`). The TPDO1 scope
(:mod:`prm9tool.device.canlink.pdo_scope`) is not used: its samples carry no demand value.
"""

from __future__ import annotations

import math
import time
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING

import numpy as np

from prm9tool.catalogue import CATALOGUE
from prm9tool.characterize.rig import Rig, RigInfo, ValveFaultError, counts
from prm9tool.errors import CommunicationError
from prm9tool.messages import QT_TRANSLATE_NOOP

if TYPE_CHECKING:
    from prm9tool.device.canlink.session import CanopenSession
    from prm9tool.device.emulator.states import ValveStatus
    from prm9tool.device.session import ValveSession

DEMAND_KEYS = ("position_setpoint", "process_setpoint")  # the demand the master wrote
RESPONSE_OBJECTS = {"position_actual": "POSACT", "process_actual": "PRCACT"}  # 0x6301/0x6381
LATE_PERIODS = 2.0  # a sample this many periods behind its time is late
LATE_SHARE = 0.05  # at most this share of a test's samples may be late
TRIAL_LATE_SHARE = 0.01  # the pace is kept when at most this share of the trial is late
PROBES = 20  # SDO round trips measured to choose the period
MIN_PERIOD_S = 0.002  # decision: below this a loaded PC cannot keep the period by sleeping
MAX_PERIOD_S = 0.05  # the slowest pace tried (20 Hz)
TRIAL = 200  # samples of the trial run at the chosen pace
KEEP_ALIVE_S = 0.2  # SETPOVRON is written again this often (the valve drops it after 0.5 s)


class LinkTooSlowError(CommunicationError):
    """The link could not keep the sample period; the test was stopped (nothing interpolated)."""

    summary = QT_TRANSLATE_NOOP("Errors", "The link could not keep the test's sample rate.")


class CanRig(Rig):
    """A -CA valve over an open :class:`CanopenSession` (see the module docstring)."""

    def __init__(self, session: CanopenSession, period_s: float | None = None) -> None:
        super().__init__()
        self.session = session
        self._over = CATALOGUE["SETPOVR"]
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
        """Twice the 90th percentile of measured write + read round trips, rounded up to
        0.5 ms (≥ 2 ms); then tried for TRIAL samples at that pace (other threads and
        processes take their share of the PC too) and doubled while too many come late."""
        sdo = self.session.sdo
        obj = CATALOGUE["POSACT"]
        data = self._over.dtype.encode(int(self.session.read("SETPOVR")))

        def tick() -> None:
            sdo.download(self._over.index, self._over.subindex, data)  # the override is off
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
        """One override value and one reading per sample period (see the module docstring)."""
        sdo, over = self.session.sdo, self._over
        on = CATALOGUE["SETPOVRON"]
        keep_alive = max(1, round(KEEP_ALIVE_S / self.period_s))
        values = [counts(float(v)) for v in setpoint_pct]
        self.write({"SETPOVR": values[0], "SETPOVRON": 1})
        last = values[0]
        rows = np.full((len(values), len(keys)), np.nan)
        late = 0
        due = time.perf_counter()
        for i, value in enumerate(values):
            if i % keep_alive == 0:
                self.check()
                sdo.download(on.index, on.subindex, on.dtype.encode(1))
            wait = due - time.perf_counter()
            if wait > 0:
                time.sleep(wait)
            elif -wait > LATE_PERIODS * self.period_s:
                late += 1
            if value != last:
                sdo.download(over.index, over.subindex, over.dtype.encode(value))
                last = value
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

    def status(self) -> ValveStatus:
        """Status by SDO."""
        return self.session.status()

    def release(self) -> None:
        """Override off."""
        self.session.write("SETPOVRON", 0)


def rig_for_session(session: ValveSession, link: str = "USB") -> Rig:
    """The rig for an open session: :class:`CanRig` over CANopen, else a
    :class:`~prm9tool.characterize.rig.SessionRig` streaming at 5 kHz (``link`` names it)."""
    from prm9tool.characterize.rig import SessionRig
    from prm9tool.device.canlink.session import CanopenSession

    if isinstance(session, CanopenSession):
        return CanRig(session)
    return SessionRig(session, link)

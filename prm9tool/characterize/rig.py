"""The valve under test: parameters, the setpoint from the PC and synchronous measuring points.

Every procedure drives the valve's setpoint from the PC and records up to three measuring
points sampled in the same firmware cycle. :class:`EmulatorRig` steps an emulated valve itself,
as fast as the CPU allows, through the service override (SETPOVRON/SETPOVR); :class:`SessionRig`
works over a valve session with a stream (USB) through the session's setpoint link (over USB
the override) at the rate its stream gives. Over CANopen
(:class:`~prm9tool.characterize.canrig.CanRig`) the setpoint travels in RPDO1.
"""

from __future__ import annotations

import threading
import time
from abc import ABC, abstractmethod
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, TypeVar

import numpy as np

from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.scale import FULL_SCALE
from prm9tool.device.records import DeviceState, NmtState, ValveStatus
from prm9tool.device.stream import StreamReader
from prm9tool.errors import CommunicationError, Prm9Error
from prm9tool.messages import QT_TRANSLATE_NOOP

if TYPE_CHECKING:
    from prm9tool.device.emulator import EmulatedValve
    from prm9tool.device.session import ValveSession

T = TypeVar("T")
FULL = float(FULL_SCALE)  # 100 % in counts
CHUNK = 500  # samples between checks for a stop request or a fault
STOPPED = QT_TRANSLATE_NOOP("Characterize", "stopped by the user; the valve was put back as it was")
REPORTED = QT_TRANSLATE_NOOP("Characterize", "the valve reported error {0}: {1}")


ATTEMPTS = 5  # a test whose samples the link lost runs at most this often in all
LATE_SHARE = 0.05  # at most this share of a test's samples may be late or lost (bridged)
MAX_GAP_S = 0.005  # decision: a longer run of lost samples is not bridged (half of 100 Hz)


class LinkTooSlowError(CommunicationError):
    """The link could not keep the sample period; the test was stopped (nothing interpolated)."""

    summary = QT_TRANSLATE_NOOP("Errors", "The link could not keep the test's sample rate.")


def retried(run: Callable[[], T], attempts: int = ATTEMPTS) -> T:
    """``run()`` again from its start when the link lost too many of its samples (a busy PC
    over CANopen), at most ``attempts`` times in all; the last refusal is raised. ``run`` must
    bring the valve to its start itself (a step settles first)."""
    for _ in range(attempts - 1):
        try:
            return run()
        except LinkTooSlowError:
            continue
    return run()


def longest_run(mask: np.ndarray) -> int:
    """The longest run of True in ``mask``."""
    if not mask.any():
        return 0
    edges = np.flatnonzero(np.diff(np.concatenate([[0], mask.astype(np.int8), [0]])))
    return int((edges[1::2] - edges[::2]).max())


def bridged(values: np.ndarray) -> np.ndarray:
    """NaN samples replaced by the straight line between their neighbours (ends: the nearest)."""
    missing = np.isnan(values)
    if not missing.any() or missing.all():
        return values
    index = np.arange(len(values))
    out = values.copy()
    out[missing] = np.interp(index[missing], index[~missing], values[~missing])
    return out


def bridgeable(missing: np.ndarray, fs: float) -> bool:
    """True when the lost samples may be bridged for an analysis that needs every sample: at
    most :data:`LATE_SHARE` of them, none in a run longer than :data:`MAX_GAP_S`."""
    return bool(
        missing.sum() <= LATE_SHARE * len(missing) and longest_run(missing) <= MAX_GAP_S * fs
    )


class Stopped(Prm9Error):  # noqa: N818 (a user's request, not a failure)
    """The user stopped the procedure; the valve was put back as it was."""


class ValveFaultError(Prm9Error):
    """The valve reported an error during a procedure; the test was stopped."""


class WaitsForMasterError(ValveFaultError):
    """A -CA valve with CANopen on waits for its master to enable it (device state INIT): the
    caller may say how to enable it (the window's question, the command line's ``--enable``)."""


@dataclass(frozen=True)
class RigInfo:
    """What the report says about the valve and the link."""

    type_key: str
    serial: int
    firmware: str
    link: str  # how it was measured, for the report ("CANopen node 10 (…), SDO polling …")
    sample_rate_hz: float
    device_id: str = ""  # the valve's device ID (``emulator:KEY:SERIAL``, ``can:10`` …)


class Rig(ABC):
    """A valve under test (see the module docstring). ``stop`` may be set from any thread."""

    info: RigInfo

    def __init__(self) -> None:
        self.stop = threading.Event()
        self.last_demand = np.empty(0)  # the override in %, per sample of the last play()
        self.last_missing = np.zeros(0, dtype=bool)  # samples of the last play() lost (bridged)
        self.played_s = 0.0  # valve seconds played so far (the GUI's progress bar reads it)

    @abstractmethod
    def read(self, mnemonics: Sequence[str]) -> dict[str, int]:
        """Raw values of parameters."""

    @abstractmethod
    def write(self, values: Mapping[str, int]) -> None:
        """Write raw values (in the given order)."""

    @abstractmethod
    def play(self, setpoint_pct: np.ndarray, keys: Sequence[str], gaps: bool = False) -> np.ndarray:
        """Drive the override with ``setpoint_pct`` (one value per sample) and record ``keys``.

        Returns raw samples, shape (n, len(keys)), one row per sample period. A link that can
        lose samples (CANopen) bridges them and marks them in :attr:`last_missing`; ``gaps``:
        the caller's analysis takes them as missing, so more may be lost before the play is
        refused. Raises
        :class:`Stopped` when :attr:`stop` is set and :class:`ValveFaultError` on a valve error;
        the override stays on until :meth:`release`.
        """

    @abstractmethod
    def release(self) -> None:
        """Switch the override off (the valve follows its own setpoint input again)."""

    @abstractmethod
    def status(self) -> ValveStatus:
        """The valve's state and errors."""

    def ensure_active(self) -> None:
        """ValveFaultError unless the valve follows its setpoint (DEVICE_MODE_ACTIVE, no error)."""
        status = self.status()
        if status.error_code:
            raise ValveFaultError(
                QT_TRANSLATE_NOOP(
                    "Characterize", "the valve reports error {0} ({1}); nothing was tested"
                )(f"{status.error_code:#06x}", status.error_text)
            )
        if status.device_state is not DeviceState.DEVICE_MODE_ACTIVE:
            waiting = (
                status.device_state is DeviceState.INIT and status.nmt_state is not NmtState.OFF
            )
            template = (
                QT_TRANSLATE_NOOP(
                    "Characterize",
                    "the valve does not follow its setpoint: device state {0} (a -CA valve with "
                    "CANopen on waits for its master to enable it); nothing was tested",
                )
                if waiting
                else QT_TRANSLATE_NOOP(
                    "Characterize",
                    "the valve does not follow its setpoint: device state {0}; nothing was tested",
                )
            )
            seen = status.device_state.value
            if status.status_word is not None:  # over CANopen: the word it was read from
                seen = f"{seen} (status word 0x{status.status_word:04X})"
            raise (WaitsForMasterError if waiting else ValveFaultError)(template(seen))

    def check(self) -> None:
        """Raise :class:`Stopped` if a stop was requested."""
        if self.stop.is_set():
            raise Stopped(STOPPED())


def counts(pct: float) -> int:
    """Override value in counts for ``pct`` % (clipped to ±100 %)."""
    return round(min(max(pct, -100.0), 100.0) / 100.0 * FULL)


class EmulatorRig(Rig):
    """An emulated valve stepped by the procedure itself: no pacing, no link."""

    def __init__(self, valve: EmulatedValve) -> None:
        super().__init__()
        self.valve = valve
        self.info = RigInfo(
            str(valve.type_key),
            valve.serial,
            valve.firmware_version,
            "emulator (stepped faster than real time)",
            1.0 / valve.CYCLE_S,
            f"emulator:{valve.type_key}:{valve.serial}",
        )
        self.valve_seconds = 0.0  # valve time the procedures took (benchmarks)
        while valve.status().booting:
            valve.advance(0.05)

    def read(self, mnemonics: Sequence[str]) -> dict[str, int]:
        """Raw values from the object dictionary."""
        out = {}
        for mnemonic in mnemonics:
            param = CATALOGUE[mnemonic]
            out[mnemonic] = int(self.valve.read(param.index, param.subindex))
        return out

    def write(self, values: Mapping[str, int]) -> None:
        """Write into the object dictionary."""
        for mnemonic, raw in values.items():
            param = CATALOGUE[mnemonic]
            self.valve.write(param.index, param.subindex, int(raw))

    def play(self, setpoint_pct: np.ndarray, keys: Sequence[str], gaps: bool = False) -> np.ndarray:
        """One override value per 200 µs cycle; the capture records every cycle (no gaps)."""
        valve = self.valve
        over = CATALOGUE["SETPOVR"]
        self.write({"SETPOVR": counts(float(setpoint_pct[0])), "SETPOVRON": 1})
        # the emulated valve's own capture, not a session's stream (no StreamReader): the rig
        # steps the valve's time itself, so every cycle's sample is there and none can be late
        valve.capture_start(list(keys), 1)
        values = [counts(float(v)) for v in setpoint_pct]
        blocks = []
        last = None
        try:
            for start in range(0, len(values), CHUNK):
                self.check()
                for value, run in _runs(values[start : start + CHUNK]):
                    if value != last:
                        valve.write(over.index, over.subindex, value)
                        last = value
                    valve.advance(run * valve.CYCLE_S)
                valve.usb_activity()
                blocks.append(valve.capture_read())
                self.played_s += len(values[start : start + CHUNK]) * valve.CYCLE_S
                self._check_fault()
        finally:
            valve.capture_stop()
        self.valve_seconds += len(values) * valve.CYCLE_S
        self.last_demand = np.asarray(setpoint_pct, dtype=float)
        return np.concatenate(blocks)[: len(values)]

    def status(self) -> ValveStatus:
        """The emulated valve's status."""
        return self.valve.status()

    def _check_fault(self) -> None:
        status = self.valve.status()
        if status.error_code:
            raise ValveFaultError(REPORTED(f"{status.error_code:#06x}", status.error_text))

    def release(self) -> None:
        """Override off."""
        self.write({"SETPOVRON": 0})


def _runs(values: list[int]) -> list[tuple[int, int]]:
    """Run-length encoding: ``[(value, repeats), …]``."""
    runs: list[tuple[int, int]] = []
    for value in values:
        if runs and runs[-1][0] == value:
            runs[-1] = (value, runs[-1][1] + 1)
        else:
            runs.append((value, 1))
    return runs


class SessionRig(Rig):
    """Any open valve session: the setpoint is driven through the session's setpoint link
    (``session.setpoint_link()``, over USB the override) at the link's pace, samples stream in.

    The stimulus is written once per ``update`` samples (a USB report takes about 1 ms); the
    analysis uses the demand value the valve recorded, not the stimulus, so neither the
    link's latency nor its jitter enters the figures.
    """

    def __init__(self, session: ValveSession, link: str, rate_hz: int = 5000) -> None:
        super().__init__()
        self.session = session
        info = session.info
        self.info = RigInfo(
            info.type_key, info.serial, info.firmware, link, float(rate_hz), info.device_id
        )
        self.rate_hz = rate_hz
        self.update = max(1, rate_hz // 1000)
        self._link = session.setpoint_link()  # over USB the override SETPOVRON/SETPOVR
        self._wait_booted()

    def _wait_booted(self, limit: int = 5000) -> None:
        """A valve just powered up ignores its setpoint for ~2 s: ask until it has booted."""
        for _ in range(limit):
            if not self.session.status().booting:
                return
            time.sleep(0.001)
        raise ValveFaultError(
            QT_TRANSLATE_NOOP("Characterize", "the valve did not finish booting")()
        )

    def read(self, mnemonics: Sequence[str]) -> dict[str, int]:
        """Raw values over the link."""
        return {k: int(v) for k, v in self.session.read_many(list(mnemonics)).items()}

    def write(self, values: Mapping[str, int]) -> None:
        """Write over the link."""
        self.session.write_many(dict(values))

    def play(self, setpoint_pct: np.ndarray, keys: Sequence[str], gaps: bool = False) -> np.ndarray:
        """Write the stimulus at the link's pace while collecting the stream (no gaps).

        The stimulus is a function of the valve's time: each write sends the value for the
        samples received so far, so a slow link writes less often but never stretches the
        excitation. :attr:`last_demand` is the value in effect for each sample (±1 report).
        """
        session = self.session
        n = len(setpoint_pct)
        link = self._link
        # the stream reader of every capture: a valve that goes silent ends the play in the
        # capture's words instead of waiting for samples that never come
        reader = StreamReader(session, keys, self.rate_hz)
        reader.start()
        link.begin(counts(float(setpoint_pct[0])))  # again each play: the valve may have dropped it
        blocks: list[np.ndarray] = []
        demand = np.empty(n)
        try:
            while (received := reader.received) < n:
                self.check()
                value = float(setpoint_pct[received])
                link.set(counts(value))
                block = reader.read(expected=n)
                blocks.append(block)
                demand[received : received + len(block)] = value
                self.played_s += len(block) / self.rate_hz
        finally:
            reader.stop()
        status = session.status()
        if status.error_code:
            raise ValveFaultError(REPORTED(f"{status.error_code:#06x}", status.error_text))
        if "SETPOVRON" in link.objects and not session.read("SETPOVRON"):
            # the firmware drops the override after 0.5 s without a report: a PC that paused
            # the link that long left the valve on its own setpoint for the rest of the play
            raise LinkTooSlowError(
                "the link paused longer than the valve keeps its setpoint override (0.5 s "
                "without a report): the valve followed its own setpoint for part of the test; "
                "the test was stopped, nothing was measured from it"
            )
        self.last_demand = demand
        return np.concatenate(blocks)[:n]

    def status(self) -> ValveStatus:
        """Status over the link."""
        return self.session.status()

    def release(self) -> None:
        """Give the setpoint back (the link's end: over USB the override off)."""
        self._link.end()


def write_values(valve: Any, values: Mapping[str, int]) -> None:
    """Write ``values`` (raw) into the emulated ``valve``'s working memory; one the valve
    refuses (e.g. a CANopen setpoint type on an analog copy) keeps its default."""
    for mnemonic, raw in values.items():
        param = CATALOGUE[mnemonic]
        try:
            valve.write(param.index, param.subindex, raw)
        except Prm9Error:
            continue

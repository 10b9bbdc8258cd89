"""The proof of a twin (issue 31 item 4): characterize the twin with the procedure the valve
was characterized with and set the figures side by side — ratios twin/valve, and differences
in percentage points for the figures in % (overshoot, dead band, hysteresis). No Qt."""

from __future__ import annotations

import itertools
import math
import os
from dataclasses import dataclass
from typing import TYPE_CHECKING

from prm9tool.errors import Prm9Error

if TYPE_CHECKING:
    from collections.abc import Callable, Mapping

    from prm9tool.characterize.run import Characterization
    from prm9tool.device.emulator import EmulatedValve

ENABLED_S = 0.1  # the enable sequence taken before the master comes (the firmware's 1 ms task)
_channels = itertools.count()  # the private buses' channels of this process


@dataclass(frozen=True)
class Side:
    """One figure of the valve and of its twin."""

    name: str
    label: str
    unit: str
    valve: float
    twin: float

    @property
    def ratio(self) -> float:
        """twin / valve (nan when the valve's figure is 0 or not finite)."""
        if not (math.isfinite(self.valve) and math.isfinite(self.twin)) or self.valve == 0:
            return math.nan
        return self.twin / self.valve

    @property
    def difference(self) -> float:
        """twin − valve, in the figure's unit (percentage points for %)."""
        return self.twin - self.valve


CAN_LINK = "CANopen node"  # how a CAN run's link begins (CanRig's RigInfo.link)


def characterize_twin(run: Characterization, twin: str | os.PathLike[str]) -> Characterization:
    """The twin file ``twin`` characterized as ``run`` was: its profile, over the same kind of
    link. A run over CANopen (``run.info.link`` "CANopen node …") characterizes the twin as an
    emulated -CA valve on a private virtual CAN bus through the CAN master at the run's sample
    period (:func:`characterize_twin_over_can`); any other run on an emulated valve stepped as
    fast as the CPU allows, through the override at 5 kHz (a USB run's path)."""
    if run.info.link.startswith(CAN_LINK):
        return characterize_twin_over_can(run, twin)
    from prm9tool.characterize.rig import EmulatorRig
    from prm9tool.characterize.run import characterize
    from prm9tool.device.emulator.twinfile import emulated_twin

    valve = emulated_twin(os.fspath(twin))
    if valve.type_key.canopen:  # a -CA twin waits for its master, as the valve did
        _commission(valve)
    return characterize(EmulatorRig(valve), run.profile)


def characterize_twin_over_can(
    run: Characterization, twin: str | os.PathLike[str]
) -> Characterization:
    """The twin characterized as the CAN run ``run`` was: an emulated -CA valve with the
    valve's object dictionary (only the manual's objects when the valve had no others, see
    :func:`object_dictionary`) on a virtual CAN channel of its own, reached by the tool's
    CANopen master (:class:`~prm9tool.characterize.canrig.CanRig`: setpoint in RPDO1, TPDO1
    at the tool's SYNC) at the run's sample period, and stepped by that SYNC
    (:class:`~prm9tool.twin.syncstep.SyncStepper`): sample ``k`` is the twin at ``k``
    periods, as the valve's was at its SYNC. It runs in real time (the profile's length)."""
    import uuid

    import can

    from prm9tool.characterize.canrig import CanRig
    from prm9tool.characterize.run import characterize
    from prm9tool.device.canlink.bus import CanOptions
    from prm9tool.device.canlink.session import CanopenSession
    from prm9tool.device.emulator.twinfile import emulated_twin
    from prm9tool.twin.syncstep import SyncStepper

    valve = emulated_twin(os.fspath(twin), od=object_dictionary(run))
    if not valve.type_key.canopen:
        raise Prm9Error(f"the twin of a CAN run is a -CA valve, not {valve.type_key}")
    period_s = 1.0 / run.info.sample_rate_hz
    channel = f"prm9tool-twin-proof-{uuid.uuid4().hex[:12]}-{next(_channels)}"
    bus = can.Bus(interface="virtual", channel=channel, preserve_timestamps=True)
    try:
        stepper = SyncStepper(valve, bus, period_s).attach()
        slave = valve.connect_can(bus)
        try:
            _commission(valve)
            valve.advance(ENABLED_S)
            session = CanopenSession(
                CanOptions("virtual", channel), slave.node_id, type_key=str(valve.type_key)
            )
            try:
                return characterize(CanRig(session, period_s, stepper.clock), run.profile)
            finally:
                session.close()
        finally:
            slave.stop()
    finally:
        bus.shutdown()


def object_dictionary(run: Characterization) -> str:
    """The object dictionary the run's valve had, as the emulator names it: ``manual`` when
    it read none of the parameters whose address is this project's decision (a valve with
    only the objects of the manual's tables), else ``full``."""
    from prm9tool.catalogue import CATALOGUE

    decided = {p.key for p in CATALOGUE if not p.address_from_manual}
    return "full" if decided & set(run.parameters) else "manual"


def _commission(valve: EmulatedValve) -> None:
    """Boot ``valve`` and start it as its master did the valve's: NMT start, control word
    08h → 09h → 0Bh → 0Fh (manual §7.6)."""
    from prm9tool.catalogue import CATALOGUE
    from prm9tool.catalogue.commissioning import ENABLE_SEQUENCE, NmtCommand

    while valve.status().booting:
        valve.advance(0.05)
    valve.nmt_command(NmtCommand.START)
    word = CATALOGUE["CONTROLWORD"]
    for value in ENABLE_SEQUENCE:
        valve.write(word.index, word.subindex, value)


def side_by_side(run: Characterization, again: Characterization) -> list[Side]:
    """The figures both runs measured, in the valve's run's order."""
    theirs = {f.name: f for f in again.figures}
    return [
        Side(f.name, f.label, f.unit, f.value, theirs[f.name].value)
        for f in run.figures
        if f.name in theirs
    ]


# How the last column compares a figure, by its kind ("%1" the number): the figures in % by
# their difference in percentage points, the others by their ratio. The GUI passes its
# translations of the same texts.
COMPARED = {"difference": "%1 pp (twin − valve)", "ratio": "×%1 (twin/valve)"}
NOT_REACHED = "not reached"  # a figure not measured (a settling time never reached: nan)


def compared(
    side: Side,
    number: Callable[[float], str] | None = None,
    texts: Mapping[str, str] = COMPARED,
    nothing: str = "—",
) -> str:
    """The last column's cell of ``side``: ``+0.42 pp (twin − valve)`` for a figure in %,
    ``×0.987 (twin/valve)`` for the others; ``nothing`` where there is nothing to compare (a
    figure one side did not reach, a valve's figure of 0). ``number`` writes the number (the
    GUI's in the program language; by default two decimals of a difference, three of a
    ratio), ``texts`` the kinds (:data:`COMPARED`, translated)."""
    if side.unit == "%":
        kind, value = "difference", side.difference
    else:
        kind, value = "ratio", side.ratio
    if not math.isfinite(value):
        return nothing
    if number is None:
        shown = f"{value:.2f}" if kind == "difference" else f"{value:.3f}"
    else:
        shown = number(value)
    if kind == "difference" and not shown.startswith(("-", "−")):  # −0.0 has its sign
        shown = "+" + shown
    return texts[kind].replace("%1", shown)


def table(sides: list[Side]) -> list[str]:
    """The side-by-side as text lines (the command line's): a figure not reached is "not
    reached", the last column says each row's kind of comparison (:func:`compared`)."""

    def value(v: float) -> str:
        return f"{v:.4g}" if math.isfinite(v) else NOT_REACHED

    lines = [f"{'figure':<34} {'valve':>11} {'twin':>11}  {'unit':<4}  twin compared with valve"]
    for s in sides:
        lines.append(
            f"{s.label:<34} {value(s.valve):>11} {value(s.twin):>11}  {s.unit:<4}  {compared(s)}"
        )
    return lines

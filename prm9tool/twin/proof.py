"""The proof of a twin (issue 31 item 4): characterize the twin with the procedure the valve
was characterized with and set the figures side by side — ratios twin/valve, and differences
in percentage points for the figures in % (overshoot, dead band, hysteresis). No Qt."""

from __future__ import annotations

import math
import os
from dataclasses import dataclass
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from prm9tool.characterize.run import Characterization


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


def characterize_twin(run: Characterization, twin: str | os.PathLike[str]) -> Characterization:
    """The twin file ``twin`` characterized as ``run`` was (its profile), on an emulated valve
    stepped as fast as the CPU allows."""
    from prm9tool.characterize.rig import EmulatorRig
    from prm9tool.characterize.run import characterize
    from prm9tool.device.emulator.twinfile import emulated_twin

    valve = emulated_twin(os.fspath(twin))
    if valve.type_key.canopen:  # a -CA twin waits for its master, as the valve did: its
        # commissioning (NMT start, control word 08h → 09h → 0Bh → 0Fh; manual §7.6)
        from prm9tool.catalogue import CATALOGUE
        from prm9tool.catalogue.commissioning import ENABLE_SEQUENCE, NmtCommand

        while valve.status().booting:
            valve.advance(0.05)
        valve.nmt_command(NmtCommand.START)
        word = CATALOGUE["CONTROLWORD"]
        for value in ENABLE_SEQUENCE:
            valve.write(word.index, word.subindex, value)
    return characterize(EmulatorRig(valve), run.profile)


def side_by_side(run: Characterization, again: Characterization) -> list[Side]:
    """The figures both runs measured, in the valve's run's order."""
    theirs = {f.name: f for f in again.figures}
    return [
        Side(f.name, f.label, f.unit, f.value, theirs[f.name].value)
        for f in run.figures
        if f.name in theirs
    ]


def table(sides: list[Side]) -> list[str]:
    """The side-by-side as text lines (the command line's)."""
    lines = [f"{'figure':<34} {'valve':>10} {'twin':>10}  twin/valve"]
    for s in sides:
        extra = f"{s.difference:+.2f} pp" if s.unit == "%" else f"{s.ratio:.3f}"
        lines.append(f"{s.label:<34} {s.valve:>10.4g} {s.twin:>10.4g}  {extra}  {s.unit}")
    return lines

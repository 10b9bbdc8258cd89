"""The twins a serial has in the history (issue 31 item 3), for the window: the emulated
valve's choice in the connect dialog and the plant the offline tuning runs on. No Qt.

A twin is found through the serial's ``twin`` history records (``--fit-twin``,
``Valve.fit_twin``: docs/twin.md), newest first; a record whose file is gone or cannot be read
is listed with why, and is not used as a plant.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from prm9tool.errors import Prm9Error

if TYPE_CHECKING:
    from prm9tool.device.emulator.constants import PlantConstants


@dataclass(frozen=True)
class TwinChoice:
    """One twin of a serial's history: when it was fitted, its file, and why it cannot be used
    (empty when it can)."""

    serial: int
    date: str
    path: str
    problem: str = ""

    @property
    def spec(self) -> str:
        """The emulator spec of this twin (``twin:FILE``: ``--emulator``, the dialog's list)."""
        return f"twin:{self.path}"


@dataclass(frozen=True)
class TwinPlant:
    """The plant of a serial's newest usable twin, and the words that say so."""

    plant: PlantConstants
    path: str
    date: str
    serial: int

    @property
    def label(self) -> str:
        """English ("twin of serial 4101, fitted 2026-12-02 (FILE)"); a view translates the
        pattern with :func:`label_parts`."""
        return f"twin of serial {self.serial}, fitted {self.date[:10]} ({self.path})"


def twins_of(serial: int, url: str | None = None) -> list[TwinChoice]:
    """The twins recorded for ``serial``, newest first; [] when the history has none or cannot
    be read (the window then offers the plain emulated valve, as without a history)."""
    from prm9tool.history import records
    from prm9tool.twin.twinfile import read_twin

    try:
        rows = records(serial, url)
    except Prm9Error:
        return []
    out: list[TwinChoice] = []
    seen: set[str] = set()
    for row in reversed(rows):
        if row.get("operation") != "twin":
            continue
        path = str((row.get("details") or {}).get("twin_file") or "")
        if not path or path in seen:
            continue
        seen.add(path)
        problem, date = "", str(row.get("recorded_at") or "")
        try:
            twin = read_twin(path)
        except Prm9Error as exc:
            problem = str(exc)
        else:
            date = twin.date or date
            if twin.serial != serial:
                problem = f"{path} is the twin of serial {twin.serial}, not {serial}"
        out.append(TwinChoice(serial, date, path, problem))
    return out


def twin_plant(serial: int | None, url: str | None = None) -> TwinPlant | None:
    """The plant of ``serial``'s newest usable twin; None when it has none (or no serial)."""
    from prm9tool.twin.twinfile import read_twin

    if serial is None:
        return None
    for choice in twins_of(serial, url):
        if not choice.problem:
            return TwinPlant(read_twin(choice.path).plant, choice.path, choice.date, serial)
    return None


def spec_serial(spec: str) -> int | None:
    """The serial of an emulator spec (``TYPEKEY:SERIAL``, or ``twin:FILE``: its file's);
    None when it has none that can be read."""
    from prm9tool.twin.twinfile import read_twin

    if spec.startswith("twin:"):
        try:
            return read_twin(spec[len("twin:") :]).serial
        except Prm9Error:
            return None
    tail = spec.rpartition(":")[2]
    return int(tail) if tail.isdigit() else None

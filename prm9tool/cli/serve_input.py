"""``--serve-emulator``'s stdin: inject and clear physical faults while a PLC talks to the valves.

One command a line (docs/plc-testing.md, *Faults*)::

    inject <valve> <FAULT>     make the fault happen (COIL_A_OPEN, SUPPLY_LOW, …)
    clear <valve> <FAULT>      take it away again; the firmware recovers as a real valve does
    faults                     list the fault names and what is injected on each valve

``<valve>`` is a serial number, ``node:<id>``, or ``all``. A line that cannot be done is
answered in words on the serve log and changes nothing. The fault is physical (a broken wire, a
low supply): what the firmware then detects, reports by EMCY and how it reacts is the valve's
own behaviour, exactly what a PLC must handle. stdin at its end (closed, ``/dev/null``) simply
ends the listening; a terminal is read only while the process is in its foreground (reading it
from the background, ``prm9tool --serve-emulator … &``, would stop the process by SIGTTIN).
"""

from __future__ import annotations

import os
import threading
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING, TextIO

from prm9tool.device.emulator.states import Fault
from prm9tool.errors import Prm9Error

if TYPE_CHECKING:
    from prm9tool.device.emulator import EmulatedValve

USAGE = "commands: inject <serial|node:<id>|all> <FAULT>, clear <…> <FAULT>, faults"


def listen(stream: TextIO, valves: Sequence[EmulatedValve], say: Callable[[str], None]) -> None:
    """Read commands from ``stream`` in a daemon thread until it ends."""
    if _background_terminal(stream):
        return

    def run() -> None:
        for line in stream:
            if line.strip():
                say(execute(line, valves))

    threading.Thread(target=run, name="prm9-serve-input", daemon=True).start()


def execute(line: str, valves: Sequence[EmulatedValve]) -> str:
    """Do one command line; returns the line for the serve log (what was done, or why not)."""
    words = line.split()
    if words == ["faults"]:
        return _faults(valves)
    if len(words) != 3 or words[0] not in ("inject", "clear"):
        return f"not understood: {line.strip()!r} ({USAGE})"
    verb, which, name = words
    try:
        fault = Fault(name.upper())
    except ValueError:
        names = ", ".join(f.value for f in Fault)
        return f"{verb}: no fault {name!r}; faults are: {names}"
    chosen = _select(which, valves)
    if not chosen:
        return f"{verb}: no served valve {which!r} (a serial number, node:<id> or all)"
    for valve in chosen:
        try:
            (valve.inject if verb == "inject" else valve.clear)(fault)
        except Prm9Error as exc:
            return f"{verb} {fault.value} on serial {valve.serial}: {exc}"
    done = "injected" if verb == "inject" else "cleared"
    serials = ", ".join(str(v.serial) for v in chosen)
    return f"{fault.value} {done} on serial {serials}"


def _select(which: str, valves: Sequence[EmulatedValve]) -> list[EmulatedValve]:
    if which == "all":
        return list(valves)
    if which.startswith("node:"):
        node = which[5:]
        return [v for v in valves if node.isdigit() and v.node_id == int(node)]
    return [v for v in valves if which.isdigit() and v.serial == int(which)]


def _faults(valves: Sequence[EmulatedValve]) -> str:
    injected = [
        f"serial {v.serial}: {', '.join(sorted(f.value for f in v.injected())) or 'none'}"
        for v in valves
    ]
    return f"faults: {', '.join(f.value for f in Fault)}; injected: {'; '.join(injected)}"


def _background_terminal(stream: TextIO) -> bool:
    try:
        fd = stream.fileno()
        return os.isatty(fd) and os.tcgetpgrp(fd) != os.getpgrp()
    except (OSError, ValueError, AttributeError):
        return False  # no file descriptor (a test's stream) or no terminal: read it

"""The emulated valves of this process: one per serial number, made with its EEPROM image
(``<user data dir>/emulator/<serial>.json``) or from a twin file, paced in real time while a
session wants it so, and put on a python-can bus. The device factory
(:mod:`prm9tool.device.factory`) lists and opens them; tests and tools make and forget them
here. No Qt; the emulator package is imported when a valve is made.
"""

from __future__ import annotations

import threading
from collections.abc import Callable, Collection, Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import TYPE_CHECKING, Any

from prm9tool.catalogue.typekey import TypeKey
from prm9tool.errors import CanBusError, Prm9Error, TypeKeyError

if TYPE_CHECKING:
    from prm9tool.device.canlink.bus import CanOptions
    from prm9tool.device.emulator import EmulatedValve


class EmulatedValves:
    """The emulated valves of this process, one per serial number, in one registry: the
    valves, how many paced sessions run each (its real-time thread runs while > 0) and the
    object dictionary new ones get (``--od``); one lock guards them all."""

    def __init__(self) -> None:
        self.valves: dict[int, EmulatedValve] = {}
        self.running: dict[int, int] = {}
        self.twins: dict[int, Path] = {}  # serial -> the twin file its valve was made from
        self.lock = threading.Lock()
        self.od = "full"


EMULATED = EmulatedValves()


def set_emulator_od(od: str) -> None:
    """The object dictionary of the emulated valves this process makes from now on (``--od``):
    ``full`` or ``manual`` (only the objects the manual lists; prm9tool.device.emulator.manual_od).
    """
    from prm9tool.device.emulator.manual_od import OD_PROFILES

    if od not in OD_PROFILES:
        raise Prm9Error(f"--od {od}: one of {', '.join(OD_PROFILES)}")
    EMULATED.od = od


def emulated_valve(type_key: str, serial: int) -> EmulatedValve:
    """The emulated valve with ``serial`` in this process (created with its EEPROM file)."""
    from prm9tool.device.emulator import EmulatedValve

    with EMULATED.lock:
        valve = EMULATED.valves.get(serial)
        if valve is None:
            valve = EmulatedValve(
                type_key, serial, nv_path=emulator_nv_path(serial), od=EMULATED.od
            )
            EMULATED.valves[serial] = valve
        elif str(valve.type_key) != str(TypeKey.parse(type_key)):
            raise Prm9Error(
                f"emulated valve {serial} is a {valve.type_key}; choose another serial "
                f"for a {type_key}"
            )
        return valve


def twin_valve(path: str | Path) -> EmulatedValve:
    """The emulated valve of the twin file ``path`` (issue 31): the measured valve's plant
    constants, serial, type key, firmware and parameter set, made once per process and then
    found again by its serial like any emulated valve. Its parameters live in its working
    memory only (no EEPROM file: the twin file is what it starts from each time). Raises
    TwinFileError for a file that cannot be used, Prm9Error when another emulated valve has
    that serial already."""
    from prm9tool.device.emulator.twinfile import TwinFileError, emulated_twin, read_twin

    where = Path(path).expanduser().resolve()
    twin = read_twin(where)
    if not 0 < twin.serial < 2**32:
        raise TwinFileError(f"{where}: serial {twin.serial} must be a number 1…4294967295")
    with EMULATED.lock:
        valve = EMULATED.valves.get(twin.serial)
        if valve is not None:
            if EMULATED.twins.get(twin.serial) == where:
                return valve
            made = EMULATED.twins.get(twin.serial)
            raise Prm9Error(
                f"twin {where}: the emulated valve {twin.serial} is "
                + (f"the twin of {made} already" if made else f"a plain emulated {valve.type_key}")
                + " in this process, which has one emulated valve per serial: open the twin in "
                "a new process (prm9tool --emulator twin:FILE, a new Python session)"
            )
        valve = emulated_twin(twin, od=EMULATED.od)
        EMULATED.valves[twin.serial] = valve
        EMULATED.twins[twin.serial] = where
        return valve


def forget_emulated_valves() -> None:
    """Drop this process's emulated valves (their EEPROM files stay); for tests and tools."""
    from prm9tool.device.emulated import plug_cable

    with EMULATED.lock:
        for serial in EMULATED.valves:
            plug_cable(serial)
        for serial, valve in EMULATED.valves.items():
            if EMULATED.running.pop(serial, 0):
                valve.stop()
        EMULATED.valves.clear()
        EMULATED.twins.clear()


def twin_file(serial: int) -> Path | None:
    """The twin file the emulated valve ``serial`` was made from (None: a plain one)."""
    with EMULATED.lock:
        return EMULATED.twins.get(serial)


def emulator_nv_path(serial: int) -> Path:
    """The EEPROM image file of the emulated valve with ``serial``."""
    from prm9tool.paths import user_data_dir

    return user_data_dir() / "emulator" / f"{serial}.json"


def free_emulator_serial(type_key: str, first: int, taken: Collection[int] = ()) -> int:
    """The lowest serial from ``first`` on, not in ``taken``, that a ``type_key`` valve may
    have: no emulated valve of another type in this process and no EEPROM image of another
    type on disk. So ``--emulator`` of a new type does not fail on the image a valve of
    another type left at the default serial; the same type finds its stored values again."""
    from prm9tool.device.emulator.nvimage import stored_type_key

    wanted = str(TypeKey.parse(type_key))
    for serial in range(first, 2**32):
        if serial in taken:
            continue
        with EMULATED.lock:
            valve = EMULATED.valves.get(serial)
        if valve is not None:
            if str(valve.type_key) == wanted:
                return serial
            continue
        if stored_type_key(emulator_nv_path(serial)) in (None, wanted):
            return serial
    raise TypeKeyError(f"no free serial for an emulated {type_key}")


def connect_can(valve: EmulatedValve, options: CanOptions) -> Callable[[], None]:
    """Put ``valve`` on the python-can bus ``options`` (its own bit rate where none is given);
    returns what takes it off again. CanBusError when the bus cannot be opened."""
    import can

    kwargs: dict[str, Any] = {"interface": options.interface, "channel": options.channel}
    bitrate = options.bitrate if options.bitrate is not None else valve.bitrate
    if bitrate:  # default: the bit rate the valve's switches (or BITRATE) select
        kwargs["bitrate"] = bitrate
    try:
        bus = can.Bus(**kwargs)
    except (can.CanError, OSError, ValueError, ImportError) as exc:
        raise CanBusError(f"cannot open CAN bus {options}: {exc}") from exc
    slave = valve.connect_can(bus)

    def close() -> None:
        """Take the valve off the bus and release the bus."""
        slave.stop()
        bus.shutdown()

    return close


@contextmanager
def stepped_here(valve: EmulatedValve) -> Iterator[EmulatedValve]:
    """Hold a paced emulated valve's real-time thread while a procedure steps the valve itself
    (the end-of-line test of an open valve runs as fast as the CPU allows), then run it again."""
    with EMULATED.lock:
        running = EMULATED.running.get(valve.serial, 0)
    if running:
        end_paced(valve)
    try:
        yield valve
    finally:
        if running:
            run_paced(valve)


def run_paced(valve: EmulatedValve) -> None:
    """One more paced session runs ``valve``: its real-time thread runs from the first on."""
    with EMULATED.lock:
        count = EMULATED.running.get(valve.serial, 0)
        EMULATED.running[valve.serial] = count + 1
        if count == 0 and not valve.running:
            valve.start()


def end_paced(valve: EmulatedValve) -> None:
    """One paced session of ``valve`` ended: its real-time thread stops with the last one."""
    with EMULATED.lock:
        count = EMULATED.running.get(valve.serial, 0) - 1
        EMULATED.running[valve.serial] = max(count, 0)
        if count <= 0 and valve.running:
            valve.stop()

"""Finding and opening valves from a script: :func:`list_devices` and :func:`connect`.

Both go through the one device factory of the GUI and the batch mode
(:mod:`prm9tool.device.factory`), so a script sees the valves and the device IDs the
``--list-devices`` command shows. No Qt; the emulator is loaded only for ``emulator:`` IDs.
"""

from __future__ import annotations

import logging
import threading
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING

from prm9tool.device.canlink.bus import CanOptions
from prm9tool.device.factory import (
    CAN,
    EMULATOR,
    USB,
    DeviceEntry,
    can_entries,
    emulator_entries,
    open_session,
    parse_emulator_spec,
    usb_entries,
)
from prm9tool.device.records import DeviceInfo
from prm9tool.errors import CommunicationError, Prm9Error

if TYPE_CHECKING:
    from prm9tool.api.valve import Valve

__all__ = ["can_options", "connect", "list_devices"]


def can_options(
    interface: str | None = None, channel: str | None = None, bitrate: int | None = None
) -> CanOptions | None:
    """The CAN bus these python-can settings name (None when none is given); the defaults
    are the command line's (virtual, channel prm9tool, the valve's bit rate)."""
    if interface is None and channel is None and bitrate is None:
        return None
    return CanOptions.of(interface, channel, bitrate)


def list_devices(
    *,
    emulators: Sequence[str] = (),
    can_interface: str | None = None,
    can_channel: str | None = None,
    can_bitrate: int | None = None,
) -> list[DeviceInfo]:
    """The PRM9 valves that can be opened: on USB (when hidapi works), the emulated valves
    ``emulators`` names (``"TYPEKEY:SERIAL"``) and, with a CAN interface, the PRM9 nodes on
    that bus (CANopen nodes of other kinds are left out: prm9tool never writes to them).

    Each is a :class:`DeviceInfo` whose ``device_id`` :func:`connect` opens. Raises
    CanAdapterError when the CAN bus cannot be opened, TypeKeyError for a bad emulator spec.
    """
    try:
        entries = usb_entries()
    except CommunicationError:  # no hidapi on this machine: no USB valves
        entries = []
    entries += emulator_entries(emulators)
    options = can_options(can_interface, can_channel, can_bitrate)
    if options is not None:
        entries += can_entries(options)
    return [device_info(e, options) for e in entries if e.kind in (USB, EMULATOR, CAN)]


def device_info(entry: DeviceEntry, options: CanOptions | None = None) -> DeviceInfo:
    """What a listing knows of a valve, as the shared record."""
    bus = None
    if entry.kind == CAN and options is not None:
        bus = (options.interface, options.channel, options.bitrate)
    return DeviceInfo(
        type_key=entry.type_key,
        serial=entry.serial,
        firmware=entry.firmware,
        device_id=entry.device_id,
        can_bus=bus,
    )


def connect(
    device: str,
    *,
    can_interface: str | None = None,
    can_channel: str | None = None,
    can_bitrate: int | None = None,
    type_key: str | None = None,
    history_db: str | None = None,
    record_history: bool = True,
) -> Valve:
    """Open the valve ``device`` names; use it as a context manager (or call ``close()``).

    ``device``: ``"usb:PATH"`` (as :func:`list_devices` gives it) or a USB valve's serial
    number, ``"emulator:TYPEKEY[:SERIAL]"`` (an emulated valve in this process, its EEPROM in
    the user data dir; default serial 1), ``"emulator:twin:FILE"`` (the twin of one measured
    valve, its serial, plant and parameter set from the twin file: docs/twin.md) or ``"can:NODE"`` on the bus of ``can_interface``,
    ``can_channel``, ``can_bitrate`` (python-can names; default: the virtual bus
    ``prm9tool``). ``type_key``: the key on the label of a CANopen valve that does not tell
    its own. Uploads, downloads and stores go into the history database (``history_db``: an
    SQLAlchemy URL, default the GUI's) unless ``record_history`` is False.

    Raises Prm9Error for an unknown ID, TypeKeyError for a bad emulator spec, TwinFileError
    for a twin file that cannot be used, a
    CommunicationError when the valve does not answer.
    """
    from prm9tool.api.valve import Valve

    kind, _, rest = device.partition(":")
    options = can_options(can_interface, can_channel, can_bitrate)
    if kind == EMULATOR:
        key, serial = parse_emulator_spec(rest)
        device = f"{EMULATOR}:{key}:{serial}"
    elif device.isdigit():
        device = _usb_by_serial(int(device))
    elif kind == CAN:
        options = options or CanOptions()
    elif kind != USB:
        raise Prm9Error(
            f"unknown device {device!r}: expected 'usb:PATH', a serial number, "
            "'emulator:TYPEKEY[:SERIAL]', 'emulator:twin:FILE' or 'can:NODE'"
        )
    # an emulated valve runs in real time in a thread of its own while it is open, as in the GUI
    session = open_session(device, paced=True, can_link=options, label_key=type_key)
    if kind == CAN:
        session.add_close_hook(library_logs())
    return Valve(session, history_db=history_db, record_history=record_history)


_routing: list[Callable[[], None]] = []  # the undo of the routing while a CAN valve is open
_routed = 0
_routing_lock = threading.Lock()


def library_logs() -> Callable[[], None]:
    """While a script has a CANopen valve open, the ``canopen`` and ``can`` libraries'
    warnings go to the ``prm9tool.api`` logger as prm9tool's sentences (what the command line
    and the window print), not raw on standard error; returns the release (one per valve)."""
    global _routed
    from prm9tool.device.canlink.liblog import route_library_logs

    api_log = logging.getLogger("prm9tool.api")
    with _routing_lock:
        if _routed == 0:
            _routing.append(route_library_logs(lambda message: api_log.warning("%s", message)))
        _routed += 1
    released = threading.Event()

    def release() -> None:
        global _routed
        with _routing_lock:
            if released.is_set():
                return
            released.set()
            _routed -= 1
            if _routed == 0 and _routing:
                _routing.pop()()

    return release


def _usb_by_serial(serial: int) -> str:
    found = [e for e in usb_entries() if e.serial == serial]
    if not found:
        raise Prm9Error(f"no valve with serial number {serial} is connected over USB")
    return found[0].device_id

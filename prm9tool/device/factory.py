"""The one device factory of prm9tool: the GUI and the batch mode list and open valves here.

A device is a USB valve (``usb:<HID path>``), an emulated valve
(``emulator:<type key>:<serial>``; ``emulator:twin:<file>`` the twin of one measured valve,
docs/twin.md) or a valve on a CAN bus (``can:<node ID>``, on the bus of
the :class:`CanOptions` given). Emulated valves live in this process, one per serial
number (:mod:`prm9tool.device.emulated_valves`), and keep their non-volatile memory in
``<user data dir>/emulator/<serial>.json`` (``PRM9TOOL_DATA_DIR`` overrides the user data
dir), so what one run stores the next one sees.
"""

from __future__ import annotations

import logging
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from prm9tool.catalogue.typekey import DEFAULT_EMULATOR_TYPE_KEY, TypeKey
from prm9tool.device.canlink.bus import CanOptions
from prm9tool.device.emulated_valves import (
    connect_can,
    emulated_valve,
    end_paced,
    free_emulator_serial,
    run_paced,
    twin_file,
    twin_valve,
)
from prm9tool.device.records import CanNodeFacts, NmtState
from prm9tool.device.session import ValveSession
from prm9tool.errors import (
    CommunicationError,
    DeviceDisconnectedError,
    Prm9Error,
    TypeKeyError,
)

if TYPE_CHECKING:
    from prm9tool.device.emulator import EmulatedValve

log = logging.getLogger("prm9tool.device.factory")
DEFAULT_EMULATOR_TYPE = DEFAULT_EMULATOR_TYPE_KEY  # one default for the GUI and the CLI
USB, EMULATOR, CAN, NOT_PRM9 = "usb", "emulator", "can", "not-prm9"
TWIN = "twin"  # emulator:twin:FILE, --emulator twin:FILE
UNUSABLE_EMULATOR = "emulator-unusable"  # a remembered emulated valve that cannot be made
__all__ = [
    "LINKS",
    "CanOptions",
    "DeviceEntry",
    "LinkOptions",
    "list_devices",
    "open_link",
    "open_session",
]


@dataclass(frozen=True)
class DeviceEntry:
    """One valve that can be opened."""

    device_id: str
    kind: str  # "usb" | "emulator" | "can" | "not-prm9" (a CANopen node of another kind)
    # | "emulator-unusable" (a remembered spec that cannot be made; description: why)
    type_key: str
    serial: int
    firmware: str
    description: str
    nmt_state: NmtState | None = None  # CAN nodes: as the heartbeat said during the scan
    heartbeat_age_s: float | None = None  # CAN nodes: seconds since the last heartbeat
    last_emcy: str = ""  # CAN nodes: the last EMCY heard ("" none)
    error: Exception | None = None  # emulator-unusable: why, for the program language
    can: CanNodeFacts | None = None  # CAN nodes: what the description says, for the views


def parse_emulator_spec(spec: str, default_serial: int = 1) -> tuple[str, int]:
    """``TYPEKEY[:SERIAL]`` → (normalized type key, serial); raises TypeKeyError.

    ``twin:FILE`` makes the twin of that twin file the emulated valve of its serial in this
    process (:func:`twin_valve`; TwinFileError for a file that cannot be used) and returns
    its type key and serial, so whatever opens ``emulator:KEY:SERIAL`` next opens the twin.
    """
    if spec.strip().startswith(f"{TWIN}:"):
        valve = twin_valve(spec.strip()[len(TWIN) + 1 :])
        return str(valve.type_key), valve.serial
    text, serial = spec.strip() or DEFAULT_EMULATOR_TYPE, default_serial
    head, sep, tail = text.rpartition(":")
    if sep:
        if not tail.isdigit() or not 0 < int(tail) < 2**32:
            raise TypeKeyError(f"emulator {spec!r}: serial {tail!r} must be a number 1…4294967295")
        text, serial = head, int(tail)
    return str(TypeKey.parse(text)), serial


def emulator_entries(specs: Sequence[str]) -> list[DeviceEntry]:
    """Entries for ``--emulator`` specs; specs without a serial get the lowest free ones
    (:func:`free_emulator_serial`)."""
    from prm9tool.device.emulated import cable_plugged

    parsed = [parse_emulator_spec(s, 0) for s in specs]
    taken = {serial for _, serial in parsed if serial}
    entries, seen = [], set()
    for type_key, serial in parsed:
        if not serial:
            serial = free_emulator_serial(type_key, 1, taken)
            taken.add(serial)
        if serial in seen:
            raise TypeKeyError(f"two emulated valves with serial {serial}")
        seen.add(serial)
        valve = emulated_valve(type_key, serial)
        if cable_plugged(serial):  # a pulled cable: not listed, as a real valve
            entries.append(_emulator_entry(valve))
    return entries


def usable_emulators(specs: Sequence[str]) -> tuple[list[str], list[DeviceEntry]]:
    """``specs`` (each with its serial) split into those that make a valve and entries of
    kind ``emulator-unusable`` for the others, whose description says why (an EEPROM image of
    another type at that serial…), so one bad remembered valve does not hide the rest."""
    usable: list[str] = []
    unusable: list[DeviceEntry] = []
    for spec in specs:
        try:
            emulator_entries([spec])
        except Prm9Error as exc:
            key, _, serial = spec.rpartition(":")
            number = int(serial) if serial.isdigit() else 0
            unusable.append(
                DeviceEntry(
                    f"{EMULATOR}:{spec}", UNUSABLE_EMULATOR, key, number, "", str(exc), error=exc
                )
            )
        else:
            usable.append(spec)
    return usable, unusable


def _emulator_entry(valve: EmulatedValve) -> DeviceEntry:
    key = str(valve.type_key)
    twin = twin_file(valve.serial)
    what = "twin of" if twin else "emulated"
    return DeviceEntry(
        f"{EMULATOR}:{key}:{valve.serial}",
        EMULATOR,
        key,
        valve.serial,
        valve.firmware_version,
        f"{what} {key}, serial {valve.serial}" + (f" ({twin})" if twin else ""),
    )


def usb_entries() -> list[DeviceEntry]:
    """Entries for the valves on USB (raises CommunicationError when hidapi is missing)."""
    from prm9tool.device.usb.discovery import usb_valves
    from prm9tool.device.usb.transport.hidapi import shown_path

    return [
        DeviceEntry(
            f"{USB}:{v.path.decode(errors='replace')}",
            USB,
            v.type_key,
            v.serial,
            v.firmware,
            f"USB {shown_path(v.path)} {v.product}".rstrip(),  # as Device Manager shows it
        )
        for v in usb_valves()
    ]


def usb_unavailable_reason() -> str | None:
    """Why USB valves cannot be listed on this machine, or None if hidapi works."""
    from prm9tool.device.usb.transport.hidapi import load_hid

    try:
        load_hid()
    except CommunicationError as exc:
        return str(exc)
    return None


def list_devices(emulators: Sequence[str] = (), can: CanOptions | None = None) -> list[DeviceEntry]:
    """USB valves (if hidapi works), the emulated valves of ``emulators`` and, with ``can``,
    the nodes on that bus (CanAdapterError if it cannot be opened)."""
    try:
        found = usb_entries()
    except CommunicationError as exc:
        log.info("no USB valves listed: %s", exc)
        found = []
    found += emulator_entries(emulators)
    return found + (can_entries(can) if can is not None else [])


def can_entries(options: CanOptions) -> list[DeviceEntry]:
    """Every node found on the bus ``options``: PRM9 valves (``can``) and other nodes
    (``not-prm9``, never written to). CanAdapterError when the bus cannot be opened."""
    from prm9tool.device.canlink import bus, discovery
    from prm9tool.device.canlink.typekeys import remembered
    from prm9tool.paths import user_data_dir

    shared = bus.acquire(options)
    try:
        nodes = discovery.scan(shared)
        heard = {node.node_id: _heard(shared.node_seen(node.node_id)) for node in nodes}
    finally:
        bus.release(shared)
    entries = []
    for node in nodes:
        facts = CanNodeFacts(
            node_id=node.node_id, interface=options.interface, channel=options.channel,
            bitrate=options.bitrate, name=node.name, device_type=node.device_type,
            vendor=node.vendor, detail=node.detail,
        )  # fmt: skip
        if not node.usable:  # another device, or one that failed to identify itself
            text = f"node {node.node_id}: {node.problem}"
            entries.append(
                DeviceEntry(
                    node.device_id, NOT_PRM9, "", 0, "", text, *heard[node.node_id], can=facts
                )
            )
            continue
        key = node.type_key or remembered(user_data_dir(), node.serial)
        told = node.derived.describe() if node.derived else "-CA"
        entries.append(
            DeviceEntry(
                node.device_id,
                CAN,
                key or f"? ({told}; type key unknown)",
                node.serial,
                node.firmware,
                f"CANopen node {node.node_id} on {options}: {node.name}",
                *heard[node.node_id],
                can=facts,
            )
        )
    return entries


def _heard(seen: Any) -> tuple[NmtState | None, float | None, str]:
    """NMT state, heartbeat age and last EMCY of a node as the bus told them."""
    import time

    from prm9tool.device.canlink.watch import heard

    now = heard(seen, time.monotonic())
    return now.nmt_state, now.heartbeat_age_s, now.last_emcy


# --- opening ---------------------------------------------------------------------------------
@dataclass(frozen=True)
class LinkOptions:
    """How to open a link, whatever its kind: the options :func:`open_session` takes, once.

    ``paced``: an emulated valve runs in real time in its own thread (GUI); False steps its
    simulation on the link's clock (tests, tools, batch mode). ``link_paced`` (None: as
    ``paced``) holds the emulated USB link to one report per millisecond of wall-clock time.
    ``can``: the python-can bus an emulated -CA valve joins. ``can_link``: the bus of a
    ``can:NODE`` device (None: ``can``, else the virtual bus). ``type_key``: the key to use
    when a CANopen valve does not tell its own (a file's); ``label_key``: the one the user
    gave for it, remembered for its serial number.
    """

    paced: bool = True
    link_paced: bool | None = None
    can: CanOptions | None = None
    can_link: CanOptions | None = None
    type_key: str | None = None
    label_key: str | None = None


LinkOpener = Callable[[str, str, LinkOptions], ValveSession]  # (rest of the ID, ID, options)
UNKNOWN_DEVICE = "unknown device {0!r}: expected 'usb:…', 'emulator:…' or 'can:NODE'"


def open_session(
    entry: DeviceEntry | str,
    *,
    paced: bool = True,
    can: CanOptions | None = None,
    link_paced: bool | None = None,
    type_key: str | None = None,
    can_link: CanOptions | None = None,
    label_key: str | None = None,
) -> ValveSession:
    """Open a session to ``entry`` (a DeviceEntry or its ``device_id``), by the link kind its
    ID starts with (:data:`LINKS`); the options as :class:`LinkOptions` describes them.
    :func:`join_can` puts the emulated -CA valve of an open session on a bus afterwards."""
    options = LinkOptions(paced, link_paced, can, can_link, type_key, label_key)
    return open_link(entry.device_id if isinstance(entry, DeviceEntry) else entry, options)


def open_link(device_id: str, options: LinkOptions) -> ValveSession:
    """The one function that turns a device ID and options into an open link."""
    kind, _, rest = device_id.partition(":")
    opener = LINKS.get(kind)
    if opener is None:
        raise Prm9Error(UNKNOWN_DEVICE.format(device_id))
    return opener(rest, device_id, options)


class _SerialFinder:
    """Finds a USB valve again by its serial number (known once the session identified it)."""

    serial: int | None = None

    def __call__(self) -> bytes | None:
        from prm9tool.device.usb.discovery import find_serial

        return find_serial(self.serial) if self.serial is not None else None


def _open_usb(path: str, device_id: str, _options: LinkOptions) -> ValveSession:
    from prm9tool.device.usb.session import UsbSession
    from prm9tool.device.usb.transport.hidapi import HidTransport

    finder = _SerialFinder()
    transport = HidTransport(path.encode(), finder=finder)
    try:
        session = UsbSession(transport, device_id)
    except BaseException:
        transport.close()
        raise
    finder.serial = session.info.serial
    return session


def _open_emulator(rest: str, device_id: str, options: LinkOptions) -> ValveSession:
    from prm9tool.device.emulated import cable_plugged
    from prm9tool.device.usb.session import UsbSession
    from prm9tool.device.usb.transport.emulator import EmulatorTransport

    type_key, _, serial_text = rest.rpartition(":")
    serial = int(serial_text)
    link_paced = options.paced if options.link_paced is None else options.link_paced
    valve = emulated_valve(type_key, serial)
    if not cable_plugged(serial):
        raise DeviceDisconnectedError(f"the USB cable of the emulated valve {serial} is pulled")
    closers: list[Callable[[], None]] = []
    try:
        if options.paced:
            run_paced(valve)
            closers.append(lambda: end_paced(valve))
        if options.can is not None and valve.variant.canopen:
            closers.append(connect_can(valve, options.can))
        transport = EmulatorTransport(valve, paced=link_paced)
        return UsbSession(transport, device_id, on_close=lambda: _all(closers))
    except BaseException:
        _all(closers)
        raise


def _open_can(rest: str, device_id: str, options: LinkOptions) -> ValveSession:
    from prm9tool.device.canlink.session import CanopenSession

    if not rest.isdigit():
        raise Prm9Error(UNKNOWN_DEVICE.format(device_id))
    bus = options.can_link or options.can or CanOptions()
    return CanopenSession(bus, int(rest), type_key=options.type_key, label_key=options.label_key)


# The link kinds, as python-can's BACKENDS: the device ID's prefix -> the function that opens it.
LINKS: dict[str, LinkOpener] = {USB: _open_usb, EMULATOR: _open_emulator, CAN: _open_can}


def join_can(session: ValveSession, options: CanOptions) -> bool:
    """Put the emulated -CA valve behind the open ``session`` on a python-can bus.

    Returns False for a session without one (a real valve, a valve without -CA). The bus is
    released when the session closes. Raises CanBusError if the bus cannot be opened; the USB
    session is not affected. The GUI calls this after going online: python-can's import
    (~0.2 s) is then off the way to "online" (docs/PERFORMANCE.md, Startup).
    """
    from prm9tool.device.usb.session import UsbSession
    from prm9tool.device.usb.transport.emulator import EmulatorTransport

    if not isinstance(session, UsbSession):
        return False
    transport = session.transport
    if not isinstance(transport, EmulatorTransport) or not transport.valve.variant.canopen:
        return False
    session.add_close_hook(connect_can(transport.valve, options))
    return True


def _all(closers: list[Callable[[], None]]) -> None:
    for close in reversed(closers):
        close()

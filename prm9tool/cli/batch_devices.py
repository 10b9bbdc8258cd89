"""The valves a headless command works on: ``--list-devices``, the selection by
``--emulator``, ``--device``, ``--all`` and the CAN options, and opening a selected valve
(shared by ``--batch``, ``--diff`` and ``--characterize``)."""

from __future__ import annotations

import argparse
import json
import logging
import sys

from prm9tool.cli.json_output import emit_json
from prm9tool.device.factory import (
    CAN,
    EMULATOR,
    NOT_PRM9,
    USB,
    CanOptions,
    DeviceEntry,
    can_entries,
    emulator_entries,
    open_session,
    usb_entries,
    usb_unavailable_reason,
)
from prm9tool.device.session import ValveSession
from prm9tool.errors import (
    CanAdapterError,
    CommunicationError,
    ExitCode,
    FileFormatError,
    Prm9Error,
    TypeKeyError,
)

log = logging.getLogger(__name__)


class BatchError(Exception):
    """Ends the run before any valve was touched, with ``code`` and a message for stderr."""

    def __init__(self, code: ExitCode, message: str) -> None:
        super().__init__(message)
        self.code = code


# --- listing ------------------------------------------------------------------------------------
def list_devices(args: argparse.Namespace) -> int:
    """``--list-devices``: one line per valve found (``--json``: a list of the
    :class:`~prm9tool.device.records.DeviceInfo` records); exit code 4 when there is none."""
    entries = _usb(required=False) + _emulators(args) + _can(args)
    if args.json:  # what prm9tool.list_devices() returns; other CANopen nodes on stderr
        from prm9tool.api.devices import device_info

        others = [e for e in entries if e.kind == NOT_PRM9]
        for entry in others:
            print(
                f"prm9tool: {entry.device_id}: {_verdict(entry)}: {entry.description}",
                file=sys.stderr,
            )
        valves = [device_info(e, can_options(args)).to_dict() for e in entries if e not in others]
        failed = emit_json(json.dumps(valves, indent=2), args.json)
        if failed is not None:
            return failed
    for entry in entries if not args.json else []:
        if entry.kind == NOT_PRM9:
            print(f"{entry.device_id}\t{_verdict(entry)}\t{entry.description}")
            continue
        print(
            f"{entry.device_id}\t{entry.type_key}\tserial {entry.serial}\tfirmware {entry.firmware}"
        )
    if not [e for e in entries if e.kind != NOT_PRM9]:
        reason = usb_unavailable_reason()
        print("prm9tool: no valves found" + (f" ({reason})" if reason else ""), file=sys.stderr)
        return ExitCode.NO_DEVICE
    return ExitCode.OK


def _verdict(entry: DeviceEntry) -> str:
    """``not a PRM9`` for another kind of device, ``not identified`` for a node that did not
    answer, answered what no PRM9 holds or shares its node ID with another."""
    facts = entry.can
    if facts is not None and facts.device_type is not None and not facts.detail:
        return "not a PRM9"
    return "not identified"


def _emulators(args: argparse.Namespace) -> list[DeviceEntry]:
    from prm9tool.device.emulator.twinfile import TwinFileError

    try:
        return emulator_entries(args.emulator)
    except TwinFileError as exc:  # --emulator twin:FILE of a file that cannot be used
        raise BatchError(ExitCode.INVALID_FILE, f"--emulator: {exc}") from exc
    except (TypeKeyError, FileFormatError) as exc:
        raise BatchError(ExitCode.USAGE, f"--emulator: {exc}") from exc
    except Prm9Error as exc:
        raise BatchError(ExitCode.NO_DEVICE, str(exc)) from exc


def can_options(args: argparse.Namespace) -> CanOptions | None:
    """The CAN bus the command line names (None: no CAN option given)."""
    given = (args.can_interface, args.can_channel, args.can_bitrate)
    return CanOptions.from_args(args) if any(v is not None for v in given) else None


def _can(args: argparse.Namespace) -> list[DeviceEntry]:
    """The nodes on the command line's CAN bus (none without CAN options)."""
    options = can_options(args)
    if options is None:
        return []
    try:
        return can_entries(options)
    except CanAdapterError as exc:
        raise BatchError(ExitCode.COMMUNICATION, str(exc)) from exc


def _usb(required: bool) -> list[DeviceEntry]:
    try:
        return usb_entries()
    except CommunicationError as exc:
        if required:
            raise BatchError(ExitCode.NO_DEVICE, str(exc)) from exc
        return []


def select(args: argparse.Namespace) -> list[DeviceEntry]:
    """The valves the options name; BatchError (4 or 2) if that is none or ambiguous."""
    chosen = _emulators(args)
    if can_options(args) is not None:
        return _select_can(args, chosen)
    if args.device or args.all:
        usb = _usb(required=True)
        for wanted in args.device:
            chosen += _match(wanted, usb)
        if args.all:
            chosen += usb
    elif not chosen:
        usb = _usb(required=False)
        if len(usb) > 1:
            raise BatchError(
                ExitCode.USAGE, f"{len(usb)} valves are connected: choose with --device or --all"
            )
        chosen = usb
    if not chosen:
        reason = usb_unavailable_reason()
        raise BatchError(ExitCode.NO_DEVICE, "no valve found" + (f" ({reason})" if reason else ""))
    return _unique(chosen)


def _select_can(args: argparse.Namespace, chosen: list[DeviceEntry]) -> list[DeviceEntry]:
    """The valves on the CAN bus: ``--device can:N`` (checked to be a PRM9) or ``--all``."""
    found = _can(args)
    prm9 = [e for e in found if e.kind == CAN]
    for wanted in args.device:
        matches = [e for e in found if wanted in (e.device_id, str(e.serial)) and e.serial]
        matches += [e for e in found if e.device_id == wanted and e not in matches]
        if not matches:
            known = ", ".join(e.device_id for e in prm9) or "none"
            raise BatchError(
                ExitCode.NO_DEVICE,
                f"no valve {wanted!r} answers on the CAN bus {can_options(args)} (PRM9 found: {known})",
            )
        others = [e for e in matches if e.kind == NOT_PRM9]
        if others:
            said = others[0].description  # two nodes at one ID: "… writes to neither" already
            tail = "" if "writes to neither" in said else "; prm9tool does not write to it"
            raise BatchError(ExitCode.NO_DEVICE, f"{said}{tail}")
        chosen += matches
    if args.all:
        chosen += prm9
    elif not args.device and not chosen:
        if len(prm9) > 1:
            raise BatchError(
                ExitCode.USAGE, f"{len(prm9)} valves are on the bus: choose with --device or --all"
            )
        chosen = prm9
    if not chosen:
        raise BatchError(ExitCode.NO_DEVICE, f"no PRM9 found on the CAN bus {can_options(args)}")
    return _unique(chosen)


def _unique(entries: list[DeviceEntry]) -> list[DeviceEntry]:
    """Each valve once, in the order first named (``--device 41 --device /dev/hidraw0``)."""
    by_id: dict[str, DeviceEntry] = {}
    for entry in entries:
        by_id.setdefault(entry.device_id, entry)
    return list(by_id.values())


def _match(wanted: str, usb: list[DeviceEntry]) -> list[DeviceEntry]:
    found = [e for e in usb if wanted in (str(e.serial), e.device_id, e.device_id[4:])]
    if not found:
        known = ", ".join(f"{e.serial} ({e.device_id})" for e in usb) or "none"
        raise BatchError(ExitCode.NO_DEVICE, f"no valve {wanted!r} is connected (found: {known})")
    return found


def open_entry(
    entry: DeviceEntry, can: CanOptions | None = None, label_key: str | None = None
) -> ValveSession:
    """Open a session as the headless commands do (``--batch``, ``--diff``); ``label_key``:
    ``--type-key``."""
    return open_valve(entry) if can is None else open_valve(entry, can, label_key=label_key)


def open_valve(
    entry: DeviceEntry,
    can: CanOptions | None = None,
    type_key: str | None = None,
    label_key: str | None = None,
) -> ValveSession:
    """Open one selected valve; ``type_key``: the file's, for a valve that does not tell its
    own; ``label_key``: ``--type-key`` (first, remembered). An emulated valve is stepped on
    the link clock; its link runs at USB speed."""
    return open_session(
        entry,
        paced=False,
        link_paced=True,
        can_link=can,
        type_key=type_key,
        label_key=label_key,
    )


def listed_again(args: argparse.Namespace, serials: set[int]) -> dict[int, str]:
    """After the run: the valves among ``serials`` that are listed now (serial → device ID),
    on the links the command line names. One listing, no retry; nothing is opened. A listing
    that fails finds none."""
    found: list[DeviceEntry] = []
    for listing in (lambda: _emulators(args), lambda: _usb(required=False), lambda: _can(args)):
        try:
            found += listing()
        except (BatchError, Prm9Error) as exc:
            log.info("listing the valves again failed: %s", exc)
    openable = (CAN, USB, EMULATOR)
    return {e.serial: e.device_id for e in found if e.kind in openable and e.serial in serials}

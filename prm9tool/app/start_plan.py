"""The GUI's start plan: what the command line asks the window to do once it is shown — open a
file, say why the user's spools.json was left out, go online with an emulated valve
(``--emulator [TYPEKEY[:SERIAL]]``, ``twin:FILE``), a listed valve (``--device``) or a node on
the command line's CAN bus (``--device can:NODE``). :func:`plan_from` reads the options,
:func:`start` carries the plan out on the window.
"""

from __future__ import annotations

import argparse
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from prm9tool.errors import Prm9Error
    from prm9tool.online.connection_protocol import ListedValves, ValveListing
    from prm9tool.views.main_window import MainWindow


@dataclass
class StartPlan:
    """What to do after the window is shown."""

    file: Path | None
    emulators: list[str]
    devices: list[str]
    spools_problem: Prm9Error | None = None  # why the user's spools.json was left out


def plan_from(args: argparse.Namespace, spools_problem: Prm9Error | None = None) -> StartPlan:
    """Read the GUI-relevant options of the command line (and what went wrong before)."""
    emulators = [
        _emulator_spec(spec) for spec in (getattr(args, "emulator", None) or []) if spec is not None
    ]
    file = Path(args.file) if getattr(args, "file", None) else None
    devices = list(getattr(args, "device", None) or [])
    return StartPlan(file, emulators, devices, spools_problem)


def _emulator_spec(spec: str) -> str:
    """``TYPEKEY[:SERIAL]`` with the defaults filled in: without a serial the first one from
    1001 on that is free for this type (``emulated_valves.free_emulator_serial``).
    ``twin:FILE`` stays as it is (the twin file names its serial; :func:`_normal_spec` reads
    it)."""
    from prm9tool.device.emulated_valves import free_emulator_serial
    from prm9tool.device.factory import TWIN
    from prm9tool.errors import TypeKeyError
    from prm9tool.views.hid_dialog import DEFAULT_EMULATOR_SERIAL, DEFAULT_EMULATOR_TYPE_KEY

    if spec and spec.startswith(f"{TWIN}:"):
        return spec
    key, _, serial = (spec or DEFAULT_EMULATOR_TYPE_KEY).partition(":")
    key = key or DEFAULT_EMULATOR_TYPE_KEY
    if not serial:
        try:
            serial = str(free_emulator_serial(key, DEFAULT_EMULATOR_SERIAL))
        except TypeKeyError:  # a bad type key: reported where the spec is opened
            serial = str(DEFAULT_EMULATOR_SERIAL)
    return f"{key}:{serial}"


def start(window: MainWindow, plan: StartPlan) -> None:
    """Say why spools.json was left out, open the file and/or go online, as asked."""
    from PySide6.QtCore import QCoreApplication

    if plan.spools_problem is not None:
        _report_spools_problem(window, plan.spools_problem)
    if plan.file is not None:
        window.files.open_path(plan.file, ask=False)
    if plan.emulators:
        _start_emulated(window, plan.emulators)
    elif plan.devices and plan.devices[0].startswith("can:"):
        window.valve.go_online(plan.devices[0])  # a node on the command line's CAN bus
    elif plan.devices:
        wanted_id = plan.devices[0]

        def listed(found: ListedValves) -> None:  # the valves are listed off the GUI thread
            entries = [] if isinstance(found, Exception) else found
            wanted = [e for e in entries if _matches(e, wanted_id)]
            if wanted:
                window.valve.go_online(wanted[0])
            else:
                message = QCoreApplication.translate("App", "--device {0}: no such valve")
                window.status.showMessage(message.format(wanted_id), 10000)

        window.connection.list_devices_async((), listed)


def _report_spools_problem(window: MainWindow, problem: Prm9Error) -> None:
    """A message (not blocking the window) that the user's spools.json is broken."""
    from PySide6.QtCore import QCoreApplication

    from prm9tool.translate import error_text
    from prm9tool.views import prompts

    text = QCoreApplication.translate(
        "App", "{0}\n\nUntil the file is corrected, prm9tool knows only the spools it ships."
    )
    title = QCoreApplication.translate("App", "Spool catalogue")
    prompts.inform(window, prompts.Icon.Warning, title, text.format(error_text(problem)))


def _start_emulated(window: MainWindow, specs: list[str]) -> None:
    """Remember the emulated valves in the HID configuration and go online with the first.

    The device id goes to the connection as it is, so the device layer is imported in the
    connection's worker thread while the window is already shown.
    """
    from prm9tool.errors import Prm9Error
    from prm9tool.translate import error_text
    from prm9tool.views import prompts
    from prm9tool.views.hid_dialog import (
        EMULATORS_KEY,
        SELECTED_KEY,
        one_per_serial,
        saved_emulators,
    )

    try:
        normal = [_normal_spec(spec) for spec in specs]
    except Prm9Error as exc:  # a bad type key or serial, a twin file that cannot be used
        prompts.inform(window, prompts.Icon.Warning, "--emulator", error_text(exc))
        return
    known = saved_emulators(window.settings)
    window.settings.setValue(EMULATORS_KEY, one_per_serial(known + normal))
    device_id = f"emulator:{normal[0]}"
    window.settings.setValue(SELECTED_KEY, device_id)
    window.valve.go_online(device_id)


def _normal_spec(spec: str) -> str:
    """``TYPEKEY:SERIAL`` with the type key checked and written the canonical way; of
    ``twin:FILE`` the twin's (made here: the emulated valve of its serial in this process;
    TwinFileError for a file that cannot be used)."""
    from prm9tool.catalogue.typekey import TypeKey
    from prm9tool.device import factory
    from prm9tool.errors import TypeKeyError
    from prm9tool.messages import QT_TRANSLATE_NOOP

    if spec.startswith(f"{factory.TWIN}:"):
        key, number = factory.parse_emulator_spec(spec)
        return f"{key}:{number}"
    key, _, serial = spec.rpartition(":")
    if not serial.isdigit() or not 0 < int(serial) < 2**32:
        raise TypeKeyError(
            QT_TRANSLATE_NOOP("App", "--emulator {0}: the serial number must be 1 … 4294967295")(
                repr(spec)
            )
        )
    return f"{TypeKey.parse(key)}:{int(serial)}"


def _matches(entry: ValveListing, wanted: str) -> bool:
    return wanted in (entry.device_id, str(entry.serial))

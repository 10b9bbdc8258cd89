"""Communication → Online, HID configuration, CAN bus: finding the valve to go online with
(the one chosen before, the only one, or the user's choice), asking for the type key of a
CANopen valve that does not tell it, and connecting.

Nothing here touches the device: the ValveConnection lists the valves off the GUI thread.
"""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtCore import QObject, QSettings, QTimer
from PySide6.QtWidgets import QDialog, QWidget

from prm9tool.online.connection import ValveConnection
from prm9tool.online.connection_protocol import ListedValves, ValveListing
from prm9tool.translate import error_text
from prm9tool.views.hid_dialog import (
    SELECTED_KEY,
    UNUSABLE,
    HidConfigurationDialog,
    saved_emulators,
)


class ValveFinder(QObject):
    """Finds the valve to go online with and connects; ``post`` shows a status-bar message."""

    def __init__(
        self,
        window: QWidget,
        connection: ValveConnection,
        settings: QSettings,
        post: Callable[[str], None],
    ) -> None:
        super().__init__(window)
        self._window = window
        self._connection = connection
        self._settings = settings
        self._post = post
        connection.type_key_needed.connect(self.on_type_key_needed)
        from prm9tool.online.trace_recording import BusRecording

        self.recording = BusRecording(self)  # Record… / Stop: CAN bus dialog, trace window

    def configure_hid(self) -> ValveListing | None:
        """Show the HID configuration; returns the chosen device entry (or None)."""
        dialog = HidConfigurationDialog(
            self._connection.list_devices_async, self._settings, self._window
        )
        if dialog.exec() != QDialog.DialogCode.Accepted:
            return None
        return dialog.selected_entry()

    def configure_can_bus(self) -> None:
        """Communication → CAN bus: choose the bus and a valve on it, then go online with it."""
        from prm9tool.online.bus_monitor import BusMonitor
        from prm9tool.online.lss_commissioning import LssCommissioning
        from prm9tool.views.canbus.bus_dialog import CanBusDialog

        def scan(bus: dict[str, object], deliver: Callable[[ListedValves], None]) -> None:
            self._connection.list_devices_async((), deliver, bus)

        device = self._connection.device if self._connection.is_online else None
        bus = getattr(device, "can_bus", None)  # online over CAN: the session's bus
        monitor = BusMonitor()
        lss = LssCommissioning() if bus is None else None  # LSS would move the session's valve
        dialog = CanBusDialog(scan, self._settings, self._window, monitor, lss, self.recording)
        if device is not None and bus is not None:
            interface, channel, bitrate = bus
            watched = {"interface": interface, "channel": channel, "bitrate": bitrate}
            dialog.watch_session_bus(watched, device)
        elif device is not None:
            dialog.keep_online(device.device_id)
        accepted = dialog.exec() == QDialog.DialogCode.Accepted
        monitor.stop()
        monitor.deleteLater()
        if lss is not None:
            lss.deleteLater()
        if not accepted:
            return
        device_id = dialog.selected_device_id()
        if device_id is not None and not self._connection.is_online:
            self.connect_to(device_id)

    def chosen_entry(self, entries: ListedValves) -> ValveListing | None:
        """The valve to go online with among the listed ``entries`` (or the exception listing
        raised): the one chosen before, the only one, or ask."""
        if isinstance(entries, Exception):  # a broken USB stack must not prevent the dialog
            self._post(self.tr("Listing the valves failed: {0}").format(error_text(entries)))
            entries = []
        found = [e for e in entries if e.kind != UNUSABLE]  # the dialog says why not
        selected = str(self._settings.value(SELECTED_KEY, ""))
        for entry in found:
            if entry.device_id == selected:
                return entry
        if len(found) == 1:
            return found[0]
        return self.configure_hid()

    def go_online(self, entry: ValveListing | str | None = None) -> None:
        """Connect to ``entry`` (a listed valve or a device id); without one, retry the valve
        chosen last: a CAN node directly, else list the valves (off the GUI thread) and take
        :meth:`chosen_entry`."""
        if self._connection.is_online:
            return
        if entry is not None:
            self.connect_to(entry)
            return
        chosen = str(self._settings.value(SELECTED_KEY, ""))
        if chosen.startswith("can:"):  # a CAN node is not listed: retry it as it was chosen
            self.connect_to(chosen)
            return
        self._post(self.tr("Looking for valves…"))
        self._connection.list_devices_async(saved_emulators(self._settings), self._on_listed)

    def _on_listed(self, entries: ListedValves) -> None:
        if self._connection.is_online or self._connection.is_busy:
            return  # connected meanwhile (the HID dialog, the command line)
        entry = self.chosen_entry(entries)
        if entry is not None:
            self.connect_to(entry)

    def on_type_key_needed(self, device_id: str, serial: int, told: str) -> None:
        """Going online with a CANopen valve that does not tell its type key (``--device
        can:N``): ask for the key on its label (until it fits or the user cancels), remember
        it for the serial number and go online again."""
        from prm9tool.views.canbus.bus_dialog import ask_type_key

        while True:
            key, problem = ask_type_key(self._window, serial, told)
            if not problem:
                break
            self._post(problem)
        if key is not None:
            self._connect_when_idle(device_id)

    def _connect_when_idle(self, device_id: str) -> None:
        """Go online once the failed attempt has finished (its end is still queued)."""
        if self._connection.is_online:
            return
        if self._connection.is_busy:
            QTimer.singleShot(50, lambda: self._connect_when_idle(device_id))
            return
        self.connect_to(device_id)

    def connect_to(self, entry: ValveListing | str) -> None:
        """Go online with ``entry`` now."""
        device_id = entry if isinstance(entry, str) else entry.device_id
        self._settings.setValue(SELECTED_KEY, device_id)  # going online again retries this one
        self._post(self.tr("Connecting to {0}…").format(_name(entry)))
        self._connection.go_online(entry)


def _name(entry: ValveListing | str) -> str:
    if isinstance(entry, str):
        return entry.removeprefix("emulator:")
    return f"{entry.type_key} #{entry.serial}"

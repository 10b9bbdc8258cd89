"""Valve → Restore factory values and Valve → Restart valve: the two commands that restart the
valve (after the user confirmed that the hydraulics are disconnected), and what the GUI does
with the set it comes back with — the factory set taken into the document with the backup
named, or the restarted valve compared with the document as on going online (a changed node ID
or bit rate may have moved it; the session followed).

Nothing here touches the device: the connection runs the valve service's operations in its
worker thread and reports their results (``finished``).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass

from PySide6.QtCore import QObject, QSettings
from PySide6.QtWidgets import QDialog, QWidget

from prm9tool.model.document import ParameterDocument, Raw
from prm9tool.online.connection import ValveConnection
from prm9tool.online.sync import ValveSync
from prm9tool.views import prompts
from prm9tool.views.online_dialogs import RestartDialog
from prm9tool.views.operation_progress import OperationProgress
from prm9tool.views.valve.upload import ValveUpload

FACTORY = "restore_factory"  # the connection's operation names
AFTER_RESTART = "after_restart"


class ValveRestarts(QObject):
    """Asks, starts and reports Restore factory values and Restart valve."""

    def __init__(
        self,
        window: QWidget,
        doc: ParameterDocument,
        connection: ValveConnection,
        sync: ValveSync,
        settings: QSettings,
        uploads: ValveUpload,
        progress: OperationProgress,
        post: Callable[[str], None],
        take_values: Callable[[Mapping[str, Raw], str], None],
        compare: Callable[[Mapping[str, Raw]], None],
    ) -> None:
        super().__init__(window)
        self._window, self._doc, self._connection = window, doc, connection
        self._sync, self._settings, self._uploads = sync, settings, uploads
        self._progress, self._post = progress, post
        self._take_values, self._compare = take_values, compare
        self._restarted_from = ""  # device ID before the restart (a restart may move it)

    def restore_factory(self) -> None:
        """Factory values: online into the valve (backup, reset, restart, after the user
        confirmed that the hydraulics are disconnected), offline into the document."""
        if self._connection.is_online:
            if RestartDialog(self._window, factory=True).exec() != QDialog.DialogCode.Accepted:
                return
            self._progress.start(FACTORY, self.tr("Restoring the factory values…"), False)
            self._connection.factory_reset(FACTORY)
            return
        answer = prompts.ask(
            self._window,
            prompts.Icon.Question,
            self.tr("Restore factory values"),
            self.tr("Set every parameter of the document to the factory default?"),
            prompts.Button.Yes | prompts.Button.No,
            prompts.Button.No,
        )
        if answer == prompts.Button.Yes:
            defaults = ParameterDocument(self._doc.type_key).values
            self._doc.set_values(defaults, self.tr("Restore factory values"))

    def restart(self) -> None:
        """Restart the valve after the user confirmed that the hydraulics are disconnected."""
        dialog = RestartDialog(self._window)
        if dialog.exec() != QDialog.DialogCode.Accepted:
            return
        device = self._connection.device
        self._restarted_from = device.device_id if device is not None else ""
        self._progress.start("restart", self.tr("Restarting the valve…"), cancellable=False)
        self._connection.restart_valve(AFTER_RESTART)

    def finished(self, name: str, result: object) -> bool:
        """The connection finished operation ``name`` with ``result``; False when it is not
        one of these two."""
        if name == FACTORY and isinstance(result, tuple):
            values, backup = result
            self._on_factory_reset(_FactoryReset(values, None if backup is None else str(backup)))
        elif name == AFTER_RESTART and isinstance(result, Mapping):
            self._report_restart()  # recorded by the valve service (as every door's restart)
            self._sync.stop()
            self._compare(result)
        else:
            return False
        return True

    def _report_restart(self) -> None:
        """Say that the valve restarted — and where, when a changed node ID or bit rate moved
        it and the session followed (the CAN bus dialog then remembers the new bit rate)."""
        device = self._connection.device
        if device is None or device.device_id == self._restarted_from:
            self._post(self.tr("The valve restarted"))
            return
        bus = getattr(device, "can_bus", None)
        if bus is not None and bus[2]:
            from prm9tool.views.canbus.bus_dialog import BITRATE_KEY

            self._settings.setValue(BITRATE_KEY, bus[2])
        rate = self.tr("{0} kbit/s").format(bus[2] // 1000) if bus and bus[2] else ""
        self._post(
            self.tr("The valve restarted at {0} {1}; prm9tool found it there").format(
                device.device_id, rate
            )
        )

    def _on_factory_reset(self, result: _FactoryReset) -> None:
        self._uploads.last_stored = None  # the valve no longer holds the last upload
        self._take_values(result.values, self.tr("Factory values of the valve"))
        if result.backup is not None:
            self._post(
                self.tr(
                    "Factory values restored; the valve's previous parameters are in {0}"
                ).format(result.backup)
            )
        else:  # its backup was kept from before: still say it was done
            self._post(self.tr("Factory values restored; the valve's backup from before is kept"))


@dataclass(frozen=True)
class _FactoryReset:
    """Result of the factory reset: the valve's values now, and the backup taken before."""

    values: dict[str, Raw]
    backup: str | None

"""Valve → Enable valve / Disable valve: the manual's commissioning (§7.6 steps 4-5).

Enabling starts the node (NMT start on a CAN bus) and steps the control word 08h → 09h →
0Bh → 0Fh, so the spool follows its setpoint; disabling goes back to INIT and pre-operational.
The valve session does it the same way on every link (ValveSession.commission); this module
only asks first and reports the state reached.
"""

from __future__ import annotations

from PySide6.QtCore import QObject, Signal
from PySide6.QtWidgets import QWidget

from prm9tool.online.connection import ValveConnection
from prm9tool.views import prompts

ENABLE, DISABLE = "commission", "decommission"


class Commissioning(QObject):
    """Asks, runs the commissioning job and says what the valve reached."""

    message_posted = Signal(str)

    def __init__(self, connection: ValveConnection, window: QWidget) -> None:
        super().__init__(window)
        self._connection, self._window = connection, window
        connection.operation_finished.connect(self._on_connection_operation_finished)

    def enable(self) -> None:
        """Start the node and enable the device, after the user confirmed it is safe."""
        answer = prompts.ask(
            self._window,
            prompts.Icon.Warning,
            self.tr("Enable valve"),
            self.tr(
                "The valve is started (NMT start) and enabled (control word 08h → 09h → 0Bh → "
                "0Fh): the spool then follows its setpoint and moves the hydraulics. Enable it?"
            ),
            prompts.Button.Yes | prompts.Button.No,
            prompts.Button.No,
        )
        if answer == prompts.Button.Yes:
            self._connection.run_job(ENABLE, lambda session: session.commission())

    def disable(self) -> None:
        """Back to INIT (control word 0Bh → 09h → 08h) and NMT pre-operational."""
        self._connection.run_job(DISABLE, lambda session: session.decommission())

    def _on_connection_operation_finished(self, name: str, result: object) -> None:
        if name not in (ENABLE, DISABLE):
            return
        state = str(getattr(result, "device_state", ""))
        self.message_posted.emit(self.tr("The valve is in state {0}").format(state))

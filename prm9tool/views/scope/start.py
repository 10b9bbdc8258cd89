"""Starting the scope's setpoint generator: the checks and the questions before the valve moves.

The waveform must fit the setpoint range; the user confirms that the machine may move; a valve
that waits for its CANopen master (or is not enabled) would not move at all, so NMT start and
the enable sequence are offered first (manual §7.6). The measured demand value then becomes
the step figures' reference: it is what the valve made of the setpoint, on its own clock.
"""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication
from PySide6.QtWidgets import QWidget

from prm9tool.catalogue.commissioning import Blocker, NmtCommand
from prm9tool.catalogue.signals import MAX_CHANNELS
from prm9tool.errors import ValueRangeError
from prm9tool.online.connection_protocol import StatusView
from prm9tool.online.valve_control import ValveControl, blocker_text, status_blocker
from prm9tool.scope import GeneratorSettings
from prm9tool.translate import error_text
from prm9tool.views import prompts
from prm9tool.views.scope.panels import ChannelPanel
from prm9tool.views.scope.readout import StepPanel

ENABLEABLE = (Blocker.WAITING_FOR_MASTER, Blocker.DISABLED, Blocker.HOLD, Blocker.NMT_STOPPED)
DEMAND = "demand"


class GeneratorStart(QWidget):
    """Asks before the generator starts (an invisible helper of the scope widget)."""

    def __init__(self, control: ValveControl | None, parent: QWidget) -> None:
        super().__init__(parent)
        self._control = control
        self.hide()

    def confirmed(self, settings: GeneratorSettings, status: StatusView | None) -> bool:
        """True when ``settings`` fit and the user agreed to start; a valve that would not
        follow is offered to be enabled first."""
        owner = self.parentWidget()
        title = self.tr("Setpoint generator")
        try:
            settings.check()
        except ValueRangeError as exc:
            prompts.inform(owner, prompts.Icon.Warning, title, error_text(exc))
            return False
        answer = prompts.ask(
            owner,
            prompts.Icon.Warning,
            title,
            self.tr(
                "The generator will drive the valve's setpoint and the valve will move.\n"
                "Make sure the machine is safe to move. Start the generator?"
            ),
            prompts.Button.Yes | prompts.Button.No,
            prompts.Button.No,
        )
        if answer != prompts.Button.Yes:
            return False
        self._offer_enable(status)
        return True

    def _offer_enable(self, status: StatusView | None) -> None:
        offer_enable(self.parentWidget(), self._control, status, self.tr("Setpoint generator"))


def offer_enable(
    parent: QWidget | None, control: ValveControl | None, status: StatusView | None, title: str
) -> None:
    """A valve that waits for its CANopen master (or is not enabled) would not move: offer NMT
    start and the enable sequence (manual §7.6). Queued on the connection, they run before a
    job queued after this call (the generator's waveform, a tuning test)."""
    reason = status_blocker(status)
    if control is None or reason not in ENABLEABLE:
        return
    assert reason is not None
    answer = prompts.ask(
        parent,
        prompts.Icon.Question,
        title,
        QCoreApplication.translate(
            "GeneratorStart",
            "The valve does not follow its setpoint: {0}\n\nEnable it now (NMT start, "
            "control word 08h → 09h → 0Bh → 0Fh)?",
        ).format(blocker_text(reason, status)),
        prompts.Button.Yes | prompts.Button.No,
        prompts.Button.Yes,
    )
    if answer != prompts.Button.Yes:
        return
    if status is not None and str(status.nmt_state) in ("pre-operational", "stopped"):
        control.nmt(NmtCommand.START)
    control.enable()


def measure_against_demand(channels: ChannelPanel, steps: StepPanel) -> None:
    """Record the valve's demand value (first, when there is room) and make it the step
    figures' reference: the measured setpoint, not the one the program meant to send."""
    keys = channels.selected()
    if DEMAND not in keys and len(keys) < MAX_CHANNELS:
        channels.set_selected([DEMAND, *keys])
        keys = channels.selected()
    if DEMAND in keys:
        steps.reference.setCurrentIndex(steps.reference.findData(keys.index(DEMAND)))

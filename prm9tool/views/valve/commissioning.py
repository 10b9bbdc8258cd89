"""Commissioning buttons of the valve status window: NMT and the enable sequence (manual §7.6).

A -CA valve as delivered waits for a CANopen master; on the desk the user is that master:
"Start (NMT)" and "Enable" (control word 08h → 09h → 0Bh → 0Fh) make it follow its setpoint,
"Disable" and "Pre-operational"/"Stop" take it back, in the order of commissioning: NMT first,
then the enable sequence. Below them, in lines of a fixed height, why the valve does not
follow its setpoint, or that it does. No button is the default: Enter never moves the valve.
"""

from __future__ import annotations

from PySide6.QtWidgets import QGridLayout, QGroupBox, QPushButton, QWidget

from prm9tool.catalogue.commissioning import Blocker, NmtCommand
from prm9tool.online.connection_protocol import StatusView
from prm9tool.online.valve_control import ValveControl, blocker_text, status_blocker
from prm9tool.views.fixed_lines import FixedLinesLabel

REASON_LINES = 4


class CommissioningPanel(QGroupBox):
    """NMT start/pre-operational/stop, Enable and Disable, and why the valve stands still."""

    def __init__(self, control: ValveControl, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._control = control
        self._status: StatusView | None = None
        self.reason = FixedLinesLabel(REASON_LINES)  # its length never moves the buttons
        self.buttons = {
            name: QPushButton()
            for name in ("enable", "disable", "nmt_start", "nmt_preop", "nmt_stop")
        }
        for button in self.buttons.values():  # Enter must not move the valve
            button.setAutoDefault(False)
            button.setDefault(False)
        grid = QGridLayout(self)
        for column, name in enumerate(("nmt_start", "nmt_preop", "nmt_stop")):
            grid.addWidget(self.buttons[name], 0, column)
        for column, name in enumerate(("enable", "disable")):
            grid.addWidget(self.buttons[name], 1, column)
        grid.addWidget(self.reason, 2, 0, 1, 3)
        actions = {
            "enable": control.enable,
            "disable": control.disable,
            "nmt_start": lambda: control.nmt(NmtCommand.START),
            "nmt_preop": lambda: control.nmt(NmtCommand.PRE_OPERATIONAL),
            "nmt_stop": lambda: control.nmt(NmtCommand.STOP),
        }
        for name, action in actions.items():
            self.buttons[name].clicked.connect(lambda _=False, act=action: act())
        self.retranslate()
        self.show_status(None)

    def retranslate(self) -> None:
        """Set every text in the current language."""
        self.setTitle(self.tr("Commissioning"))
        texts = {
            "enable": (
                self.tr("Enable"),
                self.tr(
                    "Control word 0x6040: 08h → 09h → 0Bh → 0Fh (manual §7.6): resets a fault, "
                    "then DISABLED, HOLD, DEVICE_MODE_ACTIVE. The valve follows its setpoint."
                ),
            ),
            "disable": (
                self.tr("Disable"),
                self.tr("Control word 0x6040: 0Fh → 0Bh → 09h → 08h, back to INIT."),
            ),
            "nmt_start": (self.tr("NMT start"), self.tr("NMT start: operational (PDOs run)")),
            "nmt_preop": (self.tr("NMT pre-operational"), self.tr("NMT enter pre-operational")),
            "nmt_stop": (self.tr("NMT stop"), self.tr("NMT stop: only NMT is answered")),
        }
        for name, (label, tip) in texts.items():
            self.buttons[name].setText(label)
            self.buttons[name].setToolTip(tip)
        self.show_status(self._status)

    def show_status(self, status: StatusView | None) -> None:
        """Follow the valve's status (None: offline)."""
        self._status = status
        online = status is not None and self._control.connection.is_online
        nmt = str(status.nmt_state) if status is not None else "off"
        canopen = online and nmt not in ("off", "")  # off: analog only, it enables itself
        for name, button in self.buttons.items():
            button.setEnabled(canopen and not (name.startswith("nmt") and nmt == "initialising"))
        reason = status_blocker(status) if online else Blocker.OFFLINE
        if reason is None:
            self.reason.setText(self.tr("The valve follows its setpoint (DEVICE_MODE_ACTIVE)."))
        else:
            text = blocker_text(reason, status, in_status=True)
            self.reason.setText(self.tr("The valve does not follow its setpoint: {0}").format(text))

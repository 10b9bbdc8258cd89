"""The emulated valve's world (Valve → Emulated valve): its inputs, rotary switches and faults.

The menu injects the physical faults the emulator knows (manual table 5-1: a disconnected or
shorted coil, a cut setpoint, sensor or LVDT wire, the supply out of range, over-temperature)
and pulls the USB cable; the dialog sets the analog inputs, the supply voltage, the ambient
temperature and the rotary switches. Everything goes through :class:`ValveControl` (the
connection's worker), never to the device directly. Only an emulated valve has these.
"""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication, QEvent
from PySide6.QtGui import QAction
from PySide6.QtWidgets import (
    QComboBox,
    QDialog,
    QDialogButtonBox,
    QDoubleSpinBox,
    QFormLayout,
    QLabel,
    QMenu,
    QVBoxLayout,
    QWidget,
)

from prm9tool.catalogue.canopen_switches import node_position
from prm9tool.model.document import ParameterDocument
from prm9tool.online.valve_control import ValveControl
from prm9tool.views.actions import MainActions

CURRENT_SIGNAL_TYPES = range(6)  # signal types 0…5 are currents (table 7-15), the others volts


def fault_names() -> dict[str, str]:
    """The emulator's faults in words (the program language)."""
    translate = QCoreApplication.translate  # the name pyside6-lupdate looks for
    return {
        "COIL_A_OPEN": translate("EmulatedValve", "Coil A disconnected"),
        "COIL_A_OVERCURRENT": translate("EmulatedValve", "Coil A short circuit (over-current)"),
        "COIL_B_OPEN": translate("EmulatedValve", "Coil B disconnected"),
        "COIL_B_OVERCURRENT": translate("EmulatedValve", "Coil B short circuit (over-current)"),
        "SETPOINT_WIRE_BREAK": translate("EmulatedValve", "Setpoint wire break"),
        "SENSOR_BREAK": translate("EmulatedValve", "External sensor wire break"),
        "POSITION_SENSOR_BREAK": translate(
            "EmulatedValve", "Spool position sensor (LVDT) wire break"
        ),
        "SUPPLY_LOW": translate("EmulatedValve", "Supply too low (17 V)"),
        "SUPPLY_HIGH": translate("EmulatedValve", "Supply too high (31 V)"),
        "OVER_TEMPERATURE": translate("EmulatedValve", "Over-temperature (105 °C)"),
    }


class EmulatedValveMenu(QMenu):
    """Valve → Emulated valve: inputs and switches…, one checkable action per fault, the cable."""

    def __init__(
        self, control: ValveControl, document: ParameterDocument, parent: QWidget | None = None
    ) -> None:
        super().__init__(parent)
        self.setObjectName("menu_emulated_valve")
        self._control, self._document = control, document
        self.inputs_action = QAction(self)
        self.inputs_action.triggered.connect(self.show_dialog)
        self.cable_action = QAction(self)
        self.cable_action.triggered.connect(control.pull_cable)
        self.fault_actions: dict[str, QAction] = {}
        self.addAction(self.inputs_action)
        self.addSeparator()
        self._faults_end = self.addSeparator()  # the fault actions go between the separators
        self.addAction(self.cable_action)
        self.dialog: EmulatedValveDialog | None = None
        control.emulator_changed.connect(self._on_control_emulator_changed)
        self._on_control_emulator_changed(control.emulator_state)

    def attach(self, actions: MainActions) -> EmulatedValveMenu:
        """Put this menu at the end of the main window's Valve menu; returns itself."""
        actions.menus["valve"].addSeparator()
        actions.menus["valve"].addMenu(self)
        return self

    def _on_control_emulator_changed(self, state: object | None) -> None:
        available = tuple(getattr(state, "faults_available", ()))
        if available != tuple(self.fault_actions):
            self._rebuild(available)
        present: frozenset[str] = frozenset(getattr(state, "faults", ()))
        for name, action in self.fault_actions.items():
            action.setChecked(name in present)
        self.setEnabled(state is not None)
        self.menuAction().setEnabled(state is not None)
        self.retranslate()

    def _rebuild(self, faults: tuple[str, ...]) -> None:
        for action in self.fault_actions.values():
            self.removeAction(action)
            action.deleteLater()
        self.fault_actions = {}
        for name in faults:
            action = QAction(name, self)
            action.setCheckable(True)
            action.setObjectName(f"action_fault_{name}")
            action.toggled.connect(lambda on, fault=name: self._on_fault_toggled(fault, on))
            self.insertAction(self._faults_end, action)
            self.fault_actions[name] = action

    def _on_fault_toggled(self, fault: str, on: bool) -> None:
        present = fault in getattr(self._control.emulator_state, "faults", frozenset())
        if on != present:  # a user's click, not the state pushed in
            self._control.set_fault(fault, on)

    def retranslate(self) -> None:
        """Set every text in the current language."""
        self.setTitle(self.tr("E&mulated valve"))
        self.inputs_action.setText(self.tr("&Inputs and switches…"))
        self.inputs_action.setStatusTip(
            self.tr("Setpoint and sensor signals, supply, temperature and rotary switches")
        )
        self.cable_action.setText(self.tr("&Pull the USB cable"))
        self.cable_action.setStatusTip(self.tr("The link drops as when a real cable is pulled"))
        names = fault_names()
        for name, action in self.fault_actions.items():
            action.setText(names.get(name, name))
            action.setStatusTip(self.tr("Inject this fault into the emulated valve, or repair it"))

    def changeEvent(self, event: QEvent) -> None:
        """Retranslate when the program language changes."""
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate()
        super().changeEvent(event)

    def show_dialog(self) -> EmulatedValveDialog:
        """Show the (non-modal) inputs and switches dialog."""
        if self.dialog is None:
            self.dialog = EmulatedValveDialog(self._control, self._document, self.parentWidget())
        self.dialog.show()
        self.dialog.raise_()
        return self.dialog


class EmulatedValveDialog(QDialog):
    """The emulated valve's analog inputs, supply, ambient temperature and rotary switches."""

    def __init__(
        self, control: ValveControl, document: ParameterDocument, parent: QWidget | None = None
    ) -> None:
        super().__init__(parent)
        self._control, self._document = control, document
        self.fields: dict[str, QDoubleSpinBox] = {}
        ranges = {
            "setpoint": (-22.0, 22.0, 2),
            "sensor": (-22.0, 22.0, 2),
            "supply_voltage": (0.0, 40.0, 2),
            "ambient_temperature": (-40.0, 150.0, 1),
        }
        for name, (low, high, decimals) in ranges.items():
            box = QDoubleSpinBox()
            box.setRange(low, high)
            box.setDecimals(decimals)
            box.setKeyboardTracking(False)  # one change per value, not per keystroke
            box.valueChanged.connect(lambda value, n=name: self._on_field_changed(n, value))
            self.fields[name] = box
        self.switches = {name: QComboBox() for name in ("switch_baud", "switch_node")}
        for name, combo in self.switches.items():
            for position in range(16):
                combo.addItem(f"{position:X}", position)  # texts: retranslate()
            combo.activated.connect(
                lambda _=0, n=name, c=combo: self._on_field_changed(n, c.currentData())
            )
        self.labels = {name: QLabel() for name in (*self.fields, *self.switches)}
        self.note = QLabel()
        self.note.setWordWrap(True)
        form = QFormLayout()
        for name, widget in (*self.fields.items(), *self.switches.items()):
            form.addRow(self.labels[name], widget)
        buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Close)
        buttons.rejected.connect(self.close)
        layout = QVBoxLayout(self)
        layout.addLayout(form)
        layout.addWidget(self.note)
        layout.addWidget(buttons)
        control.emulator_changed.connect(self.show_state)
        self.retranslate()
        self.show_state(control.emulator_state)

    def retranslate(self) -> None:
        """Set every text in the current language."""
        self.setWindowTitle(self.tr("Emulated valve"))
        setpoint_unit = self._unit("AINSETP")
        texts = {
            "setpoint": self.tr("Setpoint input [{0}]:").format(setpoint_unit),
            "sensor": self.tr("External sensor input [{0}]:").format(self._unit("SENSTYPE")),
            "supply_voltage": self.tr("Supply voltage [V]:"),
            "ambient_temperature": self.tr("Ambient temperature [°C]:"),
            "switch_baud": self.tr("Interface / bit-rate switch:"),
            "switch_node": self.tr("Node-ID switch:"),
        }
        for name, label in self.labels.items():
            label.setText(texts[name])
        node = self.switches["switch_node"]
        for position in range(16):
            node.setItemText(position, self._node_position_text(position))
        self.note.setText(
            self.tr(
                "The valve reads its rotary switches at power-up only: restart it "
                "(Valve → Restart valve) for a new position to apply. The setpoint input counts "
                "only while the valve takes its setpoint from the analog input (no CANopen, "
                "no setpoint generator)."
            )
        )

    def _node_position_text(self, position: int) -> str:
        """``1 — LSS, automatic bit rate``: what a node-ID switch position means (table 7-17)."""
        decoded = node_position(position)
        if decoded.software:
            meaning = self.tr("node ID and bit rate by software (NODEID, BITRATE)")
        elif decoded.lss:
            meaning = self.tr("LSS: node ID from an LSS master, automatic bit rate")
        else:
            meaning = self.tr("node {0}").format(decoded.node_id)
        return f"{position:X} — {meaning}"

    def _unit(self, mnemonic: str) -> str:
        if mnemonic not in self._document.values:
            return "V"
        return "mA" if self._document.values[mnemonic] in CURRENT_SIGNAL_TYPES else "V"

    def changeEvent(self, event: QEvent) -> None:
        """Retranslate when the program language changes."""
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate()
        super().changeEvent(event)

    def show_state(self, state: object | None) -> None:
        """Show the emulated valve's inputs and switches (None: none connected)."""
        self.setEnabled(state is not None)
        if state is None:
            return
        inputs = dict(getattr(state, "inputs", {}))
        for name, box in self.fields.items():
            box.blockSignals(True)
            box.setValue(float(inputs.get(name, 0.0)))
            box.blockSignals(False)
        has_sensor = bool(getattr(state, "sensor", False))
        self.fields["sensor"].setVisible(has_sensor)
        self.labels["sensor"].setVisible(has_sensor)
        canopen = bool(getattr(state, "canopen", False))
        for position, name in enumerate(self.switches):
            combo = self.switches[name]
            combo.setCurrentIndex(int(getattr(state, "switches", (0, 0))[position]))
            combo.setVisible(canopen)
            self.labels[name].setVisible(canopen)

    def _on_field_changed(self, name: str, value: float) -> None:
        self._control.set_input(name, float(value))

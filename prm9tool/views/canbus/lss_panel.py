"""The CAN bus dialog's "devices without a node ID": valves at node-ID switch 1 (LSS, manual
table 7-17) found by Fastscan, and "Assign node ID…" (CiA 305; docs/can-link.md).

The panel only shows and asks; the LSS jobs run off the GUI thread in
:class:`~prm9tool.online.lss_commissioning.LssCommissioning`. "Assign node ID…" proposes the
first node ID no node answers at, refuses one that answers (the job checks once more on the
bus), and once the valve answers at its new ID the panel emits :attr:`LssPanel.assigned_id`
(``can:NODE``) so the dialog goes online with it.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from PySide6.QtCore import Signal
from PySide6.QtWidgets import (
    QHBoxLayout,
    QInputDialog,
    QLabel,
    QPushButton,
    QTableWidgetItem,
    QVBoxLayout,
    QWidget,
)
from shiboken6 import isValid

from prm9tool.online.lss_commissioning import (
    Assigned,
    LssCommissioning,
    LssDevice,
)
from prm9tool.views.row_table import row_table

if TYPE_CHECKING:
    pass


class LssPanel(QWidget):
    """Devices without a node ID and the assignment of one."""

    assigned_id = Signal(str)  # can:NODE of a valve that answers at its new node ID
    assigned_many = Signal()  # several valves got their node IDs: search the bus again

    def __init__(
        self,
        lss: LssCommissioning,
        bus: Callable[[], dict[str, object]],
        taken: Callable[[], set[int]],
        parent: QWidget | None = None,
    ) -> None:
        """``bus()``: the bus the dialog names; ``taken()``: node IDs that answer on it."""
        super().__init__(parent)
        self._lss, self._bus, self._taken = lss, bus, taken
        self._devices: list[LssDevice] = []
        lss.scanned.connect(self._on_scanned)
        lss.assigned.connect(self._on_assigned)
        lss.assigned_all.connect(self._on_assigned_all)
        lss.failed.connect(self._on_failed)
        title = QLabel(self.tr("Devices without a node ID (node-ID switch at 1: LSS)"))
        self.table = row_table(
            [
                self.tr("Serial"),
                self.tr("Device"),
                self.tr("Vendor ID"),
                self.tr("Product code"),
                self.tr("Revision"),
            ]
        )
        self.table.setMaximumHeight(170)
        self.table.itemSelectionChanged.connect(self._update_buttons)
        self.look = QPushButton(self.tr("Look for devices without a node ID"))
        self.look.clicked.connect(self.start_scan)
        self.assign = QPushButton(self.tr("Assign node ID…"))
        self.assign.clicked.connect(self._on_assign_clicked)
        self.assign_all = QPushButton(self.tr("Assign node IDs to all…"))
        self.assign_all.clicked.connect(self._on_assign_all_clicked)
        self.state = QLabel()
        self.state.setWordWrap(True)
        buttons = QHBoxLayout()
        buttons.addWidget(self.look)
        buttons.addWidget(self.assign)
        buttons.addWidget(self.assign_all)
        buttons.addStretch(1)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addWidget(title)
        layout.addWidget(self.table)
        layout.addLayout(buttons)
        layout.addWidget(self.state)
        self._update_buttons()

    def start_scan(self) -> None:
        """Fastscan the dialog's bus (off the GUI thread)."""
        if self._lss.busy:
            return
        self.state.setText(self.tr("Looking for devices without a node ID (LSS Fastscan)…"))
        self._lss.scan(self._bus())
        self._update_buttons()

    def selected(self) -> LssDevice | None:
        """The chosen device without a node ID (None: none)."""
        row = self.table.currentRow()
        return self._devices[row] if 0 <= row < len(self._devices) else None

    def _on_scanned(self, devices: list[LssDevice]) -> None:
        if not isValid(self):
            return
        self._devices = list(devices)
        self.table.setRowCount(len(devices))
        for row, device in enumerate(devices):
            name = self.tr("PRM9") if device.is_prm9 else self.tr("not a PRM9")
            cells = (
                str(device.serial),
                name,
                f"0x{device.vendor:X}",
                f"0x{device.product:X}",
                f"0x{device.revision:X}",
            )
            for column, text in enumerate(cells):
                self.table.setItem(row, column, QTableWidgetItem(text))
        if devices:
            self.table.selectRow(0)
            self.state.setText(self.tr("%n device(s) without a node ID.", "", len(devices)))
        else:
            self.state.setText(
                self.tr(
                    "No device without a node ID answered: every device has one, or none is at "
                    "node-ID switch 1, or the bus runs at another bit rate."
                )
            )
        self._update_buttons()

    def _on_assign_clicked(self) -> None:
        device = self.selected()
        if device is None or self._lss.busy:
            return
        taken = self._taken()
        proposal = next((n for n in range(1, 128) if n not in taken), 1)
        node, ok = QInputDialog.getInt(
            self,
            self.tr("Assign node ID"),
            self.tr(
                "Node ID for serial {0} (1…127; stored in the valve, used from now on and after "
                "every power-up):"
            ).format(device.serial),
            proposal,
            1,
            127,
        )
        if not ok:
            return
        if node in taken:
            self.state.setText(
                self.tr("Node ID {0} is taken: a node answers there. Choose another one.").format(
                    node
                )
            )
            return
        self.state.setText(
            self.tr("Giving serial {0} node ID {1} and storing it…").format(device.serial, node)
        )
        self._lss.assign(self._bus(), device, node)
        self._update_buttons()

    def _on_assign_all_clicked(self) -> None:
        """Every device listed gets a node ID: consecutive free ones from the first asked for,
        in the order of the serial numbers (one action for a machine's valves)."""
        if not self._devices or self._lss.busy:
            return
        taken = self._taken()
        proposal = next((n for n in range(1, 128) if n not in taken), 1)
        first, ok = QInputDialog.getInt(
            self,
            self.tr("Assign node IDs to all"),
            self.tr(
                "First node ID: the {0} valves get consecutive free node IDs from it, in the "
                "order of their serial numbers (stored in each valve):"
            ).format(len(self._devices)),
            proposal,
            1,
            127,
        )
        if not ok:
            return
        free = [n for n in range(first, 128) if n not in taken]
        devices = sorted(self._devices, key=lambda d: d.serial)
        if len(free) < len(devices):
            self.state.setText(
                self.tr(
                    "From node ID {0} on there are only {1} free node IDs for {2} valves."
                ).format(first, len(free), len(devices))
            )
            return
        plan = list(zip(devices, free, strict=False))
        self.state.setText(
            self.tr("Giving node IDs: {0}…").format(", ".join(f"{d.serial} → {n}" for d, n in plan))
        )
        self._lss.assign_all(self._bus(), plan)
        self._update_buttons()

    def _on_assigned_all(self, done: list[Assigned]) -> None:
        if not isValid(self):
            return
        given = {a.device for a in done}
        self._on_scanned([d for d in self._devices if d not in given])
        self.state.setText(
            self.tr("Given and stored: {0}. Searching the bus again…").format(
                ", ".join(f"{a.device.serial} → {a.device_id}" for a in done)
            )
        )
        self.assigned_many.emit()

    def _on_assigned(self, assigned: Assigned) -> None:
        if not isValid(self):
            return
        self._devices = [d for d in self._devices if d != assigned.device]
        self._on_scanned(self._devices)
        self.state.setText(
            self.tr("Serial {0} answers as {1} (stored). Going online with it…").format(
                assigned.device.serial, assigned.device_id
            )
        )
        self.assigned_id.emit(assigned.device_id)

    def _on_failed(self, job: str, reason: str) -> None:
        if isValid(self):
            if job in ("scan", "assign"):  # the dialog says the others
                self.state.setText(reason)
            self._update_buttons()

    def _update_buttons(self) -> None:
        idle = not self._lss.busy
        self.look.setEnabled(idle)
        self.assign.setEnabled(idle and self.selected() is not None)
        self.assign_all.setEnabled(idle and bool(self._devices))

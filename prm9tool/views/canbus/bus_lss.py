"""The CAN bus dialog's bus-wide LSS actions: "Find bit rate" (listen-only), "Change node ID by
LSS…" for a configured valve at node-ID switch 1, and "Change bit rate by LSS…" for every such
valve together — each after the warning that prm9tool's own link moves (docs/can-link.md). The
jobs run off the GUI thread in :class:`~prm9tool.online.lss_commissioning.LssCommissioning`.
"""

from __future__ import annotations

from typing import Protocol

from PySide6.QtCore import QObject
from PySide6.QtWidgets import QComboBox, QInputDialog, QLabel, QPushButton, QTableWidget, QWidget
from shiboken6 import isValid

from prm9tool.online.connection_protocol import ValveListing
from prm9tool.online.lss_commissioning import FoundRate, LssCommissioning, RateChanged
from prm9tool.views import prompts


class LssHost(Protocol):
    """What the LSS actions use of the CAN bus dialog (``CanBusDialog``, which holds them:
    typed by what they need, this module stays below the dialog)."""

    bitrate: QComboBox
    state: QLabel
    table: QTableWidget

    @property
    def entries(self) -> list[ValveListing]: ...

    def bus(self) -> dict[str, object]: ...

    def taken(self) -> set[int]: ...

    def selected_device_id(self) -> str | None: ...

    def search_bus(self) -> None: ...

    def stop_monitor(self) -> None: ...

    def update_ok(self) -> None: ...

    def on_lss_assigned(self, device_id: str) -> None: ...


class BusLssActions(QObject):
    """The CAN bus dialog's "Find bit rate" and "Change node ID by LSS…" (off the GUI thread
    in :class:`LssCommissioning`); hidden without one."""

    def __init__(self, dialog: LssHost, widget: QWidget, lss: LssCommissioning | None) -> None:
        """``widget``: the dialog as a widget (the parent of the questions it asks)."""
        super().__init__(widget)
        self._dialog, self._widget, self._lss = dialog, widget, lss
        self.find_rate = QPushButton(self.tr("Find bit rate"))
        self.find_rate.setToolTip(
            self.tr("Listen at each bit rate in listen-only mode (nothing is sent)")
        )
        self.find_rate.clicked.connect(self._on_find_rate_clicked)
        self.renumber = QPushButton(self.tr("Change node ID by LSS…"))
        self.renumber.clicked.connect(self._on_renumber_clicked)
        self.change_rate = QPushButton(self.tr("Change bit rate by LSS…"))
        self.change_rate.clicked.connect(self._on_change_rate_clicked)
        for button in (self.find_rate, self.renumber, self.change_rate):
            button.setVisible(lss is not None)
        if lss is not None:
            lss.bitrate_found.connect(self._on_rate_found)
            lss.renumbered.connect(lambda done: dialog.on_lss_assigned(done.device_id))
            lss.failed.connect(self._on_lss_failed)
            lss.rate_changed.connect(self._on_rate_changed)

    def set_selected(self, selected: bool) -> None:
        """Enable "Change node ID by LSS…" for a chosen valve while no LSS job runs."""
        idle = self._lss is not None and not self._lss.busy
        self.renumber.setEnabled(idle and selected)
        self.change_rate.setEnabled(idle)

    def _on_find_rate_clicked(self) -> None:
        d = self._dialog
        if self._lss is None or self._lss.busy:
            return
        d.stop_monitor()  # it holds the adapter at the rate set now
        self.find_rate.setEnabled(False)
        d.state.setText(self.tr("Listening at each bit rate (listen-only: nothing is sent)…"))
        self._lss.find_bitrate(d.bus())

    def _on_rate_found(self, found: FoundRate) -> None:
        d = self._dialog
        if not isValid(self._widget):
            return
        self.find_rate.setEnabled(True)
        d.bitrate.setCurrentIndex(max(d.bitrate.findData(found.bitrate), 0))
        nodes = ", ".join(str(n) for n in found.nodes) or self.tr("none identified")
        d.state.setText(
            self.tr("The bus runs at {0} kbit/s (frames from nodes: {1}). Search the bus.").format(
                found.bitrate // 1000, nodes
            )
        )

    def _on_lss_failed(self, job: str, reason: str) -> None:
        d = self._dialog
        if isValid(self._widget) and job in ("bitrate", "renumber", "rate"):
            self.find_rate.setEnabled(True)
            self.change_rate.setEnabled(True)
            d.state.setText(reason)
            d.update_ok()

    def _on_renumber_clicked(self) -> None:
        """The chosen valve (node-ID switch at 1) gets another node ID by LSS, with the warning
        that prm9tool's own link to it moves."""
        d = self._dialog
        device_id = d.selected_device_id()
        if device_id is None or self._lss is None or self._lss.busy:
            return
        entry = d.entries[d.table.currentRow()]
        old, taken = int(device_id.removeprefix("can:")), d.taken()
        proposal = next((n for n in range(1, 128) if n not in taken), 1)
        new, ok = QInputDialog.getInt(
            self._widget,
            self.tr("Change node ID by LSS"),
            self.tr("New node ID for serial {0}, now {1} (1…127):").format(entry.serial, old),
            proposal,
            1,
            127,
        )
        if not ok or new == old:
            return
        if new in taken:
            d.state.setText(
                self.tr("Node ID {0} is taken: a node answers there. Choose another one.").format(
                    new
                )
            )
            return
        answer = prompts.ask(
            self._widget,
            prompts.Icon.Warning,
            self.tr("Change node ID by LSS"),
            self.tr(
                "Serial {0} will answer at node {2} instead of {1}, stored in the valve (its "
                "node-ID switch must be at 1: LSS). prm9tool's own link moves with it: a "
                "connection to can:{1} ends, and prm9tool goes online with can:{2}. A PLC that "
                "addresses node {1} no longer reaches the valve. Change it?"
            ).format(entry.serial, old, new),
            prompts.Button.Yes | prompts.Button.No,
            prompts.Button.No,
        )
        if answer != prompts.Button.Yes:
            return
        d.state.setText(
            self.tr("Changing the node ID of serial {0} to {1}…").format(entry.serial, new)
        )
        self.renumber.setEnabled(False)
        self._lss.renumber(d.bus(), old, new)

    def _on_change_rate_clicked(self) -> None:
        """Every valve at node-ID switch 1 goes to another bit rate by LSS, together, after a
        warning that the other nodes and prm9tool's own link must follow."""
        d = self._dialog
        if self._lss is None or self._lss.busy:
            return
        old = int(str(d.bitrate.currentData()))
        rates = [d.bitrate.itemText(i) for i in range(d.bitrate.count())]
        text, ok = QInputDialog.getItem(
            self._widget,
            self.tr("Change bit rate by LSS"),
            self.tr("New bit rate of the bus:"),
            rates,
            d.bitrate.currentIndex(),
            False,
        )
        if not ok or text not in rates:
            return
        new = int(str(d.bitrate.itemData(rates.index(text))))
        if new == old:
            return
        answer = prompts.ask(
            self._widget,
            prompts.Icon.Warning,
            self.tr("Change bit rate by LSS"),
            self.tr(
                "Every valve at node-ID switch 1 (LSS) switches from {1} kbit/s to {0} kbit/s "
                "together and stores it. Nodes whose switches set the bit rate (node-ID switch "
                "0 or 2…F) and the PLC keep {1} kbit/s: set them too before the machine runs "
                "again, or the bus stops working. prm9tool's own link moves to {0} kbit/s. "
                "Change the bit rate?"
            ).format(new // 1000, old // 1000),
            prompts.Button.Yes | prompts.Button.No,
            prompts.Button.No,
        )
        if answer != prompts.Button.Yes:
            return
        d.stop_monitor()
        self.change_rate.setEnabled(False)
        d.state.setText(self.tr("Changing the bit rate to {0} kbit/s by LSS…").format(new // 1000))
        self._lss.change_rate(d.bus(), new)

    def _on_rate_changed(self, done: RateChanged) -> None:
        d = self._dialog
        if not isValid(self._widget):
            return
        self.change_rate.setEnabled(True)
        d.bitrate.setCurrentIndex(max(d.bitrate.findData(done.bitrate), 0))
        kbit = done.bitrate // 1000
        if d.bus()["interface"] == "socketcan":
            channel = d.bus()["channel"]
            d.state.setText(
                self.tr(
                    "{0} valve(s) switched to {1} kbit/s. prm9tool cannot change the bit rate of "
                    "a socketcan interface: sudo ip link set {2} down && sudo ip link set {2} up "
                    "type can bitrate {3}, then search the bus."
                ).format(done.devices, kbit, channel, done.bitrate)
            )
            return
        d.state.setText(
            self.tr("{0} valve(s) switched to {1} kbit/s; prm9tool follows.").format(
                done.devices, kbit
            )
        )
        d.search_bus()

"""Communication → CAN bus: choose a CAN adapter, look at the nodes on the bus, pick a valve.

Interface (python-can's name), channel and bit rate are remembered in QSettings. "Search the
bus" scans node IDs 1…127 off the GUI thread (ValveConnection.list_devices_async with the bus)
and lists every node: PRM9 valves with type key, serial and firmware, other nodes as "not a
PRM9" (not selectable), each with its NMT state, heartbeat age and last EMCY. From the search
on, a :class:`~prm9tool.online.bus_monitor.BusMonitor` keeps these live while the dialog is open
(fed off the GUI thread, a few times a second): the ages tick, a node that boots is marked so, a
node that appears is added ("new on the bus"), one whose heartbeat stops is shown silent (the
network view; the table is :mod:`.node_table`). OK goes online with the chosen valve
(``can:NODE``). docs/can-link.md.
"""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtCore import QCoreApplication, QSettings
from PySide6.QtWidgets import (
    QComboBox,
    QDialog,
    QDialogButtonBox,
    QFormLayout,
    QHBoxLayout,
    QInputDialog,
    QLabel,
    QLineEdit,
    QPushButton,
    QVBoxLayout,
    QWidget,
)
from shiboken6 import isValid

from prm9tool.catalogue.can_adapters import adapters, default_adapter, usual_channel
from prm9tool.catalogue.can_type_keys import remember
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.errors import TypeKeyError
from prm9tool.online.bus_monitor import BusMonitor, HeardNode
from prm9tool.online.connection_protocol import ListedValves, ValveIdentity, ValveListing
from prm9tool.online.lss_commissioning import LssCommissioning
from prm9tool.online.trace_recording import BusRecording
from prm9tool.paths import user_data_dir
from prm9tool.translate import error_text
from prm9tool.views.canbus.bus_lss import BusLssActions
from prm9tool.views.canbus.lss_panel import LssPanel
from prm9tool.views.canbus.node_table import NodeTable
from prm9tool.views.help_dialog import add_context_help
from prm9tool.views.trace.record_controls import RecordControls

INTERFACE_KEY, CHANNEL_KEY, BITRATE_KEY = "can/interface", "can/channel", "can/bitrate"
BITRATES = (20_000, 50_000, 125_000, 250_000, 500_000, 800_000, 1_000_000)  # table 7-17
DEFAULT_BITRATE = 500_000  # delivery state (manual table 7-22)
# (bus as a dict, deliver): scans off the GUI thread, deliver(entries or exception) on it
Scanner = Callable[[dict[str, object], Callable[[ListedValves], None]], None]


def saved_bus(settings: QSettings) -> dict[str, object]:
    """The bus the user chose last (``interface``, ``channel``, ``bitrate``)."""
    bitrate = settings.value(BITRATE_KEY, DEFAULT_BITRATE)
    try:
        rate: int | None = int(str(bitrate)) or None
    except ValueError:
        rate = DEFAULT_BITRATE
    return {
        "interface": str(settings.value(INTERFACE_KEY, default_adapter().interface)),
        "channel": str(settings.value(CHANNEL_KEY, default_adapter().channel)),
        "bitrate": rate,
    }


class CanBusDialog(QDialog):
    """The CAN bus, its nodes and the valve to go online with."""

    def __init__(
        self,
        scan: Scanner,
        settings: QSettings,
        parent: QWidget | None = None,
        monitor: BusMonitor | None = None,
        lss: LssCommissioning | None = None,
        recording: BusRecording | None = None,
    ) -> None:
        """``monitor``: keeps the node table live after a search (None: as the scan saw it);
        ``lss``: shows the devices without a node ID and assigns one (None: not offered);
        ``recording``: Record… / Stop for this bus (None: not offered)."""
        super().__init__(parent)
        add_context_help(self, "can")  # F1
        self._chosen: str | None = None  # a valve given its node ID here (LSS)
        self.setWindowTitle(self.tr("CAN bus"))
        self._scan, self._settings = scan, settings
        self._monitor = monitor
        self._searching = False  # a search runs: its result comes before the monitor's news
        if monitor is not None:
            monitor.nodes_heard.connect(self._on_nodes_heard)
            monitor.failed.connect(self._on_monitor_failed)
            self.finished.connect(lambda _r: monitor.stop())
        bus = saved_bus(settings)
        self.interface = QComboBox()
        self.interface.setEditable(True)
        # this platform's adapters (catalogue/can_adapters.py: pcan PCAN_USBBUS1 first on
        # Windows, socketcan can0 on Linux)
        self.interface.addItems([adapter.interface for adapter in adapters()])
        self.interface.setCurrentText(str(bus["interface"]))
        self.channel = QLineEdit(str(bus["channel"]))
        self.interface.currentTextChanged.connect(self._on_interface_changed)
        self.bitrate = QComboBox()
        for rate in BITRATES:
            self.bitrate.addItem(f"{rate // 1000} kbit/s", rate)
        self.bitrate.setCurrentIndex(max(self.bitrate.findData(bus["bitrate"]), 0))
        self.search = QPushButton(self.tr("Search the bus"))
        self.search.clicked.connect(self._on_search_clicked)
        self.state = QLabel(self.tr("Search the bus to list its nodes."))
        self.state.setWordWrap(True)
        self.nodes = NodeTable()
        self.table = self.nodes.widget
        self.table.itemSelectionChanged.connect(self.update_ok)
        self.table.doubleClicked.connect(lambda _i: self._accept_if_valve())
        self.buttons = QDialogButtonBox(
            QDialogButtonBox.StandardButton.Ok | QDialogButtonBox.StandardButton.Cancel
        )
        self.buttons.accepted.connect(self._accept_if_valve)
        self.buttons.rejected.connect(self.reject)
        form = QFormLayout()
        form.addRow(self.tr("Interface (python-can)"), self.interface)
        form.addRow(self.tr("Channel"), self.channel)
        rate_row = QHBoxLayout()
        rate_row.addWidget(self.bitrate, 1)
        self._lss = lss
        self.lss_actions = BusLssActions(self, self, lss)
        self.find_rate, self.renumber = self.lss_actions.find_rate, self.lss_actions.renumber
        rate_row.addWidget(self.find_rate)
        form.addRow(self.tr("Bit rate"), rate_row)
        layout = QVBoxLayout(self)
        layout.addLayout(form)
        layout.addWidget(self.search)
        layout.addWidget(self.state)
        layout.addWidget(self.table)
        lss_row = QHBoxLayout()
        lss_row.addWidget(self.renumber)
        lss_row.addWidget(self.lss_actions.change_rate)
        lss_row.addStretch(1)
        layout.addLayout(lss_row)
        self.lss_panel: LssPanel | None = None
        if lss is not None:
            self.lss_panel = LssPanel(lss, self.bus, self.taken, self)
            self.lss_panel.assigned_id.connect(self.on_lss_assigned)
            self.lss_panel.assigned_many.connect(self._on_search_clicked)
            layout.addWidget(self.lss_panel)
        self.record_controls: RecordControls | None = None
        if recording is not None:
            self.record_controls = RecordControls(recording, self.bus, self)
            layout.addWidget(self.record_controls)
        layout.addWidget(self.buttons)
        self.resize(1060, 620 if lss is not None else 420)
        self.update_ok()

    def bus(self) -> dict[str, object]:
        """The bus as entered."""
        return {
            "interface": self.interface.currentText().strip(),
            "channel": self.channel.text().strip(),
            "bitrate": self.bitrate.currentData(),
        }

    def _on_interface_changed(self, interface: str) -> None:
        """Another adapter chosen: its usual channel replaces the channel of the one before
        (``PCAN_USBBUS1`` for pcan, ``COM3`` for slcan on Windows) unless the user typed one
        of their own."""
        usual = usual_channel(interface.strip())
        channel = self.channel.text().strip()
        if usual is not None and (not channel or channel in {a.channel for a in adapters()}):
            self.channel.setText(usual)

    def selected_device_id(self) -> str | None:
        """``can:NODE`` of the chosen PRM9 (None: none chosen)."""
        if self._chosen is not None:
            return self._chosen
        row = self.table.currentRow()
        if not 0 <= row < len(self.nodes.entries):
            return None
        entry = self.nodes.entries[row]
        return entry.device_id if entry.kind == "can" else None

    def _remember(self) -> None:
        bus = self.bus()
        self._settings.setValue(INTERFACE_KEY, bus["interface"])
        self._settings.setValue(CHANNEL_KEY, bus["channel"])
        self._settings.setValue(BITRATE_KEY, bus["bitrate"])

    def watch_session_bus(self, bus: dict[str, object], valve: ValveIdentity) -> None:
        """Online over CAN with ``valve`` on ``bus``: the network view of that
        bus, as the nodes tell about themselves. The monitor shares the session's master
        (``bus`` as the session has it), so no second adapter is opened on the channel, and
        nothing is sent: no search (its SDO reads would meet the session's), no other valve to
        go online with. Issue 34, item 12."""
        self.nodes.watched = valve
        self.interface.setCurrentText(str(bus["interface"]))
        self.channel.setText(str(bus["channel"]))
        rate = bus.get("bitrate")
        if self.bitrate.findData(rate) < 0:
            self.bitrate.addItem(self.tr("as the adapter is set"), rate)
        self.bitrate.setCurrentIndex(self.bitrate.findData(rate))
        for widget in (self.interface, self.channel, self.bitrate, self.search):
            widget.setEnabled(False)
        self.buttons.setStandardButtons(QDialogButtonBox.StandardButton.Close)
        self.state.setText(
            self.tr(
                "Online with {0} on this bus: the nodes are shown as they tell about "
                "themselves (nothing is sent). Go offline to search the bus or to choose "
                "another valve."
            ).format(valve.device_id)
        )
        if self._monitor is not None:
            self._monitor.start(bus)

    def keep_online(self, valve: str) -> None:
        """Online with ``valve`` over another link (USB): the bus can be searched and
        watched (its own adapter), but going online with a node waits until offline."""
        self.buttons.setStandardButtons(QDialogButtonBox.StandardButton.Close)
        self.state.setText(
            self.tr(
                "Online with {0}: search the bus to watch its nodes; go offline to go "
                "online with one of them."
            ).format(valve)
        )

    def _on_search_clicked(self) -> None:
        self._remember()
        self._searching = True
        self.search.setEnabled(False)
        self.state.setText(self.tr("Searching the bus (node IDs 1…127)…"))
        if self._monitor is not None:
            self._monitor.start(self.bus())
        self._scan(self.bus(), self._on_scanned)

    def _on_scanned(self, found: ListedValves) -> None:
        if not isValid(self):
            return
        self._searching = False
        self.search.setEnabled(True)
        if isinstance(found, Exception):
            self._fill_table([])
            self.state.setText(
                self.tr("The bus could not be searched: {0}").format(error_text(found))
            )
            return
        nodes = [e for e in found if e.kind in ("can", "not-prm9")]
        self._fill_table(nodes)
        if self.lss_panel is not None:
            self.lss_panel.start_scan()
        valves = sum(e.kind == "can" for e in nodes)
        self.state.setText(
            self.tr("%n node(s) answered.", "", len(nodes))
            + " "
            + self.tr("%n of them PRM9 valve(s).", "", valves)
        )

    def _fill_table(self, entries: list[ValveListing]) -> None:
        self.nodes.fill(entries)
        self.update_ok()

    def _on_nodes_heard(self, nodes: list[HeardNode]) -> None:
        """The monitor's news: NMT state, heartbeat age, last EMCY; new and silent nodes."""
        if not isValid(self) or self._searching:
            return  # a search runs: its result comes first
        self.nodes.show_heard(nodes)

    def _on_monitor_failed(self, reason: str) -> None:
        if isValid(self):
            self.state.setText(self.tr("The bus cannot be watched: {0}").format(reason))

    @property
    def entries(self) -> list[ValveListing]:
        """The nodes the last search listed, by row."""
        return self.nodes.entries

    def search_bus(self) -> None:
        """Search the bus as entered (as the button does)."""
        self._on_search_clicked()

    def stop_monitor(self) -> None:
        """Let the live view go of the adapter (finding the bit rate opens it otherwise)."""
        if self._monitor is not None:
            self._monitor.stop()

    def taken(self) -> set[int]:
        """Node IDs that answered the search or were heard since."""
        return self.nodes.taken()

    def on_lss_assigned(self, device_id: str) -> None:
        """A valve answers at the node ID it was given: go online with it."""
        self._chosen = device_id
        self._remember()
        self.accept()

    def update_ok(self) -> None:
        ok = self.buttons.button(QDialogButtonBox.StandardButton.Ok)
        if ok is None:  # watching the session's bus: nothing to choose
            return
        ok.setEnabled(self.selected_device_id() is not None)
        self.lss_actions.set_selected(self.selected_device_id() is not None)

    def _accept_if_valve(self) -> None:
        if self.selected_device_id() is None:
            return
        entry = self.nodes.entries[self.table.currentRow()]
        if entry.type_key.startswith("?") and not self._ask_type_key(entry):
            return
        self._remember()
        self.accept()

    def _ask_type_key(self, entry: ValveListing) -> bool:
        """A real valve does not tell its type key (docs/can-link.md): ask for the one on its
        label, check it against what its objects tell, remember it for its serial number."""
        told = "E04" if "E04" in entry.type_key else "E02"
        key, problem = ask_type_key(self, entry.serial, told)
        if problem:
            self.state.setText(problem)
        return key is not None


def ask_type_key(parent: QWidget | None, serial: int, told: str) -> tuple[str | None, str]:
    """Ask for the type key on the label of valve ``serial``, whose objects say ``told`` (E02,
    E04) -CA; a fitting key is remembered for the serial number. Returns (key, "") — or (None,
    why the answer does not fit), (None, "") when the user cancelled."""
    question = (
        QCoreApplication.translate(
            "CanBusDialog",
            "The valve (serial number {0}) does not tell its type key; its objects say "
            "{1} -CA. Type key on the valve's label:",
        ).format(serial, told)
        if told
        else QCoreApplication.translate(
            "CanBusDialog",
            "The valve (serial number {0}) does not tell its type key, and its objects do not "
            "tell E02 from E04 (-CA). Type key on the valve's label:",
        ).format(serial)
    )
    text, ok = QInputDialog.getText(
        parent,
        QCoreApplication.translate("CanBusDialog", "Type key of the valve"),
        question,
        text=f"PRM9-06.3Z11/30-24{told or 'E02'}S02-CA",
    )
    if not ok:
        return None, ""
    try:
        key = TypeKey.parse(text)
    except TypeKeyError as exc:
        return None, error_text(exc)
    if (told and key.config.value != told) or not key.canopen:
        problem = QCoreApplication.translate(
            "CanBusDialog", "{0} does not fit the valve: its objects say {1} -CA."
        )
        return None, problem.format(key, told)
    remember(user_data_dir(), serial, str(key))
    return str(key), ""

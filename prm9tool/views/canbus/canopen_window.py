"""The CANopen window (manual §8.7, figure 8-17): rotary switches, terminator, node ID.

On top the two switch tables (:mod:`prm9tool.views.canbus.canopen_tables`, marks "a", "c", "d").
Below: the terminator on/off choice (mark "b") and the node ID
1…127 used when the node-ID switch is at 0 (mark "e"), plus the software bit rate.

The valve reads its switches at power-up only, so the positions shown are those of the last
start; a part of the interface switch's position that the node-ID switch overrides (its bit
rate at node switch 0 or 1, its terminator at 1) is struck through. A change is an undoable
document edit only: online, the main window's :class:`~prm9tool.online.sync.ValveSync` writes it to
the valve like every other edit, and the window then has the valve store it in non-volatile
memory, because the setting takes effect only after a restart, which reloads the stored
values. Given an access model, the window honours the catalogue's access level.
"""

from __future__ import annotations

from typing import Any

from PySide6.QtCore import QEvent, QSignalBlocker
from PySide6.QtWidgets import (
    QCheckBox,
    QComboBox,
    QDialog,
    QDialogButtonBox,
    QFormLayout,
    QGroupBox,
    QLabel,
    QSpinBox,
    QVBoxLayout,
    QWidget,
)

from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.canopen_switches import baud_position, effective, format_bitrate
from prm9tool.errors import AccessDeniedError, ValueRangeError
from prm9tool.i18n import current_language
from prm9tool.model.access import AccessModel
from prm9tool.model.document import ParameterDocument, Raw
from prm9tool.model.editing import apply_edit
from prm9tool.online.connection_protocol import ParameterConnection
from prm9tool.online.sync import ValveSync
from prm9tool.service.polling import variant_of
from prm9tool.translate import error_text
from prm9tool.views.canbus.canopen_tables import SwitchTables
from prm9tool.views.diagram.colours import toned_style
from prm9tool.views.diagram.dialogs.fields import not_on_enter
from prm9tool.views.help_dialog import add_context_help

SETTINGS = ("NODEID", "BITRATE", "CANTERM")
SWITCHES = ("SWBAUD", "SWNODE")
READ_TAG = "canopen_window"
RESTARTED = ("restart", "after_restart")  # the connection's restart; Valve → Restart valve
# written for paper, moved onto the palette by toned_style (light or dark)
RESTART_STYLE = "background: #fff4d6; color: #6b4a00; padding: 6px; border-radius: 4px;"
ERROR_STYLE = "color: #d03030; font-weight: bold;"


class CanopenWindow(QDialog):
    """Switch tables, terminator and node ID of a -CA valve."""

    def __init__(
        self,
        document: ParameterDocument,
        connection: ParameterConnection | None = None,
        parent: QWidget | None = None,
        access: AccessModel | None = None,
        sync: ValveSync | None = None,
    ) -> None:
        super().__init__(parent)
        add_context_help(self, "can")  # F1
        self._doc, self._connection, self._access = document, connection, access
        self._sync = sync  # writes document edits to the valve while online
        self.switches: tuple[int, int] | None = None  # (interface, node) at the last power-up
        self.valve_values: dict[str, Raw] = {}  # NODEID, BITRATE, CANTERM as read from the valve
        self.restart_pending = False
        self._build()
        document.value_changed.connect(self._on_document_value_changed)
        document.values_reset.connect(self.refresh)
        if access is not None:
            access.level_changed.connect(self.refresh)
        if connection is not None:
            connection.online_changed.connect(self._on_online_changed)
            connection.operation_finished.connect(self._on_operation_finished)
        self.retranslate()
        self.refresh()
        self.read_from_valve()

    # --- building ------------------------------------------------------------------------------
    def _build(self) -> None:
        self.intro, self.state_label = _label(), _label()
        self.effective_label = _label("font-weight: bold;")
        self.restart_label, self.error_label = _label(), _label()
        self._tone()
        buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Close)
        buttons.rejected.connect(self.close)
        not_on_enter(buttons)
        root = QVBoxLayout(self)
        for widget in (self.intro, self.state_label):
            root.addWidget(widget)
        root.addWidget(self._build_tables(), 1)
        for part in (self._build_settings(), self.effective_label, self.restart_label):
            root.addWidget(part)
        root.addWidget(self.error_label)
        root.addWidget(buttons)
        self.resize(880, 660)  # fits a 1024 × 768 screen with its title bar

    def _build_tables(self) -> SwitchTables:
        self.tables = SwitchTables()
        self.baud_table, self.node_table = self.tables.baud_table, self.tables.node_table
        return self.tables

    def _build_settings(self) -> QGroupBox:
        self.terminator = QCheckBox()
        self.terminator.toggled.connect(self._on_terminator_toggled)
        self.node_id = QSpinBox()
        param = CATALOGUE["NODEID"]
        self.node_id.setRange(param.raw_min, param.raw_max)
        self.node_id.setMaximumWidth(120)
        self.node_id.editingFinished.connect(self._on_node_id_edited)
        self.bitrate = QComboBox()
        self.bitrate.setMaximumWidth(160)
        self.bitrate.activated.connect(self._on_bitrate_activated)
        self.settings_box = QGroupBox()
        form = QFormLayout(self.settings_box)
        self.captions = [QLabel(), QLabel(), QLabel()]
        for caption, widget in zip(
            self.captions, (self.terminator, self.node_id, self.bitrate), strict=True
        ):
            form.addRow(caption, widget)
        return self.settings_box

    # --- texts ------------------------------------------------------------------------------------
    def retranslate(self) -> None:
        """Every visible text in the current language."""
        self.setWindowTitle(self.tr("CANopen"))
        self.intro.setText(
            self.tr(
                "The valve reads its two rotary switches at power-up only; the marked rows are "
                "the positions it read at its last start. Terminator, node ID and bit rate set "
                "here are stored in the valve and take effect after the next restart."
            )
        )
        self.tables.retranslate()
        self.captions[0].setText(self.tr("CAN terminator 120 Ω"))
        self.captions[1].setText(self.tr("Node ID (node switch at 0)"))
        self.captions[2].setText(self.tr("Bit rate (node switch at 0)"))
        self.terminator.setText(self.tr("on"))
        with QSignalBlocker(self.bitrate):
            self.bitrate.clear()
            for code, label in CATALOGUE["BITRATE"].choices:
                self.bitrate.addItem(label.get(current_language()), code)
        self.refresh()

    # --- showing ----------------------------------------------------------------------------------
    def refresh(self) -> None:
        """Redraw the tables, settings and the effective result from the current state."""
        if not hasattr(self, "bitrate"):
            return
        self.tables.show_switches(self.switches)
        self.settings_box.setTitle(self._settings_title())
        node = self.switches[1] if self.switches is not None else None
        self._show_settings(node)
        self._show_state()

    def _settings_title(self) -> str:
        """The manual's "settings made by software (USB)" (§8.7), with the link they go
        over now: online over CAN they are written as CANopen objects, not over USB."""
        device = self._connection.device if self._connection and self._online() else None
        link = str(getattr(device, "device_id", "")).partition(":")[0]
        if link == "can":
            return self.tr("Settings made by software (over CANopen)")
        if link in ("usb", "emulator"):
            return self.tr("Settings made by software (USB)")
        return self.tr("Settings made by software")

    def _value(self, mnemonic: str) -> int:
        return int(self._doc.value(mnemonic))

    def _show_settings(self, node_switch: int | None) -> None:
        software = node_switch is None or node_switch == 0
        with QSignalBlocker(self.terminator):
            self.terminator.setChecked(self._value("CANTERM") == 1)
        with QSignalBlocker(self.node_id):
            self.node_id.setValue(self._value("NODEID"))
        with QSignalBlocker(self.bitrate):
            self.bitrate.setCurrentIndex(max(0, self.bitrate.findData(self._value("BITRATE"))))
        available = self._doc.variant.canopen
        switch_tip = self.tr("The node-ID switch is not at 0: the switch sets the node ID.")
        for widget, mnemonic, needs_switch in (
            (self.terminator, "CANTERM", False),
            (self.node_id, "NODEID", True),
            (self.bitrate, "BITRATE", True),
        ):
            locked = self._locked_reason(mnemonic)
            by_switch = needs_switch and not software
            widget.setEnabled(available and not locked and not by_switch)
            widget.setToolTip(locked or (switch_tip if by_switch else ""))

    def _locked_reason(self, mnemonic: str) -> str:
        """Why the access level may not change ``mnemonic`` ('' if it may, or no model given)."""
        if self._access is None:
            return ""
        return self._access.why_locked(CATALOGUE[mnemonic])

    def _show_state(self) -> None:
        online = self._online()
        if not self._doc.variant.canopen:
            state = self.tr("This valve type has no CANopen interface (no -CA in the type key).")
        elif self.switches is None and not online:
            state = self.tr(
                "Offline: the switch positions are unknown. Settings changed here go into the "
                "document; upload it to the valve and restart the valve."
            )
        elif self.switches is None:
            state = self.tr("Reading the switch positions from the valve …")
        else:
            state = self.tr("Switch positions read from the valve at its last power-up.")
            if baud_position(self.switches[0]).can_enabled:
                state += self._override_note(self.switches[1])
        self.state_label.setText(state)
        self.effective_label.setText(self._effective_text())
        self.restart_label.setVisible(self.restart_pending)

    def _rate_text(self, kbit: int | None) -> str:
        return format_bitrate(kbit) if kbit else self.tr("automatic bit rate")

    def _override_note(self, node_switch: int) -> str:
        if node_switch == 0:
            return " " + self.tr(
                "The node-ID switch is at 0: node ID and bit rate are the ones set below (the "
                "interface switch's bit rate is struck through); its positions 9…F still "
                "switch the terminator on."
            )
        if node_switch == 1:
            return " " + self.tr(
                "The node-ID switch is at 1 (LSS, automatic bit rate): the interface switch "
                "has no function, the terminator follows the setting below."
            )
        return ""

    def _effective_text(self) -> str:
        """What the valve uses with its switches and the settings it holds (read back)."""
        if self.switches is None or not all(mn in self.valve_values for mn in SETTINGS):
            return ""
        values = [int(self.valve_values[mn]) for mn in SETTINGS]
        settings = effective(*self.switches, *values)
        if self.restart_pending:
            prefix = self.tr("After the next restart the valve uses:")
        else:
            prefix = self.tr("The valve uses:")
        if not settings.can_enabled:
            off = self.tr("CANopen off (analog setpoint only).")
            return f"{prefix} {off}"
        terminator = self.tr("on") if settings.terminator else self.tr("off")
        details = (
            self.tr("node ID %1, %2, terminator %3.")
            .replace("%1", str(settings.node_id))
            .replace("%2", self._rate_text(settings.bitrate_kbit))
            .replace("%3", terminator)
        )
        return f"{prefix} {details}"

    # --- editing ------------------------------------------------------------------------------------
    def apply(self, mnemonic: str, raw: Raw) -> bool:
        """Set a CANopen setting in the document (undoable); online, have the valve store it.

        The write itself is the sync's (it mirrors every document edit to the valve); the
        window adds the store, since the setting only takes effect after a restart.
        """
        if self._doc.value(mnemonic) == raw:
            return True
        try:
            if self._access is not None:
                apply_edit(self._doc, self._access, mnemonic, raw)
            else:
                self._doc.set_value(mnemonic, raw)
        except (ValueRangeError, AccessDeniedError) as exc:
            self.error_label.setText(error_text(exc))
            self.refresh()
            return False
        self.error_label.clear()
        self.restart_pending = True
        if self._written(mnemonic, raw):
            self._store_in_valve(mnemonic, raw)
        elif self._online():
            self.restart_label.setText(
                self.tr(
                    "Changed in the document; the valve does not follow the document now. "
                    "Upload it to the valve; the change takes effect after the valve restarts."
                )
            )
        else:
            self.restart_label.setText(
                self.tr(
                    "Changed in the document. Upload it to the valve; the change takes effect "
                    "after the valve restarts."
                )
            )
        self._show_state()
        return True

    def _written(self, mnemonic: str, raw: Raw) -> bool:
        """True if the sync wrote ``raw`` to the online valve."""
        sync = self._sync
        return (
            self._online()
            and sync is not None
            and sync.active
            and sync.valve_values.get(mnemonic) == raw
        )

    def _store_in_valve(self, mnemonic: str, raw: Raw) -> None:
        """Store (a restart reloads the stored values), and say when it applies."""
        assert self._connection is not None
        self._connection.store()
        self.valve_values[mnemonic] = raw
        self.restart_label.setText(
            self.tr(
                "Written to the valve and stored. The change takes effect after the valve "
                "restarts (Valve → Restart valve)."
            )
        )

    def _online(self) -> bool:
        return self._connection is not None and self._connection.is_online

    def _on_terminator_toggled(self, checked: bool) -> None:
        self.apply("CANTERM", 1 if checked else 0)

    def _on_node_id_edited(self) -> None:
        if self.node_id.value() != self._value("NODEID"):
            self.apply("NODEID", self.node_id.value())

    def _on_bitrate_activated(self, index: int) -> None:
        self.apply("BITRATE", self.bitrate.itemData(index))

    # --- valve ----------------------------------------------------------------------------------------
    def read_from_valve(self) -> None:
        """Ask the connected valve for its switch positions and CANopen settings."""
        if self._online() and self._valve_has_canopen():
            assert self._connection is not None
            self._connection.read_many([*SWITCHES, *SETTINGS], READ_TAG)

    def _valve_has_canopen(self) -> bool:
        """Whether the *valve* has the CANopen objects: a -CA document may go online with a
        valve without them, and its differences dialog is then the only question asked."""
        variant = variant_of(self._connection.device if self._connection else None)
        return variant is not None and variant.canopen

    def _on_operation_finished(self, name: str, result: Any) -> None:
        if name == READ_TAG and isinstance(result, dict):
            self._take_valve_values(result)
        elif name in RESTARTED:
            self.restart_pending = False
            self.switches = None
            self.valve_values = {}
            self.refresh()
            self.read_from_valve()

    def _take_valve_values(self, values: dict[str, Raw]) -> None:
        if "SWBAUD" in values and "SWNODE" in values:
            self.switches = (int(values["SWBAUD"]), int(values["SWNODE"]))
        self.valve_values = {mn: values[mn] for mn in SETTINGS if mn in values}
        self.refresh()

    def _on_online_changed(self, online: bool) -> None:
        if not online:
            self.switches = None
            self.valve_values = {}
        self.refresh()
        self.read_from_valve()

    def _on_document_value_changed(self, mnemonic: str) -> None:
        if mnemonic in SETTINGS or mnemonic in SWITCHES:
            self.refresh()

    def _tone(self) -> None:
        """The notice and error colours (written for paper) on the current palette."""
        palette = self.palette()
        self.restart_label.setStyleSheet(toned_style(RESTART_STYLE, palette))
        self.error_label.setStyleSheet(toned_style(ERROR_STYLE, palette))

    def changeEvent(self, event: QEvent) -> None:
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate()
        if event.type() == QEvent.Type.PaletteChange:
            self._tone()
        super().changeEvent(event)


def _label(style: str = "") -> QLabel:
    """A word-wrapping label with an optional style sheet."""
    label = QLabel()
    label.setWordWrap(True)
    if style:
        label.setStyleSheet(style)
    return label

"""Warns when an online change will move the valve away from prm9tool's link.

Over CANopen the node ID (NODEID 0x2030/1) and bit rate (BITRATE 0x2030/2) take effect at the
valve's next power-up or restart; prm9tool's connection then breaks. Which parameters do that is
the link's business (``DeviceInfo.link_parameters``); this module says, right when one is
changed and before any restart cuts the link, where the valve will answer afterwards — or that
the rotary switches decide (manual table 7-17) and the change does not move it. A restart from
prm9tool follows the valve there (prm9tool.device.canlink.relocate).
"""

from __future__ import annotations

from PySide6.QtCore import QObject
from PySide6.QtWidgets import QWidget

from prm9tool.catalogue.canopen_switches import effective, format_bitrate
from prm9tool.model.document import ParameterDocument
from prm9tool.online.connection import ValveConnection
from prm9tool.views import prompts

SETTINGS = ("SWBAUD", "SWNODE", "NODEID", "BITRATE", "CANTERM")


class LinkGuard(QObject):
    """Watches the document's changes while online."""

    def __init__(
        self, doc: ParameterDocument, connection: ValveConnection, window: QWidget
    ) -> None:
        super().__init__(window)
        self._doc, self._connection, self._window = doc, connection, window
        doc.value_changed.connect(self._on_document_value_changed)

    def _on_document_value_changed(self, mnemonic: str) -> None:
        device = self._connection.device
        if not self._connection.is_online or mnemonic not in getattr(device, "link_parameters", ()):
            return
        prompts.inform(
            self._window,
            prompts.Icon.Warning,
            self.tr("The connection will move"),
            self.where_after_restart(),
        )

    def where_after_restart(self) -> str:
        """Where the valve answers after its next power-up, as the user should be told."""
        value = self._doc.value
        switch_node = int(value("SWNODE"))
        after = effective(*(int(value(m)) for m in SETTINGS))
        if switch_node >= 2:
            return self.tr(
                "The node-ID switch is at position {0}: the switches decide node ID and bit rate "
                "(manual table 7-17), so this change does not move the valve; it stays at node "
                "{1}."
            ).format(switch_node, after.node_id)
        if switch_node == 1:
            return self.tr(
                "The node-ID switch is at position 1 (LSS): an LSS master sets node ID and bit "
                "rate (manual table 7-17; Communication → CAN bus). NODEID and BITRATE apply at "
                "position 0 only, so this change does not move the valve."
            )
        rate = format_bitrate(after.bitrate_kbit)
        return self.tr(
            "After the valve's next power-up or restart it answers at node {0}, {1}. Store the "
            "change and restart the valve from prm9tool (Valve → Restart valve): prm9tool then finds "
            "it there again — where it cannot change the adapter's bit rate itself "
            "(SocketCAN), it says how. After a power-up, find it under Communication → CAN bus "
            "(node {0}, bit rate {1})."
        ).format(after.node_id, rate)

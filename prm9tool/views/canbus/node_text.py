"""The CAN bus dialog's description of a node, in the program language.

The device layer describes a node in English for the command line ("CANopen node 10 on
udp_multicast channel 239.0.0.1: PRM9"); the dialog words the same facts (``CanNodeListing``)
with the program's translations. The valve's device name (0x1008) and the device's own error
text stay as they are.
"""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication

from prm9tool.online.connection_protocol import CanNodeListing, ValveListing


def bus_text(node: CanNodeListing) -> str:
    """The bus a node is on: ``udp_multicast channel 239.0.0.1, 500000 bit/s``."""
    text = QCoreApplication.translate("CanNodeText", "{0} channel {1}").format(
        node.interface, node.channel
    )
    if node.bitrate:
        text += QCoreApplication.translate("CanNodeText", ", {0} bit/s").format(node.bitrate)
    return text


def node_description(entry: ValveListing) -> str:
    """What the dialog's description column says of ``entry`` (its English description when
    it is not a CAN node)."""
    node = entry.can
    if node is None:
        return entry.description
    if entry.kind == "can":
        return QCoreApplication.translate("CanNodeText", "CANopen node {0} on {1}: {2}").format(
            node.node_id, bus_text(node), node.name
        )
    if node.device_type is None:
        return QCoreApplication.translate(
            "CanNodeText", "Node {0} does not answer as a CANopen node: {1}"
        ).format(node.node_id, node.detail)
    if node.detail:
        return QCoreApplication.translate(
            "CanNodeText", "Node {0} could not be identified: {1}"
        ).format(node.node_id, node.detail)
    vendor = (
        QCoreApplication.translate("CanNodeText", "none")
        if node.vendor is None
        else f"0x{node.vendor:X}"
    )
    return QCoreApplication.translate(
        "CanNodeText", "Node {0}: not a PRM9 (device type 0x{1:X}, vendor {2})"
    ).format(node.node_id, node.device_type, vendor)

"""The emulated valve's CANopen interface as latched at power-up: the rotary switches
(manual table 7-17, :mod:`prm9tool.catalogue.canopen_switches`), the interface objects and
what an LSS master stored, decoded into node ID, bit rate, terminator and LSS mode. A pure
function of those inputs; :class:`~.firmware.Firmware` applies the result. No Qt.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass

from prm9tool.catalogue import canopen_switches
from prm9tool.catalogue.canopen_switches import LSS_BIT_TIMINGS_KBIT as LSS_KBIT
from prm9tool.catalogue.variant import Variant


@dataclass(frozen=True)
class Interface:
    """The CANopen interface settings the valve runs with until its next power-up."""

    can_enabled: bool
    terminator: bool
    lss_mode: bool  # node-ID switch at 1: node ID by LSS, automatic bit rate
    node_id: int  # 0: none (CANopen off, or LSS mode without a stored node ID)
    bitrate: int  # bit/s; 0 when CANopen is off


def latch(
    variant: Variant,
    switches: tuple[int, int],
    value: Callable[[str], int],
    lss: Mapping[str, int],
) -> Interface:
    """Decode the latched ``switches`` (baud, node) with the objects NODEID, BITRATE, CANTERM
    (``value``) and the LSS record of the NV image (``lss``).

    At node switch 1 (LSS and automatic bit rate) the node ID is the one an LSS master stored
    (none from the factory: the valve waits for an LSS master, CiA 305) and the bit rate is the
    bus's: the emulated valve hears any rate its bus runs at, so ``bitrate`` is the rate LSS
    stored, else the interface switch's (what the bus is opened at when served).
    """
    baud, node = switches
    settings = (
        canopen_switches.effective(baud, node, value("NODEID"), value("BITRATE"), value("CANTERM"))
        if variant.canopen
        else canopen_switches.CanSettings(False, None, None, False)
    )
    lss_mode = variant.canopen and canopen_switches.node_position(node).lss
    node_id = 0
    if variant.canopen:
        node_id = settings.node_id or value("NODEID")
    if lss_mode:
        stored = lss.get("node_id", canopen_switches.LSS_UNCONFIGURED)
        node_id = stored if 1 <= stored <= 127 else 0
    bitrate = 0
    if settings.can_enabled:
        kbit = settings.bitrate_kbit or canopen_switches.baud_position(baud).bitrate_kbit
        index = lss.get("bit_timing")
        if lss_mode and index is not None and 0 <= index < len(LSS_KBIT):
            kbit = LSS_KBIT[index]
        bitrate = (kbit or 0) * 1000
    return Interface(settings.can_enabled, settings.terminator, lss_mode, node_id, bitrate)

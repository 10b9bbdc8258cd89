"""The two CANopen rotary switches of a -CA valve (manual §7.3.1 table 7-17, §8.7 fig. 8-17).

Pure data and arithmetic, no Qt: the CANopen window draws the two switch tables from it and
the diagram's CANopen block summarises the effective settings. Where table 7-17 is garbled
this reading of it applies **(inference)**:

* interface/bit-rate switch: 0 = analog only, CAN off; 1 = reserved (same as 0); 2…8 = 20 k,
  50 k, 125 k, 250 k, 500 k, 800 k, 1 M without terminator; 9…F = the same seven rates with the
  120 Ω terminator switched on (fig. 8-17 mark "c"). At 2…8 the terminator can be switched on
  over USB (CANTERM, table 7-17 "not active by default, can be activated by USB command").
* node-ID switch: 0 = node ID set by software (NODEID, table 7-17) and, **(decision)**, the bit
  rate too (BITRATE: §7.3 "node ID and bit rate can be set by software and hardware", §8.5 the
  CANopen window gives access to the bit rate); the interface switch keeps its terminator
  function, so 9…F switch the terminator on here as well. 1 = LSS and automatic bit-rate
  detection: table 7-17 says the interface switch then "has no function", so neither its bit
  rate nor its terminator apply; the terminator follows CANTERM. The node ID is the one an LSS
  master configured and stored (CiA 305; none from the factory) — :func:`effective` reports
  NODEID there, which the master side reads as "where it is now" (docs/can-link.md, LSS). 2…F = node ID 10, 15, …, 75 with the bit rate of the interface switch.
  The emulated valve's firmware decodes its switches with :func:`effective`, so the CANopen
  window and the valve cannot disagree.

Switch positions are read by the valve at power-up only.
"""

from __future__ import annotations

from dataclasses import dataclass

BITRATES_KBIT: tuple[int, ...] = (20, 50, 125, 250, 500, 800, 1000)
"""Bit rates of switch positions 2…8 (and 9…F), slowest first."""
BITRATE_CODES_KBIT: tuple[int, ...] = (1000, 800, 500, 250, 125, 50, 20)
"""Bit rate of each code of the catalogue parameter BITRATE (0 = 1 Mbit/s … 6 = 20 kbit/s)."""
POSITIONS = range(16)
LSS_BIT_TIMINGS_KBIT: tuple[int, ...] = (1000, 800, 500, 250, 125, 100, 50, 20, 10)
"""CiA 305 standard bit-timing table (table selector 0): the rate of each index 0…8."""
LSS_UNCONFIGURED = 0xFF
"""CiA 305: the node ID of an LSS slave that has none."""


def lss_bit_timing(kbit: int) -> int | None:
    """The CiA 305 table-0 index of ``kbit``; None for a rate the valve does not run at."""
    if kbit not in BITRATES_KBIT:
        return None
    return LSS_BIT_TIMINGS_KBIT.index(kbit)


@dataclass(frozen=True)
class BaudPosition:
    """What one position of the interface/bit-rate switch selects."""

    position: int
    can_enabled: bool
    bitrate_kbit: int | None
    terminator: bool  # switched on by the switch itself (positions 9…F)


@dataclass(frozen=True)
class NodePosition:
    """What one position of the node-ID switch selects."""

    position: int
    node_id: int | None  # None: set by software (0) or by LSS (1)
    software: bool  # position 0: node ID from the NODEID parameter
    lss: bool  # position 1: LSS and automatic bit rate


@dataclass(frozen=True)
class CanSettings:
    """The effective CANopen settings after power-up for given switches and parameters."""

    can_enabled: bool
    node_id: int | None  # None while CANopen is off
    bitrate_kbit: int | None  # None: automatic bit-rate detection
    terminator: bool


def baud_position(position: int) -> BaudPosition:
    """Decode interface/bit-rate switch ``position`` (0…15); ValueError outside."""
    _check(position)
    if position < 2:
        return BaudPosition(position, False, None, False)
    rate = BITRATES_KBIT[(position - 2) % len(BITRATES_KBIT)]
    return BaudPosition(position, True, rate, position >= 9)


def node_position(position: int) -> NodePosition:
    """Decode node-ID switch ``position`` (0…15); ValueError outside."""
    _check(position)
    if position == 0:
        return NodePosition(0, None, True, False)
    if position == 1:
        return NodePosition(1, None, False, True)
    return NodePosition(position, 10 + 5 * (position - 2), False, False)


def effective(
    switch_baud: int, switch_node: int, node_id: int, bitrate_code: int, canterm: int
) -> CanSettings:
    """The settings a valve with these switches and parameters (raw values) runs with."""
    baud, node = baud_position(switch_baud), node_position(switch_node)
    if not baud.can_enabled:
        return CanSettings(False, None, None, False)
    if node.lss:  # the interface switch has no function (table 7-17)
        return CanSettings(True, node_id, None, bool(canterm))
    terminator = baud.terminator or bool(canterm)
    if node.software:
        return CanSettings(True, node_id, BITRATE_CODES_KBIT[bitrate_code], terminator)
    return CanSettings(True, node.node_id, baud.bitrate_kbit, terminator)


@dataclass(frozen=True)
class Overridden:
    """Which parts of the interface switch's position the node-ID switch overrides."""

    bitrate: bool  # node switch 0: BITRATE applies; 1: automatic bit-rate detection
    terminator: bool  # node switch 1 at 9…F: the terminator follows CANTERM, not the switch


def overridden(switch_baud: int, switch_node: int) -> Overridden:
    """What of interface switch position ``switch_baud`` does not apply at ``switch_node``."""
    baud, node = baud_position(switch_baud), node_position(switch_node)
    if not baud.can_enabled:
        return Overridden(False, False)
    return Overridden(node.software or node.lss, node.lss and baud.terminator)


def format_bitrate(kbit: int | None) -> str:
    """``500 kbit/s``, ``1 Mbit/s``; ``auto`` for None."""
    if kbit is None:
        return "auto"
    return "1 Mbit/s" if kbit == 1000 else f"{kbit} kbit/s"


def _check(position: int) -> None:
    if position not in POSITIONS:
        raise ValueError(f"a rotary switch has positions 0…15 (0…F), not {position}")

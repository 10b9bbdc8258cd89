"""Commissioning a -CA valve: the NMT commands and the enable sequence of its control word.

A -CA valve with CANopen switched on boots into NMT pre-operational and device state INIT
(manual §7.4, §7.6) and waits for a CANopen master: it does not follow any setpoint until the
control word 0x6040 (CONTROLWORD) walks it to DEVICE_MODE_ACTIVE. The manual's sequence writes
08h → 09h → 0Bh → 0Fh: 08h sets R (bit 3) and so clears a fault left from power-up, then D
(bit 0, DISABLED), H (bit 1, HOLD) and M (bit 2, DEVICE_MODE_ACTIVE) follow one per write
(table 7-19). The reverse, 0Fh → 0Bh → 09h → 08h, takes it back step by step to INIT.

Both are plain object writes, the same on every link (USB, CANopen); the NMT commands are the
CiA 301 command specifiers a session sends with ``ValveSession.nmt``. No Qt.
"""

from __future__ import annotations

from enum import IntEnum, StrEnum

CONTROL_WORD = "CONTROLWORD"  # 0x6040
ENABLE_SEQUENCE: tuple[int, ...] = (0x08, 0x09, 0x0B, 0x0F)
DISABLE_SEQUENCE: tuple[int, ...] = (0x0F, 0x0B, 0x09, 0x08)


class NmtCommand(IntEnum):
    """CiA 301 NMT command specifiers (byte 0 of the NMT frame, manual §7.2)."""

    START = 0x01
    STOP = 0x02
    PRE_OPERATIONAL = 0x80
    RESET_NODE = 0x81
    RESET_COMMUNICATION = 0x82


class Blocker(StrEnum):
    """Why a valve does not follow its setpoint (none of these: it follows)."""

    OFFLINE = "offline"
    BOOTING = "booting"  # the first ~2 s after power-up (§1.5, §5.6)
    FAULT = "fault"  # an error is present or the state machine holds a fault
    WAITING_FOR_MASTER = "waiting for master"  # CANopen on, INIT: no master enabled it yet
    NMT_STOPPED = "nmt stopped"  # NMT stopped: table 7-21
    DISABLED = "disabled"  # INIT/DISABLED on a valve that runs without a master
    HOLD = "hold"  # HOLD: the position loop holds 0 % (CiA 408 hold)


_FAULT_STATES = {"FAULT", "FAULT_HOLD", "FAULT_REACTION"}


def blocker(
    device_state: str, nmt_state: str, active_errors: tuple[int, ...], booting: bool
) -> Blocker | None:
    """Why a valve in this state does not follow its setpoint; None when it does.

    ``device_state``: the CiA 408 state's name (``DEVICE_MODE_ACTIVE``, ``INIT`` …),
    ``nmt_state``: ``off`` (CANopen switched off), ``pre-operational``, ``operational``,
    ``stopped`` …, ``active_errors``: the EMCY codes of the active errors.
    """
    if booting or device_state == "NOT_READY":
        return Blocker.BOOTING
    if device_state in _FAULT_STATES or (active_errors and device_state != "DEVICE_MODE_ACTIVE"):
        return Blocker.FAULT
    if device_state == "DEVICE_MODE_ACTIVE":
        return None
    if nmt_state == "stopped":
        return Blocker.NMT_STOPPED
    if device_state == "HOLD":
        return Blocker.HOLD
    if nmt_state not in ("off", ""):
        return Blocker.WAITING_FOR_MASTER
    return Blocker.DISABLED


# Every object a setpoint link writes, whatever the link (the USB service override, CANopen
# RPDO1 per manual table 7-13): a refusal of one of them stops the setpoint generator.
SETPOINT_OBJECTS = ("SETPOVR", "SETPOVRON", "POSSETP", "PRCSETP", "RPDO1TIMER")

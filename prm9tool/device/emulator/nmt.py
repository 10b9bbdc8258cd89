"""Coupling of the CANopen NMT state machine to the device state machine (table 7-21)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from prm9tool.device.records import DeviceState, NmtState
from prm9tool.errors import ValueRangeError

if TYPE_CHECKING:
    from prm9tool.device.emulator.firmware import Firmware

NMT_EVENTS = (
    "operational",
    "stopped",
    "preoperational",
    "reset_node",
    "reset_comm",
    "comm_error",
    "sync_error",
    "rpdo_timeout",
    "rpdo_length_error",
    "rpdo_length_ok",
    "sync_ok",
    "rpdo_ok",
)
_ERROR_EVENTS = {
    "comm_error": "communication",
    "sync_error": "sync",
    "rpdo_timeout": "rpdo_timeout",
}


def apply_nmt_event(fw: Firmware, event: str) -> None:
    """Apply an NMT event (``reset_node`` is handled by the valve: it power-cycles).

    * ``stopped`` (CiA 301 transitions 5, 8) and ``reset_comm`` (12, 13, 14): a valve in
      DEVICE_MODE_ACTIVE goes to FAULT_REACTION (table 7-21, D8).
    * ``comm_error`` (heartbeat/guarding event), ``sync_error`` (SYNC missing, 0x1006) and
      ``rpdo_timeout`` (an RPDO missed its event timer 0x1400/5): the communication error
      8100h becomes present (EMCY; LED2 double, triple resp. quadruple flash, table 7-18) and
      a valve in DEVICE_MODE_ACTIVE reacts as above; it goes away with the next
      ``operational`` event, and its cause with ``sync_ok`` (a SYNC came again) resp.
      ``rpdo_ok`` (the RPDO came again): from then on a fault reset clears it.
    * ``rpdo_length_error`` (an RPDO shorter than its mapping, not processed) makes the CiA 301
      error 8210h present — EMCY, 0x1001 bit 4, 0x1003 — without a fault reaction or LED
      pattern; ``rpdo_length_ok`` (an RPDO of the right length) and ``operational`` end it.
    """
    if event not in NMT_EVENTS:
        raise ValueRangeError(f"unknown NMT event {event!r}; events are: {', '.join(NMT_EVENTS)}")
    if not fw.can_enabled or fw.booting:
        return
    sm = fw.sm
    now = fw.time
    if event in ("sync_ok", "rpdo_ok"):
        fw.faults.force("sync" if event == "sync_ok" else "rpdo_timeout", False, now)
    elif event in ("rpdo_length_error", "rpdo_length_ok"):
        fw.faults.force("pdo_length", event == "rpdo_length_error", now)
    elif event == "operational":
        fw.nmt_state = NmtState.OPERATIONAL
        for key in (*_ERROR_EVENTS.values(), "pdo_length"):
            fw.faults.force(key, False, now)
    elif event == "preoperational":
        fw.nmt_state = NmtState.PRE_OPERATIONAL
    elif event in ("stopped", "reset_comm", *_ERROR_EVENTS):
        if sm.state is DeviceState.DEVICE_MODE_ACTIVE:
            sm.fault(fw.fw.fault_reaction_s)
        if event == "stopped":
            fw.nmt_state = NmtState.STOPPED
        elif event == "reset_comm":
            fw.reset_communication()
        else:
            fw.faults.force(_ERROR_EVENTS[event], True, now)

"""The valve's status over CANopen: device state, errors, LEDs, NMT state.

Read by SDO: status word 0x6041 (the state in bits 0…3 as CiA 408 defines them, manual §7.4
delegating to the profile; flags in the upper bits are not needed here and ignored), error
register 0x1001, error history 0x1003/1, temperature 0x2002, supply 0x2003 (table 7-14); the
NMT state comes from the heartbeat (table 7-4) and the newest EMCY frame gives the active error
(table 5-1). The LEDs are derived from these as the valve lights them (tables 5-2, 7-18).
"""

from __future__ import annotations

import time
from dataclasses import replace

from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.error_kinds import ERROR_KINDS, ErrorKind
from prm9tool.device.canlink.bus import NodeSeen
from prm9tool.device.canlink.sdo import MISSING, SdoChannel
from prm9tool.device.leds import leds
from prm9tool.device.records import DeviceState, NmtState, ValveStatus
from prm9tool.errors import AccessDeniedError, SdoAbortError

# CiA 408: 0x6041 bits 3…0 = R M H D tell the device state (docs/canopen.md)
STATES = {
    0b0000: DeviceState.NOT_READY,
    0b1000: DeviceState.INIT,
    0b1001: DeviceState.DISABLED,
    0b1011: DeviceState.HOLD,
    0b1111: DeviceState.DEVICE_MODE_ACTIVE,
    0b0011: DeviceState.FAULT_HOLD,
    0b0111: DeviceState.FAULT_REACTION,
    0b0001: DeviceState.FAULT,
}
EMCY_TEXTS = {kind.code: kind.text for kind in reversed(ERROR_KINDS)}  # first listed wins


def device_state(status_word: int) -> DeviceState:
    """The state bits 0…3 of a status word 0x6041 report (CiA 408); the upper bits are flags
    and do not change it. A combination CiA 408 does not define counts as NOT_READY (the
    valve does not follow a setpoint); :func:`state_text` shows the word itself."""
    return STATES.get(status_word & 0x0F, DeviceState.NOT_READY)


def state_text(status_word: int) -> str:
    """``DEVICE_MODE_ACTIVE (status word 0x000F)``: the state and the word it was read from."""
    known = status_word & 0x0F in STATES
    state = device_state(status_word).value if known else "an undefined state"
    return f"{state} (status word 0x{status_word & 0xFFFF:04X})"


def emcy_text(code: int) -> str:
    """The English meaning of an EMCY code (manual table 5-1), or the code itself."""
    return EMCY_TEXTS.get(code, f"error 0x{code:04X}")


def read_status(sdo: SdoChannel, seen: NodeSeen) -> ValveStatus:
    """A status snapshot of the node behind ``sdo``."""
    word = sdo.read_u32(0x6041, 0) & 0xFFFF
    state = device_state(word)
    register = sdo.read_u32(0x1001, 0) & 0xFF
    code = _error_code(sdo, seen, register)
    temperature = _optional_int(sdo, *CATALOGUE["TEMP"].key, signed=True)  # 0x2002
    supply = _optional_int(sdo, *CATALOGUE["PWR"].key, signed=False)  # 0x2003
    kinds = tuple(k for k in ERROR_KINDS if k.code == code)[:1] if code else ()
    nmt = seen.nmt_state or NmtState.UNKNOWN
    return ValveStatus(
        device_state=state,
        error_code=code,
        error_text=emcy_text(code) if code else "",
        warning=False,
        active_errors=(code,) if code else (),
        error_register=register,
        leds=_leds(nmt, kinds),
        temperature_c=float(temperature or 0),
        supply_v=(supply or 0) / 1000.0,
        nmt_state=nmt,
        booting=nmt is NmtState.INITIALISING,
        status_word=word,
    )


def stopped_status(last: ValveStatus | None, node_id: int) -> ValveStatus:
    """The status of a node the tool itself stopped: a stopped node answers no SDO (CiA 301,
    manual table 7-4), so the last status read with NMT stopped and the device state table
    7-21 couples to the stop (DEVICE_MODE_ACTIVE → fault reaction → FAULT_HOLD, H being 1)."""
    if last is None:
        raise StoppedNodeError(
            f"node {node_id} is NMT stopped (this tool stopped it) and answers no SDO: send "
            "NMT start or pre-operational to read it"
        )
    state = last.device_state
    if state is DeviceState.DEVICE_MODE_ACTIVE:
        state = DeviceState.FAULT_HOLD
    kinds = tuple(k for k in ERROR_KINDS if k.code == last.error_code)[:1]
    return replace(
        last,
        device_state=state,
        nmt_state=NmtState.STOPPED,
        leds=_leds(NmtState.STOPPED, kinds),
        booting=False,
    )


class StoppedNodeError(AccessDeniedError):
    """The node is NMT stopped by this tool and cannot be read (it answers no SDO)."""


def _error_code(sdo: SdoChannel, seen: NodeSeen, register: int) -> int:
    """The active error: the newest EMCY while the register shows one, else 0x1003/1."""
    if not register:
        return 0
    if seen.emcy_code:
        return seen.emcy_code
    newest = _optional_int(sdo, 0x1003, 1, signed=False)
    return (newest or 0) & 0xFFFF


def _optional_int(sdo: SdoChannel, index: int, subindex: int = 0, *, signed: bool) -> int | None:
    try:
        data = sdo.upload(index, subindex)
    except SdoAbortError as exc:
        if exc.code in MISSING or exc.code == 0x08000024:  # no such object / no data
            return None
        raise
    return int.from_bytes(data, "little", signed=signed)


def _leds(nmt: NmtState, kinds: tuple[ErrorKind, ...]) -> tuple:  # type: ignore[type-arg]
    return leds(time.monotonic(), False, True, nmt, kinds, False)

"""Enabling a valve on any link: the control word 08h → 09h → 0Bh → 0Fh, then the state read back.

The manual's sequence (§7.4, table 7-19) is plain object writes; whether it worked only the
status word tells. :func:`enable` writes it, waits a bounded moment for DEVICE_MODE_ACTIVE and
otherwise raises :class:`NotEnabledError` saying why in words — which error is still present
and what to do — instead of returning as if the valve now followed its setpoint. The API's
``Valve.enable()`` and the window's Enable use it. No Qt.
"""

from __future__ import annotations

import time
from collections.abc import Callable

from prm9tool.catalogue.commissioning import CONTROL_WORD, DISABLE_SEQUENCE, ENABLE_SEQUENCE
from prm9tool.catalogue.error_kinds import ERROR_KINDS
from prm9tool.device.records import DeviceState, NmtState, ValveStatus
from prm9tool.device.session import ValveSession
from prm9tool.errors import AccessDeniedError
from prm9tool.messages import QT_TRANSLATE_NOOP, Message

CONFIRM_S = 0.5  # a valve takes the state at once; allow a slow link's status round trips
POLL_S = 0.02
# a fault reaction (outputs off, manual §7.4) lasts milliseconds: one more try after it
_TRANSIENT = (DeviceState.FAULT_REACTION, DeviceState.NOT_READY)
_FAULTS = (DeviceState.FAULT, DeviceState.FAULT_HOLD, DeviceState.FAULT_REACTION)
_TEXTS = {kind.code: kind.text for kind in reversed(ERROR_KINDS)}

_ERROR_PRESENT = QT_TRANSLATE_NOOP(
    "Errors",
    "the valve stays in {0}: error 0x{1} ({2}) is still present — remove its cause, then "
    "enable again (the control word 08h resets the fault once it is gone)",
)
_STILL_FAULT = QT_TRANSLATE_NOOP(
    "Errors",
    "the valve stays in {0} with no error present: it did not take the fault reset — write "
    "the control word 00h, then enable again",
)
_STOPPED = QT_TRANSLATE_NOOP(
    "Errors", "the valve is NMT stopped and takes no control word: send NMT start first"
)
_BOOTING = QT_TRANSLATE_NOOP(
    "Errors", "the valve is still starting up (about 2 s after power-up): enable it then"
)
# NOT_READY is CiA 408's state before the valve's start-up (power on, self test) is done; the
# start-up takes about 2 s after power-up (manual §1.5, §5.6), the supply 19.2 … 28 V (§2.2)
_NOT_READY = QT_TRANSLATE_NOOP(
    "Errors",
    "the valve is in NOT_READY after the control word 08h → 09h → 0Bh → 0Fh: it has not "
    "finished starting up (about 2 s after power-up) — wait until it has, then enable again; "
    "if it stays in NOT_READY, check its supply voltage (19.2 … 28 V)",
)
_OTHER = QT_TRANSLATE_NOOP(
    "Errors",
    "the valve is in {0} after the control word 08h → 09h → 0Bh → 0Fh, not DEVICE_MODE_ACTIVE",
)

_STILL_ACTIVE = QT_TRANSLATE_NOOP(
    "Errors",
    "the valve stays in DEVICE_MODE_ACTIVE after the control word 0Fh → 0Bh → 09h → 08h and "
    "still follows its setpoint — make the hydraulics safe, then look for another CANopen "
    "master enabling it or restart the valve",
)


class NotEnabledError(AccessDeniedError):
    """The enable sequence did not bring the valve to DEVICE_MODE_ACTIVE (the message says
    why and what to do)."""


class NotDisabledError(AccessDeniedError):
    """The disable sequence left the valve in DEVICE_MODE_ACTIVE: it still follows its
    setpoint (the message says so and what to do)."""


def disable(session: ValveSession, sleep: Callable[[float], None] = time.sleep) -> ValveStatus:
    """Write 0Fh → 0Bh → 09h → 08h and return the status once the valve has left
    DEVICE_MODE_ACTIVE; raise :class:`NotDisabledError` when it is still there after
    CONFIRM_S (it would go on following its setpoint)."""
    for word in DISABLE_SEQUENCE:
        session.write(CONTROL_WORD, word)
    waited = 0.0
    while True:
        status = session.status()
        if status.device_state is not DeviceState.DEVICE_MODE_ACTIVE:
            return status
        if waited >= CONFIRM_S:
            raise NotDisabledError(_STILL_ACTIVE())
        sleep(POLL_S)
        waited += POLL_S


def enable(session: ValveSession, sleep: Callable[[float], None] = time.sleep) -> ValveStatus:
    """Write 08h → 09h → 0Bh → 0Fh and return the status once DEVICE_MODE_ACTIVE; raise
    :class:`NotEnabledError` with the reason when it does not get there within CONFIRM_S."""
    status = _write_and_confirm(session, sleep)
    if status.device_state in _TRANSIENT:
        status = _write_and_confirm(session, sleep)  # the reaction is over: once more
    if status.device_state is DeviceState.DEVICE_MODE_ACTIVE:
        return status
    raise NotEnabledError(why_not(status))


def why_not(status: ValveStatus) -> Message:
    """The reason (a translatable message) a valve in ``status`` is not enabled."""
    state = status.device_state
    if status.booting:
        return _BOOTING()
    if status.nmt_state is NmtState.STOPPED:
        return _STOPPED()
    if state is DeviceState.NOT_READY:
        return _NOT_READY()
    if state in _FAULTS:
        code = next(iter(status.active_errors), status.error_code)
        if code:
            # the status names the error itself; the table by code when it is not the first
            own = status.error_text if code == status.error_code else ""
            text = own or _TEXTS.get(code, f"0x{code:04X}")
            return _ERROR_PRESENT(str(state), f"{code:04X}", text)
        return _STILL_FAULT(str(state))
    return _OTHER(str(state))


def _write_and_confirm(session: ValveSession, sleep: Callable[[float], None]) -> ValveStatus:
    for word in ENABLE_SEQUENCE:
        session.write(CONTROL_WORD, word)
    waited = 0.0
    while True:
        status = session.status()
        if status.device_state is DeviceState.DEVICE_MODE_ACTIVE or waited >= CONFIRM_S:
            return status
        if status.device_state in _FAULTS and status.device_state not in _TRANSIENT:
            return status  # a fault the sequence did not reset: no waiting changes it
        sleep(POLL_S)
        waited += POLL_S

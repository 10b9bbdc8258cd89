"""Public value types of the emulator: device states, faults, LED states and the status record."""

from __future__ import annotations

from dataclasses import dataclass
from enum import StrEnum


class DeviceState(StrEnum):
    """CiA 408 / VDMA device states (manual §7.4, figure 7-11)."""

    NOT_READY = "NOT_READY"
    INIT = "INIT"
    DISABLED = "DISABLED"
    HOLD = "HOLD"
    DEVICE_MODE_ACTIVE = "DEVICE_MODE_ACTIVE"
    FAULT_HOLD = "FAULT_HOLD"
    FAULT = "FAULT"
    FAULT_REACTION = "FAULT_REACTION"


class Fault(StrEnum):
    """Physical faults that can be injected (one per row of manual table 5-1)."""

    COIL_A_OPEN = "COIL_A_OPEN"
    COIL_A_OVERCURRENT = "COIL_A_OVERCURRENT"
    COIL_B_OPEN = "COIL_B_OPEN"
    COIL_B_OVERCURRENT = "COIL_B_OVERCURRENT"
    SETPOINT_WIRE_BREAK = "SETPOINT_WIRE_BREAK"
    SENSOR_BREAK = "SENSOR_BREAK"
    POSITION_SENSOR_BREAK = "POSITION_SENSOR_BREAK"
    SUPPLY_LOW = "SUPPLY_LOW"
    SUPPLY_HIGH = "SUPPLY_HIGH"
    OVER_TEMPERATURE = "OVER_TEMPERATURE"


@dataclass(frozen=True)
class LedState:
    """One LED as a user sees it.

    ``color``: ``off``, ``white``, ``green``, ``orange``, ``red``, ``blue``, ``magenta``.
    ``pattern``: ``off``, ``on``, ``1Hz``, ``2Hz``, ``2.5Hz`` (CiA 303 blinking),
    ``single_flash``, ``double_flash``, ``triple_flash``, ``quadruple_flash`` (CiA 303 flashes),
    ``boot`` (the power-up pattern: two white flashes in about 2 s).
    ``lit`` tells whether the LED is lit at the instant the status was taken.
    """

    color: str
    pattern: str
    lit: bool


LED_OFF = LedState("off", "off", False)


@dataclass(frozen=True)
class ValveStatus:
    """A snapshot of everything the valve shows outside: state, errors, LEDs, supply.

    ``error_code`` is the CANopen EMCY code of the most severe active error (0 = none),
    ``error_text`` its English description ("" when there is no error and no warning).
    ``nmt_state`` is ``initialising``, ``pre-operational``, ``operational``, ``stopped`` or
    ``off`` (no CANopen interface, or the interface switch at 0/1). ``status_word``: the
    CiA 408 status word 0x6041 the state was decoded from, where it was read over CANopen.
    """

    device_state: DeviceState
    error_code: int
    error_text: str
    warning: bool
    active_errors: tuple[int, ...]
    error_register: int
    leds: tuple[LedState, LedState, LedState]
    temperature_c: float
    supply_v: float
    nmt_state: str
    booting: bool
    status_word: int | None = None  # 0x6041 as read over CANopen (None: not read that way)

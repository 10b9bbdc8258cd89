"""The three LEDs (manual tables 5-1, 5-2, 7-18; CiA 303-3 blink timing).

LED1 (RGB, power) shows the valve state, LED2 (red) errors, LED3 (orange) the CANopen NMT
state. LEDs 2 and 3 exist only on -CA valves (§5.5); on other valves they read as off.
"""

from __future__ import annotations

from prm9tool.catalogue.error_kinds import CAN_ERROR_KEYS, NOTICE_KEYS, ErrorKind
from prm9tool.device.records import LED_OFF, LedState, NmtState

# (on, off) sequences in seconds; a pattern repeats with its period (CiA 303-3 timing).
_SEQUENCES: dict[str, tuple[float, ...]] = {
    "1Hz": (0.5, 0.5),
    "2Hz": (0.25, 0.25),
    "2.5Hz": (0.2, 0.2),
    "single_flash": (0.2, 1.0),
    "double_flash": (0.2, 0.2, 0.2, 1.0),
    "triple_flash": (0.2, 0.2, 0.2, 0.2, 0.2, 1.0),
    "quadruple_flash": (0.2, 0.2, 0.2, 0.2, 0.2, 0.2, 0.2, 1.0),
    "flicker": (0.05, 0.05),
}
BOOT_FLASHES = 2  # §5.6: LED1 lights white twice during the ~2 s start-up


def lit(pattern: str, t: float, boot_s: float = 1.8) -> bool:
    """Whether ``pattern`` is lit at time ``t`` (seconds since power-up)."""
    if pattern == "on":
        return True
    if pattern == "off":
        return False
    if pattern == "boot":
        slot = boot_s / (2 * BOOT_FLASHES)
        return int(t / slot) % 2 == 0
    sequence = _SEQUENCES[pattern]
    phase = t % sum(sequence)
    for i, length in enumerate(sequence):
        if phase < length:
            return i % 2 == 0
        phase -= length
    return False


def led(color: str, pattern: str, t: float) -> LedState:
    """A LED state at time ``t``."""
    if pattern == "off" or color == "off":
        return LED_OFF
    return LedState(color=color, pattern=pattern, lit=lit(pattern, t))


def can_pattern(nmt_state: NmtState) -> str:
    """LED3 pattern for an NMT state (table 7-18)."""
    return {
        "pre-operational": "2.5Hz",
        "stopped": "single_flash",
        "operational": "on",
    }.get(nmt_state, "off")


def leds(
    t: float,
    booting: bool,
    canopen: bool,
    nmt_state: NmtState,
    active: tuple[ErrorKind, ...],
    warning: bool,
) -> tuple[LedState, LedState, LedState]:
    """The three LEDs for the valve's situation at time ``t``."""
    if booting:
        extra = led("red", "on", t) if canopen else LED_OFF
        extra3 = led("orange", "on", t) if canopen else LED_OFF
        return led("white", "boot", t), extra, extra3
    led3 = led("orange", can_pattern(nmt_state), t) if canopen else LED_OFF
    active = tuple(k for k in active if k.key not in NOTICE_KEYS)  # no LED pattern of their own
    errors = [k for k in active if k.key not in CAN_ERROR_KEYS]
    can_errors = [k for k in active if k.key in CAN_ERROR_KEYS]
    if len(errors) > 1:
        led1, led2 = led("red", "2Hz", t), led("red", "2Hz", t)  # table 5-2
    elif errors:
        kind = errors[0]
        led1, led2 = led(*kind.led1, t), led("red", kind.led2, t)
    elif warning:
        led1, led2 = led("orange", "on", t), LED_OFF
    else:
        led1, led2 = led("green", "on", t), LED_OFF
    if can_errors and not errors:  # table 7-18
        led2 = led("red", can_errors[0].led2, t)
        led3 = led("orange", "single_flash", t)
    if not canopen:
        led2 = led3 = LED_OFF
    return led1, led2, led3

"""The valve's errors (manual table 5-1, with the control-deviation monitoring and the CANopen
communication errors of table 7-18): EMCY code, text, what the LEDs show and the error-register bit of
each, in order of severity. A valve fact read by the emulated valve (which detects them) and
by the CANopen link (which names what a valve reports). No Qt.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class ErrorKind:
    """One row of manual table 5-1 (plus the monitoring and communication errors)."""

    key: str
    code: int  # CANopen EMCY code
    text: str
    led1: tuple[str, str]  # colour, pattern
    led2: str  # pattern of the red error LED
    register_bit: int  # bit of 0x1001 besides bit 0 (generic), -1 = none
    fault: bool = True  # present: the spool is centred (False: reported only, no LED change)


# In order of severity (first = most severe); the order decides error_code and the LEDs.
ERROR_KINDS: tuple[ErrorKind, ...] = (
    ErrorKind("supply", 0x3410, "Supply voltage out of range", ("red", "2Hz"), "on", 2),
    ErrorKind(
        "temperature", 0x4211, "Electronics temperature above 100 °C", ("orange", "2Hz"), "on", 3
    ),
    ErrorKind("coil_a_overcurrent", 0x5411, "Solenoid A over-current", ("blue", "on"), "2Hz", 1),
    ErrorKind("coil_b_overcurrent", 0x5412, "Solenoid B over-current", ("magenta", "on"), "2Hz", 1),
    ErrorKind("coil_a_open", 0x5411, "Solenoid A disconnected", ("blue", "on"), "1Hz", 1),
    ErrorKind("coil_b_open", 0x5412, "Solenoid B disconnected", ("magenta", "on"), "1Hz", 1),
    ErrorKind(
        "position_sensor", 0x7300, "Internal position sensor error", ("red", "1Hz"), "1Hz", 7
    ),
    ErrorKind("sensor", 0x5230, "External sensor error", ("red", "1Hz"), "1Hz", 7),
    ErrorKind(
        "setpoint", 0x3420, "Setpoint signal error on the analog input", ("red", "2Hz"), "1Hz", 2
    ),
    ErrorKind(
        "monitoring",
        0x1000,
        "Control deviation beyond the monitoring threshold (0x6353)",
        ("red", "on"),
        "on",
        5,
    ),
    ErrorKind(
        "communication",
        0x8100,
        "CANopen error-control event (heartbeat or node guarding)",
        ("green", "on"),
        "double_flash",
        4,
    ),
    ErrorKind(
        "sync",
        0x8100,
        "CANopen SYNC not received within the communication cycle period (0x1006)",
        ("green", "on"),
        "triple_flash",
        4,
    ),
    ErrorKind(
        "rpdo_timeout",
        0x8100,
        "CANopen RPDO not received within its event timer (0x1400/5, 0x1401/5)",
        ("green", "on"),
        "quadruple_flash",
        4,
    ),
    ErrorKind(
        "pdo_length",
        0x8210,
        "CANopen RPDO shorter than its mapping: not processed",
        ("green", "on"),
        "off",
        4,
        fault=False,
    ),
)
# Table 7-18 rows: LED1 stays green
CAN_ERROR_KEYS = frozenset({"communication", "sync", "rpdo_timeout"})
# Errors only reported (EMCY, 0x1001, 0x1003, 0x2040): CiA 301 protocol errors with no row in
# table 7-18 (decision: no LED pattern, no fault reaction; the valve keeps controlling)
NOTICE_KEYS = frozenset(k.key for k in ERROR_KINDS if not k.fault)
KINDS = {k.key: k for k in ERROR_KINDS}
WARNING_TEXT = "Warning: electronics temperature above 70 °C"

"""Faults that can be injected into the emulated valve (the shared records: prm9tool.device.records)."""

from __future__ import annotations

from enum import StrEnum


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

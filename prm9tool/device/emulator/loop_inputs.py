"""What the emulated firmware feeds its control loop from the outside world: the setpoint
(override, object dictionary or analog input, with a cut wire) and the external sensor.

Functions of the :class:`~.firmware.Firmware`, like :mod:`.detect` and :mod:`.thermal`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from prm9tool.device.emulator import config
from prm9tool.device.emulator.inputs import CANOPEN_TYPE, INPUT_TYPES
from prm9tool.device.emulator.states import Fault

if TYPE_CHECKING:
    from prm9tool.device.emulator.fwstate import FirmwareState


def refresh_sensor(fw: FirmwareState, supply: float) -> None:
    """The external sensor's value (or its broken-wire value) into the loop's mailbox."""
    loop = fw.loop
    kind = INPUT_TYPES.get(fw.value("SENSTYPE"))
    loop.sensor_from_plant = fw.inputs["sensor_from_plant"] >= 0.5 and kind is not None
    if kind is None:
        loop.sensor_static = float(fw.value("SENSIN"))
    else:
        loop.sensor_static = kind.to_normalized(fw.inputs["sensor"], supply, fw.fw)
    broken = Fault.SENSOR_BREAK in fw.injected
    loop.sensor_break_value = (
        (kind.to_normalized(0.0, supply, fw.fw) if kind else 0.0) if broken else None
    )


def digital_setpoint(fw: FirmwareState) -> bool:
    """True if the setpoint comes from the object dictionary (0x6300/0x6380)."""
    return fw.can_enabled or fw.value("AINSETP") == CANOPEN_TYPE


def setpoint_electrical(fw: FirmwareState) -> float:
    """The analog setpoint input as the A/D converter sees it (0 with a cut wire)."""
    if Fault.SETPOINT_WIRE_BREAK in fw.injected:
        return 0.0
    return fw.inputs["setpoint"]


def raw_setpoint(fw: FirmwareState, supply: float) -> float:
    """The setpoint before polarity: override, object dictionary or analog input."""
    if fw.value("SETPOVRON"):
        return float(fw.value("SETPOVR"))
    if digital_setpoint(fw):
        mnemonic = "PRCSETP" if config.process_loop_on(fw.variant, fw.value) else "POSSETP"
        return float(fw.value(mnemonic))
    kind = INPUT_TYPES.get(fw.value("AINSETP"))
    if kind is None:
        return 0.0
    return kind.to_normalized(setpoint_electrical(fw), supply, fw.fw)

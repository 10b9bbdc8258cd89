"""Thermal model of the emulated valve: coil losses heat the electronics; the temperature reading.

First-order model (constants in :class:`~.constants.PlantConstants`, docs/emulator.md): the
temperature rise above ambient follows the coil losses plus the electronics' own loss with the
time constant ``thermal_tau_s`` (minutes), so :data:`THERMAL_TICKS` ms steps are plenty. The
coil resistance follows the model temperature, re-read by the loop when it moved by > 0.5 K.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from prm9tool.device.emulator import config
from prm9tool.device.emulator.states import Fault

if TYPE_CHECKING:
    from prm9tool.device.emulator.fwstate import FirmwareState

THERMAL_TICKS = 10  # the thermal model runs every 10 ms (time constant: minutes)
COIL_REFRESH_K = 0.5  # coil resistance re-computed when the model moved this much


def step(fw: FirmwareState, dt: float) -> None:
    """Advance the model by ``dt`` seconds and update the temperature reading."""
    ia, ib = fw.loop.current_ma
    plant = fw.plant
    r = config.coil_resistance(fw.coil_temperature, plant)
    power = r * (ia * ia + ib * ib) * 1e-6 + plant.electronics_loss_w
    rise = fw.temperature_rise
    rise += (plant.thermal_k_per_w * power - rise) * dt / plant.thermal_tau_s
    fw.temperature_rise = rise
    update_reading(fw)
    model = fw.inputs["ambient_temperature"] + rise
    if abs(model - fw.coil_temperature) > COIL_REFRESH_K:
        fw.coil_temperature = model
        fw.config_dirty = True


def update_reading(fw: FirmwareState) -> None:
    """The electronics temperature reading, °C (an injected over-temperature forces it)."""
    if Fault.OVER_TEMPERATURE in fw.injected:
        fw.temperature = fw.fw.injected_temperature_c
    else:
        fw.temperature = fw.inputs["ambient_temperature"] + fw.temperature_rise


def warning_after(fw: FirmwareState) -> bool:
    """The temperature warning (> 70 °C, manual table 5-1, with hysteresis) at the reading."""
    c = fw.fw
    temp = fw.temperature
    return temp > c.temp_warning_c or (fw.warning and temp > c.temp_warning_c - c.temp_hysteresis_c)


def update_warning(fw: FirmwareState) -> None:
    """Temperature warning (> 70 °C, manual table 5-1) with hysteresis."""
    fw.warning = warning_after(fw)

"""Raw fault conditions the firmware evaluates every 1 ms (manual table 5-1).

Each function of the table returns ``(condition, detection_delay_s)``; :class:`FaultMonitor`
debounces them. What the injected faults do physically is described in docs/emulator.md; the
conditions look at what the loop and the plant produce (LVDT loop current, coil current and PWM
duty, input signals), not at the injected faults themselves.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from prm9tool.catalogue.variant import Coils, Config
from prm9tool.device.emulator import loop_inputs
from prm9tool.device.emulator.inputs import INPUT_TYPES
from prm9tool.device.emulator.states import Fault
from prm9tool.device.records import DeviceState

OPEN_LOAD_MIN_V = 1.0  # on-state open-load check only above 1 V average at the coil (assumption)
OPEN_LOAD_MA = 10.0  # ... where a connected coil carries far more than 10 mA (assumption)

if TYPE_CHECKING:
    from prm9tool.device.emulator.fwstate import FirmwareState


def static_conditions(fw: FirmwareState) -> dict[str, tuple[bool, float]]:
    """Conditions that only inputs, parameters or injected faults change (with their delays).

    Evaluated when those change; :func:`conditions` adds the dynamic ones every 1 ms.
    """
    c = fw.fw
    return {
        "setpoint": (_setpoint_error(fw), c.setpoint_error_delay_s),
        "sensor": (_sensor_error(fw), c.sensor_error_delay_s),
    }


def static_alarm(fw: FirmwareState) -> bool:
    """True if the 1 ms task must evaluate the condition table.

    That is when a static condition or the supply is raised, or when the plant has a cut
    LVDT wire or a disconnected coil: only then can the LVDT loop current fall below 3.6 mA or
    a coil stay without current (with the wire intact the loop current stays at or above
    3.8 mA; a connected coil carries current whenever voltage is applied), so skipping the
    evaluation otherwise changes nothing.
    """
    loop = fw.loop
    return (
        any(flag for flag, _ in fw.static_conditions.values())
        or _supply_error(fw)
        or loop.lvdt_break
        or any(loop.coil_open)
    )


def conditions(fw: FirmwareState) -> dict[str, tuple[bool, float]]:
    """Every raw condition with its detection delay (static ones as last evaluated)."""
    c = fw.fw
    ia, ib = fw.loop.current_ma
    coils = fw.variant.coils
    result = dict(fw.static_conditions)
    result["coil_a_open"] = (coils is not Coils.B and _open_load(fw, 0), c.coil_open_delay_s)
    result["coil_b_open"] = (coils is not Coils.A and _open_load(fw, 1), c.coil_open_delay_s)
    result["position_sensor"] = (fw.loop.lvdt_ma < c.loop_break_ma, c.position_sensor_delay_s)
    result["coil_a_overcurrent"] = (
        coils is not Coils.B
        and _overcurrent(fw, ia, "coil_a_overcurrent", Fault.COIL_A_OVERCURRENT),
        c.overcurrent_delay_s,
    )
    result["coil_b_overcurrent"] = (
        coils is not Coils.A
        and _overcurrent(fw, ib, "coil_b_overcurrent", Fault.COIL_B_OVERCURRENT),
        c.overcurrent_delay_s,
    )
    result["supply"] = (_supply_error(fw), c.supply_delay_s)
    result["temperature"] = (_temperature_error(fw), c.temp_delay_s)
    result["monitoring"] = (_monitoring(fw), fw.monitoring_delay_s)
    return result


def _open_load(fw: FirmwareState, coil: int) -> bool:
    """Open-load diagnostic of output stage ``coil`` (0 = A, 1 = B).

    On-state (the stage applies at least OPEN_LOAD_MIN_V on average): no current flows. Off-state
    (the stage idles or the duty is tiny): the stage's test current finds no load; the averaged
    plant has no terminal voltage, so this half reads the coil's connection in the plant.
    """
    loop = fw.loop
    if loop.duty[coil] * fw.supply >= OPEN_LOAD_MIN_V:
        return loop.current_ma[coil] < OPEN_LOAD_MA
    return loop.coil_open[coil]


def _overcurrent(fw: FirmwareState, current_ma: float, key: str, fault: Fault) -> bool:
    """Comparator on the coil current; once tripped, the stage diagnostic keeps seeing the short."""
    if current_ma > fw.fw.overcurrent_ma:
        return True
    return fw.faults.is_present(key) and fault in fw.injected


def _setpoint_error(fw: FirmwareState) -> bool:
    if loop_inputs.digital_setpoint(fw) or fw.value("SETPOVRON"):
        return False
    kind = INPUT_TYPES.get(fw.value("AINSETP"))
    if kind is None:
        return False
    return kind.signal_error(loop_inputs.setpoint_electrical(fw), fw.supply, fw.fw)


def _sensor_error(fw: FirmwareState) -> bool:
    if fw.variant.config is not Config.E04:
        return False
    if Fault.SENSOR_BREAK in fw.injected:
        return True  # a cut cable draws no current from the sensor supply pin (assumption)
    kind = INPUT_TYPES.get(fw.value("SENSTYPE"))
    if kind is None or fw.inputs["sensor_from_plant"] >= 0.5:
        return False
    return kind.signal_error(fw.inputs["sensor"], fw.supply, fw.fw)


def _supply_error(fw: FirmwareState) -> bool:
    c = fw.fw
    v = fw.supply
    if fw.faults.is_present("supply"):
        hyst = c.supply_hysteresis_v
        return not c.supply_min_v + hyst <= v <= c.supply_max_v - hyst
    return not c.supply_min_v <= v <= c.supply_max_v


def _temperature_error(fw: FirmwareState) -> bool:
    c = fw.fw
    limit = c.temp_error_c
    if fw.faults.is_present("temperature"):
        limit -= c.temp_hysteresis_c
    return fw.temperature > limit


def _monitoring(fw: FirmwareState) -> bool:
    """|0x6350| beyond 0x6353, counted in DEVICE_MODE_ACTIVE; kept until the deviation is back.

    While the monitoring error holds the spool centred the demand value keeps following the
    setpoint, so the error goes away when the setpoint is brought back to where the valve is
    (decision: re-arm at the actual value).
    """
    beyond = abs(fw.loop.ctrl_dev) > fw.monitoring_threshold
    if not beyond:
        return False
    return fw.sm.state is DeviceState.DEVICE_MODE_ACTIVE or fw.faults.is_present("monitoring")

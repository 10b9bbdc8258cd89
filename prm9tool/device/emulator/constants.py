"""Plant and firmware constants of the emulator: data, each with its source or "assumption".

docs/emulator.md lists the same table for readers; this module is what the code uses. A test or
a tool may pass modified copies (``dataclasses.replace``) to :class:`EmulatedValve`.
"""

from __future__ import annotations

from dataclasses import dataclass

from prm9tool.catalogue.scale import FULL_SCALE

CYCLE_S = 200e-6  # controller cycle period (manual §2.2: 200 µs)
TICK_CYCLES = 5  # the firmware's slow task (faults, LEDs, state machine) runs every 1 ms
FULL = float(FULL_SCALE)  # normalized internal scale (prm9tool.catalogue.scale)


@dataclass(frozen=True)
class PlantConstants:
    """Physical constants of the valve and its load (all SI units unless named otherwise)."""

    coil_r20_ohm: float = 4.0  # coil resistance at 20 °C (assumption, typical 24 V solenoid)
    coil_l_h: float = 0.030  # coil inductance (assumption; L/R = 7.5 ms)
    copper_tc_per_k: float = 0.0039  # copper resistance temperature coefficient (physics)
    force_n_per_a: float = 30.0  # solenoid force constant (assumption: 78 N at 2.6 A)
    spring_n_per_m: float = 21600.0  # centring spring rate (assumption: 54 N at full stroke)
    spool_mass_kg: float = 0.06  # spool + armatures (assumption; 95 Hz natural frequency)
    damping_n_s_per_m: float = 72.0  # viscous + flow-force damping (assumption; zeta = 1)
    coulomb_friction_n: float = 0.3  # sliding friction (assumption)
    static_friction_n: float = 0.5  # break-away friction (assumption)
    stroke_m: float = 0.0025  # spool travel for 100 % opening (assumption, Dn06)
    end_stop: float = 1.15  # mechanical end stops at ±115 % of that travel (assumption)
    force_lag_s: float = 0.003  # eddy-current lag of the magnetic force (assumption)
    substeps: int = 1  # mechanical integration steps per 200 µs cycle (docs/emulator.md)
    lvdt_span: float = 1.25  # the LVDT ADC range covers ±125 % of the stroke (assumption)
    actuator_full_speed_s: float = 0.5  # E04 load: full stroke in 0.5 s at 100 % (assumption)
    actuator_return_s: float = 1.0  # single-coil valves drive a spring-return load (assumption)
    actuator_start: float = 0.5  # E04 load starts at mid-stroke (assumption)
    spool_overlap: float = 0.0  # hydraulic overlap as a fraction of stroke (assumption: none)
    thermal_k_per_w: float = 1.2  # electronics temperature rise per W of coil loss (assumption)
    thermal_tau_s: float = 600.0  # thermal time constant of the housing (assumption)
    electronics_loss_w: float = 2.0  # electronics self-heating (assumption)


@dataclass(frozen=True)
class FirmwareConstants:
    """Firmware constants that are not parameters: current loop, fault thresholds, timing."""

    adc_bits: int = 12  # A/D converters: setpoint, sensor, LVDT (manual §2.2)
    boot_s: float = 1.8  # LED1 white twice (~2 s), setpoint effective after 1-2 s (§1.5, §5.6)
    current_kp_v_per_a: float = 100.0  # current PI, proportional (assumption: ~0.3 ms loop)
    current_ki_v_per_as: float = 20000.0  # current PI, integral (assumption)
    max_current_ma: float = 4000.0  # output stage limit (manual §2.2: max 4 A)
    fault_display_hold_s: float = 10.0  # error message returns to normal ~10 s (§5.5)
    fault_reaction_s: float = 0.005  # FAULT_REACTION -> FAULT/FAULT_HOLD after outputs off
    coil_open_delay_s: float = 0.020  # open-load diagnostic debounce (assumption)
    overcurrent_ma: float = 4000.0  # over-current comparator (manual §2.2: max 4 A)
    overcurrent_delay_s: float = 0.002  # (assumption)
    loop_break_ma: float = 3.6  # 4…20 mA wire break below 3.6 mA (NAMUR NE 43; assumption)
    over_range: float = 1.05  # a voltage/current beyond 105 % of its span is a signal error
    setpoint_error_delay_s: float = 0.050  # (assumption)
    sensor_error_delay_s: float = 0.020  # (assumption)
    position_sensor_delay_s: float = 0.005  # (assumption)
    supply_min_v: float = 19.2  # manual §2.2
    supply_max_v: float = 28.0  # manual §2.2
    supply_hysteresis_v: float = 0.3  # (assumption)
    supply_delay_s: float = 0.050  # (assumption)
    temp_warning_c: float = 70.0  # manual table 5-1
    temp_error_c: float = 100.0  # manual table 5-1
    temp_hysteresis_c: float = 3.0  # (assumption)
    temp_delay_s: float = 0.100  # (assumption)
    injected_low_supply_v: float = 17.0  # what Fault.SUPPLY_LOW does to the supply
    injected_high_supply_v: float = 31.0  # what Fault.SUPPLY_HIGH does to the supply
    injected_temperature_c: float = 105.0  # what Fault.OVER_TEMPERATURE does to the reading
    override_timeout_s: float = 0.5  # setpoint override off without USB activity (decision)
    voltage_input_range_v: float = 11.0  # analog input clamps at ±11 V (assumption)
    current_input_range_ma: float = 22.0  # analog input clamps at ±22 mA (assumption)


PLANT = PlantConstants()
FIRMWARE = FirmwareConstants()

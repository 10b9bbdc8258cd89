"""The compiled loop's batches, and when it may pass the firmware's 1 ms task itself.

Most 1 ms tasks change nothing: no fault condition changes, no detection delay or display hold
ends, the state machine and the loop's mode stay, no cycle listener has anything to do (each
says for how many tasks: ``valve.add_cycle_listener(fn, quiet)``). The compiled
kernel (``_ckernel.tick_is_noop``) re-checks per millisecond what can change within a batch
(coil currents, PWM duties, LVDT loop current, control deviation, time) against the firmware
state summarized here; the first task that would do anything is left to
:meth:`.firmware.Firmware.tick`, exactly at its millisecond. Everything else this depends on
only changes in Python (a tick, a parameter or input write), which ends the compiled run.
"""

from __future__ import annotations

import math
from array import array
from typing import TYPE_CHECKING, Protocol, cast

import numpy as np

from prm9tool.device.emulator import config, detect, thermal
from prm9tool.device.emulator.constants import CYCLE_S, TICK_CYCLES
from prm9tool.device.emulator.states import Fault
from prm9tool.device.records import DeviceState

if TYPE_CHECKING:
    from prm9tool.device.emulator.fwstate import FirmwareState

MAX_DEADLINES = 16  # _ckernel.c: room for detection delays and display holds
# no limit (a batch's length bounds the ticks), and it fits a C long on every platform: 1 << 40
# was cast to a 32-bit long on Windows (LLP64) and came out negative, so the kernel gave every
# 1 ms task back to Python (no faster than the Python loop, 33x the parameters() calls)
MAX_TICKS = 2**31 - 1
THERMAL_DT = thermal.THERMAL_TICKS * TICK_CYCLES * CYCLE_S  # as Firmware.tick computes it
TICK_DEADLINES = 44  # _ckernel.c: where the deadlines start (checked by ckernel.py)
TICK_RISE, TICK_TEMPERATURE = 37, 38  # _ckernel.c: the thermal state the kernel writes back
STATIC_BITS = {"setpoint": 1 << 0, "sensor": 1 << 1, "supply": 1 << 7, "temperature": 1 << 8}
CONDITION_BITS = (  # detect.conditions' keys in the C kernel's bit order
    "setpoint",
    "sensor",
    "coil_a_open",
    "coil_b_open",
    "position_sensor",
    "coil_a_overcurrent",
    "coil_b_overcurrent",
    "supply",
    "temperature",
    "monitoring",
)
_FAULTED = (DeviceState.FAULT, DeviceState.FAULT_HOLD)


class Batches(Protocol):
    """The compiled loop (:class:`.ckernel.CompiledLoop`) as these batches drive it."""

    def prepare(self) -> None: ...
    def cycles(
        self, n: int, countdown: int, tick: array | None, program: np.ndarray | None
    ) -> tuple[int, int, int]: ...
    def write_back(self) -> None: ...


def compiled_batch(fw: FirmwareState, cycles: int, span: int) -> tuple[int, int]:
    """Run up to ``cycles`` cycles on the compiled loop: (cycles run, cycles to the next 1 ms
    task; 0 = it is due). The override program's values go in cycle by cycle."""
    gen = cast("Batches", fw.gen)
    n = min(cycles, span)
    program = None
    if fw.program is not None and fw.override_on:
        program = program_rows(fw, cycles)
        n = len(program)
    tick = parameters(fw) if n > fw.tick_countdown else None
    gen.prepare()
    n, ticks, countdown = gen.cycles(n, fw.tick_countdown, tick, program)
    gen.write_back()
    if ticks:
        fw.ticks += ticks
        commit(fw, cast("array", tick))
    if program is not None:
        program_ran(fw, program[n - 1])
    return n, countdown


def parameters(fw: FirmwareState) -> array | None:
    """The C kernel's tick parameters, or None if the next 1 ms task may do something."""
    max_ticks = listeners_quiet(fw) if fw.cycle_listeners else MAX_TICKS
    faults = fw.faults
    state = fw.sm.state
    if (
        max_ticks <= 0
        or faults.any_present
        or state is DeviceState.FAULT_REACTION
        or (fw.analog_only and not fw.booting and state in _FAULTED)
        or fw.outputs_pending()
        or thermal.warning_after(fw) != fw.warning
    ):
        return None
    c = fw.fw
    temp_alarm = fw.temperature > c.temp_warning_c
    evaluate = fw.static_alarm or faults.busy
    static_bits = ref_mask = 0
    deadlines: list[float] = []
    if evaluate or temp_alarm:
        conditions = detect.conditions(fw)
        timers = faults.timers
        for bit, key in enumerate(CONDITION_BITS):
            condition, delay = conditions[key]
            if key in STATIC_BITS and condition:
                static_bits |= STATIC_BITS[key]
            t = timers[key]
            if t.since >= 0.0:
                ref_mask |= 1 << bit
                if not t.present:
                    deadlines += (0.0, t.since, delay)
        for t in timers.values():
            if 0.0 <= t.active_until < math.inf:
                deadlines += (1.0, t.active_until, 0.0)
        if len(deadlines) > 3 * MAX_DEADLINES:
            return None
    coils = fw.variant.coils.value
    plant = fw.plant
    temp_limit = c.temp_error_c
    if faults.is_present("temperature"):
        temp_limit -= c.temp_hysteresis_c
    return array(
        "d",
        [
            CYCLE_S,
            fw.cycles,
            fw.booting,
            c.boot_s,
            max_ticks,
            fw.override_on,
            fw.override_last,
            c.override_timeout_s,
            evaluate,
            ref_mask,
            static_bits,
            c.overcurrent_ma,
            temp_alarm,
            fw.monitoring_threshold,
            fw.sm.state is DeviceState.DEVICE_MODE_ACTIVE,
            faults.is_present("monitoring"),
            fw.supply,
            fw.loop.coil_open[0],
            fw.loop.coil_open[1],
            coils != "B",
            coils != "A",
            faults.is_present("coil_a_overcurrent") and Fault.COIL_A_OVERCURRENT in fw.injected,
            faults.is_present("coil_b_overcurrent") and Fault.COIL_B_OVERCURRENT in fw.injected,
            c.loop_break_ma,
            detect.OPEN_LOAD_MIN_V,
            detect.OPEN_LOAD_MA,
            Fault.OVER_TEMPERATURE not in fw.injected,  # else the reading is forced
            fw.ticks,
            thermal.THERMAL_TICKS,
            THERMAL_DT,
            config.coil_resistance(fw.coil_temperature, plant),
            plant.electronics_loss_w,
            plant.thermal_k_per_w,
            plant.thermal_tau_s,
            fw.inputs["ambient_temperature"],
            fw.coil_temperature,
            thermal.COIL_REFRESH_K,
            fw.temperature_rise,
            fw.temperature,
            c.temp_warning_c,
            c.temp_warning_c - c.temp_hysteresis_c,
            fw.warning,
            temp_limit,
            len(deadlines) // 3,
            *deadlines,
            *[0.0] * (3 * MAX_DEADLINES - len(deadlines)),
        ],
    )


def listeners_quiet(fw: FirmwareState) -> int:
    """How many of the next 1 ms tasks every cycle listener would pass doing nothing (0: one
    has none it would, or says nothing: the next task runs in Python)."""
    quiet = fw.cycle_quiet
    first_ms = fw.ticks + 1  # the next task's millisecond (Firmware.tick counts them)
    least = MAX_TICKS
    for listener in fw.cycle_listeners:
        check = quiet.get(listener)
        if check is None:
            return 0
        least = min(least, check(first_ms))
        if least <= 0:
            return 0
    return least


def commit(fw: FirmwareState, tick: array) -> None:
    """After the kernel passed 1 ms tasks: the thermal model's state and reading as they left it.

    (The reading reaches the loop as :meth:`.firmware.Firmware.tick` hands it on.)
    """
    fw.temperature_rise = tick[TICK_RISE]
    temperature = tick[TICK_TEMPERATURE]
    if temperature != fw.temperature:
        fw.temperature = temperature
        fw.loop.temperature_c = temperature
        fw.loop.inputs_version += 1


def program_rows(fw: FirmwareState, cycles: int) -> np.ndarray:
    """The static setpoint chain of the override program's next cycles, for the compiled loop.

    The value of this cycle is applied already (``Firmware._apply_program``); the compiled loop
    takes it and the following ones cycle by cycle, instead of one batch per value.
    """
    program = fw.program
    assert program is not None
    raw = program.upcoming(fw.cycles, cycles)
    version = fw.loop.version  # a parameter write rebuilds the coefficients: a new version
    if program.chain is None or program.chain[0] != version:
        program.chain = (version, config.setpoint_chain(fw.variant, fw.value))
    rows = config.static_setpoint_array(program.chain[1], raw, fw.setp_curve)
    return np.ascontiguousarray(rows)


def program_ran(fw: FirmwareState, row: np.ndarray) -> None:
    """SETPOVR and the setpoint chain ← the last cycle's, as ``Firmware._apply_program`` sets."""
    value = int(row[0])
    if fw.od.values.get(fw.setpovr_key) != value:
        fw.od.values[fw.setpovr_key] = value
        signals = (float(row[0]), float(row[1]), float(row[2]), float(row[3]))
        fw.loop.static_signals = signals
        fw.loop.target = signals[3]
        fw.loop.inputs_version += 1

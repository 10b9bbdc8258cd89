"""When the compiled kernel may pass the firmware's 1 ms task itself: the no-op test's inputs.

Most 1 ms tasks change nothing: no fault condition changes, no detection delay or display hold
ends, the state machine and the loop's mode stay, no listener is registered. The compiled
kernel (``_ckernel.tick_is_noop``) re-checks per millisecond what can change within a batch
(coil currents, PWM duties, LVDT loop current, control deviation, time) against the firmware
state summarized here; the first task that would do anything is left to
:meth:`.firmware.Firmware.tick`, exactly at its millisecond. Everything else this depends on
only changes in Python (a tick, a parameter or input write), which ends the compiled run.
"""

from __future__ import annotations

import math
from array import array
from typing import TYPE_CHECKING

from prm9tool.device.emulator import detect, thermal
from prm9tool.device.emulator.constants import CYCLE_S
from prm9tool.device.emulator.states import Fault
from prm9tool.device.records import DeviceState

if TYPE_CHECKING:
    from prm9tool.device.emulator.firmware import Firmware

MAX_DEADLINES = 16  # _ckernel.c: room for detection delays and display holds
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


def parameters(fw: Firmware) -> array | None:
    """The C kernel's tick parameters, or None if the next 1 ms task may do something."""
    max_ticks = thermal.THERMAL_TICKS - 1 - fw.ticks % thermal.THERMAL_TICKS
    faults = fw.faults
    state = fw.sm.state
    if (
        max_ticks == 0
        or fw.cycle_listeners
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
            len(deadlines) // 3,
            *deadlines,
            *[0.0] * (3 * MAX_DEADLINES - len(deadlines)),
        ],
    )

"""The valve firmware around the control loop: power-up, the 1 ms task, faults, NV memory.

:class:`Firmware` is not thread-safe by itself; :class:`~.valve.EmulatedValve` serializes every
access with its lock.
"""

from __future__ import annotations

import os
from collections.abc import Callable
from operator import itemgetter
from typing import Any

from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.scale import FULL_SCALE
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.catalogue.variant import Coils
from prm9tool.device.emulator import config, detect, fasttick, kernels, loop_inputs, thermal
from prm9tool.device.emulator.constants import (
    CYCLE_S,
    TICK_CYCLES,
    FirmwareConstants,
    PlantConstants,
)
from prm9tool.device.emulator.faults import FaultMonitor
from prm9tool.device.emulator.interface import latch
from prm9tool.device.emulator.loopstate import (
    MODE_ACTIVE,
    MODE_HOLD,
    MODE_OFF,
    SIGNAL_ORDER,
    Curve,
    LoopState,
)
from prm9tool.device.emulator.memory import ParameterMemory
from prm9tool.device.emulator.nvimage import NvImage, is_nonvolatile
from prm9tool.device.emulator.objdict import ObjectDictionary
from prm9tool.device.emulator.override import OverrideProgram
from prm9tool.device.emulator.statemachine import DeviceStateMachine
from prm9tool.device.emulator.states import Fault
from prm9tool.device.records import DeviceState, NmtState

AUTO_CONTROL_WORD = 0x0F  # analog-only mode: the firmware enables itself (decision)
_ACTIVE_STATES = (DeviceState.HOLD, DeviceState.DEVICE_MODE_ACTIVE, DeviceState.FAULT_HOLD)


class Firmware(ParameterMemory):
    """Object dictionary, NV image, state machine, fault monitor and the loop generator."""

    def __init__(
        self,
        type_key: TypeKey,
        serial: int,
        firmware_version: str,
        nv_path: str | os.PathLike[str] | None,
        switches: tuple[int, int] | None,
        plant: PlantConstants,
        fw: FirmwareConstants,
    ) -> None:
        self.type_key = type_key
        self.variant = type_key.variant
        self.serial = serial
        self.firmware_version = firmware_version
        self.plant = plant
        self.fw = fw
        self.od = ObjectDictionary(self.variant)
        self.od.on_change = self._on_parameter_changed
        self.nv = NvImage(str(type_key), serial, nv_path)
        self.loop = LoopState()
        self.loop.actuator = plant.actuator_start if self.variant.coils is Coils.AB else 0.0
        self.sm = DeviceStateMachine()
        self.faults = FaultMonitor(fw.fault_display_hold_s)
        self.inputs: dict[str, float] = {
            "setpoint": 0.0,
            "sensor": 0.0,
            "supply_voltage": 24.0,
            "ambient_temperature": 25.0,
            "sensor_from_plant": 1.0,
        }
        defaults = (CATALOGUE["SWBAUD"].default, CATALOGUE["SWNODE"].default)
        self.switches = [int(s) for s in (switches if switches is not None else defaults)]
        self.latched_switches = (self.switches[0], self.switches[1])
        self.injected: set[Fault] = set()
        self.cycles = 0
        self.ticks = 0
        self.tick_countdown = TICK_CYCLES
        self.override_on = False
        self.monitoring_threshold = FULL_SCALE
        self.monitoring_delay_s = 1.0
        self.static_conditions: dict[str, tuple[bool, float]] = {}
        self.static_alarm = False
        self.temperature_rise = 0.0
        self.temperature = 25.0  # electronics temperature reading, °C
        self.warning = False
        self.override_last = 0.0
        self.nmt_state = NmtState.OFF
        self.booting = True
        self.node_id = self.bitrate = 0
        self.can_enabled = self.terminator = False
        self.lss_mode = False  # node-ID switch at 1 (LSS, table 7-17)
        self.cycle_listeners: list[Callable[[float], None]] = []
        # per listener that has one: how many 1 ms tasks from the given ms on it would pass
        # doing nothing (the compiled kernel may pass those tasks itself: fasttick)
        self.cycle_quiet: dict[Callable[[float], None], Callable[[int], int]] = {}
        self.program: OverrideProgram | None = None  # a setpoint waveform on SETPOVR
        self.setpovr_key = CATALOGUE["SETPOVR"].key
        self.setpoint_dirty = True
        self.config_dirty = True
        self.coil_temperature = 25.0
        self.coefficients_memo: config.Memo[dict[str, Any]] = config.Memo()
        self.curve_memo: config.Memo[Curve] = config.Memo()
        self.kernel, self.make_loop = kernels.chosen()
        self.gen: kernels.Loop = self.make_loop(self.loop)
        from prm9tool.device.emulator.odsetup import install

        install(self)
        self.power_up()

    # --- time -------------------------------------------------------------------------
    @property
    def time(self) -> float:
        """Simulated seconds since power-up."""
        return self.cycles * CYCLE_S

    def run(self, cycles: int) -> None:
        """Run ``cycles`` control cycles, with the 1 ms task every 5 cycles.

        ``self.gen`` is looked up per batch: a listener may power-cycle the valve (NMT reset
        node), which replaces the loop generator. The compiled loop also passes the 1 ms tasks
        that would change nothing (:mod:`.fasttick`) and leaves the others to :meth:`tick`.
        """
        while cycles > 0:
            span = self._apply_program() if self.program is not None else cycles
            if self.setpoint_dirty or self.config_dirty:
                self._refresh_inputs()
            if self.kernel == "compiled":
                n, countdown = fasttick.compiled_batch(self, cycles, span)
            else:
                n = min(cycles, self.tick_countdown, span)
                self.gen.send(n)
                countdown = self.tick_countdown - n
            self.cycles += n
            cycles -= n
            self.tick_countdown = countdown
            if countdown == 0:
                self.tick_countdown = TICK_CYCLES
                self.tick()

    def _apply_program(self) -> int:
        """SETPOVR ← the override program's value for this cycle; cycles it stays so.

        Only the setpoint chain is recomputed (not the whole input refresh): a sine changes
        the value nearly every cycle.
        """
        assert self.program is not None
        value, span = self.program.value_and_span(self.cycles)
        key = self.setpovr_key
        if self.od.values.get(key) != value:
            self.od.values[key] = value
            if self.override_on and not (self.setpoint_dirty or self.config_dirty):
                signals = config.static_setpoint(
                    self.variant, self.value, float(value), self.setp_curve
                )
                self.loop.static_signals = signals
                self.loop.target = signals[3]
                self.loop.inputs_version += 1
            else:
                self.setpoint_dirty = True
        return span

    # --- power ------------------------------------------------------------------------
    def power_up(self) -> None:
        """Power cycle: RAM from the NV image, switches latched, boot timeline restarted."""
        self.cycles = 0
        self.ticks = 0
        self.tick_countdown = TICK_CYCLES
        self.latched_switches = (self.switches[0], self.switches[1])
        self._load_ram()
        self.booting = True
        self.nmt_state = NmtState.INITIALISING if self.can_enabled else NmtState.OFF
        self.sm.power_on()
        self.faults.reset()
        self.warning = False
        self.od.values[CATALOGUE["SETPOVRON"].key] = 0
        self.program = None
        if self.loop.coefficients:
            self.gen.send(0)  # the plant (spool, load) keeps its physical state over a power cycle
        self.gen = self.make_loop(self.loop)
        next(self.gen)
        self.loop.mode = MODE_OFF
        self.setpoint_dirty = self.config_dirty = True

    def _load_ram(self) -> None:
        od = self.od
        od.values = {}
        for key, param in od.entries.items():
            if param.group != "od_structure":
                od.values[key] = param.default_for(self.variant)
        for mnemonic, value in self.nv.values.items():
            if od.has(mnemonic) and is_nonvolatile(od.param(mnemonic)):
                od.values[od.param(mnemonic).key] = value
        self._latch_interface()
        for param in od.entries.values():
            if param.node_relative and param.mnemonic not in self.nv.values:
                od.values[param.key] = param.default_for(self.variant, self.node_id)

    # --- CANopen interface settings (latched at power-up) ----------------------------------
    def _latch_interface(self) -> None:
        """Decode the switches, the interface objects and the LSS record (``interface.py``)."""
        latched = latch(self.variant, self.latched_switches, self.value, self.nv.lss)
        self.can_enabled, self.terminator = latched.can_enabled, latched.terminator
        self.lss_mode, self.node_id, self.bitrate = (
            latched.lss_mode,
            latched.node_id,
            latched.bitrate,
        )

    @property
    def analog_only(self) -> bool:
        """True when the valve runs from the analog input without a CANopen master."""
        return not self.can_enabled

    # --- the 1 ms task ------------------------------------------------------------------
    def tick(self) -> None:
        """Boot timeline, thermal model, fault detection, state machine, outputs, listeners.

        The common case (no fault pending, nothing near a threshold) costs a few comparisons;
        the full condition table is evaluated only when something may have changed.
        """
        now = self.time
        if self.booting and now >= self.fw.boot_s - 1e-9:
            self._boot_finished()
        self.ticks += 1
        if self.ticks % thermal.THERMAL_TICKS == 0:
            thermal.step(self, thermal.THERMAL_TICKS * TICK_CYCLES * CYCLE_S)
        faults = self.faults
        if self.static_alarm or faults.busy or self._dynamic_alarm():
            faults.update(now, detect.conditions(self))
        thermal.update_warning(self)
        sm = self.sm
        if faults.any_present:
            sm.fault(self.fw.fault_reaction_s)
        if sm.state is DeviceState.FAULT_REACTION:
            sm.tick(TICK_CYCLES * CYCLE_S)
        elif self.analog_only and not self.booting:
            self._auto_reset()
        self._update_outputs()
        if self.override_on and now - self.override_last > self.fw.override_timeout_s:
            self.od.values[CATALOGUE["SETPOVRON"].key] = 0
            self.setpoint_dirty = True
        for listener in self.cycle_listeners:
            listener(now)

    def _dynamic_alarm(self) -> bool:
        ia, ib = self.loop.current_ma
        limit = self.fw.overcurrent_ma
        if ia > limit or ib > limit or self.temperature > self.fw.temp_warning_c:
            return True
        return (
            abs(self.loop.ctrl_dev) > self.monitoring_threshold
            and self.sm.state is DeviceState.DEVICE_MODE_ACTIVE
        )

    def _boot_finished(self) -> None:
        self.booting = False
        self.sm.init_done()
        if self.can_enabled:
            startup_operational = self.od.get("NMTSTARTUP") == 0
            self.nmt_state = (
                NmtState.OPERATIONAL if startup_operational else NmtState.PRE_OPERATIONAL
            )
        else:
            self.sm.write_control_word(AUTO_CONTROL_WORD, self.faults.any_present)
        self.setpoint_dirty = True

    def _auto_reset(self) -> None:
        sm = self.sm
        if sm.state in (DeviceState.FAULT, DeviceState.FAULT_HOLD) and not self.faults.any_present:
            sm.write_control_word(AUTO_CONTROL_WORD & ~0x08, False)
            sm.write_control_word(AUTO_CONTROL_WORD, False)

    def _outputs(self) -> tuple[int, tuple[bool, bool]]:
        """The loop's mode and output stages (safety switches) for the present state."""
        state = self.sm.state
        if self.booting or self.faults.any_present or state not in _ACTIVE_STATES:
            mode = MODE_OFF
        elif state is DeviceState.DEVICE_MODE_ACTIVE:
            mode = MODE_ACTIVE
        else:
            mode = MODE_HOLD
        stage = (
            not self.faults.is_present("coil_a_overcurrent"),
            not self.faults.is_present("coil_b_overcurrent"),
        )
        return mode, stage

    def outputs_pending(self) -> bool:
        """True if the next 1 ms task hands the loop a new mode, stage or temperature."""
        mode, stage = self._outputs()
        loop = self.loop
        return mode != loop.mode or stage != loop.stage_on or self.temperature != loop.temperature_c

    def _update_outputs(self) -> None:
        mode, stage = self._outputs()
        loop = self.loop
        if mode != loop.mode or stage != loop.stage_on or self.temperature != loop.temperature_c:
            loop.mode, loop.stage_on, loop.temperature_c = mode, stage, self.temperature
            loop.inputs_version += 1

    @property
    def supply(self) -> float:
        """Supply voltage at the valve, V."""
        if Fault.SUPPLY_LOW in self.injected:
            return self.fw.injected_low_supply_v
        if Fault.SUPPLY_HIGH in self.injected:
            return self.fw.injected_high_supply_v
        return self.inputs["supply_voltage"]

    # --- inputs to the loop -----------------------------------------------------------
    def _on_parameter_changed(self, mnemonic: str) -> None:
        if mnemonic == "CONTROLWORD":
            return  # its hook told the state machine, which the 1 ms task reads, not the inputs
        self.setpoint_dirty = True
        self.config_dirty = True

    def value(self, mnemonic: str) -> int:
        """Integer RAM value of a parameter; 0 if it does not exist on this variant."""
        param = self.od.by_mnemonic.get(mnemonic)  # od.has and od.get in one lookup
        if param is None:
            return 0
        value = self.od.values[param.key]
        return value if isinstance(value, int) else 0

    def reader_for(self, mnemonics: list[str]) -> Callable[[], list[int]]:
        """A function returning :meth:`value` of each mnemonic (one C-level lookup if all are
        numbers on this variant); the loop memos' check."""
        params = [self.od.by_mnemonic.get(m) for m in mnemonics]
        if len(params) < 2 or any(p is None or p.is_string for p in params):
            return lambda: [self.value(m) for m in mnemonics]
        getter = itemgetter(*[p.key for p in params if p is not None])
        return lambda: list(getter(self.od.values))

    def _refresh_inputs(self) -> None:
        loop = self.loop
        supply = self.supply
        if self.config_dirty:
            variant, plant, fw = self.variant, self.plant, self.fw
            temperature = self.coil_temperature
            loop.coefficients = self.coefficients_memo.get(
                self.value,
                (variant, plant, fw, float(temperature).hex(), float(supply).hex()),
                lambda v: config.coefficients(variant, v, plant, fw, temperature, supply),
                self.reader_for,
            )
            loop.version += 1
            self.setp_curve = self.curve_memo.get(
                self.value, (), config.setpoint_curve, self.reader_for
            )
        loop.supply_v = supply
        loop.inputs_version += 1
        thermal.update_reading(self)
        loop.coil_open = (Fault.COIL_A_OPEN in self.injected, Fault.COIL_B_OPEN in self.injected)
        loop.coil_short = (
            Fault.COIL_A_OVERCURRENT in self.injected,
            Fault.COIL_B_OVERCURRENT in self.injected,
        )
        loop.lvdt_break = Fault.POSITION_SENSOR_BREAK in self.injected
        loop_inputs.refresh_sensor(self, supply)
        signals = config.static_setpoint(
            self.variant, self.value, loop_inputs.raw_setpoint(self, supply), self.setp_curve
        )
        loop.static_signals = signals
        loop.target = signals[3]
        self.override_on = bool(self.value("SETPOVRON"))
        self.monitoring_threshold = self.value("MONTHRES")
        self.monitoring_delay_s = self.value("MONDELAY") / 1000.0
        self.static_conditions = detect.static_conditions(self)
        self.static_alarm = detect.static_alarm(self)
        self.setpoint_dirty = self.config_dirty = False

    def flush(self) -> LoopState:
        """Make the loop write every measuring point back; returns the mailbox."""
        if self.setpoint_dirty or self.config_dirty:
            self._refresh_inputs()
        self.gen.send(0)
        return self.loop

    def compiled_state(self):  # type: ignore[no-untyped-def]
        """The compiled loop's state array as :meth:`flush` leaves it, without the copy into
        the mailbox (the PDO fast path reads its measuring points from there, pdo_fast.py).
        Only for the compiled kernel (``gen`` with ``prepare``/``write_back``)."""
        if self.setpoint_dirty or self.config_dirty:
            self._refresh_inputs()
        gen = self.gen
        gen.prepare()  # type: ignore[attr-defined]
        gen.write_back()  # type: ignore[attr-defined]
        return gen.state  # type: ignore[attr-defined]

    def signal_values(self) -> dict[str, float]:
        """Latest value of every measuring point."""
        return dict(zip(SIGNAL_ORDER, self.flush().signals, strict=True))

"""What only an emulated valve offers the program: its inputs, rotary switches and faults.

A real valve is wired to a PLC and a power supply; an emulated one gets its analog setpoint,
sensor signal, supply voltage and ambient temperature, its rotary switches and its physical
faults (a cut wire, a shorted coil, the USB cable pulled) from here. A session to an emulated
valve has an :class:`EmulatorControls` (``ValveSession.emulator``); a real valve's has None.
No Qt.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from prm9tool.errors import ValueRangeError

if TYPE_CHECKING:
    from prm9tool.device.emulator import EmulatedValve
    from prm9tool.device.usb.transport.emulator import EmulatorTransport

INPUTS = ("setpoint", "sensor", "supply_voltage", "ambient_temperature")
SWITCHES = ("switch_baud", "switch_node")


@dataclass(frozen=True)
class EmulatorState:
    """A snapshot of the emulated valve's surroundings.

    ``inputs``: electrical values (V or mA, as the signal type of AINSETP/SENSTYPE says; supply
    in V, ambient temperature in °C); ``switches``: the rotary switch positions (0…15) set now,
    ``latched``: those the valve read at its last power-up; ``faults``: the injected faults'
    names (``prm9tool.device.emulator.Fault`` values); ``sensor``: the valve has an external
    sensor input (E04); ``canopen``: it has the CANopen interface (-CA).
    """

    inputs: dict[str, float]
    switches: tuple[int, int]
    latched: tuple[int, int]
    faults: frozenset[str]
    sensor: bool
    canopen: bool
    faults_available: tuple[str, ...] = ()


def faults_for(valve: EmulatedValve) -> tuple[str, ...]:
    """The faults that can happen to ``valve``: no coil B faults on a valve with coil A only
    (and the other way round), the external sensor's wire only on an E04."""
    from prm9tool.device.emulator import Fault

    coils = valve.variant.coils.value
    names = []
    for fault in Fault:
        name = str(fault)
        if (name.startswith("COIL_A") and "A" not in coils) or (
            name.startswith("COIL_B") and "B" not in coils
        ):
            continue
        if fault is Fault.SENSOR_BREAK and valve.variant.config.value != "E04":
            continue
        names.append(name)
    return tuple(names)


class EmulatorControls:
    """Inputs, switches and faults of the emulated valve behind an emulated USB link."""

    def __init__(self, transport: EmulatorTransport) -> None:
        self._transport = transport

    @property
    def valve(self) -> EmulatedValve:
        """The emulated valve."""
        return self._transport.valve

    def state(self) -> EmulatorState:
        """Inputs, switches and injected faults as they are now."""
        valve = self.valve
        with valve.lock:
            inputs = valve.inputs()
            return EmulatorState(
                {name: inputs[name] for name in INPUTS},
                valve.switches,
                valve.latched_switches,
                frozenset(str(f) for f in valve.injected()),
                valve.variant.config.value == "E04",
                valve.variant.canopen,
                faults_for(valve),
            )

    def set_input(self, name: str, value: float) -> None:
        """Set an analog input or a rotary switch (``switch_*``: effective at the next
        power-up, as on the real valve)."""
        if name not in (*INPUTS, *SWITCHES):
            raise ValueRangeError(f"unknown input {name!r}")
        self.valve.set_input(name, value)

    def set_fault(self, fault: str, present: bool) -> None:
        """Make a physical fault happen (``present``) or repair it."""
        from prm9tool.device.emulator import Fault

        try:
            kind = Fault(fault)
        except ValueError:
            raise ValueRangeError(f"unknown fault {fault!r}") from None
        if present:
            self.valve.inject(kind)
        else:
            self.valve.clear(kind)

    def drive_setpoint(self, source: Callable[[np.ndarray], np.ndarray] | None) -> None:
        """Run a setpoint waveform on the valve's own clock, exact to its 200 µs cycle:
        ``source`` maps times (s since now) to SETPOVR raw values (None: stop). It acts while
        the link has SETPOVRON = 1, as a value written over the link would."""
        self.valve.drive_override(source)

    def pull_cable(self) -> None:
        """Pull the USB cable: the link dies, the valve runs on (its setpoint override drops
        500 ms later, as without any USB traffic)."""
        self._transport.unplug()

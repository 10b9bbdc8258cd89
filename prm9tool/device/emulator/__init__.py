"""The in-process emulator of the PRM9 valve firmware (no Qt).

``EmulatedValve`` runs the valve's 200 µs control loop against a plant model, with the object
dictionary, faults and LEDs, the CiA 408 state machine and a non-volatile memory image. Its
status is a :class:`prm9tool.device.records.ValveStatus`, like every link's. See docs/emulator.md.
"""

from prm9tool.device.emulator.states import Fault
from prm9tool.device.emulator.valve import EmulatedValve

__all__ = ["EmulatedValve", "Fault"]

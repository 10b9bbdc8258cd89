"""The in-process emulator of the PRM9 valve firmware (no Qt).

``EmulatedValve`` runs the valve's 200 µs control loop against a plant model, with the object
dictionary, faults and LEDs, the CiA 408 state machine and a non-volatile memory image.
See docs/emulator.md.
"""

from prm9tool.device.emulator.states import DeviceState, Fault, LedState, ValveStatus
from prm9tool.device.emulator.valve import EmulatedValve

__all__ = ["DeviceState", "EmulatedValve", "Fault", "LedState", "ValveStatus"]

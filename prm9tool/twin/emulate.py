"""Emulate a twin (issue 31 item 3): the emulated valve of a twin file, with its plant
constants, serial, type key, firmware version and parameter set. It lives with the twin file
in :mod:`prm9tool.device.emulator.twinfile` (the device factory opens twins); this name keeps
working."""

from prm9tool.device.emulator.twinfile import emulated_twin

__all__ = ["emulated_twin"]

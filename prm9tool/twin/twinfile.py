"""The twin file (issue 31): its reader and writer live with the emulator,
:mod:`prm9tool.device.emulator.twinfile`, so that the device factory opens a twin
(``emulator:twin:FILE``) without importing this layer; this name keeps working."""

from prm9tool.device.emulator.twinfile import (
    FORMAT,
    VERSION,
    Twin,
    TwinFileError,
    read_twin,
    write_twin,
)

__all__ = ["FORMAT", "VERSION", "Twin", "TwinFileError", "read_twin", "write_twin"]

"""Scenario steps for tests that drive emulated valves side by side (equivalence tests).

A step is ``(kind, argument)``: ``("frame", (can_id, data))`` to the valve's CANopen slave,
``("advance", seconds)``, ``("usb", (index, subindex, value))`` (a write over USB; an abort is
taken as the valve's answer), ``("inject" | "clear", fault)``, ``("input", (name, value))`` or
``("restart", None)``.
"""

from __future__ import annotations

import contextlib
import struct
from typing import Any

from prm9tool.device.emulator import EmulatedValve
from prm9tool.errors import SdoAbortError

Step = tuple[str, Any]


def sdo_download(index: int, sub: int, value: int, size: int) -> bytes:
    """An expedited SDO download request of ``size`` bytes."""
    command = {1: 0x2F, 2: 0x2B, 4: 0x23}[size]
    return struct.pack("<BHB", command, index, sub) + value.to_bytes(4, "little", signed=value < 0)


def run_step(valve: EmulatedValve, slave: Any, step: Step) -> None:
    """Apply one step to ``valve`` (and its slave, for frames, received at no time stamp)."""
    kind, arg = step
    if kind == "frame":
        can_id, data = arg
        slave.receive_data(can_id, data, 0.0)
    elif kind == "advance":
        valve.advance(arg)
    elif kind == "usb":
        with contextlib.suppress(SdoAbortError):  # refused alike (their dictionaries agree)
            valve.write(*arg)
    elif kind == "inject":
        valve.inject(arg)
    elif kind == "clear":
        valve.clear(arg)
    elif kind == "input":
        valve.set_input(*arg)
    elif kind == "restart":
        valve.restart()
    else:
        raise ValueError(f"unknown step {kind!r}")

"""Transports of the USB link: one abstract link (timeouts, retries, logging) and one class per
backend (:mod:`.hidapi` for a real valve, :mod:`.emulator` for the in-process emulated one).

Each backend is a module of its own, imported by the device factory when it is used, so a
machine without hidapi still runs the emulator.
"""

from __future__ import annotations

from prm9tool.device.usb.transport.base import LinkStats, Transport

__all__ = ["LinkStats", "Transport"]

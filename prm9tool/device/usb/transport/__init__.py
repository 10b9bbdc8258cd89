"""Transports: one abstract link (timeouts, retries, logging) and one class per backend.

Backends are imported on first use, so a machine without hidapi still runs the emulator.
"""

from __future__ import annotations

import importlib
from typing import Any

from prm9tool.device.usb.transport.base import LinkStats, Transport

__all__ = ["BACKENDS", "LinkStats", "Transport", "backend"]

BACKENDS = {
    "usb": "prm9tool.device.usb.transport.hidapi:HidTransport",
    "emulator": "prm9tool.device.usb.transport.emulator:EmulatorTransport",
}


def backend(name: str) -> Any:
    """The transport class registered as ``name`` (imported now)."""
    module_name, _, class_name = BACKENDS[name].partition(":")
    return getattr(importlib.import_module(module_name), class_name)

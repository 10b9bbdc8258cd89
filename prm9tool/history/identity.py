"""Who a valve is, as a typing protocol: the history records it, the views show it.

A session's :class:`prm9tool.device.records.DeviceInfo` satisfies it; so does a small fake in
a test. Plain Python, so the GUI's typing protocols (:mod:`prm9tool.online.connection_protocol`)
use it without loading the history's database layer.
"""

from __future__ import annotations

from typing import Protocol


class ValveIdentity(Protocol):
    """Who a valve is: what a history record and the views need (a DeviceInfo has it)."""

    @property
    def type_key(self) -> str:
        """The valve's type key."""

    @property
    def serial(self) -> int:
        """The valve's serial number."""

    @property
    def firmware(self) -> str:
        """Its firmware version."""

    @property
    def device_id(self) -> str:
        """How it was reached (``usb:…``, ``can:…``, ``emulator:…``)."""

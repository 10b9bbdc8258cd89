"""The CAN adapters a user of this platform has, as python-can names them, with a first channel.

The CAN bus dialog offers them in this order (the first is its default) and ``--help`` names
them. SocketCAN exists on Linux only; a Windows laptop has a vendor's adapter and driver: PEAK
(``pcan``, channel ``PCAN_USBBUS1``), Kvaser (``kvaser``, channel ``0``), Vector (``vector``,
``0``), IXXAT (``ixxat``, ``0``) or a serial-line adapter (``slcan`` on a COM port).
``udp_multicast`` and ``virtual`` are prm9tool's own buses (emulated valves) on every platform.
No Qt: views and the command line both read it.
"""

from __future__ import annotations

import sys
from dataclasses import dataclass


@dataclass(frozen=True)
class Adapter:
    """A python-can interface and the channel its first adapter usually has."""

    interface: str
    channel: str


WINDOWS: tuple[Adapter, ...] = (
    Adapter("pcan", "PCAN_USBBUS1"),
    Adapter("kvaser", "0"),
    Adapter("vector", "0"),
    Adapter("ixxat", "0"),
    Adapter("slcan", "COM3"),
    Adapter("gs_usb", "0"),
)
LINUX: tuple[Adapter, ...] = (
    Adapter("socketcan", "can0"),
    Adapter("pcan", "PCAN_USBBUS1"),
    Adapter("kvaser", "0"),
    Adapter("ixxat", "0"),
    Adapter("vector", "0"),
    Adapter("slcan", "/dev/ttyACM0"),
    Adapter("gs_usb", "0"),
)
MACOS: tuple[Adapter, ...] = (
    Adapter("pcan", "PCAN_USBBUS1"),  # PEAK's PCBUSB library
    Adapter("slcan", "/dev/tty.usbmodem1"),
    Adapter("gs_usb", "0"),
)
EVERYWHERE = (Adapter("udp_multicast", "239.74.163.2"), Adapter("virtual", "prm9tool"))


def adapters(platform: str | None = None) -> tuple[Adapter, ...]:
    """The adapters of ``platform`` (``sys.platform`` when None), the usual one first."""
    platform = sys.platform if platform is None else platform
    if platform == "win32":
        own = WINDOWS
    elif platform == "darwin":
        own = MACOS
    else:
        own = LINUX
    return own + EVERYWHERE


def default_adapter(platform: str | None = None) -> Adapter:
    """The adapter a new user of ``platform`` is offered first."""
    return adapters(platform)[0]


def usual_channel(interface: str, platform: str | None = None) -> str | None:
    """The first channel of ``interface`` on ``platform``; None for an interface not listed."""
    for adapter in adapters(platform):
        if adapter.interface == interface:
            return adapter.channel
    return None

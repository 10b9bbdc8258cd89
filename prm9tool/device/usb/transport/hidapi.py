"""The USB backend: 64-byte HID reports through the ``hidapi`` library.

The ``hidapi`` package installs two modules on Linux: ``hidraw`` (hidapi's hidraw backend:
the kernel's HID driver, device paths ``/dev/hidrawN``, udev permissions on those nodes) and
``hid`` (the libusb backend, which detaches the kernel driver and has paths like ``1-2:1.0``).
prm9tool uses ``hidraw`` on Linux and falls back to ``hid`` if it is missing; on Windows and
macOS ``hid`` is the native HID stack. The valve uses unnumbered reports, so every write starts
with report ID 0, which the OS strips; reads return the 64 bytes without it. The module is
imported only when a USB device is actually used, so a machine without a working hidapi runs
the emulator fine.
"""

from __future__ import annotations

import importlib
import os
import sys
import time
from collections.abc import Callable
from dataclasses import dataclass
from types import ModuleType
from typing import Any

from prm9tool.device.usb.protocol import REPORT_SIZE
from prm9tool.device.usb.transport.base import Transport
from prm9tool.errors import CommunicationError, DeviceDisconnectedError

REPORT_ID = 0
HID_MODULES = ("hidraw", "hid") if sys.platform.startswith("linux") else ("hid",)
DEFAULT_PRODUCT = "PRM9"  # product-string filter used when no VID/PID is configured


def load_hid() -> ModuleType:
    """Import hidapi (``hidraw`` on Linux, else ``hid``); CommunicationError says why not."""
    problems = []
    for name in HID_MODULES:  # lazy: USB is optional
        try:
            return importlib.import_module(name)
        except ImportError as exc:  # also covers a missing libhidapi shared library
            problems.append(f"{name}: {exc}")
    raise CommunicationError(
        f"USB is not available: the hidapi library could not be loaded ({'; '.join(problems)}). "
        "Install the 'hidapi' Python package; the emulator works without it."
    )


@dataclass(frozen=True)
class UsbFilter:
    """Which HID devices are PRM9 valves.

    The real vendor/product IDs are not public, so they come from the environment
    (``PRM9TOOL_USB_VID``, ``PRM9TOOL_USB_PID``, hexadecimal) or the caller; without them a
    device qualifies by its product string (``PRM9TOOL_USB_PRODUCT``, default ``PRM9``).
    """

    vendor_id: int = 0
    product_id: int = 0
    product: str = DEFAULT_PRODUCT

    @classmethod
    def from_env(cls) -> UsbFilter:
        """The filter configured in the environment."""
        return cls(
            _hex_env("PRM9TOOL_USB_VID"),
            _hex_env("PRM9TOOL_USB_PID"),
            os.environ.get("PRM9TOOL_USB_PRODUCT", DEFAULT_PRODUCT),
        )

    def matches(self, info: dict[str, Any]) -> bool:
        """True if the ``hid.enumerate()`` record ``info`` is a valve."""
        if self.vendor_id or self.product_id:
            return (not self.vendor_id or info.get("vendor_id") == self.vendor_id) and (
                not self.product_id or info.get("product_id") == self.product_id
            )
        return self.product.lower() in str(info.get("product_string") or "").lower()


def shown_path(path: bytes, platform: str | None = None) -> str:
    """A HID device path as the user's system shows it. On Windows hidapi's path is the device
    interface's name, ``\\\\?\\HID#VID_0483&PID_5750#7&2a0b0f6b&0&0000#{4d1e55b2-…}``; Device
    Manager shows the device instance path ``HID\\VID_0483&PID_5750\\7&2A0B0F6B&0&0000``
    (Properties → Details), which this returns. Elsewhere the path as it is (``/dev/hidraw3``,
    ``1-2:1.0``, macOS ``DevSrvsID:4294968125``)."""
    text = path.decode(errors="replace")
    if (sys.platform if platform is None else platform) != "win32":
        return text
    name = text.removeprefix("\\\\?\\").removeprefix("\\\\.\\")
    head, _, last = name.rpartition("#")
    if head and last.startswith("{") and last.endswith("}"):  # the interface class GUID
        name = head
    return name.replace("#", "\\").upper() if "#" in name else text


def _hex_env(name: str) -> int:
    text = os.environ.get(name, "").strip()
    if not text:
        return 0
    try:
        return int(text, 16)
    except ValueError:
        raise CommunicationError(f"{name}={text!r} is not a hexadecimal USB ID") from None


def enumerate_valves(usb_filter: UsbFilter | None = None) -> list[dict[str, Any]]:
    """``hid.enumerate()`` records of every connected device the filter accepts."""
    hid = load_hid()
    usb_filter = usb_filter or UsbFilter.from_env()
    records = hid.enumerate(usb_filter.vendor_id, usb_filter.product_id)
    return [r for r in records if usb_filter.matches(r)]


class HidTransport(Transport):
    """A valve on USB, opened by its HID device path.

    ``finder`` locates the valve again after a restart (USB re-enumeration may give it a new
    path); ``settle_s`` is how long the valve needs to drop off the bus after a restart.
    """

    settle_s = 0.5

    def __init__(
        self,
        path: bytes,
        *,
        finder: Callable[[], bytes | None] | None = None,
        timeout_s: float = 0.25,
        retries: int = 3,
    ) -> None:
        super().__init__(timeout_s=timeout_s, retries=retries, name=f"usb:{path.decode()}")
        self.path = path
        self._finder = finder
        self._device = self._open(path)

    @staticmethod
    def _open(path: bytes) -> Any:
        hid = load_hid()
        device = hid.device()
        try:
            device.open_path(path)
            device.set_nonblocking(1)  # read(…, 0) must not block; timeouts > 0 still wait
        except (OSError, ValueError) as exc:
            raise DeviceDisconnectedError(
                f"cannot open USB device {shown_path(path)}: {exc}"
            ) from exc
        return device

    def _write(self, report: bytes) -> None:
        try:
            written = self._device.write(bytes([REPORT_ID]) + report)
        except (OSError, ValueError) as exc:
            raise DeviceDisconnectedError(
                f"USB valve {shown_path(self.path)} is gone: {exc}"
            ) from exc
        if written < 0:
            raise DeviceDisconnectedError(
                f"USB valve {shown_path(self.path)} is gone (write failed)"
            )

    def _read(self, timeout_s: float) -> bytes | None:
        try:
            data = self._device.read(REPORT_SIZE, max(0, round(timeout_s * 1000)))
        except (OSError, ValueError) as exc:
            raise DeviceDisconnectedError(
                f"USB valve {shown_path(self.path)} is gone: {exc}"
            ) from exc
        if not data:
            return None
        return bytes(data[:REPORT_SIZE]).ljust(REPORT_SIZE, b"\x00")

    def _close(self) -> None:
        self._device.close()

    def reconnect(self) -> None:
        """Reopen the valve after its restart (its path may change when USB re-enumerates)."""
        super().reconnect()
        with self._lock:
            self._device.close()
            time.sleep(self.settle_s)
            path = self._finder() if self._finder else self.path
            if path is None:
                self._broken = DeviceDisconnectedError(
                    f"the valve did not come back on USB after its restart ({shown_path(self.path)})"
                )
                raise self._broken
            self.path = path
            self._device = self._open(path)
            self._broken = None

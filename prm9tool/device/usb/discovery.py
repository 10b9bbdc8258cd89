"""Finding valves: USB HID devices that identify themselves with the prm9tool protocol.

A HID device qualifies by the filter of :class:`UsbFilter` (vendor/product IDs from the
environment, else the product string); it is then opened and asked to identify itself, so
each entry shows type key, serial number and firmware as the valve reports them.
"""

from __future__ import annotations

import logging
import time
from dataclasses import dataclass

from prm9tool.device.usb.protocol import PROTOCOL_VERSION, Identify, IdentifyReply
from prm9tool.device.usb.transport.hidapi import HidTransport, UsbFilter, enumerate_valves
from prm9tool.errors import CommunicationError

log = logging.getLogger("prm9tool.device.usb.discovery")
REAPPEAR_S = 10.0  # how long a restarted valve may take to come back on USB


@dataclass(frozen=True)
class UsbValve:
    """One valve found on USB."""

    path: bytes
    type_key: str
    serial: int
    firmware: str
    product: str


def identify_path(path: bytes) -> UsbValve | None:
    """Open ``path`` and ask it to identify itself; None if it does not answer properly."""
    try:
        transport = HidTransport(path, timeout_s=0.3, retries=1)
    except CommunicationError as exc:
        log.warning("cannot open %s: %s", path.decode(errors="replace"), exc)
        return None
    try:
        reply = transport.request(Identify())
    except CommunicationError as exc:
        log.warning("%s does not answer as a PRM9: %s", path.decode(errors="replace"), exc)
        return None
    finally:
        transport.close()
    if not isinstance(reply, IdentifyReply) or reply.protocol_version != PROTOCOL_VERSION:
        log.warning("%s answered identification with %r", path.decode(errors="replace"), reply)
        return None
    return UsbValve(path, reply.type_key, reply.serial, reply.firmware, "")


def usb_valves(usb_filter: UsbFilter | None = None) -> list[UsbValve]:
    """Every connected valve that identifies itself (raises CommunicationError without hidapi)."""
    found = []
    for record in enumerate_valves(usb_filter):
        valve = identify_path(record["path"])
        if valve is not None:
            product = str(record.get("product_string") or "")
            found.append(
                UsbValve(valve.path, valve.type_key, valve.serial, valve.firmware, product)
            )
    return found


def find_serial(serial: int, wait_s: float = REAPPEAR_S) -> bytes | None:
    """The HID path of the valve with ``serial``, waiting up to ``wait_s`` for it to appear."""
    deadline = time.monotonic() + wait_s
    while True:
        try:
            for valve in usb_valves():
                if valve.serial == serial:
                    return valve.path
        except CommunicationError as exc:
            log.warning("looking for valve %d: %s", serial, exc)
        if time.monotonic() >= deadline:
            return None
        time.sleep(0.25)

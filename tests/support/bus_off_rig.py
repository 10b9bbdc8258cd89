"""A CAN adapter of the tool that goes bus-off and recovers, on python-can's virtual bus
(which has no bus errors of its own).

:func:`install` wraps every bus the tool opens on one channel (``canlink.bus.open_bus``) in a
:class:`BusOffBus`; :meth:`Adapter.go_bus_off` and :meth:`Adapter.recover` switch them all, as
a CAN controller that went bus-off takes the whole adapter off the bus. Modelled on SocketCAN
(linux/can/error.h): entering bus-off puts one error frame with ``CAN_ERR_BUSOFF`` in its ID
into each open socket; after it, sending fails (python-can's ``CanOperationError``, whose text
does not say why) and no frame from the bus arrives; recovering (``restart-ms``) puts an error
frame with ``CAN_ERR_RESTARTED``, after which everything works again. The valves on the bus
stay where they are.
"""

from __future__ import annotations

import threading
from collections.abc import Callable

import can
import pytest

from prm9tool.device.canlink import bus as canlink_bus
from prm9tool.device.canlink.bus import CAN_ERR_BUSOFF, CAN_ERR_RESTARTED, CanOptions

SLICE_S = 0.01  # a bus notices the adapter's state change within this (its receive slices)


class Adapter:
    """The state of one adapter (every bus the tool opened on its channel)."""

    def __init__(self) -> None:
        self.off = False
        self.buses: list[BusOffBus] = []
        self.lock = threading.Lock()

    def go_bus_off(self) -> None:
        """The controller goes bus-off (too many transmit errors)."""
        self.off = True

    def recover(self) -> None:
        """The controller is back on the bus (SocketCAN's automatic restart)."""
        self.off = False

    def told(self) -> bool:
        """Every open bus has handed the error frame of the present state to its reader."""
        with self.lock:
            return all(bus.told_off == self.off for bus in self.buses if not bus.closed)


class BusOffBus(can.BusABC):
    """A python-can bus in front of ``inner`` that follows ``adapter``'s bus-off state."""

    def __init__(self, inner: can.BusABC, adapter: Adapter) -> None:
        self._inner = inner
        self._adapter = adapter
        self.told_off = False  # the state the last error frame told the reader
        self.closed = False
        super().__init__(channel=inner.channel_info)
        self.channel_info = f"bus-off rig on {inner.channel_info}"
        with adapter.lock:
            adapter.buses.append(self)

    def send(self, msg: can.Message, timeout: float | None = None) -> None:
        """Send, unless the adapter told its reader it is bus-off (then as SocketCAN fails)."""
        if self.told_off:
            raise can.CanOperationError("Failed to transmit: [Errno 105] No buffer space available")
        self._inner.send(msg, timeout)

    def _recv_internal(self, timeout: float | None) -> tuple[can.Message | None, bool]:
        if self._adapter.off != self.told_off:
            self.told_off = self._adapter.off
            error_class = CAN_ERR_BUSOFF if self.told_off else CAN_ERR_RESTARTED
            frame = can.Message(arbitration_id=error_class, is_error_frame=True, dlc=8,
                                data=bytes(8), channel=self.channel_info)  # fmt: skip
            return frame, False
        msg = self._inner.recv(SLICE_S if timeout is None else min(timeout, SLICE_S))
        if self.told_off:
            return None, False  # off the bus: nothing arrives
        return msg, False

    def shutdown(self) -> None:
        """Close the bus and the virtual bus behind it."""
        self.closed = True
        self._inner.shutdown()
        super().shutdown()


def install(monkeypatch: pytest.MonkeyPatch, channel: str) -> Adapter:
    """Every bus the tool opens on the virtual ``channel`` from now on sits behind the
    returned adapter (the valve's own bus does not: it is not opened through the tool)."""
    adapter = Adapter()
    real_open: Callable[..., can.BusABC] = canlink_bus.open_bus

    def open_bus(options: CanOptions, default_bitrate: int | None = None) -> can.BusABC:
        inner = real_open(options, default_bitrate)
        return BusOffBus(inner, adapter) if options.channel == channel else inner

    monkeypatch.setattr(canlink_bus, "open_bus", open_bus)
    return adapter

"""The valve session over prm9tool's USB HID protocol (docs/usb-protocol.md): one link of
:class:`prm9tool.device.session.ValveSession`, for USB valves and the emulated ones."""

from __future__ import annotations

import threading
from collections.abc import Callable, Mapping, Sequence
from typing import TypeVar

import numpy as np

from prm9tool.catalogue import Parameter
from prm9tool.device.emulated import EmulatorControls
from prm9tool.device.records import DeviceInfo, DeviceState, LedState, Steps, Value, ValveStatus
from prm9tool.device.session import ValveSession
from prm9tool.device.usb.entries import EntryIO
from prm9tool.device.usb.protocol import (
    PROTOCOL_VERSION,
    AbortReply,
    Done,
    Identify,
    IdentifyReply,
    Nmt,
    Reload,
    Request,
    Response,
    Restart,
    RestoreFactory,
    StatusReply,
    StatusRequest,
    Store,
)
from prm9tool.device.usb.stream import StreamReceiver
from prm9tool.device.usb.transport import Transport
from prm9tool.errors import CommunicationError, ProtocolError, SdoAbortError

R = TypeVar("R", bound=Response)
__all__ = ["UsbSession"]


class UsbSession(ValveSession):
    """One valve over the USB request/response protocol. The transport serializes exchanges."""

    def __init__(
        self,
        transport: Transport,
        device_id: str,
        on_close: Callable[[], None] | None = None,
    ) -> None:
        super().__init__(device_id, on_close)
        self._transport = transport
        self._stream = StreamReceiver(self._call, transport)
        self._entries = EntryIO(self._call)
        self._start()

    @property
    def transport(self) -> Transport:
        """The link this session talks over (statistics, fault injection in tests)."""
        return self._transport

    @property
    def emulator(self) -> EmulatorControls | None:
        """Inputs, switches and faults of an emulated valve (None for a real one)."""
        from prm9tool.device.usb.transport.emulator import EmulatorTransport

        if not isinstance(self._transport, EmulatorTransport):
            return None
        return EmulatorControls(self._transport)

    @property
    def closed(self) -> bool:
        """True once the transport is closed."""
        return self._transport.closed

    def identify(self) -> DeviceInfo:
        """Ask the valve who it is; refuses a valve speaking another protocol version."""
        reply = self._call(Identify(), IdentifyReply)
        if reply.protocol_version != PROTOCOL_VERSION:
            raise ProtocolError(
                f"the valve speaks USB protocol version {reply.protocol_version}; "
                f"this prm9tool speaks version {PROTOCOL_VERSION}"
            )
        return DeviceInfo(
            type_key=reply.type_key,
            serial=reply.serial,
            firmware=reply.firmware,
            protocol_version=reply.protocol_version,
            device_id=self._device_id,
        )

    def _read_entries(
        self, params: Sequence[Parameter], steps: Steps | None, cancel: threading.Event | None
    ) -> dict[str, Value | SdoAbortError]:
        return self._entries.read(params, steps, cancel)

    def _write_entries(
        self,
        params: Sequence[Parameter],
        values: Mapping[str, Value],
        steps: Steps | None,
        cancel: threading.Event | None,
    ) -> int:
        return self._entries.write(params, values, steps, cancel)

    # --- commands -------------------------------------------------------------------------
    def store(self) -> None:
        """Make the working parameters permanent (non-volatile memory)."""
        self._call(Store(), Done)

    def reload(self) -> None:
        """Working parameters ← the stored ones (the protocol's RELOAD, no restart)."""
        self._call(Reload(), Done)

    def restore_factory(self) -> None:
        """Reset the stored parameters to factory values; effective after :meth:`restart`."""
        self._call(RestoreFactory(), Done)

    def restart(self) -> None:
        """Power-cycle the valve's electronics and reconnect (only with hydraulics off)."""
        self._call(Restart(), Done)
        self._stream.forget()
        self._transport.reconnect()

    def status(self) -> ValveStatus:
        """Device state, errors, LEDs, temperature and supply voltage."""
        reply = self._call(StatusRequest(0), StatusReply)
        text = bytearray(reply.text_chunk)
        for _ in range(16):
            if len(text) >= reply.text_total:
                break
            more = self._call(StatusRequest(len(text)), StatusReply)
            if more.text_total != reply.text_total or more.text_offset != len(text):
                reply, text = more, bytearray()  # the error changed meanwhile: start over
                continue
            text += more.text_chunk
        return _status(reply, text.decode("utf-8", errors="replace"))

    def nmt(self, command: int) -> None:
        """Send an NMT command (:class:`~prm9tool.catalogue.commissioning.NmtCommand`) to the
        valve, as its CANopen master would (manual §7.2): start, stop, pre-operational, reset.
        A valve with CANopen switched off ignores it."""
        self._call(Nmt(int(command)), Done)

    # --- streaming ------------------------------------------------------------------------
    def stream_start(self, keys: Sequence[str], rate_hz: int = 5000) -> None:
        """Stream up to three measuring points (signals.py keys) at ``rate_hz``."""
        self._stream.start(keys, rate_hz)

    def stream_read(self) -> np.ndarray:
        """Samples received since the last call: shape (n, len(keys)), raw values."""
        return self._stream.read()

    @property
    def samples_lost(self) -> int:
        """Samples lost since :meth:`stream_start` (gaps in the stream sequence numbers)."""
        return self._stream.lost

    def stream_stop(self) -> None:
        """Stop streaming."""
        self._stream.stop()

    def _close_link(self) -> None:
        try:
            if self._stream.running:
                self._stream.stop()
        except CommunicationError:
            pass
        self._transport.close()

    def _call(self, request: Request, expected: type[R]) -> R:
        reply = self._transport.request(request)
        if isinstance(reply, AbortReply):
            raise SdoAbortError(reply.index, reply.subindex, reply.code)
        if not isinstance(reply, expected):
            raise ProtocolError(
                f"the valve answered {type(request).__name__} with {type(reply).__name__}"
            )
        return reply


def _status(reply: StatusReply, text: str) -> ValveStatus:
    try:
        state = DeviceState(reply.device_state)
    except ValueError:
        raise ProtocolError(f"the valve reported an unknown state {reply.device_state!r}") from None
    return ValveStatus(
        device_state=state,
        error_code=reply.error_code,
        error_text=text,
        warning=reply.warning,
        active_errors=reply.active_errors,
        error_register=reply.error_register,
        leds=tuple(LedState(color=c, pattern=p, lit=lit) for c, p, lit in reply.leds),  # type: ignore[arg-type]
        temperature_c=reply.temperature_c,
        supply_v=reply.supply_v,
        nmt_state=reply.nmt_state,
        booting=reply.booting,
    )

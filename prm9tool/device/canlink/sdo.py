"""SDO access to one node, with prm9tool's errors.

The transfers are the master's own, exact and bounded (prm9tool.device.canlink.sdo_transfer);
the ``canopen`` package's client only delivers the node's answers. This module maps the
outcomes: an abort is an :class:`SdoAbortError` with the CiA 301 code, an answer the master
had to abort a :class:`SdoTransferError` (a ProtocolError) saying why, no answer a
:class:`DeviceTimeoutError` naming node and object, a bus that refuses to send a
:class:`DeviceDisconnectedError` — :class:`CanBusOffError` when the adapter is bus-off, which
is also why no answer can arrive then. The size bound of each upload is the catalogue's
(:func:`max_bytes`).
"""

from __future__ import annotations

import threading
from typing import TYPE_CHECKING, Protocol

from prm9tool.catalogue import CATALOGUE, Parameter
from prm9tool.device.canlink.sdo_transfer import (
    DEFAULT_MAX_BYTES,
    CanopenPort,
    SdoPort,
    SdoTransfer,
    SdoTransferError,
)
from prm9tool.errors import (
    AbortCode,
    CanBusOffError,
    DeviceDisconnectedError,
    DeviceTimeoutError,
    ProtocolError,
)

if TYPE_CHECKING:
    import canopen

STRING_MAX_BYTES = 255  # the longest VISIBLE_STRING of a PRM9 (names, versions: ≤ 40 chars)
__all__ = ["MISSING", "SdoChannel", "SdoTransferError", "decoded", "max_bytes"]
MISSING = frozenset({AbortCode.NO_SUCH_OBJECT, AbortCode.NO_SUCH_SUBINDEX})
PRM9_DEVICE_TYPE = 0x198  # 0x1000: CiA 408 (manual table 7-5)
ARGO_HYTOS_VENDOR = 0xE6  # 0x1018/1 (manual §7.6 step 2)


class BusHealth(Protocol):
    """What the bus tells about itself (``bus.CanNetwork``)."""

    @property
    def error_frames(self) -> int:
        """Error frames seen on the bus so far."""

    def is_bus_off(self, refusal: BaseException | None = None) -> bool:
        """Whether the adapter is off the bus (``refusal``: its error on sending)."""


class SdoChannel:
    """Serialized SDO uploads and downloads to one node."""

    def __init__(
        self,
        node: canopen.RemoteNode,
        timeout_s: float,
        bus: BusHealth | None = None,
        port: SdoPort | None = None,
    ) -> None:
        """``bus``: its error frames are named in a timeout (a wrong bit rate shows as error
        frames and no answers), its bus-off makes a timeout or a refusal a CanBusOffError.
        ``port``: where the frames go (default: the node's COB-IDs through ``canopen``)."""
        self.node = node
        self._bus = bus
        self.timeout_s = timeout_s
        self.transfer = SdoTransfer(port or CanopenPort(node), node.id or 0)
        # one lock per node object: a scan and the session may share the node's SDO client
        self._lock: threading.Lock = node.__dict__.setdefault(
            "_prm9tool_sdo_lock", threading.Lock()
        )
        self.requests = 0  # SDO transfers started (statistics, benchmarks)

    def upload(self, index: int, subindex: int, timeout_s: float | None = None) -> bytes:
        """Read an object's bytes (SdoAbortError, DeviceTimeoutError)."""
        return self._run(index, subindex, None, timeout_s)

    def download(
        self, index: int, subindex: int, data: bytes, timeout_s: float | None = None
    ) -> None:
        """Write an object's bytes (SdoAbortError, DeviceTimeoutError)."""
        self._run(index, subindex, data, timeout_s)

    def _run(self, index: int, subindex: int, data: bytes | None, timeout_s: float | None) -> bytes:
        import can

        answer_s = timeout_s or self.timeout_s
        with self._lock:
            self.requests += 1
            try:
                if data is None:
                    bound = max_bytes(index, subindex)
                    return self.transfer.upload(index, subindex, bound, answer_s)
                self.transfer.download(index, subindex, data, answer_s)
                return b""
            except DeviceTimeoutError as exc:
                self._raise_if_bus_off(exc)
                raise DeviceTimeoutError(f"{exc}; {self._what_to_check()}") from None
            except (can.CanError, OSError, RuntimeError) as exc:  # RuntimeError: bus closed
                self._raise_if_bus_off(exc)
                raise DeviceDisconnectedError(
                    f"node {self.node.id}: the CAN bus refused to send ({exc})"
                ) from None

    def _raise_if_bus_off(self, exc: Exception) -> None:
        if self._bus is not None and self._bus.is_bus_off(exc):
            raise CanBusOffError(
                f"node {self.node.id}: the CAN adapter is bus-off ({exc})"
            ) from None

    def _what_to_check(self) -> str:
        answers = self.transfer.stats.frames
        if answers:  # it answered, then stopped: not a question of power or bit rate
            return (
                f"the node answered {answers} frames of this transfer and then stopped "
                "(it restarted, or its firmware is faulty)"
            )
        errors = self._bus.error_frames if self._bus is not None else 0
        if errors:
            return (
                f"the bus saw {errors} error frames: check that the bit rate is the valve's "
                "(delivery state 500 kbit/s) and the bus is terminated"
            )
        return "is the valve powered, on this bus, at this bit rate?"

    def read_u32(self, index: int, subindex: int) -> int:
        """An UNSIGNED32 (or shorter) object as a number (ProtocolError for another size)."""
        data = self.upload(index, subindex)
        if not 1 <= len(data) <= 4:
            raise ProtocolError(
                f"node {self.node.id}: 0x{index:04X}/{subindex} answered {len(data)} bytes for "
                "an UNSIGNED32"
            )
        return int.from_bytes(data, "little")

    def read_text(self, index: int, subindex: int = 0) -> str:
        """A VISIBLE_STRING object."""
        return self.upload(index, subindex).split(b"\0", 1)[0].decode("latin-1")

    @property
    def strays(self) -> int:
        """Answers that came when none was asked for (a second node at this node ID, or the
        late answer of a transfer that timed out: :attr:`timeouts`)."""
        return self.transfer.stats.strays

    @property
    def timeouts(self) -> int:
        """Transfers that ended without an answer."""
        return self.transfer.stats.timeouts

    def take_strays(self) -> int:
        """Drop the answers waiting now that no transfer asked for; how many there were
        (counted in :attr:`strays`)."""
        with self._lock:
            stale = self.transfer.port.drain()
            self.transfer.stats.strays += stale
            return stale


def max_bytes(index: int, subindex: int) -> int:
    """The size bound of an upload: the catalogue's type size (at least the 4 bytes of an
    expedited answer: some nodes answer a short type in 4), a string's
    :data:`STRING_MAX_BYTES`, :data:`DEFAULT_MAX_BYTES` for an object it does not know."""
    param = CATALOGUE.by_address(index, subindex)
    if param is None:
        return DEFAULT_MAX_BYTES
    return STRING_MAX_BYTES if param.is_string else max(param.dtype.size, 4)


def decoded(param: Parameter, data: bytes) -> int:
    """The number ``data`` holds as ``param``'s type: ProtocolError when it has too few bytes,
    or more whose value is not that number (an expedited answer may pad a short type to 4
    bytes, with zeros or its top bit extended; anything else in them is no value of the
    type)."""
    dtype = param.dtype
    size = dtype.size
    if len(data) < size:
        raise ProtocolError(f"{param.mnemonic}: {len(data)} bytes for a {dtype.name}")
    value = int(dtype.decode(data[:size]))
    rest = data[size:]
    padding = b"\xff" if data[size - 1] & 0x80 else b"\0"  # zeros or the sign extended
    if rest and rest not in (bytes(len(rest)), padding * len(rest)):
        raise ProtocolError(
            f"{param.mnemonic}: the answer 0x{data[::-1].hex().upper()} is no {dtype.name}"
        )
    return value

"""SDO access to one node through the ``canopen`` package's client, with prm9tool's errors.

The ``canopen`` package does the SDO protocol (expedited and segmented); this module only
maps its outcomes: an abort is an :class:`SdoAbortError` with the CiA 301 code, no answer a
:class:`DeviceTimeoutError` naming node and object, a bus that refuses to send a
:class:`DeviceDisconnectedError` — :class:`CanBusOffError` when the adapter is bus-off, which
is also why no answer can arrive then.
"""

from __future__ import annotations

import threading
from typing import TYPE_CHECKING, Protocol

from prm9tool.errors import (
    AbortCode,
    CanBusOffError,
    DeviceDisconnectedError,
    DeviceTimeoutError,
    SdoAbortError,
)

if TYPE_CHECKING:
    import canopen

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
    ) -> None:
        """``bus``: its error frames are named in a timeout (a wrong bit rate shows as error
        frames and no answers), its bus-off makes a timeout or a refusal a CanBusOffError."""
        self.node = node
        self._bus = bus
        self.timeout_s = timeout_s
        self.node.sdo.RESPONSE_TIMEOUT = timeout_s
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
        import canopen

        sdo = self.node.sdo
        with self._lock:
            self.requests += 1
            sdo.RESPONSE_TIMEOUT = timeout_s or self.timeout_s
            try:
                if data is None:
                    return bytes(sdo.upload(index, subindex))
                sdo.download(index, subindex, data)
                return b""
            except canopen.SdoAbortedError as exc:
                raise SdoAbortError(index, subindex, exc.code) from None
            except canopen.SdoCommunicationError as exc:
                self._raise_if_bus_off(exc)
                raise DeviceTimeoutError(
                    f"node {self.node.id}: no SDO answer for 0x{index:04X}/{subindex} within "
                    f"{sdo.RESPONSE_TIMEOUT:g} s ({exc}); {self._what_to_check()}"
                ) from None
            except (can.CanError, OSError) as exc:
                self._raise_if_bus_off(exc)
                raise DeviceDisconnectedError(
                    f"node {self.node.id}: the CAN bus refused to send ({exc})"
                ) from None
            finally:
                sdo.RESPONSE_TIMEOUT = self.timeout_s

    def _raise_if_bus_off(self, exc: Exception) -> None:
        if self._bus is not None and self._bus.is_bus_off(exc):
            raise CanBusOffError(
                f"node {self.node.id}: the CAN adapter is bus-off ({exc})"
            ) from None

    def _what_to_check(self) -> str:
        errors = self._bus.error_frames if self._bus is not None else 0
        if errors:
            return (
                f"the bus saw {errors} error frames: check that the bit rate is the valve's "
                "(delivery state 500 kbit/s) and the bus is terminated"
            )
        return "is the valve powered, on this bus, at this bit rate?"

    def read_u32(self, index: int, subindex: int) -> int:
        """An UNSIGNED32 (or shorter) object as a number."""
        return int.from_bytes(self.upload(index, subindex)[:4], "little")

    def read_text(self, index: int, subindex: int = 0) -> str:
        """A VISIBLE_STRING object."""
        return self.upload(index, subindex).split(b"\0", 1)[0].decode("latin-1")

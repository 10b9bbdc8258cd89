"""The measuring-point stream over CANopen: the CANopen link's counterpart of
:mod:`prm9tool.device.usb.stream`.

TPDO1 at a SYNC the tool produces when the keys are its mapped value and the node is
OPERATIONAL (:class:`~prm9tool.device.canlink.pdo_scope.PdoSampler`), else SDO reads
(:class:`~prm9tool.device.canlink.sampler.SdoSampler`); what the bus does not deliver counts
as lost. The valve reports no demand value over CANopen: the demand channel is the setpoint
this tool sends in RPDO1 (:attr:`CanStream.sent_setpoint`, set by
:mod:`~prm9tool.device.canlink.rpdo_setpoint`).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

import numpy as np

from prm9tool.device.canlink.bus import CanNetwork
from prm9tool.device.canlink.pdo_scope import NotPdoMappedError, PdoSampler
from prm9tool.device.canlink.sampler import SdoSampler
from prm9tool.device.canlink.sdo import SdoChannel


class CanStream:
    """The stream of one node: ``shared()`` its bus, ``sdo()`` its channel now (a restart may
    move both)."""

    def __init__(self, shared: Callable[[], CanNetwork], sdo: Callable[[], SdoChannel]) -> None:
        self._shared, self._sdo = shared, sdo
        self._sampler: SdoSampler | PdoSampler | None = None
        self.source = ""  # "pdo" or "sdo" while a stream runs
        # the setpoint this tool sends in RPDO1 now (measuring-point key, raw), None when it
        # does not drive the valve: the oscilloscope's demand channel over CAN
        self.sent_setpoint: tuple[str, float] | None = None

    def start(self, keys: Sequence[str], rate_hz: int) -> None:
        """Sample ``keys`` at ``rate_hz`` (a running stream stops first)."""
        self.stop()
        sdo = self._sdo()
        try:
            self._sampler = PdoSampler(self._shared(), sdo, keys, rate_hz, self._demand)
            self.source = "pdo"
        except NotPdoMappedError:
            self._sampler = SdoSampler(sdo.upload, keys, rate_hz, self._demand)
            self.source = "sdo"

    def _demand(self, key: str) -> float:
        """The setpoint this tool sends now as measuring point ``key`` (NaN: it sends none,
        or another one)."""
        sent = self.sent_setpoint
        return sent[1] if sent is not None and sent[0] == key else float("nan")

    def read(self) -> np.ndarray:
        """Samples taken since the last call: shape (n, len(keys)), raw values."""
        if self._sampler is None:
            return np.empty((0, 1))
        return self._sampler.read()

    @property
    def lost(self) -> int:
        """Sample periods the bus could not serve since :meth:`start`."""
        return self._sampler.lost if self._sampler is not None else 0

    @property
    def achieved_hz(self) -> float:
        """The rate the running stream really achieves (0 when none runs)."""
        return self._sampler.achieved_hz if self._sampler is not None else 0.0

    def stop(self) -> None:
        """Stop sampling (nothing when none runs)."""
        sampler, self._sampler = self._sampler, None
        self.source = ""
        if sampler is not None:
            sampler.stop()

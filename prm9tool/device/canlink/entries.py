"""Reading and writing parameters over CANopen, one SDO transfer each, by the catalogue's
object address: the CANopen link's counterpart of :mod:`prm9tool.device.usb.entries`.

An object the valve does not have (abort 0x06020000/0x06090011; on a real valve the objects
this project decided on) makes the parameter "not available over CANopen on this valve": it is
skipped and added to the session's ``unavailable``. What was read or written last is kept in
the upload's state (:class:`~prm9tool.device.canlink.upload_steps.CanopenUploadSteps`
``known``), and during an upload a value its snapshot shows the valve holding already is not
sent (the decisions in :mod:`prm9tool.device.canlink.upload_steps`).
"""

from __future__ import annotations

import threading
from collections.abc import Callable, Mapping, Sequence

from prm9tool.catalogue import Parameter
from prm9tool.device.canlink.sdo import MISSING, SdoChannel, decoded
from prm9tool.device.canlink.upload_steps import CanopenUploadSteps
from prm9tool.device.records import RefusedError, Steps, Value, check_cancel
from prm9tool.errors import SdoAbortError


class SdoEntries:
    """Many-entry reads and writes through ``sdo()``, the node's channel now (a restart may
    move it), noting what the valve lacks in ``unavailable`` and what it holds in ``upload``."""

    def __init__(
        self, sdo: Callable[[], SdoChannel], unavailable: set[str], upload: CanopenUploadSteps
    ) -> None:
        self._sdo = sdo
        self._unavailable = unavailable
        self._upload = upload

    def read(
        self, params: Sequence[Parameter], steps: Steps | None, cancel: threading.Event | None
    ) -> dict[str, Value | SdoAbortError]:
        """{mnemonic: value, or the abort that refused it}; what the valve lacks is left out."""
        step = steps.step if steps else "read"
        results: dict[str, Value | SdoAbortError] = {}
        for param in params:
            check_cancel(cancel, step)
            if param.mnemonic not in self._unavailable:
                outcome = self._read_one(param)
                if outcome is not None:
                    results[param.mnemonic] = outcome
            if steps:
                steps.advance(1)
        return results

    def _read_one(self, param: Parameter) -> Value | SdoAbortError | None:
        try:
            data = self._sdo().upload(param.index, param.subindex)
        except SdoAbortError as exc:
            if exc.code in MISSING:
                self._unavailable.add(param.mnemonic)
                return None
            return exc
        if param.is_string:
            value: Value = data.split(b"\0", 1)[0].decode("latin-1")
        else:
            value = decoded(param, data)
        self._upload.known[param.mnemonic] = value
        return value

    def write(
        self,
        params: Sequence[Parameter],
        values: Mapping[str, Value],
        steps: Steps | None,
        cancel: threading.Event | None,
    ) -> int:
        """Write ``values``; the number written or held already. A refusal raises
        :class:`RefusedError` with the count done before it."""
        done = 0
        upload = self._upload
        holds = upload.snapshot or {}  # during an upload: what the valve holds already
        for param in params:
            check_cancel(cancel, "write")
            if holds.get(param.mnemonic, holds) == values[param.mnemonic]:
                done += 1  # the valve holds it: not sent (the verify step reads it back)
            elif param.mnemonic not in self._unavailable:
                done += self._write_one(param, values[param.mnemonic], done)
            if steps:
                steps.advance(1)
        return done

    def _write_one(self, param: Parameter, value: Value, done: int) -> int:
        """1 when written, 0 when the valve lacks the object."""
        upload = self._upload
        try:
            upload.known.pop(param.mnemonic, None)  # unknown if the answer is lost
            self._sdo().download(param.index, param.subindex, param.dtype.encode(value))
        except SdoAbortError as exc:
            if exc.code not in MISSING:
                raise RefusedError(param.mnemonic, exc, done) from exc
            self._unavailable.add(param.mnemonic)
            return 0
        upload.known[param.mnemonic] = value
        upload.touched.append(param.mnemonic)
        return 1

"""The upload's steps over CANopen that differ from the USB link's: the snapshot for putting
the working values back, the writes left out, the verify that corrects them and how the store
is made sure of (see the decisions in prm9tool.device.canlink.session). A mixin of
:class:`~prm9tool.device.canlink.session.CanopenSession`, which owns the state it uses.
"""

from __future__ import annotations

import threading
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING

from prm9tool.catalogue import Parameter
from prm9tool.device.records import RefusedError, Steps, Value
from prm9tool.device.upload_outcome import RESTARTED_BEFORE_STORE
from prm9tool.errors import Prm9Error, SdoAbortError

if TYPE_CHECKING:
    from prm9tool.device.canlink.bus import CanNetwork


class UploadSteps:
    """The CANopen session's upload hooks (ValveSession's ``_before_upload`` … ``reload``)."""

    _snapshot: dict[str, Value] | None
    _touched: list[str]
    _known: dict[str, Value]
    _shared: CanNetwork
    node_id: int

    if TYPE_CHECKING:  # CanopenSession and ValveSession provide these

        def _read_entries(
            self, params: Sequence[Parameter], steps: Steps | None, cancel: threading.Event | None
        ) -> dict[str, Value | SdoAbortError]: ...

        def _write_entries(
            self,
            params: Sequence[Parameter],
            values: Mapping[str, Value],
            steps: Steps | None,
            cancel: threading.Event | None,
        ) -> int: ...

        def _param(self, mnemonic: str) -> Parameter: ...

    def _before_upload(self, params: Sequence[Parameter], cancel: threading.Event | None) -> None:
        """The snapshot that :meth:`reload` writes back after a failed upload: the working
        values this session read or wrote last (a download before the upload, the backup, going
        online), the others read now."""
        self._snapshot, self._touched = {}, []
        unknown = [p for p in params if p.mnemonic not in self._known]
        read = self._read_entries(unknown, None, cancel)
        known = {p.mnemonic: self._known[p.mnemonic] for p in params if p.mnemonic in self._known}
        fresh = {m: v for m, v in read.items() if not isinstance(v, SdoAbortError)}
        self._snapshot = known | fresh

    def _verify_entries(
        self,
        params: Sequence[Parameter],
        values: Mapping[str, Value],
        steps: Steps | None,
        cancel: threading.Event | None,
    ) -> dict[str, Value | SdoAbortError]:
        """Every value read back; one that was not sent (the snapshot said the valve held it)
        but reads back otherwise is written now and read back again."""
        actual = self._read_entries(params, steps, cancel)
        sent = set(self._touched)
        stale = [
            p
            for p in params
            if p.mnemonic in actual
            and p.mnemonic not in sent
            and not isinstance(actual[p.mnemonic], SdoAbortError)
            and actual[p.mnemonic] != values[p.mnemonic]
        ]
        if stale and self._snapshot is not None:
            self._snapshot.update({p.mnemonic: actual[p.mnemonic] for p in stale})  # type: ignore[misc]
            self._write_entries(stale, values, None, cancel)
            actual.update(self._read_entries(stale, None, cancel))
        return actual

    def _restart_marker(self) -> object:
        """Boot-ups heard from the node so far (a restart adds one)."""
        return self._shared.node_seen(self.node_id).boot_ups

    def _store_problem(
        self, params: Sequence[Parameter], values: Mapping[str, Value], marker: object
    ) -> tuple[dict[str, tuple[Value, Value]], str] | None:
        """No boot-up since before the first write, and the last value the upload changed
        reads back as uploaded (the module's decision)."""
        if self._shared.node_seen(self.node_id).boot_ups != marker:
            return {}, (
                "the valve restarted (its boot-up frame) during the upload: it stored its "
                "previous set, not the upload"
            )
        sample = [p for p in params if p.mnemonic == (self._touched or [""])[-1]]
        after = self._read_entries(sample, None, None)
        changed: dict[str, tuple[Value, Value]] = {
            p.mnemonic: (values[p.mnemonic], str(after.get(p.mnemonic)))
            for p in sample
            if after.get(p.mnemonic) != values[p.mnemonic]
        }
        return (changed, RESTARTED_BEFORE_STORE) if changed else None

    def reload(self) -> None:
        """Working values ← those read before the upload, for the parameters it wrote (see
        the module's decision); the stored set was never touched."""
        if self._snapshot is None:
            raise Prm9Error(
                "over CANopen the stored parameters come back only with a restart (NMT reset node)"
            )
        touched = set(self._touched)
        snapshot = {m: v for m, v in self._snapshot.items() if m in touched}
        self._snapshot, self._touched = None, []
        params = [self._param(m) for m in snapshot]
        try:
            self._write_entries(params, snapshot, None, None)
        except RefusedError as refused:
            raise refused.error from None

"""The upload's steps over CANopen that differ from the USB link's: the snapshot for putting
the working values back, the writes left out, the verify that corrects them and how the store
is made sure of (see the decisions in prm9tool.device.canlink.session). A mixin of
:class:`~prm9tool.device.canlink.session.CanopenSession`, which owns the state it uses.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING

from prm9tool.catalogue import Parameter
from prm9tool.catalogue.manual_od import NOT_KEPT_AFTER_RESTART
from prm9tool.catalogue.variant import Variant
from prm9tool.device.canlink.storing import (
    KEPT_AS_WRITTEN,
    VERIFIED_RESTART,
    safe_order,
    store_kind,
)
from prm9tool.device.records import RefusedError, Steps, Value
from prm9tool.device.upload_outcome import RESTARTED_BEFORE_STORE, differences
from prm9tool.errors import CommunicationError, Prm9Error, SdoAbortError

if TYPE_CHECKING:
    from prm9tool.device.canlink.bus import CanNetwork
    from prm9tool.device.canlink.sdo import SdoChannel

BOOT_WAIT_S = 10.0  # NMT reset node / power-up → answering again (the valve takes ~2 s, §7.6)


class UploadSteps:
    """The CANopen session's upload hooks (ValveSession's ``_before_upload`` … ``reload``)."""

    _snapshot: dict[str, Value] | None
    _stored_backup: dict[str, Value] | None
    _touched: list[str]
    _known: dict[str, Value]
    _shared: CanNetwork
    node_id: int
    variant: Variant
    store_done: str | None
    _store: str | None = None  # how this valve keeps parameters (canlink.storing), once known
    verify_by_restart = False  # after the store: NMT reset node, then read every value back
    _restarted = False  # that restart found the store not kept (ValveSession._restarted)

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

        @property
        def sdo(self) -> SdoChannel: ...

        def restart(self) -> None: ...

    def _before_upload(self, params: Sequence[Parameter], cancel: threading.Event | None) -> None:
        """The snapshot that :meth:`reload` writes back after a failed upload: the working
        values this session read or wrote last (a download before the upload, the backup, going
        online), the others read now. First: how the valve keeps parameters (a valve that
        cannot store refuses the upload here, before anything is written)."""
        self._store = store_kind(self.sdo)
        self._restarted = False
        self.store_done = self._store if self._kept else None  # each write is kept as it lands
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

    @property
    def _kept(self) -> bool:
        return self._store == KEPT_AS_WRITTEN

    def _write_order(self, params: list[Parameter], values: Mapping[str, Value]) -> list[Parameter]:
        """On a valve that keeps every write: an order that never leaves a refused set."""
        if not self._kept or self._snapshot is None:
            return params
        return safe_order(self.variant, params, self._snapshot, values)

    def _restart_marker(self) -> object:
        """Boot-ups heard from the node so far (a restart adds one)."""
        return self._shared.node_seen(self.node_id).boot_ups

    def _store_problem(
        self, params: Sequence[Parameter], values: Mapping[str, Value], marker: object
    ) -> tuple[dict[str, tuple[Value, Value]], str] | None:
        """No boot-up since before the first write, and the last value the upload changed
        reads back as uploaded (the module's decision). A valve that keeps every write has
        kept each value as it landed (the verify read them all). Then, if asked, the restart
        verification."""
        if self._kept:
            return self._restart_check(params, values)
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
        return (changed, RESTARTED_BEFORE_STORE) if changed else self._restart_check(params, values)

    def _restart_check(
        self, params: Sequence[Parameter], values: Mapping[str, Value]
    ) -> tuple[dict[str, tuple[Value, Value]], str] | None:
        """With :attr:`verify_by_restart`: NMT reset node, then every value read back."""
        if not self.verify_by_restart:
            return None
        self.restart()
        actual = self._read_entries(params, None, None)
        changed = differences([p for p in params if p.mnemonic in actual], values, actual)
        if changed:
            if self._kept:  # each write is durable: the backup goes back as after any failure
                self._snapshot = self._stored_backup
            else:  # the restart put the stored set into the working values: nothing to put
                # back — writing the backup without a store would leave a set it does not keep
                self._snapshot, self._restarted = {}, True
            return changed, NOT_KEPT_AFTER_RESTART
        self.store_done = VERIFIED_RESTART
        return None

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
        if self._kept:
            self._put_back(params, snapshot)
            return
        try:
            self._write_entries(params, snapshot, None, None)
        except RefusedError as refused:
            raise refused.error from None

    def _put_back(self, params: list[Parameter], backup: dict[str, Value]) -> None:
        """A valve that keeps every write: the backup's values written back in a safe order
        and read back; Prm9Error says exactly what the valve holds where that fails."""
        written = {m: self._known.get(m, "?") for m in backup}  # what the upload left
        try:
            self._await_answer()
            now = self._read_entries(params, None, None)
            holds = {m: v for m, v in now.items() if not isinstance(v, SdoAbortError)}
            ordered = safe_order(self.variant, params, holds, backup)
            refused = ""
            try:
                self._write_entries(ordered, backup, None, None)
            except RefusedError as exc:
                refused = f"{exc.mnemonic} refused ({exc.error}); "
            after = self._read_entries(params, None, None)
        except CommunicationError as exc:
            shown = ", ".join(f"{m} = {v}" for m, v in written.items())
            raise Prm9Error(
                f"the valve does not answer ({exc}); as it keeps every write it holds what the "
                f"upload wrote ({shown}) and its previous values for the rest"
            ) from exc
        wrong = {m: after.get(m) for m in backup if after.get(m) != backup[m]}
        if wrong:
            shown = "; ".join(
                f"{m} = {v} (before the upload {backup[m]})" for m, v in wrong.items()
            )
            raise Prm9Error(f"{refused}the valve holds: {shown}; every other value as before")

    def _await_answer(self) -> None:
        """Until the node answers again (it may be restarting: power dip, NMT reset)."""
        deadline = time.monotonic() + BOOT_WAIT_S
        while True:
            try:
                self.sdo.upload(0x1000, 0)
                return
            except CommunicationError:
                if time.monotonic() > deadline:
                    raise

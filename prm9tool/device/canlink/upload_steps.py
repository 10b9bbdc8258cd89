"""The upload's steps over CANopen that differ from the USB link's: the snapshot for putting
the working values back, the writes left out, the verify that corrects them and how the store
is made sure of (the decisions below). A part the
:class:`~prm9tool.device.canlink.session.CanopenSession` holds as its
:attr:`~prm9tool.device.session.ValveSession.upload_steps`; it owns the upload's state, the
session its SDO channel and the bus.

**Decision (reverting a failed upload).** CiA 301 has no "reload the stored set into RAM"
short of resetting the node, which power-cycles the electronics and drops the spool. So
before an upload writes anything the session reads the working values of the parameters it is
going to write (a snapshot) and, after a failed upload, writes them back: the valve then runs
on with the values it had, its stored set untouched, and nothing moves. The snapshot costs one
SDO read per parameter, except for the values this session read or wrote last (the batch's
backup and the GUI's going online read them all): docs/can-link.md, docs/PERFORMANCE.md.

**Decision (fewer frames, the same guarantees).** An upload does not send a value the snapshot
shows the valve holding already (the verify step reads every value back all the same, and one
that reads back otherwise is written and verified after all); and it makes sure of the store
not by reading every value once more but by watching for the node's boot-up frame — which a
node sends whenever it restarts (CiA 301) — from before the first write until the store's
acknowledgement, plus one read-back of a value the upload changed. A valve that restarted
before the store stored its old set, and said so on the bus.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable, Mapping, Sequence

from prm9tool.catalogue import Parameter
from prm9tool.catalogue.manual_od import NOT_KEPT_AFTER_RESTART
from prm9tool.device.canlink.sdo import SdoChannel
from prm9tool.device.canlink.storing import (
    KEPT_AS_WRITTEN,
    VERIFIED_RESTART,
    safe_order,
    store_kind,
)
from prm9tool.device.records import RefusedError, Steps, Value
from prm9tool.device.session import UploadSteps, ValveSession
from prm9tool.device.upload_outcome import RESTARTED_BEFORE_STORE, differences
from prm9tool.errors import CommunicationError, Prm9Error, SdoAbortError

BOOT_WAIT_S = 10.0  # NMT reset node / power-up → answering again (the valve takes ~2 s, §7.6)


class CanopenUploadSteps(UploadSteps):
    """The CANopen session's steps of the upload (:class:`UploadSteps`), with the state they
    keep between the session's reads, writes and store: ``sdo()`` is the node's channel now
    (a restart may move it), ``boot_ups()`` the boot-ups heard from it, ``refusal()`` the
    session's last word before anything is written (None: go on)."""

    def __init__(
        self,
        session: ValveSession,
        sdo: Callable[[], SdoChannel],
        boot_ups: Callable[[], int],
        refusal: Callable[[], Prm9Error | None],
    ) -> None:
        super().__init__(session)
        self._sdo, self._boot_ups, self._refusal = sdo, boot_ups, refusal
        self.snapshot: dict[str, Value] | None = None  # None: no upload is running
        self._stored_backup: dict[str, Value] | None = None  # the snapshot of the last store
        self.touched: list[str] = []  # parameters the running upload wrote
        self.known: dict[str, Value] = {}  # the valve's working values as last read/written
        self._store: str | None = None  # how this valve keeps parameters (storing), once known

    def store_kind(self) -> str:
        """How this valve keeps parameters (prm9tool.device.canlink.storing), asked once."""
        self._store = self._store or store_kind(self._sdo())
        return self._store

    def stored(self) -> None:
        """The store was acknowledged: nothing to put back any more — unless the restart
        verification finds the valve did not keep the upload (:meth:`_restart_check`)."""
        self._stored_backup, self.snapshot = self.snapshot, None

    def before(self, params: Sequence[Parameter], cancel: threading.Event | None) -> None:
        """The snapshot that :meth:`reload` writes back after a failed upload: the working
        values this session read or wrote last (a download before the upload, the backup, going
        online), the others read now. First: how the valve keeps parameters (a valve that
        cannot store refuses the upload here, before anything is written). Last: the
        session's refusal (a type key given for a valve that lacks its objects)."""
        self._store = store_kind(self._sdo())
        self.restarted = False
        session = self._session
        session.store_done = self._store if self.kept else None  # each write kept as it lands
        self.snapshot, self.touched = {}, []
        unknown = [p for p in params if p.mnemonic not in self.known]
        read = session._read_entries(unknown, None, cancel)
        known = {p.mnemonic: self.known[p.mnemonic] for p in params if p.mnemonic in self.known}
        fresh = {m: v for m, v in read.items() if not isinstance(v, SdoAbortError)}
        self.snapshot = known | fresh
        refusal = self._refusal()
        if refusal is not None:
            self.snapshot = None  # nothing was written: nothing to put back
            raise refusal

    def verify(
        self,
        params: Sequence[Parameter],
        values: Mapping[str, Value],
        steps: Steps | None,
        cancel: threading.Event | None,
    ) -> dict[str, Value | SdoAbortError]:
        """Every value read back; one that was not sent (the snapshot said the valve held it)
        but reads back otherwise is written now and read back again."""
        session = self._session
        actual = session._read_entries(params, steps, cancel)
        sent = set(self.touched)
        stale = [
            p
            for p in params
            if p.mnemonic in actual
            and p.mnemonic not in sent
            and not isinstance(actual[p.mnemonic], SdoAbortError)
            and actual[p.mnemonic] != values[p.mnemonic]
        ]
        if stale and self.snapshot is not None:
            self.snapshot.update({p.mnemonic: actual[p.mnemonic] for p in stale})  # type: ignore[misc]
            session._write_entries(stale, values, None, cancel)
            actual.update(session._read_entries(stale, None, cancel))
        return actual

    @property
    def kept(self) -> bool:
        """True on a valve that keeps every write (no store command: manual table 7-13)."""
        return self._store == KEPT_AS_WRITTEN

    def order(self, params: list[Parameter], values: Mapping[str, Value]) -> list[Parameter]:
        """On a valve that keeps every write: an order that never leaves a refused set."""
        if not self.kept or self.snapshot is None:
            return params
        return safe_order(self._session.variant, params, self.snapshot, values)

    def marker(self) -> object:
        """Boot-ups heard from the node so far (a restart adds one)."""
        return self._boot_ups()

    def store_problem(
        self, params: Sequence[Parameter], values: Mapping[str, Value], marker: object
    ) -> tuple[dict[str, tuple[Value, Value]], str] | None:
        """No boot-up since before the first write, and the last value the upload changed
        reads back as uploaded (the module's decision). A valve that keeps every write has
        kept each value as it landed (the verify read them all). Then, if asked, the restart
        verification."""
        if self.kept:
            return self._restart_check(params, values)
        if self._boot_ups() != marker:
            return {}, (
                "the valve restarted (its boot-up frame) during the upload: it stored its "
                "previous set, not the upload"
            )
        sample = [p for p in params if p.mnemonic == (self.touched or [""])[-1]]
        after = self._session._read_entries(sample, None, None)
        changed: dict[str, tuple[Value, Value]] = {
            p.mnemonic: (values[p.mnemonic], str(after.get(p.mnemonic)))
            for p in sample
            if after.get(p.mnemonic) != values[p.mnemonic]
        }
        return (changed, RESTARTED_BEFORE_STORE) if changed else self._restart_check(params, values)

    def _restart_check(
        self, params: Sequence[Parameter], values: Mapping[str, Value]
    ) -> tuple[dict[str, tuple[Value, Value]], str] | None:
        """With the session's ``verify_by_restart``: NMT reset node, then every value read
        back."""
        session = self._session
        if not session.verify_by_restart:
            return None
        session.restart()
        actual = session._read_entries(params, None, None)
        changed = differences([p for p in params if p.mnemonic in actual], values, actual)
        if changed:
            if self.kept:  # each write is durable: the backup goes back as after any failure
                self.snapshot = self._stored_backup
            else:  # the restart put the stored set into the working values: nothing to put
                # back — writing the backup without a store would leave a set it does not keep
                self.snapshot, self.restarted = {}, True
            return changed, NOT_KEPT_AFTER_RESTART
        session.store_done = VERIFIED_RESTART
        return None

    def reload(self) -> None:
        """Working values ← those read before the upload, for the parameters it wrote (see
        the module's decision); the stored set was never touched."""
        if self.snapshot is None:
            raise Prm9Error(
                "over CANopen the stored parameters come back only with a restart (NMT reset node)"
            )
        touched = set(self.touched)
        snapshot = {m: v for m, v in self.snapshot.items() if m in touched}
        self.snapshot, self.touched = None, []
        params = [self._session._param(m) for m in snapshot]
        if self.kept:
            self._put_back(params, snapshot)
            return
        try:
            self._session._write_entries(params, snapshot, None, None)
        except RefusedError as refused:
            raise refused.error from None

    def _put_back(self, params: list[Parameter], backup: dict[str, Value]) -> None:
        """A valve that keeps every write: the backup's values written back in a safe order
        and read back; Prm9Error says exactly what the valve holds where that fails."""
        session = self._session
        written = {m: self.known.get(m, "?") for m in backup}  # what the upload left
        try:
            self._await_answer()
            now = session._read_entries(params, None, None)
            holds = {m: v for m, v in now.items() if not isinstance(v, SdoAbortError)}
            ordered = safe_order(session.variant, params, holds, backup)
            refused = ""
            try:
                session._write_entries(ordered, backup, None, None)
            except RefusedError as exc:
                refused = f"{exc.mnemonic} refused ({exc.error}); "
            after = session._read_entries(params, None, None)
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
                self._sdo().upload(0x1000, 0)
                return
            except CommunicationError:
                if time.monotonic() > deadline:
                    raise

"""One open valve as every front door uses it: :class:`ValveService`.

The GUI's worker thread (``online/connection.py``), the command line (``cli/``) and the Python
API (:class:`prm9tool.api.valve.Valve`) each hold a session of the device layer
(:class:`~prm9tool.device.session.ValveSession`) and run the operations below on it through
the valve's service: the checks of a user's value, the upload sequence, the history records,
who owns the valve's motion and what an NMT command this program sent means for the answers
that follow. One service per session (:func:`service_for`), so every door on one open valve
shares its state. No Qt.
"""

from __future__ import annotations

import os
import threading
import weakref
from collections.abc import Callable, Mapping
from pathlib import Path
from typing import TYPE_CHECKING

from prm9tool.catalogue import CAPPED_BY, CATALOGUE, Parameter
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.errors import CommunicationError, Prm9Error
from prm9tool.service import motion, upload
from prm9tool.service.commissioning import Commissioning
from prm9tool.service.rigs import characterize_session, profile_of, session_rig
from prm9tool.service.values import (
    ReadOnlyError,
    caps_held,
    check_rules,
    read_only_text,
    user_value,
)

if TYPE_CHECKING:
    from prm9tool.analysis.profile import Profile
    from prm9tool.characterize.drift import DriftReport
    from prm9tool.characterize.run import Characterization
    from prm9tool.device.records import Progress, UploadResult, Value, ValveStatus
    from prm9tool.device.session import ValveSession
    from prm9tool.history.recorder import Details
    from prm9tool.service.autotune import AutotuneOutcome, AutotuneSettings
    from prm9tool.service.history import HistoryHook
    from prm9tool.twin.fitvalve import ValveTwin

__all__ = ["ValveService", "service_for"]


def _in_catalogue_range(param: Parameter, raw: Value) -> bool:
    return not isinstance(raw, int) or param.raw_min <= raw <= param.raw_max


class ValveService:
    """The operations on one open valve, the same for every door.

    ``history``: the observer that records every operation (None: history off). Thread-safe
    as far as the link serializes its exchanges; the motion owner is thread-safe.
    """

    def __init__(self, session: ValveSession, history: HistoryHook | None = None) -> None:
        # weakly: service_for keeps one service per session without keeping the session alive
        self._session = weakref.ref(session)
        self.history = history
        self.motion = motion.owner_of(session)
        self.variant = TypeKey.parse(session.info.type_key).variant
        self._params = {p.mnemonic: p for p in CATALOGUE.for_variant(self.variant)}
        # NMT, control word, and what an NMT stop this program sent means for what follows
        self.commissioning = Commissioning(lambda: self.session)

    # --- who ------------------------------------------------------------------------------
    @property
    def session(self) -> ValveSession:
        """The device layer's session of this valve (whoever uses the service holds it)."""
        session = self._session()
        if session is None:
            raise CommunicationError("the valve's session is closed")
        return session

    @property
    def type_key(self) -> TypeKey:
        """The valve's type key, parsed."""
        return TypeKey.parse(self.session.info.type_key)

    def parameter(self, mnemonic: str) -> Parameter:
        """The catalogue entry of one of this valve's parameters; KeyError names the valve."""
        param = self._params.get(mnemonic)
        if param is None:
            raise KeyError(f"{mnemonic!r} is not a parameter on a {self.variant.label} valve")
        return param

    # --- single values --------------------------------------------------------------------
    def check(self, values: Mapping[str, object]) -> dict[str, Value]:
        """The raw values of ``values`` (display values or texts as typed) if this valve
        would take them: each as :func:`~prm9tool.service.values.user_value` checks it, then
        together with the valve's caps (LIMTA at most its CURNORM). Sends nothing."""
        params = {m: self.parameter(m) for m in values}
        held = caps_held(self.session, values)  # LIMTA's range is 0 … the valve's CURNORM
        raw = {m: user_value(params[m], v, held) for m, v in values.items()}
        check_rules(self.session, raw, held)
        return raw

    def check_raw(self, values: Mapping[str, Value]) -> None:
        """Raw values as the window's document holds them: writable and in range (the
        document checked the rules); the same words as :meth:`check`. A mnemonic this valve
        lacks is left to the link, which names it."""
        held: dict[str, Value] | None = None
        for mnemonic, raw in values.items():
            param = self._params.get(mnemonic)
            if param is None:
                continue
            if not param.writable:
                raise ReadOnlyError(read_only_text(mnemonic))
            cap = CAPPED_BY.get(mnemonic)
            if cap is not None and not _in_catalogue_range(param, raw):
                held = caps_held(self.session, values) if held is None else held
                param.check_raw(raw, held.get(cap))  # 0 … CURNORM, as the editors say
            param.check_raw(raw)

    def write_raw(self, values: Mapping[str, Value]) -> None:
        """Write raw values. A value out of range is refused before anything is sent; a
        read-only parameter among them is not sent, the others are written, then
        ReadOnlyError names it (the window's bulk write of a document's differences)."""
        read_only = [m for m in values if m in self._params and not self._params[m].writable]
        writable = {m: v for m, v in values.items() if m not in read_only}
        self.check_raw(writable)
        if writable:
            self.session.write_many(writable)
        if read_only:
            raise ReadOnlyError(read_only_text(read_only[0]))

    def read_each(self, mnemonics: list[str]) -> dict[str, Value | Prm9Error]:
        """Each value one by one, or why the valve could not give it (the object-dictionary
        browser's Read all: one refusal does not hide the others)."""
        values: dict[str, Value | Prm9Error] = {}
        for mnemonic in mnemonics:
            try:
                values[mnemonic] = self.session.read(mnemonic)
            except Prm9Error as exc:
                values[mnemonic] = exc
        return values

    def status(self) -> ValveStatus:
        """:meth:`Commissioning.status`: a valve this program stopped by NMT says so."""
        return self.commissioning.status()

    # --- the parameter set ----------------------------------------------------------------
    def download(
        self,
        progress: Progress | None = None,
        cancel: threading.Event | None = None,
        purpose: str = "",
        record_later: bool = False,
    ) -> dict[str, Value]:
        """The valve's parameter set (working values), recorded as a download; with
        ``record_later`` the record is made now and written by the history's ``write_later``
        (the GUI: the values need not wait for the database to open)."""
        values = dict(self.session.download(progress, cancel))
        if self.history is not None:
            record = self.history.download_later if record_later else self.history.download
            record(self.session, values, purpose)
        return values

    def upload(
        self,
        values: Mapping[str, Value],
        *,
        backup: bool = True,
        rules: bool = True,
        verify_by_restart: bool = False,
        progress: Progress | None = None,
        cancel: threading.Event | None = None,
        purpose: str = "",
        on_backup: Callable[[Path | None], None] | None = None,
    ) -> UploadResult:
        """:func:`prm9tool.service.upload.upload` with this valve's history."""
        return upload.upload(
            self.session, values, history=self.history, backup=backup, rules=rules,
            verify_by_restart=verify_by_restart, progress=progress, cancel=cancel,
            purpose=purpose, on_backup=on_backup,
        )  # fmt: skip

    def store(self, progress: Progress | None = None) -> dict[str, Value]:
        """The working parameters become the stored ones, read back and recorded."""
        from prm9tool.service.history import store_and_read

        return store_and_read(self.session, self.history, progress)

    def backup(
        self, progress: Progress | None = None, cancel: threading.Event | None = None
    ) -> Path | None:
        """The valve's backup file unless it has one (recorded); the new file or None."""
        from prm9tool.files.backup import ensure_backup

        path = ensure_backup(self.session, progress, cancel)
        if path is not None and self.history is not None:
            self.history.backup(self.session, path)
        return path

    def restore_factory(
        self, *, backup: bool = True, restart: bool = True
    ) -> tuple[dict[str, Value] | None, Path | None]:
        """Restore factory values, the one operation of every door (the window's online,
        ``--restore-factory``, the API's ``restore_factory()``): the backup (as before the
        first upload; recorded), the stored parameters reset to the factory values, then the
        restart that makes them effective (the caller confirmed that the hydraulics are off)
        and the factory set read back. Returns that set and the new backup file (None: it had
        one, or ``backup`` is False); recorded as ``restore-factory`` with the set read back.
        ``restart=False``: only the reset (nothing moves; the valve runs on its old set until
        a :meth:`restart`): returns no set, recorded without one."""
        path = self.backup() if backup else None
        self.session.restore_factory()
        values: dict[str, Value] | None = None
        if restart:
            try:
                self._restart()
                values = dict(self.session.download())
            except Prm9Error as exc:  # half done: the reset is in the valve, say so
                self._record_factory(path, None, "restart-failed")
                exc.args = (f"{exc}; {_factory_loaded(path)}",)
                raise
        self._record_factory(path, values, "ok")
        return values, path

    def _record_factory(
        self, path: Path | None, values: dict[str, Value] | None, outcome: str
    ) -> None:
        if self.history is not None:
            details: Details = {"backup": None if path is None else str(path)}
            self.history.add(self.session, "restore-factory", outcome, values, details)

    def restart(self, command: str | None = None) -> None:
        """Restart the valve's electronics and reconnect (the caller confirmed that the
        hydraulics are off: the spool moves to its rest position while it boots); recorded
        (``restart``, without a parameter set; ``command``: what ran it)."""
        self._restart()
        self._record_restart(None, command)

    def _restart(self) -> None:
        self.session.restart()
        self.commissioning.restarted()

    def _record_restart(self, values: Mapping[str, Value] | None, command: str | None) -> None:
        if self.history is not None:
            details: Details = {"command": command} if command else {}
            self.history.add(self.session, "restart", "ok", values, details)

    def restart_and_read(self, command: str | None = None) -> dict[str, Value]:
        """:meth:`restart`, then read the stored parameters the valve runs with now; recorded
        with them (the window's Restart valve)."""
        self._restart()
        values = dict(self.session.download())
        self._record_restart(values, command)
        return values

    # --- motion ---------------------------------------------------------------------------
    def characterize(
        self, profile: Profile | str | os.PathLike[str] | None = None,
        progress: Callable[[str], None] | None = None,
    ) -> Characterization:  # fmt: skip
        """The end-of-line test (``--characterize``'s) on this valve, recorded; refused with
        MotionBusyError while another motion (a generator) runs on it."""
        with motion.claim(self.session, "characterization"):
            result = characterize_session(self.session, profile, progress)
        if self.history is not None:
            self.history.characterization(self.session, result)
        return result

    def autotune(
        self,
        settings: AutotuneSettings | None = None,
        apply: bool = False,
        progress: Callable[[str], None] | None = None,
    ) -> AutotuneOutcome:
        """The Tuning window's autotune on this valve (``service/autotune.py``): the proposal,
        checked against the acceptance profile, the valve's own gains back afterwards;
        ``apply``: then write the proposed gains and store them, when the proposal passes the
        acceptance profile and its model is trustworthy (``may_apply``). Refused with MotionBusyError
        while another motion runs; recorded in the history as the window records it."""
        from prm9tool.service import autotune as tuning

        checked = (settings or tuning.AutotuneSettings()).checked()
        with motion.claim(self.session, "autotune"):
            with session_rig(self.session) as rig:
                proposal = tuning.run(rig, checked, progress)
            apply = apply and tuning.may_apply(proposal)
            if apply:
                self.write_raw(proposal.values)
                self.store()  # read back and recorded, as every door's store
        if self.history is not None:
            outcome, details = tuning.details(proposal, apply)
            self.history.add(self.session, "autotune", outcome, None, details)
        return tuning.AutotuneOutcome(proposal, apply)

    def fit_twin(
        self,
        path: str | os.PathLike[str],
        profile: Profile | str | os.PathLike[str] | None = None,
        progress: Callable[[str], None] | None = None,
    ) -> ValveTwin:
        """Characterize this valve (recorded as :meth:`characterize` records it), fit its twin
        from the run and write the twin file ``path`` (docs/twin.md); the twin is recorded in
        the history (operation ``twin``). Prm9Error when the run has no position-loop step."""
        from prm9tool.twin.fitvalve import history_details, history_outcome, twin_of_run

        result = self.characterize(profile, progress)
        twin = twin_of_run(result, path)
        if self.history is not None:
            self.history.twin_of(result, history_outcome(twin.fit), history_details(twin.fit, path))
        return twin

    def signature(
        self, profile: Profile | str | os.PathLike[str] | None = None,
        progress: Callable[[str], None] | None = None,
    ) -> DriftReport:  # fmt: skip
        """The field signature (≤ 20 s of motion) compared with the valve's birth certificate
        in the history (:mod:`prm9tool.characterize.drift`), recorded as a ``signature``;
        NoReferenceError (nothing moved) without one or with the history off; MotionBusyError
        while another motion runs on the valve."""
        from prm9tool.characterize.drift import signature

        records = self.history.records_of if self.history is not None else None
        with motion.claim(self.session, "signature"), session_rig(self.session) as rig:
            report = signature(rig, records, profile_of(profile), progress)
        if self.history is not None:
            self.history.signature_of(report)
        return report

    # --- files ----------------------------------------------------------------------------
    def export_dcf(self, path: str | os.PathLike[str]) -> int:
        """The valve's CiA 306 DCF with its working values (downloaded now) and the node ID
        and bit rate it runs with after power-up; returns that node ID."""
        from prm9tool.device.session import NotAvailableError
        from prm9tool.service.export import SETTINGS, write_dcf

        values = dict(self.session.download())
        settings: dict[str, Value] = {}
        for mnemonic in SETTINGS:
            if mnemonic in values or mnemonic not in self._params:
                continue
            try:
                settings.update(self.session.read_many([mnemonic]))
            except (NotAvailableError, CommunicationError):  # not on this link
                continue
        return write_dcf(path, self.session.info.type_key, values, {**values, **settings})


def _factory_loaded(backup: Path | None) -> str:
    """What a restore of the factory values whose restart failed has done already."""
    kept = (
        f"the valve's previous parameters are in {backup}"
        if backup is not None
        else "the valve's backup from before is kept"
    )
    return (
        "the factory values were already loaded in the valve: they take effect at its next "
        f"restart or power-up ({kept}); restart it (hydraulics disconnected) and check its "
        "parameters"
    )


_SERVICES: weakref.WeakKeyDictionary[object, ValveService] = weakref.WeakKeyDictionary()
_LOCK = threading.Lock()


def service_for(session: ValveSession, history: HistoryHook | None = None) -> ValveService:
    """The one service of an open session (made on first use; ``history`` attaches the
    observer when given)."""
    with _LOCK:
        service = _SERVICES.get(session)
        if service is None:
            service = _SERVICES[session] = ValveService(session, history)
        elif history is not None:
            service.history = history
        return service

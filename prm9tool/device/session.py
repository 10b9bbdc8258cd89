"""The valve session: what the GUI and the batch mode do with one valve, over any link.

Long operations are synchronous (run them off the GUI thread), report ``progress(done, total,
step)`` and stop at the next report when ``cancel`` is set. Failures raise the typed errors of
:mod:`prm9tool.errors`; an upload never stores anything it has not read back and compared.

**The upload contract, the same on every link** (it lives here once, in
:class:`ValveSession`; the USB link stores with its STORE command, the CANopen link writes
"save" into 0x1010/1):

1. *write* every value; a refusal ends the upload (``failed_step`` ``write``);
2. *verify*: read every value back and compare (``verify``);
3. *store*: send the store command, then make sure the valve did not restart between the
   verify and the store (``store``). ``stored`` is True only if the valve acknowledged the
   store **and** it stored the verified working values. The store copies the working values
   into non-volatile memory and a restart replaces the working values with the stored ones, so
   a valve that restarted (brown-out) before the store stored its old set. How a link makes
   sure is its own (:meth:`UploadSteps.store_problem`, the link's part of the upload): over
   USB it reads every value back once more and compares — a valve that restarted reads back
   its old values; over CANopen the master watches the node's boot-up frame, which a
   restarting node sends (CiA 301), from before the first write to the store's
   acknowledgement, and reads back one value the upload changed
   (prm9tool.device.canlink.upload_steps). A refused store (abort, e.g. 0x08000020) is
   ``failed_step`` ``store`` with the reason in ``failure``.

A link may leave out writing a value the valve is known to hold already (read during this
upload or just before it); the verify step still reads every value back, and a value that
reads back differently from what the link believed is written and verified after all
(:meth:`UploadSteps.verify`).

After any failure (also a cancel) the session asks the valve to reload its stored parameters
(USB: RELOAD; CANopen: the master writes back the working values it read before the upload,
prm9tool.device.canlink.upload_steps), so it runs on its stored set.
"""

from __future__ import annotations

import logging
import threading
import time
from abc import ABC, abstractmethod
from collections.abc import Callable, Mapping, Sequence

import numpy as np

from prm9tool.catalogue import CATALOGUE, Parameter
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.device.emulated import EmulatorControls
from prm9tool.device.records import (
    DeviceInfo,
    OperationCancelledError,
    Progress,
    RefusedError,
    Steps,
    UploadResult,
    Value,
    ValveStatus,
    check_cancel,
)
from prm9tool.device.setpoint import OverrideSetpoint, SetpointLink
from prm9tool.device.upload_outcome import (
    RESTARTED_BEFORE_STORE,
    differences,
    reload_outcome,
    since,
    step_error,
)
from prm9tool.errors import CommunicationError, Prm9Error, SdoAbortError

log = logging.getLogger("prm9tool.device.session")
__all__ = ["NotAvailableError", "UploadSteps", "ValveSession"]


class NotAvailableError(Prm9Error):
    """Parameters whose objects the valve does not have on this link (a real valve over
    CANopen lacks the objects this project decided on: abort 0x06020000/0x06090011)."""

    def __init__(self, mnemonics: Sequence[str]) -> None:
        self.mnemonics = tuple(mnemonics)
        super().__init__(f"not available over CANopen on this valve: {', '.join(mnemonics)}")


class UploadSteps:
    """The link's own steps of the upload contract, a part its session holds
    (:attr:`ValveSession.upload_steps`; the contract itself is :meth:`ValveSession.upload`).

    This one is the USB link's: nothing before the first write, every value written in the
    file's order and read back, the store made sure of by reading every value back once more,
    and after a failure the valve reloads its stored set itself (:meth:`ValveSession.reload`).
    A link that needs more (CANopen: a snapshot to put back, writes left out, the boot-up
    watch, verification by restart) gives its session another part
    (prm9tool.device.canlink.upload_steps)."""

    def __init__(self, session: ValveSession) -> None:
        self._session = session
        # the upload restarted the valve (verification by restart) and found its store not
        # kept: the valve runs on what it came back with (a link that can verify by restart)
        self.restarted = False

    @property
    def kept(self) -> bool:
        """True on a valve that keeps every write (a failed upload puts the backup back)."""
        return False

    def before(self, params: Sequence[Parameter], cancel: threading.Event | None) -> None:
        """Runs before an upload writes anything (a link that cannot reload the stored set
        without a restart takes its snapshot of the working values here)."""
        del params, cancel  # the USB protocol reloads the stored set itself

    def order(self, params: list[Parameter], values: Mapping[str, Value]) -> list[Parameter]:
        """The order the upload writes ``params`` in (a link may need a safe one)."""
        del values
        return params

    def marker(self) -> object:
        """Taken before an upload writes anything; :meth:`store_problem` gets it back (a link
        that can watch the valve restart notes its state here)."""
        return None

    def verify(
        self,
        params: Sequence[Parameter],
        values: Mapping[str, Value],
        steps: Steps | None,
        cancel: threading.Event | None,
    ) -> dict[str, Value | SdoAbortError]:
        """The verify step's read-back of every value (a link that left out writes corrects
        them here; see the module docstring)."""
        del values
        return self._session._read_entries(params, steps, cancel)

    def store_problem(
        self, params: Sequence[Parameter], values: Mapping[str, Value], marker: object
    ) -> tuple[dict[str, tuple[Value, Value]], str] | None:
        """After the acknowledged store: (mismatches, why) when the stored set may not be the
        upload, None when it is. Here: every value read back once more and compared."""
        del marker
        changed = differences(params, values, self._session._read_entries(params, None, None))
        return (changed, RESTARTED_BEFORE_STORE) if changed else None


class ValveSession(ABC):
    """One open valve, whatever the link: the interface the GUI, ``--batch`` and the backups use.

    The behaviour that must be the same on every link lives here once: range checks, the
    transactional upload (write all → read back and compare → store), download, parameters the
    valve lacks on this link (:attr:`unavailable`), close hooks. A link is one subclass
    (:class:`prm9tool.device.usb.session.UsbSession`,
    :class:`prm9tool.device.canlink.session.CanopenSession`) implementing the abstract
    methods; a link whose upload needs steps of its own gives the session another
    :class:`UploadSteps` part (:attr:`upload_steps`). Thread-safe as far as the link serializes
    its exchanges.
    """

    # after the store, restart the valve and read every value back (the hydraulics are off: the
    # caller confirmed it); a link with that step (CANopen) acts on it, the others ignore it
    verify_by_restart = False

    def __init__(self, device_id: str, on_close: Callable[[], None] | None = None) -> None:
        self._device_id = device_id
        self._on_close: list[Callable[[], None]] = [on_close] if on_close is not None else []
        self.unavailable: set[str] = set()  # parameters this valve lacks on this link
        self.store_done: str | None = None  # how the last store kept the set (UploadResult)
        self.upload_steps = UploadSteps(self)  # the link's steps of the upload (a part)

    def _start(self) -> None:
        """Identify the valve once the link is up (subclasses call this from __init__)."""
        self.info = self.identify()
        self.variant = TypeKey.parse(self.info.type_key).variant
        self._params = {p.mnemonic: p for p in CATALOGUE.for_variant(self.variant)}

    # --- what a link implements -----------------------------------------------------------
    @abstractmethod
    def identify(self) -> DeviceInfo:
        """Ask the valve who it is (refusing a valve this link cannot work with)."""

    @abstractmethod
    def _read_entries(
        self, params: Sequence[Parameter], steps: Steps | None, cancel: threading.Event | None
    ) -> dict[str, Value | SdoAbortError]:
        """Values by mnemonic; a refused entry maps to its SdoAbortError. A parameter the
        valve lacks on this link is added to :attr:`unavailable` and left out."""

    @abstractmethod
    def _write_entries(
        self,
        params: Sequence[Parameter],
        values: Mapping[str, Value],
        steps: Steps | None,
        cancel: threading.Event | None,
    ) -> int:
        """Write in order; returns how many were written, raises RefusedError on a refusal.
        A parameter the valve lacks is added to :attr:`unavailable`, skipped, not counted."""

    @abstractmethod
    def store(self) -> None:
        """Make the working parameters permanent (non-volatile memory)."""

    @abstractmethod
    def reload(self) -> None:
        """Working parameters ← the stored ones (non-volatile memory), without moving the
        spool; after a failed upload."""

    @abstractmethod
    def restore_factory(self) -> None:
        """Reset the stored parameters to factory values; effective after :meth:`restart`."""

    @abstractmethod
    def restart(self) -> None:
        """Power-cycle the valve's electronics and reconnect (only with hydraulics off)."""

    @abstractmethod
    def status(self) -> ValveStatus:
        """Device state, errors, LEDs, temperature and supply voltage."""

    @abstractmethod
    def stream_start(self, keys: Sequence[str], rate_hz: int = 5000) -> None:
        """Stream up to three measuring points (signals.py keys) at about ``rate_hz``."""

    @abstractmethod
    def stream_read(self) -> np.ndarray:
        """Samples received since the last call: shape (n, len(keys)), raw values."""

    @property
    @abstractmethod
    def samples_lost(self) -> int:
        """Samples lost since :meth:`stream_start`."""

    @abstractmethod
    def stream_stop(self) -> None:
        """Stop streaming."""

    @abstractmethod
    def nmt(self, command: int) -> None:
        """Send an NMT command (:class:`~prm9tool.catalogue.commissioning.NmtCommand`) to the
        valve, as its CANopen master would (manual §7.2): start, stop, pre-operational, reset.
        A valve with CANopen switched off ignores it."""

    def setpoint_link(self) -> SetpointLink:
        """How the PC drives this valve's setpoint (the generator, the tuning procedures):
        the service override SETPOVRON/SETPOVR unless the link has its own way."""
        return OverrideSetpoint(self)

    @property
    def emulator(self) -> EmulatorControls | None:
        """Inputs, switches and faults of an emulated valve behind this link (None for a real
        one, and for any valve reached over a CAN bus)."""
        return None

    @property
    @abstractmethod
    def closed(self) -> bool:
        """True once the link is closed."""

    @abstractmethod
    def _close_link(self) -> None:
        """Stop any stream and release the link (called once)."""

    # --- single values --------------------------------------------------------------------
    def read(self, mnemonic: str) -> Value:
        """Raw value of one parameter (NotAvailableError: the valve lacks it on this link)."""
        values = self.read_many([mnemonic])
        if mnemonic not in values:
            raise NotAvailableError([mnemonic])
        return values[mnemonic]

    def write(self, mnemonic: str, raw: Value) -> None:
        """Write one raw value (ValueRangeError before sending, SdoAbortError if refused)."""
        self.write_many({mnemonic: raw})

    def read_many(self, mnemonics: Sequence[str]) -> dict[str, Value]:
        """Raw values of several parameters; those the valve lacks on this link
        (:attr:`unavailable`) are left out."""
        params = [self._param(m) for m in mnemonics]
        results = self._read_entries(params, None, None)
        for param in params:
            outcome = results.get(param.mnemonic)
            if isinstance(outcome, SdoAbortError):
                raise outcome
        return {m: results[m] for m in mnemonics if m in results}  # type: ignore[misc]

    def write_many(self, values: Mapping[str, Value]) -> None:
        """Write several raw values; all are range-checked before the first is sent."""
        params = self._checked(values)
        try:
            self._write_entries(params, values, None, None)
        except RefusedError as refused:
            raise refused.error from None
        missing = sorted(set(values) & self.unavailable)
        if missing:
            raise NotAvailableError(missing)

    # --- upload / download ----------------------------------------------------------------
    def upload(
        self,
        values: Mapping[str, Value],
        progress: Progress | None = None,
        cancel: threading.Event | None = None,
    ) -> UploadResult:
        """Write all → read back and compare → store and confirm (the module's contract).

        A refusal or mismatch returns a result with ``failed_step``; a broken link raises the
        communication error with the failed step named and how far the upload got: attributes
        ``step``, ``written`` (values the valve confirmed), ``verified`` (all read back equal)
        and ``reloaded``. Either way nothing was stored unless ``stored`` is True. After any
        failure (also a cancel) the session asks the valve to reload its stored parameters into
        its working values, so it does not run on with a half-written set; the result or the
        error says whether that worked.
        """
        start = time.monotonic()
        params = self._checked(values)
        total = 2 * len(params) + 1
        step, writing, verified = "write", Steps(progress, total, 0, "write"), False
        link = self.upload_steps
        try:
            link.before(params, cancel)
            params = link.order(params, values)
            marker = link.marker()
            written = self._write_entries(params, values, writing, cancel)
            step = "verify"
            verify = Steps(progress, total, len(params), step)
            params = [p for p in params if p.mnemonic not in self.unavailable]
            actual = link.verify(params, values, verify, cancel)
            mismatches = differences(params, values, actual)
            if mismatches:
                return self._failed(written, mismatches, start, "verify")
            step, verified = "store", True
            check_cancel(cancel, step)
            self.store()
            problem = link.store_problem(params, values, marker)
            if problem is not None:
                return self._failed(written, problem[0], start, "store", True, problem[1])
        except RefusedError as refused:
            refusal: tuple[Value, Value] = (values[refused.mnemonic], str(refused.error))
            return self._failed(refused.done, {refused.mnemonic: refusal}, start, "write")
        except SdoAbortError as exc:
            if step != "store":  # a whole request refused while writing or reading back
                raise
            why = f"the valve refused to store the parameters: {exc}"
            return self._failed(written, {}, start, "store", True, why)
        except OperationCancelledError as exc:
            reverted = self._revert()
            raise OperationCancelledError(exc.step, reload_outcome(reverted, link.kept)) from exc
        except CommunicationError as exc:
            reverted = self._revert()
            raise step_error(exc, step, reverted, writing.done, verified, link.kept) from exc
        if progress:
            progress(total, total, "store")
        skipped = tuple(sorted(set(values) & self.unavailable))
        return UploadResult(
            written=written,
            verified=True,
            stored=True,
            duration_s=since(start),
            skipped=skipped,
            store=self.store_done,
        )

    def download(
        self, progress: Progress | None = None, cancel: threading.Event | None = None
    ) -> dict[str, Value]:
        """The raw values of the *.prm parameter set of the valve's variant."""
        params = CATALOGUE.file_parameters(self.variant)
        results = self._read_entries(params, Steps(progress, len(params), 0, "download"), cancel)
        for outcome in results.values():
            if isinstance(outcome, SdoAbortError):
                raise outcome
        return dict(results)  # type: ignore[arg-type]

    def close(self) -> None:
        """Stop any stream and close the link (idempotent)."""
        if self.closed:
            return
        self._close_link()
        hooks, self._on_close = self._on_close, []  # each hook runs once
        for hook in reversed(hooks):  # the last one added is undone first
            hook()

    def add_close_hook(self, hook: Callable[[], None]) -> None:
        """Call ``hook`` when the session closes (before the hooks added earlier); at once if
        it is closed already (a hook added from another thread while the session closed)."""
        self._on_close.append(hook)
        if self.closed and hook in self._on_close:
            self._on_close.remove(hook)
            hook()

    def __enter__(self) -> ValveSession:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    # --- internals ------------------------------------------------------------------------
    def _failed(
        self,
        written: int,
        mismatches: dict[str, tuple[Value, Value]],
        start: float,
        step: str,
        verified: bool = False,
        failure: str | None = None,
    ) -> UploadResult:
        problem = self._revert()
        return UploadResult(
            written=written,
            verified=verified,
            stored=False,
            mismatches=mismatches,
            duration_s=since(start),
            failed_step=step,
            reloaded=problem is None,
            reload_error=problem,
            restarted=self.upload_steps.restarted,
            failure=failure,
            store=self.store_done,
        )

    def _revert(self) -> str | None:
        """After a failed upload: working values ← stored ones (best effort); why it failed."""
        try:
            self.reload()
        except Prm9Error as exc:
            log.warning("%s: reloading the stored parameters failed: %s", self._device_id, exc)
            return str(exc)
        return None

    def _param(self, mnemonic: str) -> Parameter:
        param = self._params.get(mnemonic)
        if param is None:
            where = "" if mnemonic in CATALOGUE else " in the catalogue"
            raise Prm9Error(f"{mnemonic}: no such parameter{where} on a {self.variant.label} valve")
        return param

    def _checked(self, values: Mapping[str, Value]) -> list[Parameter]:
        params = [self._param(m) for m in values]
        for param in params:
            param.check_raw(values[param.mnemonic])
        return params

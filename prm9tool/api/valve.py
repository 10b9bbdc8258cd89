"""One open valve for a script: :class:`Valve` (what :func:`prm9tool.connect` returns).

A thin, typed layer over the session every link implements
(:class:`prm9tool.device.session.ValveSession`): values in display units instead of raw
ones, the parameter set as a :class:`~prm9tool.api.params.ParameterSet`, the upload with the
batch mode's type check and backup, and what it did recorded in the history. No Qt.
"""

from __future__ import annotations

import contextlib
import logging
import os
import threading
from collections.abc import Callable, Iterator, Mapping, Sequence
from typing import TYPE_CHECKING

from prm9tool.api.params import Display, ParameterSet, as_parameter_set, display, lookup
from prm9tool.catalogue import CATALOGUE, Parameter
from prm9tool.catalogue.commissioning import NmtCommand
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.device.records import DeviceInfo, Progress, UploadResult, Value, ValveStatus
from prm9tool.errors import AccessDeniedError, Prm9Error
from prm9tool.service.upload import check_type
from prm9tool.service.valve import ValveService, service_for

if TYPE_CHECKING:
    from prm9tool.analysis.profile import Profile
    from prm9tool.api.measure import Captured, SetpointGenerator
    from prm9tool.characterize.drift import DriftReport
    from prm9tool.characterize.run import Characterization
    from prm9tool.device.emulated import EmulatorControls
    from prm9tool.device.session import ValveSession
    from prm9tool.scope.generator import Waveform
    from prm9tool.service.autotune import AutotuneOutcome
    from prm9tool.twin.fitvalve import ValveTwin

log = logging.getLogger("prm9tool.api")
__all__ = ["ReadBackError", "Valve"]


class ReadBackError(Prm9Error):
    """A value written to the valve read back differently (``wrote``, ``read``: display)."""

    def __init__(self, mnemonic: str, wrote: Display, read: Display) -> None:
        super().__init__(f"{mnemonic}: wrote {wrote}, the valve reads back {read}")
        self.mnemonic, self.wrote, self.read = mnemonic, wrote, read


class Valve:
    """One open valve, whatever the link (USB, emulated, CANopen).

    ``valve["LIMTA"]`` reads a parameter in display units, ``valve["LIMTA"] = 1800`` checks
    it against the catalogue (ValueRangeError, nothing sent), writes it and reads it back
    (ReadBackError when it differs); the working value, not stored until :meth:`store` (or an
    :meth:`upload`). An unknown mnemonic is a KeyError. Not thread-safe across threads that
    share one Valve; the link serializes its exchanges.
    """

    def __init__(
        self,
        session: ValveSession,
        *,
        history_db: str | None = None,
        record_history: bool = True,
        command: str = "python API",
    ) -> None:
        from prm9tool.service.history import open_history

        self._session = session
        # the history observer (None: off); the records' "command" detail names the door
        report = lambda problem: log.warning("history: %s", problem)  # noqa: E731
        history = open_history(history_db, command, report) if record_history else None
        self._service: ValveService = service_for(session, history)
        self._params = {p.mnemonic: p for p in CATALOGUE.for_variant(session.variant)}

    # --- who -----------------------------------------------------------------------------------
    @property
    def info(self) -> DeviceInfo:
        """Who the valve is: type key, serial number, firmware, device ID, link."""
        return self._session.info

    @property
    def type_key(self) -> TypeKey:
        """The valve's type key, parsed."""
        return TypeKey.parse(self.info.type_key)

    @property
    def session(self) -> ValveSession:
        """The device layer's session under this valve (for what this API does not cover)."""
        return self._session

    @property
    def service(self) -> ValveService:
        """The valve service every door shares (prm9tool.service.valve)."""
        return self._service

    @property
    def emulator(self) -> EmulatorControls | None:
        """Inputs, rotary switches and faults of an emulated valve (None for a real one)."""
        return self._session.emulator

    @property
    def closed(self) -> bool:
        """True once the valve is closed."""
        return self._session.closed

    def parameter(self, mnemonic: str) -> Parameter:
        """The catalogue entry (unit, range, texts) of one of this valve's parameters."""
        return lookup(self._params, mnemonic, f"on a {self._session.variant.label} valve")

    # --- single values ------------------------------------------------------------------------
    def __getitem__(self, mnemonic: str) -> Display:
        param = self.parameter(mnemonic)
        return display(param, self._session.read(mnemonic))

    def __setitem__(self, mnemonic: str, value: Display) -> None:
        param = self.parameter(mnemonic)
        # ValueRangeError (wrong type, not a number, out of range), ReadOnlyError: nothing sent
        raw = self.check({mnemonic: value})[mnemonic]
        self._session.write(mnemonic, raw)
        back = self._session.read(mnemonic)
        if back != raw:
            raise ReadBackError(mnemonic, display(param, raw), display(param, back))

    def check(self, values: Mapping[str, Display]) -> dict[str, Value]:
        """The raw values of ``values`` (display units) if this valve would take them: each in
        its catalogue range and, together with what the valve holds, within the rules between
        parameters (LIMTA/LIMTB at most its CURNORM, manual table 7-14). ValueRangeError
        names what is not (``True``, ``None``, ``"abc"`` are not numbers), ReadOnlyError (an
        AccessDeniedError) a read-only parameter; KeyError an unknown mnemonic. The same
        check and words as ``--set`` and the window. Sends nothing, reads the caps."""
        for mnemonic in values:
            self.parameter(mnemonic)
        return self._service.check(values)

    def read(self, *mnemonics: str) -> dict[str, Display]:
        """Several parameters at once, in display units."""
        params = [self.parameter(m) for m in mnemonics]
        raw = self._session.read_many(list(mnemonics))
        return {p.mnemonic: display(p, raw[p.mnemonic]) for p in params if p.mnemonic in raw}

    def status(self) -> ValveStatus:
        """Device state, errors, LEDs, temperature, supply voltage and NMT state now. After
        this script's own ``nmt("stop")`` a valve that cannot answer says why (NmtStoppedError,
        a DeviceTimeoutError)."""
        return self._service.status()

    def wait_booted(self, timeout_s: float = 5.0) -> ValveStatus:
        """Ask for the status until the valve has finished booting (about 2 s after power-up
        or a restart, manual §1.5, §5.6), and return it; DeviceTimeoutError after
        ``timeout_s``. A booting valve ignores its setpoint, NMT commands and the control word.
        """
        return self._service.commissioning.wait_booted(timeout_s)

    # --- the parameter set --------------------------------------------------------------------
    def download(self, progress: Progress | None = None) -> ParameterSet:
        """The valve's parameter set (the working values; the *.prm file's parameters)."""
        values = self._service.download(progress)
        info = self.info
        return ParameterSet(
            info.type_key, values, serial=info.serial, firmware=info.firmware or None
        )

    def upload(
        self,
        params: Mapping[str, Display],
        *,
        force_type: bool = False,
        backup: bool = True,
        verify_by_restart: bool = False,
        confirm_hydraulics_off: bool = False,
        progress: Progress | None = None,
        cancel: threading.Event | None = None,
    ) -> UploadResult:
        """Write all values, read every one back and compare, then store: transactional.

        ``params``: a :class:`ParameterSet` (its type key must be the valve's; another key of
        the same variant with ``force_type``; another variant never: TypeKeyError, nothing
        written) or a mapping of display values for this valve. ``backup``: first save the
        valve's parameters as its backup file, unless it has one (as the GUI and ``--batch``
        do). A refused or differing value returns a result with ``stored`` False and
        ``failed_step`` set; the valve then runs on its stored set. A broken link raises the
        CommunicationError naming the failed step. ``verify_by_restart`` (CANopen, as
        ``--batch --verify-by-restart``): after the store, restart the valve and read every
        value back — the spool drops to its rest position, so only with the hydraulics off,
        which the caller confirms with ``confirm_hydraulics_off=True`` (AccessDeniedError
        without it, nothing sent); a link without that step ignores it.
        """
        if verify_by_restart and not confirm_hydraulics_off:
            raise AccessDeniedError(
                "verify_by_restart restarts the valve and its spool drops to the rest position: "
                "switch the hydraulics off and add confirm_hydraulics_off=True"
            )
        wanted = as_parameter_set(params, self.type_key)
        check_type(wanted.type_key, self.type_key, force_type, "force_type=True")
        # the one upload sequence (prm9tool.service.upload): rules, backup, upload, history
        return self._service.upload(
            wanted.raw, backup=backup, verify_by_restart=verify_by_restart, progress=progress,
            cancel=cancel,
        )  # fmt: skip

    def store(self) -> None:
        """Make the working parameters permanent (the valve's non-volatile memory). Recorded
        as the GUI's Valve → Store is: with the set read back after the store."""
        self._service.store()

    def restore_factory(
        self,
        *,
        confirm_hydraulics_off: bool = False,
        only_reset: bool = False,
        backup: bool = True,
    ) -> ParameterSet | None:
        """Restore the factory values as the window (online) and ``--restore-factory`` do:
        first save the valve's parameters as its backup file, unless it has one; reset the
        stored parameters to the factory values; restart the valve, which makes them
        effective; return the factory set read back (as :meth:`download`). The restart moves
        the spool to its rest position: only with the hydraulics off, which the caller
        confirms with ``confirm_hydraulics_off=True`` (AccessDeniedError without it, nothing
        sent). ``only_reset=True``: only the reset (nothing moves, no confirmation needed;
        the valve runs on its old set until :meth:`restart`); returns None."""
        if not (confirm_hydraulics_off or only_reset):
            raise AccessDeniedError(
                "restore_factory() restarts the valve to make the factory values effective, "
                "and a restart moves the spool to its rest position: switch the hydraulics off "
                "and call restore_factory(confirm_hydraulics_off=True), or "
                "restore_factory(only_reset=True) to reset now and restart() later"
            )
        values, _path = self._service.restore_factory(backup=backup, restart=not only_reset)
        if values is None:
            return None
        info = self.info
        return ParameterSet(
            info.type_key, values, serial=info.serial, firmware=info.firmware or None
        )

    def restart(self, *, confirm_hydraulics_off: bool = False) -> None:
        """Restart the valve's electronics and reconnect. The spool moves to its rest position
        while the valve boots: only with the hydraulics off, which the caller confirms with
        ``confirm_hydraulics_off=True`` (AccessDeniedError without it, nothing sent)."""
        if not confirm_hydraulics_off:
            raise AccessDeniedError(
                "a restart moves the spool to its rest position: switch the hydraulics off "
                "and call restart(confirm_hydraulics_off=True)"
            )
        self._service.restart()

    # --- operation ----------------------------------------------------------------------------
    def nmt(self, command: NmtCommand | str) -> None:
        """Send an NMT command as the valve's CANopen master would (manual §7.2): an
        :class:`NmtCommand` or its name (``"start"``, ``"stop"``, ``"pre-operational"``,
        ``"reset-node"``, ``"reset-communication"``). A valve with CANopen off ignores it."""
        self._service.commissioning.nmt(command)

    def enable(self) -> None:
        """Control word 08h → 09h → 0Bh → 0Fh (manual §7.4, table 7-19): from INIT or a
        fault whose cause is gone to DEVICE_MODE_ACTIVE, where the valve follows its setpoint.
        Raises :class:`~prm9tool.device.enabling.NotEnabledError` (an AccessDeniedError) when
        the valve does not get there, saying why (e.g. which error is still present)."""
        self._service.commissioning.enable()

    def commission(self) -> ValveStatus:
        """What its CANopen master does to a -CA valve as delivered (and ``--enable`` and
        the window's "Enable it now?"): NMT start when it waits in pre-operational or
        stopped, then :meth:`enable`; a valve still booting is waited for. Returns the
        status after; NotEnabledError as :meth:`enable`."""
        return self._service.commissioning.commission()

    def disable(self) -> None:
        """Control word 0Fh → 0Bh → 09h → 08h: back to INIT step by step. Raises
        :class:`~prm9tool.device.enabling.NotDisabledError` (an AccessDeniedError) when the
        valve stays in DEVICE_MODE_ACTIVE, still following its setpoint."""
        self._service.commissioning.disable()

    def capture(
        self, signals: Sequence[str], seconds: float = 1.0, rate_hz: int | None = None
    ) -> Captured:
        """Record up to three measuring points for ``seconds`` at the valve's sample rate.

        ``signals``: the catalogue's signal keys (``demand``, ``position_actual``,
        ``current_a`` …: docs/api.md lists them). Returns one array per key in its display
        unit (%, mA, V, °C) and ``"t"``, the time of each sample in seconds from the first;
        ``.units`` names each unit, ``.to_dataframe()`` gives pandas users a DataFrame.
        ``rate_hz``: default the fastest the link streams without losing samples (over
        CANopen taken again slower while it lost some; SamplesLostError where even 62 Hz
        did); a rate asked for keeps a lost sample as NaN in its place.
        """
        from prm9tool.api.measure import capture

        return capture(self._session, signals, seconds, rate_hz)

    def generator(
        self,
        waveform: Waveform | str = "square",
        *,
        amplitude: float = 10.0,
        offset: float = 0.0,
        period: float = 1.0,
    ) -> SetpointGenerator:
        """The setpoint generator on this valve (not started): use it as a context manager,
        or call ``start()`` and ``stop()``. ``waveform`` ``step``, ``square`` or ``sine``,
        ``amplitude`` and ``offset`` in % of the setpoint range, ``period`` in s."""
        from prm9tool.api.measure import SetpointGenerator
        from prm9tool.scope.generator import GeneratorSettings
        from prm9tool.scope.generator import Waveform as Shape

        settings = GeneratorSettings(Shape(waveform), amplitude, offset, period)
        return SetpointGenerator(self._session, settings)

    def characterize(
        self,
        profile: Profile | str | os.PathLike[str] | None = None,
        progress: Callable[[str], None] | None = None,
    ) -> Characterization:
        """The end-of-line test (step responses, Bode, static characteristic) against an
        acceptance profile (a LIMITS.toml path or a Profile; default the built-in one), as
        ``--characterize`` runs it; ``report_data(result)`` of
        :mod:`prm9tool.characterize.run` is its JSON report. The result is recorded in the
        history as ``--characterize`` records it (a ``characterization`` record: verdict,
        figures, the parameters the valve ran with); a run that raises records nothing.
        Refused (MotionBusyError, nothing moved) while this valve's setpoint generator runs."""
        with _enable_hint():
            return self._service.characterize(profile, progress)

    def autotune(
        self,
        loop: str = "position",
        *,
        method: str = "model",
        overshoot_pct: float = 10.0,
        settling_ms: float | None = None,
        amplitude_pct: float | None = None,
        limit_pct: float = 60.0,
        profile: Profile | str | os.PathLike[str] | None = None,
        apply: bool = False,
        progress: Callable[[str], None] | None = None,
    ) -> AutotuneOutcome:
        """The Tuning window's autotune of ``loop`` (``position``; ``process`` on E04): steps
        with the present gains, a plant model fitted, gains chosen for ``overshoot_pct`` and
        ``settling_ms`` (``method="critical"``: P only with rising gain until the loop
        oscillates, stopped at ±``limit_pct``), the proposal checked against the acceptance
        profile. The valve's own gains are back afterwards; ``apply=True`` then writes the
        proposed ones and stores them. Returns an AutotuneOutcome (``proposed``, ``passes``,
        ``verdict()``, ``to_dict()``), recorded in the history as the window records it
        (``autotune``). Moves the spool. Refused (MotionBusyError, nothing moved) while this
        valve's setpoint generator runs; ValueError for a setting out of its range."""
        from prm9tool.analysis.profile import Profile as ProfileType
        from prm9tool.analysis.profile import load_profile
        from prm9tool.service.autotune import AutotuneSettings

        if profile is not None and not isinstance(profile, ProfileType):
            profile = load_profile(os.fspath(profile))
        settings = AutotuneSettings(loop, method, overshoot_pct, settling_ms, amplitude_pct,
                                    limit_pct, profile)  # fmt: skip
        with _enable_hint():
            return self._service.autotune(settings, apply, progress)

    def fit_twin(
        self,
        path: str | os.PathLike[str],
        profile: Profile | str | os.PathLike[str] | None = None,
        progress: Callable[[str], None] | None = None,
    ) -> ValveTwin:
        """The valve's twin (docs/twin.md), as ``--fit-twin OUT.toml --device ID`` makes it:
        the end-of-line test (moves the spool; recorded as :meth:`characterize` records it),
        its position-loop steps fitted by least squares, the twin file written to ``path``
        and recorded in the history (operation ``twin``). The result has the run, the fit
        (``fit.constants``: which constants the data determine) and the path; open the twin
        with ``prm9tool.connect(f"emulator:twin:{path}")``."""
        with _enable_hint():
            return self._service.fit_twin(path, profile, progress)

    def signature(
        self,
        profile: Profile | str | os.PathLike[str] | None = None,
        progress: Callable[[str], None] | None = None,
    ) -> DriftReport:
        """The field signature compared with the valve's birth certificate, as ``--signature``
        runs it (docs/twin.md "The birth certificate"): at most 20 s of motion (the spool
        moves: make sure the hydraulics are safe for it), each figure compared with the same
        figure of the valve's end-of-line test in the history and judged against the
        profile's ``[drift]`` limits. The result: ``passed``, ``drifted`` (the figures beyond
        their limit), ``lines()`` (in words), ``to_dict()`` (the JSON report); recorded as a
        ``signature``. NoReferenceError, nothing moved, when the history holds no
        characterization of this serial (run :meth:`characterize` first) or is off;
        MotionBusyError while this valve's setpoint generator runs."""
        with _enable_hint():
            return self._service.signature(profile, progress)

    def export_eds(self, path: str | os.PathLike[str]) -> None:
        """Write the CiA 306 EDS of this valve's type (what ``--export-eds TYPEKEY -o
        FILE.eds`` writes); a valve without CANopen is a TypeKeyError."""
        from prm9tool.service.export import write_eds

        write_eds(path, self.info.type_key)

    def export_dcf(self, path: str | os.PathLike[str]) -> int:
        """Write the valve's CiA 306 DCF (its working values, the node ID and bit rate it runs
        with after power-up), as the window's File → Export DCF and ``--export-dcf`` do;
        returns the node ID. TypeKeyError for a valve without CANopen (-CA)."""
        return self._service.export_dcf(path)

    # --- closing ------------------------------------------------------------------------------
    def close(self) -> None:
        """Close the link (idempotent)."""
        self._session.close()
        if (history := self._service.history) is not None:
            history.recorder.close()
            self._service.history = None

    def __enter__(self) -> Valve:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def __repr__(self) -> str:
        info = self.info
        state = "closed" if self.closed else "open"
        return f"<Valve {info.device_id} {info.type_key} serial {info.serial} ({state})>"


@contextlib.contextmanager
def _enable_hint() -> Iterator[None]:
    """A -CA valve that waits for its CANopen master: the error says how a script enables it."""
    from prm9tool.characterize.rig import WaitsForMasterError

    try:
        yield
    except WaitsForMasterError as exc:
        raise WaitsForMasterError(
            f"{exc}; call valve.commission() first (NMT start, then the control word 08h → 09h "
            "→ 0Bh → 0Fh, as its master does)"
        ) from None

"""One open valve for a script: :class:`Valve` (what :func:`prm9tool.connect` returns).

A thin, typed layer over the session every link implements
(:class:`prm9tool.device.session.ValveSession`): values in display units instead of raw
ones, the parameter set as a :class:`~prm9tool.api.params.ParameterSet`, the upload with the
batch mode's type check and backup, and what it did recorded in the history. No Qt.
"""

from __future__ import annotations

import logging
import os
import threading
import time
from collections.abc import Callable, Mapping, Sequence
from typing import TYPE_CHECKING

from prm9tool.api.params import Display, ParameterSet, as_parameter_set, display, lookup
from prm9tool.catalogue import CAPPED_BY, CATALOGUE, Parameter
from prm9tool.catalogue.commissioning import (
    CONTROL_WORD,
    DISABLE_SEQUENCE,
    NmtCommand,
)
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.device.records import DeviceInfo, Progress, UploadResult, Value, ValveStatus
from prm9tool.device.session import NotAvailableError
from prm9tool.device.upload_outcome import type_problem
from prm9tool.errors import (
    AccessDeniedError,
    DeviceTimeoutError,
    Prm9Error,
    TypeKeyError,
    ValueRangeError,
)

if TYPE_CHECKING:
    import numpy as np

    from prm9tool.analysis.profile import Profile
    from prm9tool.api.measure import SetpointGenerator
    from prm9tool.characterize.run import Characterization
    from prm9tool.device.emulated import EmulatorControls
    from prm9tool.device.session import ValveSession
    from prm9tool.online.recording import HistoryHook
    from prm9tool.scope.generator import Waveform

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
        self._session = session
        self._history_db, self._record_history = history_db, record_history
        self._command = command  # the records' "command" detail (the CLI's --set names itself)
        self._hook: HistoryHook | None = None
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
        raw = self.check({mnemonic: value})[mnemonic]  # ValueRangeError: nothing is sent
        self._session.write(mnemonic, raw)
        back = self._session.read(mnemonic)
        if back != raw:
            raise ReadBackError(mnemonic, display(param, raw), display(param, back))

    def check(self, values: Mapping[str, Display]) -> dict[str, Value]:
        """The raw values of ``values`` (display units) if this valve would take them: each in
        its catalogue range and, together with what the valve holds, within the rules between
        parameters (LIMTA/LIMTB at most its CURNORM, manual table 7-14). ValueRangeError
        names what is not; KeyError an unknown mnemonic. Sends nothing, reads the caps."""
        raw: dict[str, Value] = {}
        for mnemonic, value in values.items():
            param = self.parameter(mnemonic)
            raw[mnemonic] = param.to_raw(value)
            param.check_raw(raw[mnemonic])
        self._check_rules(raw)
        return raw

    def read(self, *mnemonics: str) -> dict[str, Display]:
        """Several parameters at once, in display units."""
        params = [self.parameter(m) for m in mnemonics]
        raw = self._session.read_many(list(mnemonics))
        return {p.mnemonic: display(p, raw[p.mnemonic]) for p in params if p.mnemonic in raw}

    def status(self) -> ValveStatus:
        """Device state, errors, LEDs, temperature, supply voltage and NMT state now."""
        return self._session.status()

    def wait_booted(self, timeout_s: float = 5.0) -> ValveStatus:
        """Ask for the status until the valve has finished booting (about 2 s after power-up
        or a restart, manual §1.5, §5.6), and return it; DeviceTimeoutError after
        ``timeout_s``. A booting valve ignores its setpoint, NMT commands and the control word.
        """
        deadline = time.monotonic() + timeout_s
        while (status := self._session.status()).booting:
            if time.monotonic() > deadline:
                raise DeviceTimeoutError(f"the valve has not finished booting in {timeout_s} s")
        return status

    # --- the parameter set --------------------------------------------------------------------
    def download(self, progress: Progress | None = None) -> ParameterSet:
        """The valve's parameter set (the working values; the *.prm file's parameters)."""
        values = self._session.download(progress)
        info = self.info
        if (history := self._history()) is not None:
            history.download(self._session, values, "")
        return ParameterSet(
            info.type_key, values, serial=info.serial, firmware=info.firmware or None
        )

    def upload(
        self,
        params: Mapping[str, Display],
        *,
        force_type: bool = False,
        backup: bool = True,
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
        CommunicationError naming the failed step.
        """
        wanted = as_parameter_set(params, self.type_key)
        problem = type_problem(wanted.type_key, self.type_key, force_type, "force_type=True")
        if problem is not None:
            raise TypeKeyError(problem)
        values = wanted.raw
        self._check_rules(values)  # a set the valve would refuse to store: nothing is sent
        if backup:
            self._backup(progress, cancel)
        if (history := self._history()) is None:
            return self._session.upload(values, progress, cancel)
        return history.upload(self._session, values, progress, cancel)  # as the GUI records it

    def store(self) -> None:
        """Make the working parameters permanent (the valve's non-volatile memory). Recorded
        as the GUI's Valve → Store is: with the set read back after the store."""
        if (history := self._history()) is None:
            self._session.store()
        else:
            from prm9tool.online.recording import store_and_read

            store_and_read(self._session, history)

    def restore_factory(self, *, backup: bool = True) -> None:
        """Reset the stored parameters to the factory values; they take effect at the next
        :meth:`restart`. ``backup``: first save the valve's parameters as its backup file,
        unless it has one (as the GUI does)."""
        path = self._backup(None, None) if backup else None
        self._session.restore_factory()
        if (history := self._history()) is not None:
            # no parameter set: the valve runs on its old one until the restart
            history.add(self._session, "restore-factory", "ok", None, {"backup": path})

    def restart(self, *, confirm_hydraulics_off: bool = False) -> None:
        """Restart the valve's electronics and reconnect. The spool moves to its rest position
        while the valve boots: only with the hydraulics off, which the caller confirms with
        ``confirm_hydraulics_off=True`` (AccessDeniedError without it, nothing sent)."""
        if not confirm_hydraulics_off:
            raise AccessDeniedError(
                "a restart moves the spool to its rest position: switch the hydraulics off "
                "and call restart(confirm_hydraulics_off=True)"
            )
        self._session.restart()

    # --- operation ----------------------------------------------------------------------------
    def nmt(self, command: NmtCommand | str) -> None:
        """Send an NMT command as the valve's CANopen master would (manual §7.2): an
        :class:`NmtCommand` or its name (``"start"``, ``"stop"``, ``"pre-operational"``,
        ``"reset-node"``, ``"reset-communication"``). A valve with CANopen off ignores it."""
        if isinstance(command, str):
            name = command.strip().upper().replace("-", "_").replace(" ", "_")
            if name not in NmtCommand.__members__:
                known = ", ".join(m.lower().replace("_", "-") for m in NmtCommand.__members__)
                raise ValueError(f"unknown NMT command {command!r}: one of {known}")
            command = NmtCommand[name]
        self._session.nmt(int(command))

    def enable(self) -> None:
        """Control word 08h → 09h → 0Bh → 0Fh (manual §7.4, table 7-19): from INIT or a
        fault whose cause is gone to DEVICE_MODE_ACTIVE, where the valve follows its setpoint.
        Raises :class:`~prm9tool.device.enabling.NotEnabledError` (an AccessDeniedError) when
        the valve does not get there, saying why (e.g. which error is still present)."""
        from prm9tool.device.enabling import enable

        enable(self._session)

    def disable(self) -> None:
        """Control word 0Fh → 0Bh → 09h → 08h: back to INIT step by step."""
        for word in DISABLE_SEQUENCE:
            self._session.write(CONTROL_WORD, word)

    def capture(
        self, signals: Sequence[str], seconds: float = 1.0, rate_hz: int | None = None
    ) -> dict[str, np.ndarray]:
        """Record up to three measuring points for ``seconds`` at the valve's sample rate.

        ``signals``: the catalogue's signal keys (``demand``, ``position_actual``,
        ``current_a`` …: docs/api.md lists them). Returns one array per key in its display
        unit (%, mA, V, °C) and ``"t"``, the time of each sample in seconds from the first.
        ``rate_hz``: default the fastest the link streams without losing samples.
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
        figures, the parameters the valve ran with); a run that raises records nothing."""
        from prm9tool.api.measure import characterize

        result = characterize(self._session, profile, progress)
        if (history := self._history()) is not None:
            history.characterization(self._session, result)
        return result

    # --- closing ------------------------------------------------------------------------------
    def close(self) -> None:
        """Close the link (idempotent)."""
        self._session.close()
        if self._hook is not None:
            self._hook.recorder.close()
            self._hook = None

    def __enter__(self) -> Valve:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def __repr__(self) -> str:
        info = self.info
        state = "closed" if self.closed else "open"
        return f"<Valve {info.device_id} {info.type_key} serial {info.serial} ({state})>"

    # --- internals ----------------------------------------------------------------------------
    def _check_rules(self, values: Mapping[str, Value]) -> None:
        """ValueRangeError naming every cross-parameter rule ``values`` break with the
        valve's own caps (LIMTA/LIMTB at most its CURNORM, manual table 7-14)."""
        caps = {CAPPED_BY[m] for m in values if m in CAPPED_BY}
        try:
            held = self._session.read_many(sorted(caps)) if caps else {}
        except NotAvailableError:  # a valve without the object: it checks the cap itself
            held = {}
        problems = CATALOGUE.check_rules(self._session.variant, {**values, **held})
        errors = [p.message for p in problems if p.severity == "error"]
        if errors:
            raise ValueRangeError("; ".join(errors))

    def _backup(self, progress: Progress | None, cancel: threading.Event | None) -> str | None:
        """Save the valve's parameters as its backup file unless it has one, and record it;
        the file's path (None: it had one)."""
        from prm9tool.files.backup import ensure_backup

        path = ensure_backup(self._session, progress, cancel)
        if path is None:
            return None
        if (history := self._history()) is not None:
            history.backup(self._session, path)
        return str(path)

    def _history(self) -> HistoryHook | None:
        """The history this valve records into (opened on first use); None with
        ``record_history=False``. A record the database cannot take is logged, never raised."""
        if not self._record_history:
            return None
        if self._hook is None:
            from prm9tool.history.recorder import Recorder
            from prm9tool.online.recording import HistoryHook

            report = lambda problem: log.warning("history: %s", problem)  # noqa: E731
            recorder = Recorder(self._history_db)
            self._hook = HistoryHook(recorder, report, {"command": self._command})
        return self._hook

"""Measuring with a valve from a script: :func:`capture`, :class:`SetpointGenerator` and
:func:`characterize`, each on the device layer's session and the engines the GUI and the
command line use (the oscilloscope's stream, the setpoint generator's driver, the end-of-line
test). No Qt.
"""

from __future__ import annotations

import logging
import os
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from prm9tool.catalogue.signals import BY_KEY, MAX_CHANNELS, signals_for
from prm9tool.errors import Prm9Error, ValueRangeError
from prm9tool.service.stream import SamplesLostError, record

if TYPE_CHECKING:
    from prm9tool.analysis.profile import Profile
    from prm9tool.characterize.run import Characterization
    from prm9tool.device.session import ValveSession
    from prm9tool.scope.generator import GeneratorSettings

__all__ = ["Captured", "SamplesLostError", "SetpointGenerator", "capture", "characterize"]

log = logging.getLogger("prm9tool.api")


class Captured(dict[str, np.ndarray]):
    """What :func:`capture` recorded: a mapping of each signal's key (and ``"t"``) to its
    samples, with :attr:`units` (the display unit of each, ``"s"`` for ``"t"``) and
    :meth:`to_dataframe` for pandas users (pandas is optional, not a dependency)."""

    units: dict[str, str]
    rate_hz: int

    def to_dataframe(self) -> Any:
        """A pandas ``DataFrame`` indexed by ``t``, one column per signal named
        ``"key [unit]"``; ImportError saying so where pandas is not installed."""
        try:
            import pandas as pd
        except ImportError as exc:
            raise ImportError(
                "to_dataframe() needs pandas (pip install pandas); the capture itself is a "
                "dict of numpy arrays"
            ) from exc
        columns = {f"{key} [{self.units[key]}]": v for key, v in self.items() if key != "t"}
        return pd.DataFrame(columns, index=pd.Index(self["t"], name="t [s]"))


def capture(
    session: ValveSession, keys: Sequence[str], seconds: float, rate_hz: int | None = None
) -> Captured:
    """``seconds`` of the measuring points ``keys`` in display units, plus ``"t"`` (s): the
    valve service's recording (:func:`prm9tool.service.stream.record`, the oscilloscope's
    stream reader) with units.

    At the default rate (``rate_hz`` None) nothing is lost: over CANopen a capture that lost a
    sample (the PC got busier than during the trial) is taken again at half the pace, and
    SamplesLostError says so where even the slowest pace lost some. With ``rate_hz`` a lost
    sample is NaN in its place."""
    keys = list(keys)
    _check_keys(session, keys)
    taken = record(session, keys, seconds, rate_hz)
    return _recorded(keys, taken.samples, taken.rate_hz)


def _recorded(keys: list[str], samples: np.ndarray, rate: int) -> Captured:
    data = Captured((key, samples[:, i] * BY_KEY[key].scale) for i, key in enumerate(keys))
    data["t"] = np.arange(len(samples)) / rate
    data.units = {**{key: BY_KEY[key].unit for key in keys}, "t": "s"}
    data.rate_hz = rate
    return data


def _check_keys(session: ValveSession, keys: list[str]) -> None:
    if not 1 <= len(keys) <= MAX_CHANNELS:
        raise ValueRangeError(f"capture: 1 to {MAX_CHANNELS} measuring points, not {len(keys)}")
    here = {s.key for s in signals_for(session.variant)}
    for key in keys:
        if key == "t":
            raise ValueRangeError("capture: 't' is the time the result adds, not a signal")
        if key not in here:
            known = ", ".join(s.key for s in signals_for(session.variant))
            where = "" if key in BY_KEY else " of the catalogue"
            raise ValueRangeError(
                f"capture: {key!r} is not a measuring point{where} on a "
                f"{session.variant.label} valve (known: {known})"
            )


class SetpointGenerator:
    """A waveform on the valve's setpoint (the GUI's setpoint generator, the same driver).

    ``with valve.generator("square", amplitude=20, period=0.5): data = valve.capture(...)``.
    Over USB it drives the service override SETPOVRON/SETPOVR, over CANopen RPDO1; when it
    stops the valve takes its setpoint from where it did before. A refusal while it runs ends
    it and is raised by :meth:`stop` (the valve's Prm9Error). While it runs it owns the valve's
    motion: a characterization refuses to start (MotionBusyError), and a second generator too.
    When the block under ``with`` raises (a capture that lost the link), that error is what
    the script sees; a failure to give the setpoint back is then logged and added as a note.
    """

    def __init__(self, session: ValveSession, settings: GeneratorSettings) -> None:
        from prm9tool.service.motion import owner_of
        from prm9tool.service.setpoint_driver import SetpointDriver

        settings.check()  # ValueRangeError: the waveform leaves the setpoint range
        self.settings = settings
        self.error: Prm9Error | None = None
        self._running = False
        self._motion = owner_of(session)
        self._driver = SetpointDriver(session, settings, self._refused)

    @property
    def running(self) -> bool:
        """True between :meth:`start` and :meth:`stop`."""
        return self._running

    def start(self) -> None:
        """Take the setpoint over and run the waveform (raises what the valve answered;
        MotionBusyError while another motion runs on the valve, nothing sent)."""
        if self._running:
            return
        self._motion.take("generator")
        try:
            self._driver.start()
        except BaseException:
            self._motion.release("generator")
            raise
        self._running = True

    def stop(self) -> None:
        """End the waveform and give the setpoint back; raises a refusal met while running."""
        if self._running:
            self._running = False
            try:
                self._driver.stop(switch_off=self.error is None)
            finally:
                self._motion.release("generator")
        if self.error is not None:
            raise self.error

    def __enter__(self) -> SetpointGenerator:
        self.start()
        return self

    def __exit__(self, exc_type: object, exc: BaseException | None, tb: object) -> None:
        if exc is None:
            self.stop()
            return
        try:  # the block's own error is the one that matters (the link lost in a capture)
            self.stop()
        except Exception as cleanup:  # reported with the block's error
            log.warning("setpoint generator: could not give the setpoint back: %s", cleanup)
            exc.add_note(f"and then the setpoint generator could not stop: {cleanup}")

    def __repr__(self) -> str:
        s = self.settings
        state = "running" if self._running else "stopped"
        return (
            f"<SetpointGenerator {s.waveform.value} amplitude {s.amplitude} % offset "
            f"{s.offset} % period {s.period} s ({state})>"
        )

    def _refused(self, mnemonic: str, error: Prm9Error) -> None:
        self.error = error
        del mnemonic  # the error names the object


def characterize(
    session: ValveSession,
    profile: Profile | str | os.PathLike[str] | None,
    progress: Callable[[str], None] | None,
) -> Characterization:
    """The end-of-line test of ``--characterize`` on the open ``session`` (the valve service's,
    :meth:`prm9tool.service.valve.ValveService.characterize`: refused while a generator runs;
    not recorded)."""
    from prm9tool.service.motion import claim
    from prm9tool.service.rigs import characterize_session

    with claim(session, "characterization"):
        return characterize_session(session, profile, progress)

"""Simulated closed-loop step responses for tuning the PIDT1 controllers (online layer, QtCore).

The controller dialogs show how the loop answers a setpoint step with the gains being tried.
The answer comes from the emulator's firmware (the same 200 µs control loop and plant the
emulated valve runs), stepped faster than real time in a worker thread; the GUI thread only
receives finished :class:`StepResponse` objects through a queued signal.

The simulated valve is an analog-only copy of the document's valve type (no CANopen master
needed) with the document's parameters. The setpoint chain in front of the loop under test is
made transparent (±10 V input, no threshold, no ramps, no linearization) so the response shows
the loop alone; for the process loop (E04) the deviation gain/offset stay, they are part of it.
"""

from __future__ import annotations

import math
import threading
from collections.abc import Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
from PySide6.QtCore import QCoreApplication, QObject, Signal

from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.characterize.autotune import emulated_step
from prm9tool.characterize.frame import LOOPS
from prm9tool.characterize.procedures import STEP_CAPTION
from prm9tool.characterize.transparent import NO_SHAPING, UNITY_GAIN
from prm9tool.errors import Prm9Error
from prm9tool.i18n import format_number
from prm9tool.messages import Number
from prm9tool.model.document import ParameterDocument
from prm9tool.scope.measure import StepFigures as ScopeFigures
from prm9tool.scope.measure import step_figures
from prm9tool.translate import translated

if TYPE_CHECKING:
    from prm9tool.device.emulator import EmulatedValve
    from prm9tool.device.emulator.constants import PlantConstants
    from prm9tool.online.twins import TwinPlant

Raw = int | str

_TRANSPARENT: dict[str, int] = {"AINSETP": 9, "INVERSEP": 0, **NO_SHAPING}
# The position loop alone: spool position control mode (no process loop on E04), no gain/offset.
_POSITION_ONLY: dict[str, int] = {"CTRLMODE": 2, **UNITY_GAIN}


@dataclass(frozen=True)
class StepFigures:
    """Figures of a step response, in % of the step and seconds."""

    overshoot_pct: float
    rise_time_s: float | None  # 10 → 90 % of the step; None if never reached
    settling_time_s: float | None  # into ±2 % of the final value for good; None if not settled
    steady_error_pct: float


@dataclass(frozen=True)
class StepResponse:
    """One simulated step: time (s, 0 = step) and the loop's setpoint and actual value (%)."""

    loop: str
    values: dict[str, int]
    t: tuple[float, ...]
    setpoint: tuple[float, ...]
    actual: tuple[float, ...]
    step_pct: float

    def measured(self) -> ScopeFigures | None:
        """The oscilloscope's figures of this step (None: the actual value did not move)."""
        t = np.asarray(self.t)
        return step_figures(t, np.asarray(self.actual), np.asarray(self.setpoint))

    def figures(self) -> StepFigures:
        """Overshoot, rise time, settling time and steady-state error relative to the step.

        The oscilloscope's definitions (:func:`prm9tool.scope.step_figures`, reference = the
        simulated setpoint), so the controller dialog and the scope give the same figures.
        """
        measured = self.measured()
        if measured is None:  # the actual value did not move at all
            return StepFigures(0.0, None, None, 100.0)
        step = measured.target - measured.initial
        error = measured.steady_state_error / step * 100.0 if step else math.nan
        return StepFigures(
            measured.overshoot,
            None if math.isnan(measured.rise_time) else measured.rise_time,
            None if math.isnan(measured.settling_time) else measured.settling_time,
            error,
        )

    def summary(self) -> str:
        """One line for the dialog: the step and its window, overshoot, rise time, settling
        time (or what the response did instead), remaining error."""
        f = self.figures()
        measured = self.measured()
        translate = QCoreApplication.translate  # the name pyside6-lupdate looks for

        def ms(value: float | None) -> str:
            return (
                translate("StepResponse", "not reached")
                if value is None
                else f"{format_number(value * 1000.0, 1)} ms"
            )

        why = measured.not_settled("%") if measured is not None else None
        caption = STEP_CAPTION(
            Number("0"),
            Number(f"{self.step_pct:g}"),
            Number(f"{self.t[0] * 1000.0:.0f}".replace("-", "−")),
            Number(f"{self.t[-1] * 1000.0:.0f}"),
        )
        return (
            translate(
                "StepResponse",
                "{0}: overshoot {1} %, rise time {2}, settling (±2 %) {3}, remaining error {4} %",
            )
            .replace("{0}", translated(caption))
            .replace("{1}", format_number(f.overshoot_pct, 1))
            .replace("{2}", ms(f.rise_time_s))
            .replace("{3}", ms(f.settling_time_s) if why is None else translated(why))
            .replace("{4}", format_number(f.steady_error_pct, 1))
        )


def simulation_values(base: Mapping[str, Raw], loop: str) -> dict[str, Raw]:
    """The parameter set the simulated valve gets: ``base`` with the chain made transparent."""
    values = dict(base)
    values.update(_TRANSPARENT)
    if loop == "position":
        values.update(_POSITION_ONLY)
    return values


def simulate_step(
    type_key: str | TypeKey,
    values: Mapping[str, Raw],
    loop: str,
    plant: PlantConstants | None = None,
) -> StepResponse:
    """Run the emulated valve through a setpoint step and return the loop's response.

    The autotune's step (:func:`prm9tool.characterize.autotune.emulated_step`: from rest at
    0 %, the same window, every 200 µs cycle), so the dialog and the autotune give the same
    figures for the same gains. Blocking (tens of milliseconds): call it off the GUI thread.
    Raises Prm9Error subclasses if the emulated valve refuses a parameter. ``plant``: the
    emulated valve's plant constants (a twin's, :mod:`prm9tool.online.twins`; default: the
    emulator's).
    """
    valve = _prepared_valve(type_key, values, loop, plant)
    lp = LOOPS[loop]
    result = emulated_step(valve, loop, lp.step_pct, lp.simulated_s)
    channels = result.record.channels
    return StepResponse(
        loop,
        {mn: int(v) for mn, v in values.items() if mn.startswith(("POS", "PRC"))},
        tuple(float(v) for v in result.record.t),
        tuple(float(v) for v in channels[lp.setpoint]),
        tuple(float(v) for v in channels[lp.actual]),
        lp.step_pct,
    )


def _prepared_valve(
    type_key: str | TypeKey,
    values: Mapping[str, Raw],
    loop: str,
    plant: PlantConstants | None = None,
) -> EmulatedValve:
    """A fresh analog-only emulated valve holding the simulation's parameter set."""
    from prm9tool.device.emulator import EmulatedValve  # lazy: the emulator is heavy to import

    analog = analog_type_key(type_key)
    valve = EmulatedValve(analog) if plant is None else EmulatedValve(analog, plant=plant)
    for mnemonic, raw in simulation_values(values, loop).items():
        param = CATALOGUE.get(mnemonic)
        if param is not None and param.writable and param.applies(analog.variant):
            valve.write(param.index, param.subindex, raw)
    if loop == "process":
        valve.set_input("sensor_from_plant", 1)
    return valve


def analog_type_key(type_key: str | TypeKey) -> TypeKey:
    """The same valve without CANopen: it runs from its analog input, no master needed."""
    key = TypeKey.parse(str(type_key))
    return TypeKey(key.size, key.spool, key.flow, key.supply, key.config, False)


def power_up(valve: EmulatedValve, limit_s: float = 5.0, step_s: float = 0.05) -> None:
    """Advance through the boot timeline until the setpoint is effective, then settle."""
    elapsed = 0.0
    while valve.status().booting and elapsed < limit_s:
        valve.advance(step_s)
        elapsed += step_s
    valve.advance(step_s)


class _Relay(QObject):
    """Carries results from the worker thread to the GUI thread (queued signals)."""

    finished = Signal(object)
    failed = Signal(str)


class StepSimulator(QObject):
    """Runs :func:`simulate_step` in a worker thread; the newest request wins.

    ``request(values)`` may be called as often as a slider moves: while one simulation runs,
    only the latest pending request is kept and run next.
    """

    response_ready = Signal(object)  # StepResponse
    failed = Signal(str)

    def __init__(
        self,
        type_key: str,
        base_values: Mapping[str, Raw],
        loop: str,
        parent: QObject | None = None,
        twin: TwinPlant | None = None,
    ) -> None:
        super().__init__(parent)
        self.twin = twin  # the plant it runs on: this twin's, else (None) the emulator's
        if loop not in LOOPS:
            raise ValueError(f"unknown loop {loop!r}; expected one of {', '.join(LOOPS)}")
        self.type_key, self.loop = type_key, loop
        self._base = dict(base_values)
        self._lock = threading.Lock()
        self._pending: dict[str, int] | None = None
        self._thread: threading.Thread | None = None
        self._stopped = False
        self._relay = _Relay()
        self._relay.finished.connect(self.response_ready)
        self._relay.failed.connect(self.failed)

    @classmethod
    def for_document(cls, document: ParameterDocument, loop: str) -> StepSimulator:
        """A simulator for ``document``'s valve type and current parameter values, on the
        plant of the newest twin the history has for the document's serial (if any)."""
        from prm9tool.online.twins import twin_plant

        twin = twin_plant(document.source_serial)
        return cls(str(document.type_key), dict(document.values), loop, twin=twin)

    @property
    def busy(self) -> bool:
        """True while a simulation runs or waits."""
        thread = self._thread
        return thread is not None and thread.is_alive()

    def request(self, controller_values: Mapping[str, int]) -> None:
        """Simulate with ``controller_values`` overriding the base set (asynchronous)."""
        with self._lock:
            if self._stopped:
                return
            self._pending = dict(controller_values)
            if self._thread is None or not self._thread.is_alive():
                self._thread = threading.Thread(
                    target=self._work, name="step-simulator", daemon=True
                )
                self._thread.start()

    def stop(self, timeout: float = 5.0) -> None:
        """Drop pending requests and wait for a running simulation to end."""
        with self._lock:
            self._stopped = True
            self._pending = None
            thread = self._thread
        if thread is not None:
            thread.join(timeout)

    def _work(self) -> None:
        relay = self._relay  # keeps the relay alive while the thread runs
        while True:
            with self._lock:
                values, self._pending = self._pending, None
            if values is None:
                return
            try:
                plant = self.twin.plant if self.twin is not None else None
                response = simulate_step(self.type_key, {**self._base, **values}, self.loop, plant)
            except (Prm9Error, ValueError) as exc:
                relay.failed.emit(str(exc))
                continue
            relay.finished.emit(response)

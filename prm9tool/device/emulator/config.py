"""From parameter values to loop coefficients, and the static part of the setpoint chain.

The firmware rebuilds the coefficients when a parameter changes (never per cycle). The blocks
from the setpoint input to the linearization are memoryless, so they are evaluated when their
input or a parameter changes; inputs only change between batches of cycles, so this gives the
same values the firmware would compute every 200 µs.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any, Generic, TypeVar

import numpy as np

from prm9tool.catalogue import dither
from prm9tool.catalogue.variant import Coils, Config, Variant
from prm9tool.device.emulator.constants import CYCLE_S, FULL, FirmwareConstants, PlantConstants
from prm9tool.device.emulator.inputs import INPUT_TYPES
from prm9tool.device.emulator.loopstate import Curve, evaluate_curve, prepare_curve

Values = Callable[[str], int]
T = TypeVar("T")
LETTERS = "ABCDEFGHI"
LVDT_SATURATION_MA = 3.8  # an intact 4…20 mA loop never reads lower (NAMUR NE 43; assumption)


class Memo(Generic[T]):
    """The last result of a pure function of parameter values and a few other inputs.

    :meth:`get` computes again only when an input or one of the values the last computation
    read has changed, else it returns the same object: a parameter write that leaves every
    value the loop's coefficients depend on as it was (an upload of the set the valve already
    has) costs a comparison, not a rebuild. Which values a computation reads may depend on
    values (a branch reads what it needs); unchanged values take the same branches. Pass
    floats among ``inputs`` as ``float.hex`` so that they compare bit for bit.
    """

    def __init__(self) -> None:
        self._inputs: tuple[object, ...] | None = None
        self._names: list[str] = []  # the values the last computation read, in order
        self._values: list[int] = []
        self._result: Any = None
        self._reader: Callable[[], list[int]] | None = None  # see get()

    def get(
        self,
        values: Values,
        inputs: tuple[object, ...],
        compute: Callable[[Values], T],
        reader_for: Callable[[list[str]], Callable[[], list[int]]] | None = None,
    ) -> T:
        """``compute(values)``, or its last result if nothing it depends on has changed.

        ``reader_for(names)``: a function that returns ``[values(m) for m in names]`` in one
        call; the check, run after every parameter write, then costs one call, not one per value.
        """
        if inputs == self._inputs:
            current = self._reader() if self._reader else [values(m) for m in self._names]
            if current == self._values:
                return self._result  # type: ignore[no-any-return]
        names: list[str] = []
        read: list[int] = []

        def recording(mnemonic: str) -> int:
            value = values(mnemonic)
            names.append(mnemonic)
            read.append(value)
            return value

        self._result = result = compute(recording)
        self._inputs, self._names, self._values = inputs, names, read
        self._reader = reader_for(names) if reader_for else None
        return result


def curve_of(values: Values, prefix: str) -> Curve:
    """The 9-point characteristic ``prefix`` (``SETPLIN`` or ``SENSLIN``)."""
    xs = [values(f"{prefix}X{k}") for k in LETTERS]
    ys = [values(f"{prefix}Y{k}") for k in LETTERS]
    return prepare_curve(xs, ys)


def setpoint_curve(values: Values) -> Curve:
    """The setpoint linearization's characteristic (``SETPLIN``)."""
    return curve_of(values, "SETPLIN")


def ramp_step(ms: int) -> float:
    """Counts per cycle of a ramp that takes ``ms`` for a 100 % step (0 = no ramp)."""
    return FULL * CYCLE_S / (ms / 1000.0) if ms > 0 else 1e12


def pidt1(kp: int, ki: int, kd: int, t1: int) -> tuple[float, float, float, float]:
    """Discrete PIDT1 coefficients from the raw parameters (Kp ×0.01, Ki ×0.1 1/s, ms ×0.01).

    The loop computes, per cycle ``dt``::

        I += Ki·dt·e
        D  = T1/(T1+dt)·D + Kd/(T1+dt)·(e − e_prev)      (backward Euler of Kd·s/(1+T1·s))
        u  = Kp·e + I + D
    """
    kd_s = kd * 1e-5
    t1_s = t1 * 1e-5
    denom = t1_s + CYCLE_S
    return kp * 0.01, ki * 0.1 * CYCLE_S, kd_s / denom, t1_s / denom


def gain_offset(gain: int, offset: int) -> tuple[float, float]:
    """Slope and jump of the dead-band compensation: ``y = off + x·g·(1 − off/100 %)``."""
    return gain / FULL * (FULL - offset) / FULL, float(offset)


def coil_discrete(r_ohm: float, plant: PlantConstants) -> tuple[float, float]:
    """Exact discretization of L·di/dt = u − R·i over one cycle: i' = a·i + b·u (mA, V)."""
    a = math.exp(-r_ohm * CYCLE_S / plant.coil_l_h)
    return a, (1.0 - a) / r_ohm * 1000.0


def coil_resistance(temperature_c: float, plant: PlantConstants) -> float:
    """Coil resistance at the electronics temperature (coil and electronics assumed equal)."""
    return plant.coil_r20_ohm * (1.0 + plant.copper_tc_per_k * (temperature_c - 20.0))


def process_loop_on(variant: Variant, values: Values) -> bool:
    """True if the process PIDT1 closes the outer loop (E04 in control mode 4)."""
    return variant.config is Config.E04 and values("CTRLMODE") == 4


def coefficients(
    variant: Variant,
    values: Values,
    plant: PlantConstants,
    fw: FirmwareConstants,
    temperature_c: float,
    supply_v: float,
) -> dict[str, Any]:
    """Every coefficient the control loop reads (see kernel.control_loop)."""
    curnorm = values("CURNORM")
    r_coil = coil_resistance(temperature_c, plant)
    e04 = variant.config is Config.E04
    return {
        "e04_plant": e04,
        "process_loop": process_loop_on(variant, values),
        "coils": variant.coils.value,
        "ramp_steps": tuple(
            ramp_step(values(mn))
            for mn in ("RAMPSETPOSUP", "RAMPSETPOSDOWN", "RAMPSETNEGUP", "RAMPSETNEGDOWN")
        ),
        "position_pid": pidt1(values("POSKP"), values("POSKI"), values("POSKD"), values("POST1")),
        "process_pid": pidt1(values("PRCKP"), values("PRCKI"), values("PRCKD"), values("PRCT1"))
        if e04
        else (0.0, 0.0, 0.0, 0.0),
        "ma_per_count": curnorm / FULL,
        "limits_ma": (
            min(values("LIMTA"), fw.max_current_ma),
            min(values("LIMTB"), fw.max_current_ma),
        ),
        "dither": (  # the rule the current-limiter dialog draws too (catalogue.dither)
            dither.amplitude_ma(values("DTAMP"), curnorm),
            2.0 * math.pi * dither.frequency_hz(values("DYNFREQ")) * CYCLE_S,
        ),
        "current_pi": (
            fw.current_kp_v_per_a / 1000.0,
            fw.current_ki_v_per_as * CYCLE_S / 1000.0,
            plant.coil_r20_ohm / 1000.0,
            plant.coil_r20_ohm / 1000.0,
        ),
        "max_current_v": 40.0,
        "mechanics": _mechanics(plant),
        "lvdt": _lvdt(plant, fw),
        "sensor": _sensor(variant, values, supply_v, fw),
        "sensor_curve": curve_of(values, "SENSLIN") if e04 else prepare_curve([0, 1], [0, 1]),
        "deviation_gain": (
            *gain_offset(values("GAINSETPOS"), values("OFFSETPOS")),
            *gain_offset(values("GAINSETNEG"), values("OFFSETNEG")),
        ),
        "actuator": (
            CYCLE_S / plant.actuator_full_speed_s / plant.stroke_m,
            plant.spool_overlap * plant.stroke_m,
            0.0 if variant.coils is Coils.AB else CYCLE_S / plant.actuator_return_s,
        ),
        "coil_discrete": (*coil_discrete(r_coil, plant), *coil_discrete(r_coil, plant)),
    }


def _mechanics(plant: PlantConstants) -> tuple[float, ...]:
    h = CYCLE_S / plant.substeps
    return (
        plant.force_n_per_a / 1000.0,
        plant.spring_n_per_m,
        plant.damping_n_s_per_m,
        plant.coulomb_friction_n,
        plant.static_friction_n,
        h / plant.spool_mass_kg,
        h,
        plant.substeps,
        plant.stroke_m * plant.end_stop,
        1.0 - math.exp(-CYCLE_S / plant.force_lag_s),
    )


def _lvdt(plant: PlantConstants, fw: FirmwareConstants) -> tuple[float, ...]:
    """A/D (counts per m, step, reading of a cut wire); 4…20 mA loop (mA per m, lowest mA).

    The loop current is 12 mA at the centre and 4 / 20 mA at −/+ ``lvdt_span`` of the stroke.
    """
    step = 2.0 * plant.lvdt_span * FULL / 2**fw.adc_bits
    ma_per_m = 8.0 / (plant.lvdt_span * plant.stroke_m)
    return FULL / plant.stroke_m / step, step, -plant.lvdt_span * FULL, ma_per_m, LVDT_SATURATION_MA


def _sensor(
    variant: Variant, values: Values, supply_v: float, fw: FirmwareConstants
) -> tuple[float, ...]:
    """Sensor A/D folded into ``s0 = round(act·a + b)·q + o``, then polarity, offset, gain."""
    if variant.config is not Config.E04:
        return (0.0, 0.0, 0.0, 0.0, False, 0.0, 1.0, False)
    code = values("SENSTYPE")
    kind = INPUT_TYPES.get(code, INPUT_TYPES[9])
    lo, hi = kind.span(supply_v)
    clamp = fw.current_input_range_ma if kind.unit == "mA" else fw.voltage_input_range_v
    step = 2.0 * clamp / 2**fw.adc_bits
    scale = (2.0 * FULL if kind.bipolar else FULL) / (hi - lo)
    offset = -FULL if kind.bipolar else 0.0
    return (
        (hi - lo) / step,
        lo / step,
        step * scale,
        offset - lo * scale,
        values("SENSINV") == 1,
        float(values("SENSOFFS")),
        values("SENSGAIN") / FULL,
        values("SENSLINON") == 1,
    )


def static_setpoint(
    variant: Variant, values: Values, raw: float, curve: Curve
) -> tuple[float, float, float, float]:
    """Polarity, threshold, gain/offset (E02 / control mode 2) and linearization of ``raw``."""
    x = -raw if values("INVERSEP") == 1 else raw
    if variant.coils is not Coils.AB and x < 0.0:
        x = 0.0  # single-coil valves: the negative side does not exist
    if abs(x) < values("THRESETP"):
        x = 0.0
    after_threshold = x
    if not process_loop_on(variant, values):
        if x > 0.0:
            g, off = gain_offset(values("GAINSETPOS"), values("OFFSETPOS"))
            x = off + x * g
        elif x < 0.0:
            g, off = gain_offset(values("GAINSETNEG"), values("OFFSETNEG"))
            x = -off + x * g
        x = min(max(x, -FULL), FULL)
    after_gain = x
    if values("SETPLINON") == -1:
        x = evaluate_curve(curve, x)
    return raw, after_threshold, after_gain, x


SetpointChain = tuple[bool, bool, int, bool, float, float, float, float, bool]


def setpoint_chain(variant: Variant, values: Values) -> SetpointChain:
    """The parameters :func:`static_setpoint` reads, for :func:`static_setpoint_array`."""
    return (
        values("INVERSEP") == 1,
        variant.coils is not Coils.AB,
        values("THRESETP"),
        not process_loop_on(variant, values),
        *gain_offset(values("GAINSETPOS"), values("OFFSETPOS")),
        *gain_offset(values("GAINSETNEG"), values("OFFSETNEG")),
        values("SETPLINON") == -1,
    )


def static_setpoint_array(chain: SetpointChain, raw: np.ndarray, curve: Curve) -> np.ndarray:
    """:func:`static_setpoint` of every value of ``raw``: rows (raw, threshold, gain, linear).

    The same IEEE operations element by element (numpy rounds each one like Python does), so
    every row equals the tuple :func:`static_setpoint` returns, bit for bit (the generator's
    waveform in the compiled loop; tests/test_emulator_kernels.py).
    """
    inverse, one_coil, threshold, gain_on, gp, op, gn, on_, linearize = chain
    raw = np.asarray(raw, dtype=np.float64)
    x = -raw if inverse else raw.copy()
    if one_coil:
        x[x < 0.0] = 0.0
    x[np.abs(x) < threshold] = 0.0
    after_threshold = x.copy()
    if gain_on:
        pos, neg = x > 0.0, x < 0.0
        x[pos] = op + x[pos] * gp
        x[neg] = -on_ + x[neg] * gn
        x = np.minimum(np.maximum(x, -FULL), FULL)
    after_gain = x.copy()
    if linearize:
        i = np.searchsorted(np.asarray(curve[0]), x, side="right")
        x = np.asarray(curve[2])[i] + np.asarray(curve[1])[i] * x
    return np.column_stack((raw, after_threshold, after_gain, x))

"""The compiled control loop is bit-identical to the Python reference (docs/emulator.md).

Each variant runs the same seeded random scenario twice, once per kernel (together minutes of
simulated time): setpoints, sensor and supply inputs, parameter writes, injected and cleared
faults, power cycles, captures and the setpoint generator's waveforms. After every step the
whole observable state is compared exactly: every measuring point, every object-dictionary
entry, the device state, the fault timers and history, the thermal model, the plant, the
captured samples, and the times of the 1 ms tasks' events (EMCY changes, listener calls).
Floats are compared by their bits (``float.hex``): no tolerance is needed because the C kernel
evaluates the same IEEE operations in the same order (no fused multiply-add), and its ``sin``
is the C library's, which CPython's ``math.sin`` also calls.
"""

from __future__ import annotations

import math
import random
from collections.abc import Callable, Iterator
from typing import Any

import numpy as np
import pytest

from prm9tool.catalogue import CATALOGUE
from prm9tool.device.emulator import EmulatedValve, kernels
from prm9tool.device.emulator.kernels import compiled_unavailable
from prm9tool.device.emulator.states import Fault
from prm9tool.errors import Prm9Error

pytestmark = pytest.mark.skipif(
    compiled_unavailable() is not None, reason=f"compiled kernel: {compiled_unavailable()}"
)

# (type key, switches): every variant, -CA both in analog mode and with CANopen on
VARIANTS = {
    "E02": ("PRM9-06.3Z11/30-24E02S02", None),
    "E04": ("PRM9-06.3Z11/30-24E04S02", None),
    "E02 coil A": ("PRM9-06.2Z51/30-24E02S02", None),
    "E02 coil B": ("PRM9-06.2Z61/30-24E02S02", None),
    "E04 coil A -CA analog": ("PRM9-06.2Z51/30-24E04S02-CA", (0, 2)),
    "E04 coil B -CA": ("PRM9-06.2Z61/30-24E04S02-CA", None),
    "E04 -CA analog": ("PRM9-06.3Z11/30-24E04S02-CA", (0, 2)),
    "E02 -CA": ("PRM9-06.3Z11/30-24E02S02-CA", None),
}
# per variant and kernel: 8 variants make 2 min 40 s of simulated time per kernel. Every variant
# meets every kind of event within its first seconds (EVERY_KIND, asserted) and a present fault
# is mostly cleared again (the valve goes on working); the rest repeats them at random. With 60 s
# per variant and only some kinds forced, the test took 75 s of CPU and caught fewer broken
# reference lines (docs/PERFORMANCE.md "Equivalence test"); now ~10 s.
SIMULATED_S = 20.0
# what every variant's scenario does early on, in this order (a sine with the override on, then
# off, then the generator off); the test checks each happened
EVERY_KIND = (
    "capture",
    "inject",
    "sine on",
    "parameter",
    "input",
    "clear",
    "restart",
    "setpoint",
    "sine off",
    "generator off",
)
PARAMETERS = (  # what a user tunes while the valve runs
    "RAMPSETPOSUP",
    "RAMPSETPOSDOWN",
    "RAMPSETNEGUP",
    "RAMPSETNEGDOWN",
    "POSKP",
    "POSKI",
    "POSKD",
    "POST1",
    "PRCKP",
    "PRCKI",
    "PRCKD",
    "PRCT1",
    "DTAMP",
    "DYNFREQ",
    "LIMTA",
    "LIMTB",
    "CURNORM",
    "THRESETP",
    "GAINSETPOS",
    "OFFSETPOS",
    "GAINSETNEG",
    "OFFSETNEG",
    "INVERSEP",
    "SETPLINON",
    "SENSLINON",
    "SENSINV",
    "SENSOFFS",
    "SENSGAIN",
    "SENSTYPE",
    "CTRLMODE",
    "MONTHRES",
    "MONDELAY",
    "SETPOVRON",
)
CAPTURE_KEYS = ("position_actual", "current_a", "current_b", "demand", "pwm_a", "sensor_raw")
Step = Callable[[EmulatedValve], Any]


def scenario(seed: int, canopen: bool) -> Iterator[tuple[str, Step, float]]:
    """(description, action, simulated seconds after it) until SIMULATED_S are used up."""
    rng = random.Random(seed)
    used = 0.0
    if canopen:
        yield "start", lambda v: v.nmt_command(1), 2.0
        yield "enable", lambda v: [v.write(0x6040, 0, w) for w in (0x01, 0x03, 0x07, 0x0F)], 0.01
        used += 2.01
    # every kind of event early in every variant, then a random mix until the time is used up
    first = list(EVERY_KIND)
    injected: list[Fault] = []
    while used < SIMULATED_S:
        forced = first.pop(0) if first else None
        kind = forced or rng.choice(
            ("setpoint",) * 6 + ("parameter",) * 5 + ("input", "fault", "capture", "generator")
        )
        # mostly short steps (every 1 ms task boundary is exercised), some long ones
        after = rng.choice((0.0002, 0.0006, 0.001, 0.0034, 0.05, 0.3, 1.0, 3.0))
        if kind == "setpoint":
            volts = round(rng.uniform(-10.0, 10.0), 3)
            yield f"setpoint {volts}", lambda v, x=volts: v.set_input("setpoint", x), after
        elif kind == "parameter":
            param = CATALOGUE[rng.choice(PARAMETERS)]
            value = rng.choice(
                (param.raw_min, param.raw_max, rng.randint(param.raw_min, param.raw_max))
            )
            yield (
                f"{param.mnemonic}={value}",
                lambda v, k=param.key, x=value: v.write(*k, x),
                after,
            )
        elif kind == "input":
            name, value = rng.choice(
                (
                    ("sensor", round(rng.uniform(-2.0, 22.0), 2)),
                    ("sensor_from_plant", float(rng.random() < 0.6)),
                    ("supply_voltage", rng.choice((24.0, 18.5, 30.0, 12.0, 40.0))),
                    ("ambient_temperature", rng.choice((25.0, 72.0, 99.0, 105.0, 40.0))),
                )
            )
            yield f"{name}={value}", lambda v, n=name, x=value: v.set_input(n, x), after
        elif kind == "restart":
            yield "restart", lambda v: v.restart(), after
        elif kind in ("fault", "inject", "clear"):
            if kind == "inject" or (kind == "fault" and rng.random() < 0.5):
                fault = rng.choice(list(Fault))
                injected.append(fault)
                yield f"inject {fault}", lambda v, f=fault: v.inject(f), after
            else:  # mostly one that is present, so that the valve works again
                fault = rng.choice(injected if injected and rng.random() < 0.7 else list(Fault))
                yield f"clear {fault}", lambda v, f=fault: v.clear(f), after
            if kind == "fault" and rng.random() < 0.1:
                yield "restart", lambda v: v.restart(), 0.0
        elif kind == "capture":
            keys = rng.sample(CAPTURE_KEYS, rng.randint(1, 3))
            decimation = rng.choice((1, 1, 3, 10))
            yield (
                f"capture {keys}/{decimation}",
                lambda v, k=keys, d=decimation: v.capture_start(k, d),
                after,
            )
        elif kind == "generator off" or (kind == "generator" and rng.random() < 0.4):
            yield "generator off", lambda v: v.drive_override(None), after
        else:
            freq = rng.choice((2.0, 20.0, 133.0))
            amp = rng.randint(1000, 16000)
            on = {"sine on": True, "sine off": False}.get(kind, rng.random() < 0.8)

            def wave(times: np.ndarray, f: float = freq, a: int = amp) -> np.ndarray:
                return np.round(a * np.sin(2.0 * np.pi * f * times))

            def drive(v: EmulatedValve, w: Callable[..., Any] = wave, o: bool = on) -> None:
                v.write(*CATALOGUE["SETPOVRON"].key, int(o))
                v.drive_override(w)

            # the reference applies a waveform one batch per value (~20 µs per cycle): kept
            # short, shorter still with the override off (a full input refresh per cycle)
            after = min(after, 0.3 if on else 0.05)
            yield f"sine {freq} Hz ±{amp} on={on}", drive, after
        used += after


def kind_of(text: str) -> str:
    """The kind of event (EVERY_KIND, or the CANopen start) a scenario step's text says."""
    word = text.split()[0]
    if word.split("=")[0] in PARAMETERS:
        return "parameter"
    if "=" in word:
        return "input"
    if word == "sine":
        return "sine on" if "on=True" in text else "sine off"
    return "generator off" if text.startswith("generator off") else word


def snapshot(valve: EmulatedValve, events: list[Any]) -> dict[str, Any]:
    """Everything observable, floats as their bits."""
    fw = valve.firmware
    od = {}
    for key, param in fw.od.entries.items():
        try:
            od[key] = fw.od.read(*key)
        except Prm9Error as exc:
            od[key] = type(exc).__name__
        del param
    timers = {
        k: (t.since.hex(), t.present, float(t.active_until).hex())
        for k, t in fw.faults.timers.items()
    }
    loop = fw.flush()
    return {
        "time": (fw.cycles, fw.ticks, fw.tick_countdown),
        "signals": {k: float(x).hex() for k, x in fw.signal_values().items()},
        "od": _bits(od),
        "status": repr(valve.status()),
        "faults": (timers, tuple(fw.faults.history), fw.faults.busy, fw.faults.any_present),
        "thermal": _bits((fw.temperature, fw.temperature_rise, fw.coil_temperature, fw.warning)),
        "plant": _bits((loop.spool_m, loop.spool_v, loop.actuator, loop.sensor_chain)),
        "outputs": _bits((loop.ctrl_dev, loop.current_ma, loop.duty, loop.lvdt_ma)),
        "capture": [float(x).hex() for x in valve.capture_read().ravel()],
        "events": _bits(events[:]),
    }


def _bits(value: Any) -> Any:
    if isinstance(value, float):
        return value.hex()
    if isinstance(value, (tuple, list)):
        return type(value)(_bits(v) for v in value)
    if isinstance(value, dict):
        return {k: _bits(v) for k, v in value.items()}
    return value


def run(kernel: str, type_key: str, switches: Any, seed: int) -> list[tuple[str, Any]]:
    """The scenario on a valve with ``kernel``: (step, snapshot) after every step."""
    kernels.use(kernel)
    try:
        valve = EmulatedValve(type_key, switches=switches)
    finally:
        kernels.use(None)
    assert valve.firmware.kernel == kernel
    fw = valve.firmware
    events: list[Any] = []
    valve.add_error_listener(lambda code, reg: events.append((fw.cycles, code, reg)))
    record = []
    canopen = valve.can_enabled
    if canopen:  # a listener every 1 ms, as the CANopen slave registers one
        valve.add_cycle_listener(lambda now: events.append(now) if fw.cycles % 997 == 0 else None)
    valve.advance(2.0)
    rng_watchdog = random.Random(seed + 1)
    for text, step, after in scenario(seed, canopen):
        try:
            step(valve)
        except Prm9Error as exc:  # out-of-range writes are refused alike by both
            text += f" refused: {type(exc).__name__}"
        if rng_watchdog.random() < 0.9:  # the override's watchdog mostly kept alive
            valve.usb_activity()
        valve.advance(after)
        record.append((text, snapshot(valve, events)))
        events.clear()
    return record


@pytest.mark.slow
@pytest.mark.parametrize("name", list(VARIANTS))
def test_compiled_kernel_is_bit_identical_to_the_reference(name: str) -> None:
    type_key, switches = VARIANTS[name]
    seed = sum(map(ord, name))
    reference = run("python", type_key, switches, seed)
    compiled = run("compiled", type_key, switches, seed)
    assert len(reference) == len(compiled) > 2 * len(EVERY_KIND)
    for k, ((text, want), (_, got)) in enumerate(zip(reference, compiled, strict=True)):
        if want != got:
            diff = {key: (want[key], got[key]) for key in want if want[key] != got[key]}
            detail = {key: _first_difference(a, b) for key, (a, b) in diff.items()}
            pytest.fail(f"step {k} ({text}) differs: {detail}")
    # the scenario did reach what it is meant to exercise
    assert {kind_of(text) for text, _ in reference} >= set(EVERY_KIND)
    assert any(snap["capture"] for _, snap in reference)
    assert any(snap["faults"][1] for _, snap in reference), "no error ever became active"


def _first_difference(a: Any, b: Any) -> Any:
    if isinstance(a, dict) and isinstance(b, dict):
        for key in a:
            if a.get(key) != b.get(key):
                return key, _first_difference(a.get(key), b.get(key))
    if isinstance(a, (list, tuple)) and isinstance(b, (list, tuple)):
        for i, (x, y) in enumerate(zip(a, b, strict=False)):
            if x != y:
                return i, _first_difference(x, y)
        return f"lengths {len(a)} != {len(b)}"
    return a, b


def test_capture_and_generator_are_exercised_by_a_sine_on_the_compiled_kernel() -> None:
    """A sine on the override reaches the loop (the scenario's waveforms are not no-ops)."""
    kernels.use("compiled")
    try:
        valve = EmulatedValve(VARIANTS["E02"][0])
    finally:
        kernels.use(None)
    valve.advance(2.0)
    valve.write(*CATALOGUE["SETPOVRON"].key, 1)
    valve.drive_override(lambda t: np.round(8000 * np.sin(2 * math.pi * 20.0 * t)))
    valve.capture_start(["setpoint_raw"])
    valve.usb_activity()
    valve.advance(0.05)
    samples = valve.capture_read()[:, 0]
    assert len(samples) == 250
    assert samples.max() > 7000 and samples.min() < -7000


@pytest.fixture
def fresh_choice() -> Iterator[None]:
    """The process's kernel choice forgotten before and after (chosen at the next valve)."""
    kernels.use(None)
    yield
    kernels.use(None)


def test_the_compiled_kernel_is_the_default_and_said_once_in_the_log(
    fresh_choice: None, monkeypatch: pytest.MonkeyPatch, caplog: pytest.LogCaptureFixture
) -> None:
    monkeypatch.delenv(kernels.ENV, raising=False)
    with caplog.at_level("INFO", logger=kernels.__name__):
        first = EmulatedValve(VARIANTS["E02"][0])
        second = EmulatedValve(VARIANTS["E04"][0])
    assert first.firmware.kernel == second.firmware.kernel == "compiled"
    said = [r.getMessage() for r in caplog.records if r.name == kernels.__name__]
    assert said == ["emulator: compiled control loop"]


def test_the_environment_variable_forces_the_python_kernel(
    fresh_choice: None, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv(kernels.ENV, "python")
    assert EmulatedValve(VARIANTS["E02"][0]).firmware.kernel == "python"


def test_an_unknown_kernel_name_is_a_clear_error(
    fresh_choice: None, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv(kernels.ENV, "fortran")
    with pytest.raises(
        Prm9Error, match=r"PRM9TOOL_EMULATOR_KERNEL='fortran': use 'python' or 'compiled'"
    ):
        EmulatedValve(VARIANTS["E02"][0])


def test_a_forced_compiled_kernel_that_is_unavailable_is_a_clear_error_and_else_python_runs(
    fresh_choice: None, monkeypatch: pytest.MonkeyPatch, caplog: pytest.LogCaptureFixture
) -> None:
    monkeypatch.setattr(kernels, "compiled_unavailable", lambda: "no _ckernel (no compiler)")
    monkeypatch.setenv(kernels.ENV, "compiled")
    with pytest.raises(Prm9Error, match="compiled kernel is unavailable: no _ckernel"):
        EmulatedValve(VARIANTS["E02"][0])
    monkeypatch.delenv(kernels.ENV)
    kernels.use(None)
    with caplog.at_level("WARNING", logger=kernels.__name__):
        valve = EmulatedValve(VARIANTS["E02"][0])
    assert valve.firmware.kernel == "python"
    assert "compiled control loop unavailable (no _ckernel (no compiler))" in caplog.text

"""The firmware rebuilds the loop's coefficients only when something they depend on changed."""

from __future__ import annotations

import contextlib
import random

from prm9tool.catalogue import CATALOGUE
from prm9tool.device.emulator import EmulatedValve, config
from prm9tool.errors import SdoAbortError

E04 = "PRM9-06.3Z11/30-24E04S02-CA"


def test_memo_computes_again_only_when_a_value_it_read_or_an_input_changed():
    values = {"MODE": 0, "GAIN": 5, "OTHER": 1}
    calls = []

    def compute(read):
        calls.append(1)
        return (read("MODE"), read("GAIN") if read("MODE") == 1 else None)

    memo: config.Memo[tuple] = config.Memo()
    first = memo.get(values.__getitem__, ((1.0).hex(),), compute)
    assert memo.get(values.__getitem__, ((1.0).hex(),), compute) is first and len(calls) == 1
    values["OTHER"] = 2  # not read
    values["GAIN"] = 6  # not read either while MODE is 0 (the branch that reads it was not taken)
    assert memo.get(values.__getitem__, ((1.0).hex(),), compute) is first and len(calls) == 1
    values["MODE"] = 1
    assert memo.get(values.__getitem__, ((1.0).hex(),), compute) == (1, 6) and len(calls) == 2
    values["GAIN"] = 7  # read now
    assert memo.get(values.__getitem__, ((1.0).hex(),), compute) == (1, 7) and len(calls) == 3
    memo.get(values.__getitem__, ((-0.0).hex(),), compute)
    memo.get(values.__getitem__, ((0.0).hex(),), compute)  # equal as floats, not bit for bit
    assert len(calls) == 5


def test_the_coefficients_always_equal_a_fresh_computation():
    """Random parameter writes, input changes and time: after each, the coefficients the loop
    runs on are bit for bit those computed from scratch, and the memo did save rebuilds."""
    valve = EmulatedValve(E04, 1)
    fw = valve.firmware
    sensor_type = CATALOGUE["SENSTYPE"]
    valve.write(sensor_type.index, sensor_type.subindex, 10)  # ratiometric: supply / 2 counts
    rng = random.Random(24)
    params = [p for p in CATALOGUE.file_parameters(valve.variant) if not p.is_string]
    rebuilt = []
    original = config.coefficients

    def counting(*args, **kwargs):
        rebuilt.append(1)
        return original(*args, **kwargs)

    config.coefficients = counting  # type: ignore[assignment]
    try:
        for step in range(300):
            param = rng.choice(params)
            if param is sensor_type:
                continue  # keep the type whose coefficients depend on the supply voltage
            if step % 3:  # the value it has (an upload of the same set) or a new one
                value = fw.od.values[param.key]
            else:
                value = rng.randint(param.raw_min, param.raw_max)
            with contextlib.suppress(SdoAbortError):  # a cross-parameter limit refused it
                valve.write(param.index, param.subindex, value)
            if step % 10 == 0:
                valve.set_input("supply_voltage", rng.choice([24.0, 18.0, 30.5]))
            valve.advance(rng.choice([0.0002, 0.001, 0.05]))
            fresh = original(fw.variant, fw.value, fw.plant, fw.fw, fw.coil_temperature, fw.supply)
            assert repr(fw.loop.coefficients) == repr(fresh), f"step {step}: {param.mnemonic}"
            assert repr(fw.setp_curve) == repr(config.curve_of(fw.value, "SETPLIN"))
    finally:
        config.coefficients = original  # type: ignore[assignment]
    assert 0 < len(rebuilt) < 250  # unchanged values were not rebuilt

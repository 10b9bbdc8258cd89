"""The compiled kernel passes the quiet 1 ms tasks itself on every platform (prm9tool's
``fasttick``): under Wine it gave every one back to Python, as the tick limit ``MAX_TICKS``
(1 << 40) was cast to a C ``long``, 32 bits on Windows, and came out negative."""

from __future__ import annotations

import ctypes

import pytest

from prm9tool.device.emulator import EmulatedValve, fasttick
from prm9tool.device.emulator.kernels import compiled_unavailable

LONG_32 = (-(2**31), 2**31 - 1)  # a C long on Windows (LLP64); 64 bits on Linux


def test_the_tick_limit_fits_a_32_bit_c_long() -> None:
    low, high = LONG_32
    assert low <= fasttick.MAX_TICKS <= high
    assert ctypes.c_int32(fasttick.MAX_TICKS).value == fasttick.MAX_TICKS  # passes unchanged


@pytest.mark.skipif(compiled_unavailable() is not None, reason="no compiled kernel")
def test_a_quiet_valve_leaves_few_1_ms_tasks_to_python(monkeypatch: pytest.MonkeyPatch) -> None:
    """One second of a valve at rest: the kernel passes nearly every 1 ms task itself, so the
    tick parameters are made per batch, not per millisecond (299 against 9 900 calls under
    Wine for the same run)."""
    valve = EmulatedValve("PRM9-06.3Z11/30-24E02S02", 1)
    fw = valve.firmware
    assert fw.kernel == "compiled"
    valve.advance(2.0)  # booted, at rest
    calls = {"parameters": 0, "python tick": 0}
    made, python_tick = fasttick.parameters, fw.tick

    def counted(fw):  # type: ignore[no-untyped-def]
        calls["parameters"] += 1
        return made(fw)

    def counted_tick() -> None:
        calls["python tick"] += 1
        python_tick()

    monkeypatch.setattr(fasttick, "parameters", counted)
    monkeypatch.setattr(fw, "tick", counted_tick)
    ticks = fw.ticks
    valve.advance(1.0)
    assert fw.ticks - ticks == 1000  # every 1 ms task ran, ...
    assert calls["python tick"] <= 100  # ... nearly all of them in the kernel
    assert calls["parameters"] <= 100

"""The PDO fast paths send and store exactly what the object dictionary's path does.

:mod:`prm9tool.device.emulator.pdo_fast` builds a TPDO's data from the compiled loop's state,
and :meth:`ObjectDictionary.write_mapped` writes an RPDO's entries by a plan made once per
mapping (docs/PERFORMANCE.md, "issue 30, third stop"). Three valves get the same seeded random
frames and steps — SYNC, RPDO1 (some too short), SDO writes, inputs, faults, time in uneven
steps, NMT commands, power cycles: one on the fast paths, one on the compiled kernel with the
object dictionary's paths (``read_mapped`` and ``write_bytes`` entry by entry) and one on the
Python kernel. Every frame each sends and, after every step, its object dictionary, device
state and loop outputs must be the same; at the end every measuring point too.
"""

from __future__ import annotations

import random
import struct
from typing import Any

import pytest
from support.valve_steps import run_step, sdo_download

from prm9tool.catalogue import CATALOGUE
from prm9tool.device.emulator import EmulatedValve, Fault, kernels
from prm9tool.device.emulator.kernels import compiled_unavailable
from prm9tool.device.emulator.objdict import ObjectDictionary
from prm9tool.errors import SdoAbortError

pytestmark = pytest.mark.skipif(
    compiled_unavailable() is not None, reason=f"compiled kernel: {compiled_unavailable()}"
)

E02 = "PRM9-06.3Z11/30-24E02S02-CA"
E04 = "PRM9-06.3Z11/30-24E04S02-CA"
NODE = 10
STEPS = 3000


class Recorder:
    """A python-can bus as far as the CANopen slave sends on it (no receive thread)."""

    def __init__(self) -> None:
        self.frames: list[tuple[int, bytes]] = []

    def send(self, msg: Any, timeout: float | None = None) -> None:
        self.frames.append((msg.arbitration_id, bytes(msg.data)))

    def recv(self, timeout: float | None = None) -> None:
        return None


def _reference_write(od: ObjectDictionary, entries: Any, data: bytes) -> list[SdoAbortError]:
    """write_mapped as it was: write_bytes of each entry's bytes in turn."""
    refused: list[SdoAbortError] = []
    offset = 0
    for index, sub, bits in entries:
        size = bits // 8
        try:
            od.write_bytes(index, sub, data[offset : offset + size])
        except SdoAbortError as exc:
            refused.append(exc)
        offset += size
    return refused


def _valve(type_key: str, kernel: str, fast: bool) -> tuple[EmulatedValve, Recorder, Any]:
    kernels.use(kernel)
    try:
        valve = EmulatedValve(type_key, 1)
    finally:
        kernels.use(None)
    if not fast:  # the object dictionary's paths for this valve only
        od = valve.firmware.od
        valve.pdo_sampler = lambda entries: None  # type: ignore[method-assign]
        od.write_mapped = lambda entries, data: _reference_write(od, entries, data)  # type: ignore[method-assign]
    bus = Recorder()
    return valve, bus, valve.connect_can(bus, receive=False)  # type: ignore[arg-type]


def _state(valve: EmulatedValve, versions: bool = True) -> tuple[Any, ...]:
    """What a step leaves behind, read without side effects (no flush)."""
    fw = valve.firmware
    loop = fw.loop
    return (
        sorted(fw.od.values.items()),
        fw.sm.state,
        fw.sm.control_word,
        float(loop.ctrl_dev).hex(),
        loop.mode,
        loop.inputs_version if versions else None,
        fw.faults.code(),
        fw.time,
    )


def _steps(seed: int, process: bool) -> list[tuple[str, Any]]:
    """The scenario: commissioning as the PLC rig does it, then random steps."""
    rng = random.Random(seed)
    steps: list[tuple[str, Any]] = [
        ("advance", 2.0),
        ("frame", (0x600 + NODE, sdo_download(0x1800, 2, 1, 1))),
    ]
    if process:
        steps.append(("frame", (0x600 + NODE, sdo_download(0x6043, 0, 4, 1))))
    steps.append(("frame", (0, bytes((1, NODE)))))
    for word in (8, 9, 11, 15):
        steps.append(("frame", (0x600 + NODE, sdo_download(0x6040, 0, word, 2))))
    monthres = CATALOGUE["MONTHRES"]
    for _ in range(STEPS):
        kind = rng.random()
        if kind < 0.35:
            steps.append(("frame", (0x80, b"")))
        elif kind < 0.65:
            word = rng.choice((0x0F, 0x0F, 0x0F, 0x0B, 0x09, 0x08, 0x07, 0x8F))
            setpoint = rng.choice((8000, -8000, rng.randint(-16384, 16384), 20000))
            data = struct.pack("<HH", word, setpoint & 0xFFFF)
            if rng.random() < 0.03:
                data = data[:3]  # too short: EMCY 8210
            steps.append(("frame", (0x200 + NODE, data)))
        elif kind < 0.85:
            steps.append(("advance", rng.choice((0.001, 0.002, 0.003, 0.007, 0.012))))
        elif kind < 0.89:
            value = rng.choice((0, 50, 400, 2000, 16384))
            steps.append(
                ("frame", (0x600 + NODE, sdo_download(monthres.index, monthres.subindex, value, 2)))
            )
        elif kind < 0.91:
            value = rng.randint(-16384, 16384)
            steps.append(("frame", (0x600 + NODE, sdo_download(0x6300, 1, value, 2))))
        elif kind < 0.93:
            steps.append(
                (
                    "frame",
                    (0x600 + NODE, sdo_download(0x1800, 2, rng.choice((0, 1, 1, 1, 2, 255)), 1)),
                )
            )
        elif kind < 0.95:
            steps.append((rng.choice(("inject", "clear")), rng.choice(list(Fault))))
        elif kind < 0.97:
            steps.append(("input", (rng.choice(("supply_voltage", "sensor")), rng.uniform(0, 30))))
        elif kind < 0.99:
            steps.append(("frame", (0, bytes((rng.choice((1, 1, 1, 1, 2, 0x80, 0x82)), NODE)))))
        elif kind < 0.998:
            steps.append(("advance", 0.5))
        else:
            steps.append(("restart", None))
    return steps


@pytest.mark.parametrize(("type_key", "seed"), [(E02, 1), (E02, 2), (E04, 3)])
def test_fast_pdo_paths_send_and_store_what_the_object_dictionary_does(type_key: str, seed: int):
    valves = [
        _valve(type_key, kernel, fast)
        for kernel, fast in (("compiled", True), ("compiled", False), ("python", False))
    ]
    for number, step in enumerate(_steps(seed, process=type_key == E04)):
        for valve, _, slave in valves:
            run_step(valve, slave, step)
        first = valves[0]
        for k, other in enumerate(valves[1:], 1):
            assert other[1].frames == first[1].frames, f"step {number}: {step}"
            # the input version counts refreshes: the Python kernel's 1 ms tasks make more of
            # them than the compiled kernel, which passes the tasks that change nothing
            versions = k == 1
            assert _state(other[0], versions) == _state(first[0], versions), f"step {number}"
    sent = [can_id for can_id, _ in valves[0][1].frames]
    assert sent.count(0x180 + NODE) > 100  # TPDO1 on SYNC, the fast path's frames
    signals = [valve.firmware.signal_values() for valve, _, _ in valves]
    assert signals[1] == signals[0] and signals[2] == signals[0]
    assert valves[0][0].pdo_sampler(((0x6041, 0, 16), (0x6301, 1, 16))) is not None


def test_write_mapped_refuses_and_stores_as_write_bytes_does():
    """Every mapping the catalogue's RPDOs can have, plus entries that do not exist, are read
    only or have another size, with random data: the same aborts and the same values."""
    rng = random.Random(7)
    fast, reference = EmulatedValve(E04, 1), EmulatedValve(E04, 1)
    candidates = [
        (0x6040, 0, 16),
        (0x6300, 1, 16),
        (0x6380, 1, 16),
        (0x2100, 2, 16),
        (0x6041, 0, 16),  # read-only
        (0x6043, 0, 8),  # choices
        (0x6353, 1, 16),  # a range
        (0x1017, 0, 16),
        (0x6300, 1, 8),  # not its size
        (0x7777, 0, 16),  # no such object
        (0x6300, 9, 16),  # no such sub-index
        (0x1008, 0, 32),  # a string
    ]
    for _ in range(3000):
        entries = tuple(rng.choice(candidates) for _ in range(rng.randint(1, 3)))
        data = bytes(rng.getrandbits(8) for _ in range(rng.randint(0, 8)))
        with fast.lock, reference.lock:
            got = fast.firmware.od.write_mapped(entries, data)
            want = _reference_write(reference.firmware.od, entries, data)
        assert [(e.index, e.subindex, e.code) for e in got] == [
            (e.index, e.subindex, e.code) for e in want
        ], (entries, data)
        assert fast.firmware.od.values == reference.firmware.od.values, (entries, data)


def test_read_all_answers_what_read_does_address_by_address():
    """The slave's poll and heartbeat read by one look-up: stored, live (getters), write-only,
    unstored and missing entries mixed, after writes and a power cycle (a new RAM image)."""
    rng = random.Random(11)
    valve = EmulatedValve(E02, 1)
    od = valve.firmware.od
    keys = sorted(od.entries)
    stored = [k for k in keys if k in od.values and k not in od.getters]
    candidates = [*stored[:40], *list(od.getters)[:10], *keys[-20:], (0x7777, 0), (0x1017, 0)]

    def one_by_one(addresses: tuple[tuple[int, int], ...]) -> tuple[Any, ...] | int:
        try:
            return tuple(od.read(*a) for a in addresses)
        except SdoAbortError as exc:
            return exc.code

    plain_seen = 0
    for round_ in range(400):
        if round_ == 200:
            valve.restart()
        addresses = tuple(rng.choice(candidates) for _ in range(rng.randint(1, 6)))
        if rng.random() < 0.5:
            addresses = tuple(rng.sample(stored, rng.randint(2, 6)))  # all plain
            plain_seen += 1
        valve.write(0x1017, 0, rng.randint(0, 3000))
        want = one_by_one(addresses)
        try:
            got: tuple[Any, ...] | int = od.read_all(addresses)
        except SdoAbortError as exc:
            got = exc.code
        assert got == want, addresses
    assert plain_seen > 100

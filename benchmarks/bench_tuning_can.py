"""The frequency response over CANopen at the bus's pace, quiet and on a loaded PC.

An emulated PRM9-06 E02 -CA valve runs in real time on a python-can ``virtual`` bus in this
process (NMT started, enabled as its master would: control word 08h→09h→0Bh→0Fh); prm9tool opens
it as ``can:10`` at 500 kbit/s and the :class:`~prm9tool.characterize.canrig.CanRig` samples at
the bus's pace: the setpoint in RPDO1 and the actual position in TPDO1 at a SYNC the tool
produces, each sample's time from its SYNC's number. A ±10 % sweep of 1–200 Hz over 4 s (limited
to 100 Hz by the 1 kHz sample rate) is run twice: on a quiet PC and with a busy-loop process on
every core. Printed for each: the sample rate, the samples lost, the wall time against the
sweep's 4 s, and the −3 dB and −90° frequencies against the reference measured in the same run:
the same sweep (1–100 Hz, 4 s) on the same emulated valve stepped directly at 5 kHz. Goal:
within 5 % both times, at ≥ 1 kHz.

    .venv/bin/python benchmarks/bench_tuning_can.py [--quick]

``--quick``: one short sweep (2 s), quiet only (the CI smoke run).
"""

from __future__ import annotations

import argparse
import multiprocessing
import os
import time
from collections.abc import Iterator
from contextlib import contextmanager

import can

from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.commissioning import ENABLE_SEQUENCE, NmtCommand
from prm9tool.characterize.canrig import CanRig
from prm9tool.characterize.procedures import BodeResult, bode_test
from prm9tool.characterize.rig import EmulatorRig
from prm9tool.device.canlink.bus import CanOptions
from prm9tool.device.canlink.session import CanopenSession
from prm9tool.device.emulator import EmulatedValve

TYPE_KEY = "PRM9-06.3Z11/30-24E02S02-CA"
BITRATE = 500_000
SWEEP_S = 4.0


def _spin(stop: multiprocessing.synchronize.Event) -> None:  # type: ignore[name-defined]
    while not stop.is_set():
        pass


@contextmanager
def busy_cores(count: int) -> Iterator[None]:
    """``count`` busy-loop processes for the duration."""
    stop = multiprocessing.Event()
    workers = [multiprocessing.Process(target=_spin, args=(stop,)) for _ in range(count)]
    for worker in workers:
        worker.start()
    try:
        yield
    finally:
        stop.set()
        for worker in workers:
            worker.join()


def over_can(sweep_s: float) -> tuple[BodeResult, CanRig, float]:
    """The sweep over CAN on a fresh emulated valve: result, rig, wall time."""
    channel = f"bench-tuning-can-{time.monotonic_ns()}"
    valve = EmulatedValve(TYPE_KEY, 4711)
    bus = can.Bus(interface="virtual", channel=channel)
    slave = valve.connect_can(bus)
    valve.advance(2.5)  # boot
    word = CATALOGUE["CONTROLWORD"]
    valve.nmt_command(NmtCommand.START)  # the setpoint travels in RPDO1: OPERATIONAL
    for value in ENABLE_SEQUENCE:
        valve.write(word.index, word.subindex, value)
    valve.start()
    try:
        with CanopenSession(CanOptions("virtual", channel, BITRATE), 10) as session:
            rig = CanRig(session)
            started = time.perf_counter()
            result = bode_test(rig, 10.0, 0.0, 1.0, 200.0, sweep_s)
            return result, rig, time.perf_counter() - started
    finally:
        valve.stop()
        slave.stop()
        bus.shutdown()


def report(label: str, result: BodeResult, rig: CanRig, wall: float, ref: BodeResult) -> None:
    """One run's lines."""
    n = len(result.record.t)
    bw, ref_bw = result.response.bandwidth_hz(), ref.response.bandwidth_hz()
    p90, ref_90 = result.response.phase_90_hz(), ref.response.phase_90_hz()
    print(f"{label}: {rig.info.sample_rate_hz:g} Hz ({rig.info.link})")
    print(f"  sweep {result.record.t[-1] + 1 / rig.info.sample_rate_hz:g} s to "
          f"{result.limited_to_hz or 200:g} Hz: wall {wall:.2f} s; samples lost "
          f"{int(rig.last_missing.sum())} of {n} in the sweep, {rig.lost} of {rig.samples} "
          "in all plays")  # fmt: skip
    print(f"  -3 dB at {bw:.2f} Hz over CAN, {ref_bw:.2f} Hz at 5 kHz "
          f"(ratio {bw / ref_bw:.3f})")  # fmt: skip
    print(f"  -90 deg at {p90:.2f} Hz over CAN, {ref_90:.2f} Hz at 5 kHz "
          f"(ratio {p90 / ref_90:.3f})")  # fmt: skip


def main() -> None:
    """One run (see the module docstring)."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="one short quiet sweep (CI)")
    quick = parser.parse_args().quick
    sweep_s = 2.0 if quick else SWEEP_S
    reference = bode_test(EmulatorRig(EmulatedValve(TYPE_KEY[:-3])), 10.0, 0.0, 1.0, 100.0, sweep_s)
    report("quiet PC", *over_can(sweep_s), reference)
    if quick:
        return
    cores = os.cpu_count() or 1
    with busy_cores(cores):
        report(f"loaded PC ({cores} busy-loop processes)", *over_can(sweep_s), reference)


if __name__ == "__main__":
    main()

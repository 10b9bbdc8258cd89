"""Characterization over the CANopen link: the sample rate the link keeps, and a sweep at it.

An emulated PRM9-06 E02 -CA valve runs in real time on a python-can ``virtual`` bus in this
process (enabled as its master would: control word 08h→09h→0Bh→0Fh); prm9tool opens it as
``can:10`` and the :class:`~prm9tool.characterize.canrig.CanRig` chooses its sample period from
measured SDO round trips. Printed: the period, a 4 s 1–200 Hz sweep's wall time against its 4 s
(the reference: real time), the samples taken late, the frequency the sweep was limited to, and
the −3 dB frequency measured, against the same sweep (1–50 Hz) on the emulator at 5 kHz in the
same run.

    .venv/bin/python benchmarks/bench_tuning_can.py [--quick]

``--quick`` (a smoke run) sweeps 1.5 s, or as long as the link's pace needs.
"""

from __future__ import annotations

import argparse
import time

import can

from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.commissioning import ENABLE_SEQUENCE, NmtCommand
from prm9tool.characterize.canrig import CanRig
from prm9tool.characterize.procedures import SWEEP_MIN_SAMPLES, bode_test
from prm9tool.characterize.rig import EmulatorRig
from prm9tool.device.canlink.bus import CanOptions
from prm9tool.device.canlink.session import CanopenSession
from prm9tool.device.emulator import EmulatedValve

TYPE_KEY = "PRM9-06.3Z11/30-24E02S02-CA"
SWEEP_S = 4.0


def main() -> None:
    """One run (see the module docstring)."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="a smoke run: seconds, not figures")
    quick = parser.parse_args().quick
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
        with CanopenSession(CanOptions("virtual", channel), 10) as session:
            rig = CanRig(session)
            # a smoke run sweeps just long enough for the pace the rig keeps on this PC
            fs = rig.info.sample_rate_hz
            sweep_s = max(1.5, 1.2 * SWEEP_MIN_SAMPLES / fs) if quick else SWEEP_S
            started = time.perf_counter()
            result = bode_test(rig, 10.0, 0.0, 1.0, 200.0, sweep_s)
            wall = time.perf_counter() - started
            n = len(result.record.t)
            print(f"sample period {rig.period_s * 1000:g} ms ({rig.info.sample_rate_hz:g} Hz)")
            print(f"sweep {sweep_s:g} s: wall {wall:.2f} s (wall / real time {wall / sweep_s:.2f})")
            print(f"late samples {rig.late} of {n}; {result.note}")
            can_bw = result.response.bandwidth_hz()
            reference = bode_test(
                EmulatorRig(EmulatedValve(TYPE_KEY[:-3])), 10.0, 0.0, 1.0, 50.0, sweep_s
            )
            ref_bw = reference.response.bandwidth_hz()
            print(f"-3 dB at {can_bw:.1f} Hz over CAN, {ref_bw:.1f} Hz at 5 kHz "
                  f"(ratio {can_bw / ref_bw:.3f})")  # fmt: skip
            can_90, ref_90 = result.response.phase_90_hz(), reference.response.phase_90_hz()
            print(f"-90 deg at {can_90:.1f} Hz over CAN, {ref_90:.1f} Hz at 5 kHz "
                  f"(ratio {can_90 / ref_90:.3f})")  # fmt: skip
    finally:
        valve.stop()
        slave.stop()
        bus.shutdown()


if __name__ == "__main__":
    main()

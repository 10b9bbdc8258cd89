"""A capture over CANopen at its default rate and at the bus's 1 kHz: the samples lost.

An emulated PRM9-06 E02 -CA valve runs in real time on a python-can ``virtual`` bus in this
process (NMT started, enabled as its master would: control word 08h→09h→0Bh→0Fh); prm9tool opens
it as ``can:10`` and captures the actual position for 1 s, three times at the default rate
(``prm9tool.api.measure.capture`` without ``rate_hz``: the first pace a 0.25 s trial kept
without loss, taken again at half the pace while it lost samples) and three times at the bus's
1 kHz, on the PC as it is and with a busy-loop
process on every core. Printed: the rate, the share of NaN (lost) samples, the wall time.

    .venv/bin/python benchmarks/bench_capture_can.py [--quick]

``--quick`` (the CI smoke run): one capture of each kind, 0.3 s, on the PC as it is.
"""

from __future__ import annotations

import argparse
import os
import time

import can
import numpy as np
from bench_tuning_can import busy_cores

from prm9tool.api.measure import SamplesLostError, capture
from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.commissioning import ENABLE_SEQUENCE, NmtCommand
from prm9tool.device.canlink.bus import CanOptions
from prm9tool.device.canlink.session import CanopenSession
from prm9tool.device.emulator import EmulatedValve

TYPE_KEY = "PRM9-06.3Z11/30-24E02S02-CA"


def runs(label: str, repeats: int = 3, seconds: float = 1.0) -> None:
    """``repeats`` captures at the default rate and as many at 1 kHz on a fresh valve."""
    channel = f"bench-capture-can-{time.monotonic_ns()}"
    valve = EmulatedValve(TYPE_KEY, 4712)
    bus = can.Bus(interface="virtual", channel=channel)
    slave = valve.connect_can(bus)
    valve.advance(2.5)  # boot
    word = CATALOGUE["CONTROLWORD"]
    valve.nmt_command(NmtCommand.START)
    for value in ENABLE_SEQUENCE:
        valve.write(word.index, word.subindex, value)
    valve.start()
    try:
        with CanopenSession(CanOptions("virtual", channel, 1_000_000), 10) as session:
            for rate in (None,) * repeats + (1000,) * repeats:
                started = time.perf_counter()
                how = "default" if rate is None else "1 kHz"
                try:
                    data = capture(session, ["position_actual"], seconds, rate)
                except SamplesLostError as exc:
                    print(f"{label}, {how}: refused ({exc})")
                    continue
                wall = time.perf_counter() - started
                hz = 1.0 / float(data["t"][1] - data["t"][0])
                lost = 100.0 * float(np.isnan(data["position_actual"]).mean())
                print(f"{label}, {how}: {hz:.0f} Hz, {lost:.1f} % lost, wall {wall:.2f} s")
    finally:
        valve.stop()
        slave.stop()
        bus.shutdown()


def main() -> None:
    """The PC as it is, then with a busy loop per core (``--quick``: as it is, once)."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="one short capture of each kind")
    if parser.parse_args().quick:
        runs("as it is", repeats=1, seconds=0.3)
        return
    runs("as it is")
    cores = os.cpu_count() or 1
    with busy_cores(cores):
        runs(f"{cores} busy loops")


if __name__ == "__main__":
    main()

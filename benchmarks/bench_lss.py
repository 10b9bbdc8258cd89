"""LSS commissioning (prm9tool.device.canlink.lss) against emulated valves at node-ID switch 1.

Prints, for N valves without a node ID on a python-can virtual bus (real time):

* the Fastscan of all of them (``LssMasterLink.scan``): wall time, LSS frames on the bus, the
  answer delay the probe measured and the per-step wait derived from it;
* giving each its node ID (``assign``: selective switch, inquire, configure, store, release)
  and the wait until it answers SDO there;
* as the reference in the same run, the SDO node scan of ``--list-devices``
  (``discovery.scan``: 127 requests, 0.3 s listening) once they have their IDs.

    .venv/bin/python benchmarks/bench_lss.py [--valves 2] [--quick]

``--quick`` (a smoke run): one valve.
"""

from __future__ import annotations

import argparse
import itertools
import time

import can

from prm9tool.device.canlink import discovery
from prm9tool.device.canlink.bus import CanOptions, acquire, release
from prm9tool.device.canlink.lss import LssMasterLink
from prm9tool.device.canlink.lss_nodes import answers_at
from prm9tool.device.emulator import EmulatedValve

E04 = "PRM9-06.3Z11/30-24E04S02-CA"


class Counter(can.Listener):
    """Counts the LSS frames (0x7E4, 0x7E5) seen on the bus."""

    def __init__(self) -> None:
        self.frames = 0

    def on_message_received(self, msg: can.Message) -> None:
        if msg.arbitration_id in (0x7E4, 0x7E5):
            self.frames += 1


def main() -> None:
    """Run the measurement and print the figures."""
    parser = argparse.ArgumentParser()
    parser.add_argument("--valves", type=int, default=2)
    parser.add_argument("--quick", action="store_true", help="a smoke run: seconds, not figures")
    args = parser.parse_args()
    count = 1 if args.quick else args.valves
    channel = f"bench-lss-{time.monotonic_ns()}"
    valves, slaves, buses = [], [], []
    for serial in itertools.islice(itertools.count(4711), count):
        valve = EmulatedValve(E04, serial, switches=(6, 1))
        bus = can.Bus(interface="virtual", channel=channel)
        slaves.append(valve.connect_can(bus))
        valves.append(valve)
        buses.append(bus)
        valve.start()
    counter_bus = can.Bus(interface="virtual", channel=channel)
    counter = Counter()
    notifier = can.Notifier(counter_bus, [counter])
    shared = acquire(CanOptions("virtual", channel))
    try:
        link = LssMasterLink(shared)
        start = time.perf_counter()
        found = link.scan()
        scan_s = time.perf_counter() - start
        scan_frames = counter.frames
        assert len(found) == count, found
        latency = link.latency_s or 0.0
        print(f"{count} valves at switch 1, virtual bus")
        print(
            f"Fastscan of all: {scan_s:.2f} s ({scan_s / count:.2f} s per valve), "
            f"{scan_frames} LSS frames; first answer after {latency * 1000:.2f} ms, "
            f"step wait {max(10 * latency, 0.05) * 1000:.0f} ms"
        )
        times = []
        for node, address in enumerate(found, start=21):
            start = time.perf_counter()
            link.assign(address, node)
            configured = time.perf_counter() - start
            assert answers_at(shared, node, address.serial, 10.0)
            times.append((configured, time.perf_counter() - start))
        for node, (configured, answered) in enumerate(times, start=21):
            print(f"assign node {node}: configured and stored {configured:.2f} s, "
                  f"answers SDO after {answered:.2f} s")  # fmt: skip
        start = time.perf_counter()
        nodes = discovery.scan(shared)
        reference = time.perf_counter() - start
        assert len(nodes) == count
        print(f"reference: SDO node scan (--list-devices) {reference:.2f} s; "
              f"Fastscan / node scan = {scan_s / reference:.1f}")  # fmt: skip
    finally:
        release(shared)
        notifier.stop()
        counter_bus.shutdown()
        for valve, slave, bus in zip(valves, slaves, buses, strict=True):
            valve.stop()
            slave.stop()
            bus.shutdown()


if __name__ == "__main__":
    main()

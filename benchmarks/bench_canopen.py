"""SDO round-trip time through the ``canopen`` package against the paced emulated valve.

Measures N expedited SDO reads (0x1018/4, serial number) of an emulated PRM9-...-CA running in
real time (``valve.start()``), and, in the same run and on the same kind of bus, two
references: a raw python-can echo (one frame out, one frame back through a Notifier thread)
and the canopen package's own SDO server (``LocalNode``). The manual (table 7-2) gives a
typical SDO answer < 10 ms and at most 150 ms for the real valve.

    .venv/bin/python benchmarks/bench_canopen.py [--reads 1000]
"""

from __future__ import annotations

import argparse
import statistics
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

import can
import canopen

from prm9tool.device.emulator import EmulatedValve
from prm9tool.files.eds import export_eds

TYPE_KEY = "PRM9-06.3Z11/30-24E02S02-CA"
NODE = 10


def timed(n: int, once: Callable[[], object]) -> list[float]:
    """``n`` timings of ``once()`` in seconds, after up to 50 warm-up calls."""
    for _ in range(min(50, n)):  # warm-up
        once()
    samples = []
    for _ in range(n):
        start = time.perf_counter()
        once()
        samples.append(time.perf_counter() - start)
    return samples


def _summary(name: str, samples: list[float]) -> dict[str, float]:
    ordered = sorted(samples)
    figures = {
        "median": statistics.median(ordered) * 1e3,
        "p99": ordered[min(len(ordered) - 1, int(0.99 * len(ordered)))] * 1e3,
        "max": ordered[-1] * 1e3,
    }
    print(
        f"{name:<34} median {figures['median']:7.3f} ms   p99 {figures['p99']:7.3f} ms   "
        f"max {figures['max']:7.3f} ms   (n={len(samples)})"
    )
    return figures


def _network(channel: str) -> canopen.Network:
    network = canopen.Network()
    network.NOTIFIER_CYCLE = 0.05
    network.connect(interface="virtual", channel=channel)
    return network


def bench_echo(n: int) -> list[float]:
    """Raw python-can: send a frame, a Notifier-thread listener sends one back."""
    channel = f"bench-echo-{time.monotonic_ns()}"
    master = can.Bus(interface="virtual", channel=channel)
    echo_bus = can.Bus(interface="virtual", channel=channel)

    def echo(msg: can.Message) -> None:
        echo_bus.send(can.Message(arbitration_id=0x58A, data=msg.data, is_extended_id=False))

    notifier = can.Notifier(echo_bus, [echo], timeout=0.05)
    request = can.Message(arbitration_id=0x60A, data=bytes(8), is_extended_id=False)

    def once() -> None:
        master.send(request)
        assert master.recv(1.0) is not None

    try:
        return timed(n, once)
    finally:
        notifier.stop()
        echo_bus.shutdown()
        master.shutdown()


def bench_local_node(n: int, eds: Path) -> list[float]:
    """The canopen package's own SDO server (LocalNode) answering the same read."""
    channel = f"bench-local-{time.monotonic_ns()}"
    server_net, client_net = _network(channel), _network(channel)
    local = canopen.LocalNode(NODE, str(eds))
    local.sdo[0x1018][4].raw = 200123
    server_net.add_node(local)
    remote = canopen.RemoteNode(NODE, str(eds))
    client_net.add_node(remote)
    try:
        return timed(n, lambda: remote.sdo.upload(0x1018, 4))
    finally:
        client_net.disconnect()
        server_net.disconnect()


def bench_emulator(n: int, eds: Path) -> list[float]:
    """The paced emulated valve (control loop running in real time) answering SDO reads."""
    channel = f"bench-valve-{time.monotonic_ns()}"
    valve = EmulatedValve(TYPE_KEY, serial=200123)
    valve_bus = can.Bus(interface="virtual", channel=channel)
    slave = valve.connect_can(valve_bus)
    network = _network(channel)
    node = canopen.RemoteNode(NODE, str(eds))
    network.add_node(node)
    valve.start()
    try:
        node.nmt.wait_for_bootup(10.0)
        return timed(n, lambda: node.sdo.upload(0x1018, 4))
    finally:
        valve.stop()
        network.disconnect()
        slave.stop()
        valve_bus.shutdown()


def main() -> None:
    """Run the three measurements and print the figures and ratios."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--reads", type=int, default=1000)
    parser.add_argument("--quick", action="store_true", help="a smoke run: seconds, not figures")
    args = parser.parse_args()
    n = 20 if args.quick else args.reads
    with tempfile.TemporaryDirectory() as folder:
        eds = Path(folder) / "prm9.eds"
        eds.write_text(export_eds(TYPE_KEY), encoding="ascii")
        echo = _summary("python-can virtual echo", bench_echo(n))
        local = _summary("canopen LocalNode SDO read", bench_local_node(n, eds))
        valve = _summary("emulated PRM9 (paced) SDO read", bench_emulator(n, eds))
    print(
        f"emulator / LocalNode: median x{valve['median'] / local['median']:.2f}, "
        f"p99 x{valve['p99'] / local['p99']:.2f};  "
        f"emulator / raw echo: median x{valve['median'] / echo['median']:.2f}"
    )
    verdict = "within" if valve["median"] < 10 and valve["max"] < 150 else "OUTSIDE"
    print(f"manual table 7-2 (typical < 10 ms, max 150 ms): {verdict}")


if __name__ == "__main__":
    main()

"""The CANopen link of prm9tool (device/canlink) against the emulated E04 -CA valve.

Prints, for one full E04 upload (write → verify → store, the upload contract of
prm9tool.device.session, as the CANopen link does it: values the valve holds already are not
sent, the store is made sure of by the node's boot-up frame and one read-back) over a python-can
virtual bus:

* the frames on the bus against the minimum the payload needs (one expedited SDO request +
  answer per value written, per value read back, and the store: 2 frames each), the
  time on the virtual bus, and the time those frames need on the wire at 500 and 125 kbit/s
  from their bit lengths (an 8-byte standard frame: 111 bits without stuff bits, 135 with the
  worst case, plus 3 bits of interframe space);
* what the scope gets per channel by SDO sampling (measured on the virtual bus, and the bus
  limit at 500 kbit/s);
* the SDO round trip of the session against the ``canopen`` package's own LocalNode server in
  the same run (same bus kind, same client).

    .venv/bin/python benchmarks/bench_can_link.py [--reads 500]
"""

from __future__ import annotations

import argparse
import statistics
import tempfile
import time
from pathlib import Path

import can
import canopen
from bench_canopen import timed

from prm9tool.device.canlink.bus import CanOptions
from prm9tool.device.canlink.session import CanopenSession
from prm9tool.device.emulator import EmulatedValve

E04 = "PRM9-06.3Z11/30-24E04S02-CA"
NODE = 10
BITS = 111 + 3  # an 8-byte standard data frame without stuff bits, with interframe space
BITS_STUFFED = 135 + 3  # the same with the worst-case stuff bits


class Counter(can.Listener):
    """Counts the frames seen on the bus (requests and answers alike)."""

    def __init__(self) -> None:
        self.frames = 0

    def on_message_received(self, msg: can.Message) -> None:
        self.frames += 1


def _changed(session: CanopenSession) -> dict[str, int | str]:
    """The whole file set, a few values changed within the catalogue's rules."""
    values = session.download()
    values.update(LIMTA=1500, LIMTB=1600, DYNFREQ=120, DTAMP=1000)
    return values


def _wire_ms(frames: int, bitrate: int, bits: int = BITS) -> float:
    return frames * bits / bitrate * 1000


def _upload_frames(
    session: CanopenSession, counter: Counter, values: dict[str, int | str]
) -> tuple[int, float, bool]:
    time.sleep(0.05)
    before, start = counter.frames, time.perf_counter()
    result = session.upload(values)
    elapsed = time.perf_counter() - start
    time.sleep(0.05)
    return counter.frames - before, elapsed, result.stored


def upload_figures(channel: str, folder: Path) -> None:
    """Frames and times of a full upload: into a session that has not read the values yet
    (cold) and into one that has (after a download: the batch's backup, the GUI online)."""
    valve = EmulatedValve(E04, 4711, nv_path=folder / "4711.json")
    valve_bus = can.Bus(interface="virtual", channel=channel)
    slave = valve.connect_can(valve_bus)
    valve.advance(2.5)
    listen = can.Bus(interface="virtual", channel=channel)
    counter = Counter()
    notifier = can.Notifier(listen, [counter])
    options = CanOptions("virtual", channel)
    try:
        with CanopenSession(options, NODE) as session:
            factory = session.download()
            values = _changed(session)
        with CanopenSession(options, NODE) as session:
            cold = _upload_frames(session, counter, values)
            warm = _upload_frames(session, counter, factory)
    finally:
        notifier.stop()
        listen.shutdown()
        slave.stop()
        valve_bus.shutdown()
    n, k = len(values), sum(values[m] != factory[m] for m in values)
    minimum = 2 * n + 2 * n + 2  # write + verify + store, one SDO exchange each
    print(f"E04 upload of {n} parameters, {k} of them changed (stored: {cold[2]} / {warm[2]})")
    print(
        f"  frames the payload needs (write + verify + store): {minimum}; the design sends "
        f"snapshot reads (cold) + the {k} changed writes + {n} verify reads + store + 1 read "
        f"after it: cold {4 * n + 2 * k + 4}, after a download {2 * n + 2 * k + 4}"
    )
    for name, (frames, elapsed, _) in (("cold (snapshot read)", cold), ("after a download", warm)):
        print(
            f"  {name}: {frames} frames -> {frames / minimum:.2f}x the minimum; "
            f"{elapsed * 1000:.1f} ms on the virtual bus"
        )
        for rate in (500_000, 125_000):
            wire, worst = _wire_ms(frames, rate), _wire_ms(frames, rate, BITS_STUFFED)
            least = _wire_ms(minimum, rate)
            print(
                f"    at {rate // 1000} kbit/s: {wire:.0f} ms on the wire ({worst:.0f} ms with "
                f"worst-case stuffing); the payload's minimum {least:.0f} ms -> {wire / least:.2f}x"
            )


def scope_figures(channel: str, folder: Path) -> None:
    """Samples per second per channel by SDO sampling, 1 and 3 channels."""
    valve = EmulatedValve(E04, 4712, nv_path=folder / "4712.json")
    valve_bus = can.Bus(interface="virtual", channel=channel)
    slave = valve.connect_can(valve_bus)
    valve.advance(2.5)
    try:
        with CanopenSession(CanOptions("virtual", channel), NODE) as session:
            for keys in (["position_actual"], ["position_actual", "process_actual", "temperature"]):
                session.stream_start(keys, 5000)
                time.sleep(1.0)
                rate = session.sample_rate_hz
                session.stream_stop()
                limit = 500_000 / (2 * BITS) / len(keys)
                print(
                    f"  scope, {len(keys)} channel(s) by SDO: {rate:.0f} samples/s per channel on "
                    f"the virtual bus; the 500 kbit/s bus allows at most {limit:.0f}"
                )
    finally:
        slave.stop()
        valve_bus.shutdown()
    pdo_figures(channel + "-pdo", folder)


def pdo_figures(channel: str, folder: Path) -> None:
    """TPDO1 at the tool's SYNC, the valve running in real time and OPERATIONAL."""
    valve = EmulatedValve(E04, 4714, nv_path=folder / "4714.json")
    valve_bus = can.Bus(interface="virtual", channel=channel)
    slave = valve.connect_can(valve_bus)
    valve.start()
    time.sleep(2.5)
    try:
        with CanopenSession(CanOptions("virtual", channel), NODE) as session:
            session.write("HEARTBEAT", 20)
            session.write("CTRLMODE", 2)
            session.nmt(0x01)
            time.sleep(0.2)
            for rate_hz in (1000, 500):
                session.stream_start(["position_actual"], rate_hz)
                time.sleep(1.0)
                got, lost, source = (
                    session.sample_rate_hz,
                    session.samples_lost,
                    session.stream_source,
                )
                session.stream_stop()
                print(
                    f"  scope by TPDO1 ({source}) at a {1000 / rate_hz:g} ms SYNC: {got:.0f} samples/s "
                    f"on the virtual bus, {lost} SYNC periods without a sample"
                )
    finally:
        valve.stop()
        slave.stop()
        valve_bus.shutdown()
    sync_and_tpdo1 = (47 + 3) + (47 + 32 + 3)  # SYNC (no data) + TPDO1 (4 bytes), bits
    print(
        f"  a 1 ms SYNC + TPDO1 takes {sync_and_tpdo1 * 1000 / 500_000 * 100:.0f} % of a "
        f"500 kbit/s bus, {sync_and_tpdo1 * 1000 / 125_000 * 100:.0f} % of 125 kbit/s"
    )


def several_valves_figures(channel: str, folder: Path, count: int = 3) -> None:
    """``count`` valves on one bus: uploaded one after another and interleaved (threads, as
    ``--batch`` does); frames on the bus and time on the virtual bus."""
    from concurrent.futures import ThreadPoolExecutor

    valves, buses, slaves = [], [], []
    for k in range(count):
        valve = EmulatedValve(E04, 4720 + k, nv_path=folder / f"{4720 + k}.json")
        valve.set_input("switch_node", 2 + k)  # nodes 10, 15, 20
        valve.restart()
        bus = can.Bus(interface="virtual", channel=channel)
        slaves.append(valve.connect_can(bus))
        valve.advance(2.5)
        valves.append(valve)
        buses.append(bus)
    options = CanOptions("virtual", channel)
    sessions = [CanopenSession(options, 10 + 5 * k) for k in range(count)]
    try:
        sets = [_changed(session) for session in sessions]
        start = time.perf_counter()
        for session, values in zip(sessions, sets, strict=True):
            session.upload(values)
        one_by_one = time.perf_counter() - start
        start = time.perf_counter()
        with ThreadPoolExecutor(max_workers=count) as pool:
            list(pool.map(lambda pair: pair[0].upload(pair[1]), zip(sessions, sets, strict=True)))
        interleaved = time.perf_counter() - start
    finally:
        for session in sessions:
            session.close()
        for slave, bus in zip(slaves, buses, strict=True):
            slave.stop()
            bus.shutdown()
    print(
        f"  {count} valves on one bus: one after another {one_by_one * 1000:.0f} ms, interleaved "
        f"{interleaved * 1000:.0f} ms on the virtual bus (x{one_by_one / interleaved:.2f}); on the "
        "wire the frames are the same, so a loaded bus gains nothing from interleaving beyond "
        "hiding each node's answer time"
    )


def round_trip_figures(channel: str, folder: Path, reads: int) -> None:
    """SDO read: the session against canopen's LocalNode, same run."""
    valve = EmulatedValve(E04, 4713, nv_path=folder / "4713.json")
    valve_bus = can.Bus(interface="virtual", channel=channel)
    slave = valve.connect_can(valve_bus)
    valve.advance(2.5)
    try:
        with CanopenSession(CanOptions("virtual", channel), NODE) as session:
            ours = timed(reads, lambda: session.read("SNV"))
    finally:
        slave.stop()
        valve_bus.shutdown()
    ref_channel = channel + "-ref"
    server = canopen.Network()
    server.connect(interface="virtual", channel=ref_channel)
    od = canopen.ObjectDictionary()
    var = canopen.objectdictionary.ODVariable("serial", 0x1018, 0)
    var.data_type, var.default = canopen.objectdictionary.UNSIGNED32, 4713
    od.add_object(var)
    server.add_node(canopen.LocalNode(NODE, od))
    client = canopen.Network()
    client.connect(interface="virtual", channel=ref_channel)
    remote = client.add_node(NODE, canopen.ObjectDictionary())
    try:
        reference = timed(reads, lambda: remote.sdo.upload(0x1018, 0))
    finally:
        client.disconnect()
        server.disconnect()
    a, b = statistics.median(ours), statistics.median(reference)
    print(
        f"  SDO read round trip, median of {reads}: session {a * 1e6:.0f} µs, canopen LocalNode "
        f"{b * 1e6:.0f} µs -> ratio {a / b:.2f}"
    )


def main() -> None:
    """Run the three measurements."""
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--reads", type=int, default=500)
    parser.add_argument("--quick", action="store_true", help="a smoke run: seconds, not figures")
    args = parser.parse_args()
    if args.quick:
        args.reads = 20
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        stamp = time.monotonic_ns()
        upload_figures(f"bench-up-{stamp}", folder)
        scope_figures(f"bench-scope-{stamp}", folder)
        round_trip_figures(f"bench-rt-{stamp}", folder, args.reads)
        several_valves_figures(f"bench-many-{stamp}", folder)


if __name__ == "__main__":
    main()

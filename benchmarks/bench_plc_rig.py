"""The emulated valves as a PLC's test rig: N valves in one ``--serve-emulator`` process, the PLC
in this one (the ``canopen`` package for commissioning, python-can for SYNC, RPDO1 and TPDO1),
on python-can's udp_multicast bus inside a private network namespace (``unshare -n``, loopback
only: multicast never leaves the machine).

Per valve count it prints the share of TPDO1 frames that arrived within 1 ms of their SYNC
(kernel reception time stamps on both ends), the p50/p99/max latency after SYNC, the SYNCs
actually sent per second, the EMCYs seen (none expected: every one is a false alarm here),
and the machine's load average; the single-valve run of the same invocation is the reference.

    .venv/bin/python benchmarks/bench_plc_rig.py [--valves 1,4,8,16,32] [--seconds 10] [--quick]

The SYNC period is 1 ms up to 16 valves and 2 ms above (the issue's 32 valves at 2 ms).
``--quick`` (a smoke run, CI): 1 and 2 valves for 1 s each. Needs ``unshare -n`` (root or user
namespaces); without it the benchmark says so and exits 0.
"""

from __future__ import annotations

import argparse
import bisect
import os
import shutil
import signal
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from dataclasses import dataclass
from pathlib import Path

E02 = "PRM9-06.3Z11/30-24E02S02-CA"
GROUP = "239.74.163.11"
NAMESPACE = "ip link set lo up && ip link set lo multicast on && ip route add 224.0.0.0/4 dev lo"
ON_TIME_S = 0.001
FAULTY = 2  # the node whose coil A is disconnected for the middle third of each run
INSIDE = "PRM9_BENCH_PLC_RIG_INSIDE"
sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
from prm9tool.device.emulator.canopen_hub import enlarge_receive_buffer  # noqa: E402


@dataclass
class Result:
    """One run's figures."""

    valves: int
    period_ms: float
    on_time: float  # share of the expected TPDO1 frames within ON_TIME_S of their SYNC
    fifo_on_time: float  # the same with each TPDO1 answering the oldest unanswered SYNC
    received: float  # share of the expected TPDO1 frames received at all
    p50_ms: float
    p99_ms: float
    max_ms: float
    syncs_per_s: float
    emcy: int
    load: float
    dropped: int  # datagrams the kernel dropped for a full socket buffer (either process)
    plc_dropped: int  # of those, dropped at the PLC's own socket
    serve_cpu: float  # CPU seconds the serving process used per second of the run


def main() -> int:
    """Parse the options, run inside a private network namespace, print the table."""
    parser = argparse.ArgumentParser()
    parser.add_argument("--valves", default="1,4,8,16,32")
    parser.add_argument("--seconds", type=float, default=10.0)
    parser.add_argument("--quick", action="store_true", help="a smoke run: seconds, not figures")
    parser.add_argument("--profile", help="sample the serving process's stacks into this file")
    args = parser.parse_args()
    if os.environ.get(INSIDE) != "1":
        return _enter_namespace()
    counts = [1, 2] if args.quick else [int(n) for n in args.valves.split(",")]
    seconds = 1.0 if args.quick else args.seconds
    if counts[0] != 1:
        counts.insert(0, 1)  # the reference
    print(f"PLC rig on udp_multicast {GROUP}, {seconds:g} s per run, load before "
          f"{os.getloadavg()[0]:.2f}")  # fmt: skip
    per_frame(500 if args.quick else 5000)
    print(f"{'valves':>6} {'SYNC':>6} {'on time':>8} {'FIFO':>7} {'got':>7} {'p50':>7} {'p99':>7} "
          f"{'max':>7} {'SYNC/s':>7} {'EMCY':>5} {'load':>5} {'drops':>6} {'PLC':>6} {'CPU':>5}")  # fmt: skip
    results = []
    for count in counts:
        profile = f"{args.profile}.{count}" if args.profile else None
        result = run(count, 1.0 if count <= 16 else 2.0, seconds, profile)
        results.append(result)
        print(f"{result.valves:>6} {result.period_ms:>4g}ms {result.on_time:>8.2%} "
              f"{result.fifo_on_time:>7.2%} "
              f"{result.received:>7.1%} "
              f"{result.p50_ms:>5.2f}ms {result.p99_ms:>5.2f}ms {result.max_ms:>5.1f}ms "
              f"{result.syncs_per_s:>7.0f} {result.emcy:>5} {result.load:>5.2f} {result.dropped:>6} {result.plc_dropped:>6} {result.serve_cpu:>5.2f}",
              flush=True)  # fmt: skip
    reference = results[0]
    for result in results[1:]:
        print(f"{result.valves} valves: on-time share {result.on_time:.2%} against "
              f"{reference.on_time:.2%} for one valve; p99 {result.p99_ms / max(reference.p99_ms, 1e-3):.1f}x")  # fmt: skip
    return 0


def per_frame(n: int) -> None:
    """The per-frame path of one served valve, in process with a bus that sends nothing: what
    a SYNC (TPDO1 sampled and encoded) and an RPDO1 cost, against udp_multicast's decoding and
    1 ms of the control loop."""
    import can
    import can.interfaces.udp_multicast.utils as udp

    from prm9tool.device.emulator import EmulatedValve

    class NullBus(can.BusABC):
        def __init__(self) -> None:
            super().__init__(channel="null")

        def send(self, msg: can.Message, timeout: float | None = None) -> None:
            pass

        def _recv_internal(self, timeout: float | None) -> tuple[None, bool]:
            time.sleep(timeout or 0.01)
            return None, False

    bus = NullBus()
    valve = EmulatedValve(E02, 1)
    slave = valve.connect_can(bus, receive=False)
    valve.advance(2.0)

    def frame(can_id: int, data: bytes) -> can.Message:
        return can.Message(arbitration_id=can_id, data=data, is_extended_id=False,
                           timestamp=time.time())  # fmt: skip

    for data in (bytes.fromhex("2F00180201000000"), *(bytes([0x2B, 0x40, 0x60, 0, w, 0, 0, 0])
                 for w in (8, 9, 11, 15))):  # fmt: skip
        slave.receive_frame(frame(0x60A, data))
    slave.receive_frame(frame(0, b"\x01\x0a"))
    slave.receive_frame(frame(0x60A, bytes([0x2B, 0x40, 0x60, 0, 15, 0, 0, 0])))
    sync, rpdo = frame(0x80, b""), frame(0x20A, bytes([15, 0, 0x40, 0x1F]))
    packed = udp.pack_message(rpdo)
    steps = {
        "SYNC (TPDO1 out)": lambda: slave.receive_frame(sync),
        "RPDO1": lambda: slave.receive_frame(rpdo),
        "udp_multicast decode": lambda: udp.unpack_message(packed, replace={"timestamp": 1.0}),
        "udp_multicast encode": lambda: udp.pack_message(rpdo),
        "1 ms of the loop": lambda: valve.advance(0.001),
    }
    costs = []
    for name, step in steps.items():
        started = time.perf_counter()
        for _ in range(n):
            step()
        costs.append(f"{name} {(time.perf_counter() - started) / n * 1e6:.1f} us")
    print("per frame: " + ", ".join(costs))
    slave.stop()
    bus.shutdown()


def _enter_namespace() -> int:
    if shutil.which("unshare") is None or shutil.which("ip") is None:
        print("bench_plc_rig: needs unshare and ip (iproute2); skipped")
        return 0
    probe = subprocess.run(["unshare", "-n", "sh", "-c", NAMESPACE], capture_output=True,
                           text=True, check=False)  # fmt: skip
    if probe.returncode != 0:
        print(f"bench_plc_rig: a private network namespace is not permitted: {probe.stderr}")
        return 0
    command = " ".join([sys.executable, *map(_quote, sys.argv)])
    env = {**os.environ, INSIDE: "1"}
    return subprocess.run(["unshare", "-n", "sh", "-c", f"{NAMESPACE} && exec {command}"],
                          env=env, check=False).returncode  # fmt: skip


def _quote(text: str) -> str:
    return "'" + text.replace("'", "'\\''") + "'"


def run(count: int, period_ms: float, seconds: float, profile: str | None = None) -> Result:
    """Serve ``count`` valves (nodes 1…count), commission them, run SYNC for ``seconds``."""
    import can

    with tempfile.TemporaryDirectory() as data:
        serve = _serve(count, data, profile)
        try:
            bus = can.Bus(interface="udp_multicast", channel=GROUP)
            enlarge_receive_buffer(bus)  # the PLC takes 2N + 1 frames a millisecond too
            try:
                _commission(bus, count)
                return _measure(bus, count, period_ms, seconds, serve)
            finally:
                bus.shutdown()
        finally:
            serve.send_signal(signal.SIGTERM)
            try:
                serve.wait(20)
            except subprocess.TimeoutExpired:
                serve.kill()


def _caused(node: int, data: bytes, count: int) -> bool:
    """The EMCY of the fault the benchmark injects on FAULTY (5411, and its 0000 reset)."""
    code = int.from_bytes(bytes(data[:2]), "little")
    return count >= FAULTY and node == FAULTY and code in (0x5411, 0x0000)


def _serve(count: int, data: str, profile: str | None) -> subprocess.Popen[str]:
    sampler = [str(Path(__file__).with_name("stack_sampler.py")), profile] if profile else []
    command = [sys.executable, *sampler, "-m", "prm9tool", "--can-interface", "udp_multicast",
               "--can-channel", GROUP]  # fmt: skip
    for node in range(1, count + 1):
        command += ["--serve-emulator", f"{E02}:{7000 + node}", "--node-id", str(node)]
    env = {**os.environ, "PRM9TOOL_DATA_DIR": data}
    root = Path(__file__).resolve().parent.parent
    env["PYTHONPATH"] = os.pathsep.join(filter(None, [str(root), env.get("PYTHONPATH")]))
    return subprocess.Popen(command, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                            stdin=subprocess.PIPE, text=True)  # fmt: skip


def _commission(bus, count: int) -> None:  # type: ignore[no-untyped-def]
    """Boot-up of every node, then per node: no heartbeat, TPDO1 every SYNC, TPDO2 off,
    RPDO1 asynchronous, NMT start, control word 08h → 09h → 0Bh → 0Fh (docs/plc-testing.md)."""
    import can

    booted: set[int] = set()
    deadline = time.monotonic() + 30 + count
    while len(booted) < count:
        assert time.monotonic() < deadline, f"boot-ups of {sorted(booted)} only"
        msg = bus.recv(0.5)
        if msg is not None and msg.arbitration_id & 0x780 == 0x700 and bytes(msg.data) == b"\0":
            booted.add(msg.arbitration_id & 0x7F)
    for node in range(1, count + 1):
        for frame in (
            "2B 17 10 00 00 00 00 00",  # heartbeat off
            f"23 00 18 01 {0x80 + node:02X} 01 00 00",  # TPDO1 on 0x180 + node
            "2F 00 18 02 01 00 00 00",  # TPDO1 every SYNC
            f"23 01 18 01 {0x80 + node:02X} 02 00 80",  # TPDO2 off
        ):
            _sdo(bus, node, frame)
    bus.send(can.Message(arbitration_id=0, data=b"\x01\x00", is_extended_id=False))
    time.sleep(0.2)
    for node in range(1, count + 1):
        for word in (0x08, 0x09, 0x0B, 0x0F):
            _sdo(bus, node, f"2B 40 60 00 {word:02X} 00 00 00")


def _sdo(bus, node: int, frame: str) -> None:  # type: ignore[no-untyped-def]
    import can

    data = bytes.fromhex(frame)
    for _attempt in range(5):
        bus.send(can.Message(arbitration_id=0x600 + node, data=data, is_extended_id=False))
        deadline = time.monotonic() + 1.0
        while time.monotonic() < deadline:
            msg = bus.recv(0.2)
            if msg is not None and msg.arbitration_id == 0x580 + node:
                assert msg.data[0] == 0x60, f"node {node} refused {frame}: {bytes(msg.data).hex()}"
                return
    raise AssertionError(f"node {node}: no answer to {frame}")


def _udp_drops() -> int:
    """RcvbufErrors of this network namespace (/proc/net/snmp, Udp)."""
    lines = [line.split() for line in Path("/proc/net/snmp").read_text().splitlines()
             if line.startswith("Udp:")]  # fmt: skip
    header, values = lines[0], lines[1]
    return int(values[header.index("RcvbufErrors")])


def _socket_drops(bus) -> int:  # type: ignore[no-untyped-def]
    """The drops column of /proc/net/udp for the PLC's socket."""
    inode = str(os.fstat(bus.fileno()).st_ino)
    for line in Path("/proc/net/udp").read_text().splitlines()[1:]:
        fields = line.split()
        if fields[9] == inode:
            return int(fields[-1])
    return 0


def _fifo_on_time(sync_times: list[float], per_node) -> int:  # type: ignore[no-untyped-def]
    """TPDO1 frames within ON_TIME_S when each answers the oldest SYNC its node has not
    answered yet: exact without lost frames; with losses a lower bound (later frames count
    against earlier SYNCs), as the latest-SYNC matching of :func:`_match` is an upper one."""
    return sum(
        0.0 <= got - sent <= ON_TIME_S
        for times in per_node
        for sent, got in zip(sync_times, times, strict=False)
    )


def _match(sync_times: list[float], per_node) -> tuple[list[float], int]:  # type: ignore[no-untyped-def]
    """Latency of each TPDO1 after the latest SYNC sent before it (each SYNC answered at most
    once per node: a lost frame does not shift the rest); the count within ON_TIME_S."""
    latencies: list[float] = []
    on_time = 0
    for times in per_node:
        used = -1
        for got in times:
            k = bisect.bisect_right(sync_times, got) - 1
            if k < 0 or k == used:
                continue
            used = k
            latency = got - sync_times[k]
            latencies.append(latency)
            on_time += latency <= ON_TIME_S
    latencies.sort()
    return latencies or [float("nan")], on_time


def _cpu_s(pid: int) -> float:
    """User + system CPU seconds of process ``pid`` so far (/proc/PID/stat)."""
    fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def _measure(bus, count: int, period_ms: float, seconds: float, serve) -> Result:  # type: ignore[no-untyped-def]
    import can

    sync_times: list[float] = []
    tpdo: dict[int, list[float]] = {node: [] for node in range(1, count + 1)}
    emcy = [0]
    stop = threading.Event()

    def receive() -> None:
        while not stop.is_set() or bus_pending():
            msg = bus.recv(0.05)
            if msg is None:
                if stop.is_set():
                    return
                continue
            cob, node = msg.arbitration_id & 0x780, msg.arbitration_id & 0x7F
            if cob == 0x180 and node in tpdo:
                tpdo[node].append(msg.timestamp)
            elif cob == 0x080 and node and not _caused(node, msg.data, count):
                emcy[0] += 1  # an EMCY the PLC did not cause (the injected fault's are)

    def bus_pending() -> bool:
        return False

    def fault(verb: str) -> None:  # on the serve command's stdin (docs/plc-testing.md)
        if count >= FAULTY:
            serve.stdin.write(f"{verb} node:{FAULTY} COIL_A_OPEN\n")
            serve.stdin.flush()

    drops_before, plc_before = _udp_drops(), _socket_drops(bus)
    receiver = threading.Thread(target=receive, daemon=True)
    receiver.start()
    period = period_ms / 1000.0
    rpdo = [can.Message(arbitration_id=0x200 + node, data=bytes([0x0F, 0, 0, 0]),
                        is_extended_id=False) for node in range(1, count + 1)]  # fmt: skip
    sync = can.Message(arbitration_id=0x080, data=b"", is_extended_id=False)
    pid = serve.pid
    cpu_before = _cpu_s(pid)
    injected = cleared = False
    start = time.monotonic()
    n = 0
    while time.monotonic() - start < seconds:
        n += 1
        delay = start + n * period - time.monotonic()
        if delay > 0:
            time.sleep(delay)
        sync_times.append(time.time())
        bus.send(sync)
        if not injected and n * period >= seconds / 3:
            injected = True
            fault("inject")  # the valve faults: its TPDO1 shows FAULT_HOLD, 5411 is caused
        elif not cleared and n * period >= 2 * seconds / 3:
            cleared = True
            fault("clear")
        setpoint = (8000 if (n // 500) % 2 else -8000).to_bytes(2, "little", signed=True)
        for message in rpdo:  # RPDO1 every SYNC: control word 0Fh, a ±50 % square
            message.data[2:4] = setpoint
            bus.send(message)
    elapsed = time.monotonic() - start
    cpu = (_cpu_s(pid) - cpu_before) / elapsed
    time.sleep(0.2)
    stop.set()
    receiver.join()
    latencies, on_time = _match(sync_times, tpdo.values())
    fifo = _fifo_on_time(sync_times, tpdo.values())
    received = sum(len(t) for t in tpdo.values())
    expected = len(sync_times) * count
    return Result(
        count,
        period_ms,
        on_time / max(expected, 1),
        fifo / max(expected, 1),
        received / max(expected, 1),
        statistics.median(latencies) * 1e3,
        latencies[min(len(latencies) - 1, int(0.99 * len(latencies)))] * 1e3,
        max(latencies) * 1e3,
        len(sync_times) / elapsed,
        emcy[0],
        os.getloadavg()[0],
        _udp_drops() - drops_before,
        _socket_drops(bus) - plc_before,
        cpu,
    )


if __name__ == "__main__":
    sys.exit(main())

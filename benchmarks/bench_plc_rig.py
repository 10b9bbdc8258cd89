"""The emulated valves as a PLC's test rig: N valves in one ``--serve-emulator`` process, the PLC
in this one (the ``canopen`` package for commissioning, python-can for SYNC, RPDO1 and TPDO1),
on python-can's udp_multicast bus inside a private network namespace (``unshare -n``, loopback
only: multicast never leaves the machine).

Per valve count it prints the share of TPDO1 frames that arrived within 1 ms of their SYNC
(kernel reception time stamps on both ends), the p50/p99/max latency after SYNC, the SYNCs
actually sent per second, the EMCYs seen (none expected: every one is a false alarm here),
and the machine's load average; the single-valve run of the same invocation is the reference.

    .venv/bin/python benchmarks/bench_plc_rig.py [--valves 1,4,8,16,32] [--seconds 10] [--quick]
        [--compare OTHER_CHECKOUT] [--profile OUT] [--dump PREFIX] [--floor]

First the per-frame path in CPU time (what N valves need of a core per period) and the PLC's
own cost per frame; then the rig, with each process's CPU and run-queue wait per second (the
OS's share). The PLC here is lean (frames through ``canopen_udp``, no ``can.Message``), so the
figures are the serving process's. ``--compare`` serves each run from another checkout and
from this one in turn and prints the ratios (docs/PERFORMANCE.md, "The PLC rig").
``--dump`` writes each run's SYNC send times and each node's TPDO1 reception times to
``PREFIX.TREE.N.json`` (where the late frames are: docs/PERFORMANCE.md).

The SYNC period is 1 ms up to 16 valves and 2 ms above (the issue's 32 valves at 2 ms), or
``--period MS`` for every run.
``--floor`` first serves each run with ``serve_floor.py``: nodes that only answer frames, no
valve behind them — the share of TPDO1 on time that no implementation of the served valves
can beat on this machine, measured beside the real one.
``--quick`` (a smoke run, CI): 1 and 2 valves for 1 s each, the floor too. Needs ``unshare -n`` (root or user
namespaces); without it the benchmark says so and exits 0.
"""

from __future__ import annotations

import argparse
import bisect
import json
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
PER_FRAME_GROUP = "239.74.163.13"  # the per-frame measurement's own bus (sends go nowhere)
NAMESPACE = "ip link set lo up && ip link set lo multicast on && ip route add 224.0.0.0/4 dev lo"
ON_TIME_S = 0.001
FAULTY = 2  # the node whose coil A is disconnected for the middle third of each run
INSIDE = "PRM9_BENCH_PLC_RIG_INSIDE"
FLOOR = "(serve_floor.py)"  # --floor: the "tree" of nodes that only answer frames
TREE = os.environ.get("PRM9_BENCH_TREE") or str(Path(__file__).resolve().parent.parent)
sys.path.insert(0, TREE)  # the prm9tool under test (--compare: another checkout's)
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
    serve_wait: float  # seconds its threads waited, runnable, for a CPU per second of the run
    plc_cpu: float  # the same two for this (the PLC's) process
    plc_wait: float


def main() -> int:
    """Parse the options, run inside a private network namespace, print the table."""
    parser = argparse.ArgumentParser()
    parser.add_argument("--valves", default="1,4,8,16,32")
    parser.add_argument("--seconds", type=float, default=10.0)
    parser.add_argument("--quick", action="store_true", help="a smoke run: seconds, not figures")
    parser.add_argument("--profile", help="sample the serving process's stacks into this file")
    parser.add_argument("--compare", metavar="TREE",
                        help="another checkout of prm9tool (e.g. before a change): each run "
                        "serves from it and from this tree in turn, and the ratios are printed")  # fmt: skip
    parser.add_argument("--period", type=float, metavar="MS",
                        help="the SYNC period for every run (default: 1 ms, 2 ms above 16 valves)")  # fmt: skip
    parser.add_argument("--dump", metavar="PREFIX",
                        help="write each run's SYNC and TPDO1 times to PREFIX.N.json")  # fmt: skip
    parser.add_argument("--serve-lag", action="store_true",
                        help="also print the serving process's own view: each valve's SYNC "
                        "handled how long after it arrived (benchmarks/serve_lag.py)")  # fmt: skip
    parser.add_argument("--toggle-min-batch", metavar="A,B",
                        help="with --serve-lag: switch the valves' batch size between A and B "
                        "cycles every 0.5 s, figures per size (a paired comparison)")  # fmt: skip
    parser.add_argument("--toggle-quiet-ticks", action="store_true",
                        help="with --serve-lag: switch between the compiled kernel passing the "
                        "valves' quiet 1 ms tasks and every 1 ms task in Python, every 0.5 s")  # fmt: skip
    parser.add_argument("--floor", action="store_true",
                        help="serve with benchmarks/serve_floor.py instead of prm9tool: nodes "
                        "that only answer frames (the machine's floor for any implementation)")  # fmt: skip
    parser.add_argument("--per-frame-only", type=int, metavar="N", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if os.environ.get(INSIDE) != "1":
        return _enter_namespace()
    if args.per_frame_only:
        per_frame(args.per_frame_only)
        return 0
    if args.quick:
        args.serve_lag = args.floor = True  # the probe and the floor are smoke-run too
    counts = [1, 2] if args.quick else [int(n) for n in args.valves.split(",")]
    seconds = 1.0 if args.quick else args.seconds
    if counts[0] != 1:
        counts.insert(0, 1)  # the reference
    print(f"PLC rig on udp_multicast {GROUP}, {seconds:g} s per run, load before "
          f"{os.getloadavg()[0]:.2f}")  # fmt: skip
    trees = [("this", TREE)] if not args.compare else [("compare", args.compare), ("this", TREE)]
    if args.floor:
        trees = [("floor", FLOOR), *trees]
    for label, tree in trees:
        print(f"[{label}: {tree}]", flush=True)
        subprocess.run([sys.executable, __file__, "--per-frame-only",
                        str(500 if args.quick else 5000)], env={**os.environ, "PRM9_BENCH_TREE": tree},
                       check=False)  # fmt: skip
        if label == "floor":
            continue
        if label == "this":
            _plc_side(500 if args.quick else 5000)
    print(f"{'tree':>7} {'valves':>6} {'SYNC':>6} {'on time':>8} {'FIFO':>7} {'got':>7} {'p50':>7} "
          f"{'p99':>7} {'max':>7} {'SYNC/s':>7} {'EMCY':>5} {'load':>5} {'drops':>6} {'PLC':>6} "
          f"{'CPU':>5} {'wait':>5} {'PLC CPU':>7} {'wait':>5}")  # fmt: skip
    results: dict[str, list[Result]] = {label: [] for label, _ in trees}
    for count in counts:
        for label, tree in trees:  # alternating: the load changes between runs
            profile = f"{args.profile}.{label}.{count}" if args.profile else None
            dump = f"{args.dump}.{label}.{count}.json" if args.dump else None
            period = args.period or (1.0 if count <= 16 else 2.0)
            lag = _lag_probe(args, label, count) if tree != FLOOR else []
            result = run(count, period, seconds, profile, tree, dump, lag)
            results[label].append(result)
            print(f"{label:>7} {result.valves:>6} {result.period_ms:>4g}ms {result.on_time:>8.2%} "
                  f"{result.fifo_on_time:>7.2%} "
                  f"{result.received:>7.1%} "
                  f"{result.p50_ms:>5.2f}ms {result.p99_ms:>5.2f}ms {result.max_ms:>5.1f}ms "
                  f"{result.syncs_per_s:>7.0f} {result.emcy:>5} {result.load:>5.2f} {result.dropped:>6} {result.plc_dropped:>6} {result.serve_cpu:>5.2f} {result.serve_wait:>5.2f} {result.plc_cpu:>7.2f} {result.plc_wait:>5.2f}",
                  flush=True)  # fmt: skip
            if lag:
                from serve_lag import summary

                print("\n".join(summary(lag[1])), flush=True)
                Path(lag[1]).unlink()
    mine = results["this"]
    reference = mine[0]
    for result in mine[1:]:
        print(f"{result.valves} valves: on-time share {result.on_time:.2%} against "
              f"{reference.on_time:.2%} for one valve; p99 {result.p99_ms / max(reference.p99_ms, 1e-3):.1f}x")  # fmt: skip
    if args.floor:
        for floor, served in zip(results["floor"], mine, strict=True):
            print(f"{served.valves} valves: on time {served.on_time:.2%} served, "
                  f"{floor.on_time:.2%} at the floor (serve_floor.py), its CPU "
                  f"{served.serve_cpu:.2f} / {floor.serve_cpu:.2f} core")  # fmt: skip
    if args.compare:
        for before, after in zip(results["compare"], mine, strict=True):
            print(f"{after.valves} valves, this tree against the compared one: on time "
                  f"{after.on_time:.2%} / {before.on_time:.2%}, received {after.received:.1%} / "
                  f"{before.received:.1%}, serve CPU per frame received "
                  f"{_cpu_per_frame(after) / max(_cpu_per_frame(before), 1e-9):.2f}x")  # fmt: skip
    return 0


def _lag_probe(args: argparse.Namespace, label: str, count: int) -> list[str]:
    """The serve_lag.py command-line prefix for this run (empty: no --serve-lag)."""
    if not args.serve_lag:
        return []
    out = str(Path(tempfile.gettempdir()) / f"prm9-serve-lag.{os.getpid()}.{label}.{count}.json")
    toggle = ["--toggle-min-batch", args.toggle_min_batch] if args.toggle_min_batch else []
    if args.toggle_quiet_ticks:
        toggle = ["--toggle-quiet-ticks"]
    return [str(Path(__file__).with_name("serve_lag.py")), out, *toggle]


def _cpu_per_frame(result: Result) -> float:
    """CPU seconds of the serving process per TPDO1 it got out (a rough per-frame cost)."""
    return result.serve_cpu / max(result.received * result.valves * 1000 / result.period_ms, 1e-9)


def per_frame(n: int) -> None:
    """CPU cost of the per-frame path of one served valve (µs), on a udp_multicast bus of its
    own inside the namespace, the way the tree under test serves it (``canopen_udp`` where the
    tree has it, else python-can's ``can.Message``), and what N valves need per millisecond of
    one core; then the PLC side: python-can's path against the lean one this benchmark uses."""
    import can
    import can.interfaces.udp_multicast.utils as udp

    from prm9tool.device.emulator import EmulatedValve

    try:
        from prm9tool.device.emulator import canopen_udp
    except ImportError:  # a tree from before the fast path (--compare)
        canopen_udp = None  # type: ignore[assignment]
    bus = can.Bus(interface="udp_multicast", channel=PER_FRAME_GROUP)
    valve = EmulatedValve(E02, 1)
    slave = valve.connect_can(bus, receive=False)
    valve.advance(2.0)
    fast = canopen_udp is not None and hasattr(slave, "receive_data")

    def frame(can_id: int, data: bytes) -> can.Message:
        return can.Message(arbitration_id=can_id, data=data, is_extended_id=False,
                           timestamp=time.time())  # fmt: skip

    def deliver(can_id: int, data: bytes) -> None:  # as the tree's SharedBus hands it on
        raw = udp.pack_message(frame(can_id, data))
        if fast:
            can_id, data = canopen_udp.decode(raw)  # type: ignore[union-attr,misc]
            slave.receive_data(can_id, data, time.time())
        else:
            slave.receive_frame(udp.unpack_message(raw, replace={"timestamp": time.time()},
                                                   check=True))  # fmt: skip

    for data in (bytes.fromhex("2F00180201000000"), *(bytes([0x2B, 0x40, 0x60, 0, w, 0, 0, 0])
                 for w in (8, 9, 11, 15))):  # fmt: skip
        deliver(0x60A, data)
    deliver(0, b"\x01\x0a")
    deliver(0x60A, bytes([0x2B, 0x40, 0x60, 0, 15, 0, 0, 0]))
    rpdo_data = bytes([15, 0, 0x40, 0x1F])
    packed = udp.pack_message(frame(0x20A, rpdo_data))
    if fast:
        decode = lambda: canopen_udp.decode(packed)  # type: ignore[union-attr]  # noqa: E731
    else:
        decode = lambda: udp.unpack_message(packed, replace={"timestamp": 1.0}, check=True)  # noqa: E731
    valve.start()  # paced: the watches on the wall clock, as served
    deliver_raw_sync = lambda: deliver_raw(0x80, b"")  # noqa: E731
    steps = {
        "decode": decode,
        "SYNC (TPDO1 out)": deliver_raw_sync,
        "RPDO1": lambda: deliver_raw(0x20A, rpdo_data),
        "hub: wait asked": slave.rx_wait_s,  # per valve; per frame before, per ms now
        "hub: judged quiet": lambda: slave.judge_quiet(time.monotonic() * 1e3),  # per valve, ms
    }
    sync_msg, rpdo_msg = frame(0x80, b""), frame(0x20A, rpdo_data)

    def deliver_raw(can_id: int, data: bytes) -> None:  # the handling alone, decoded already
        if fast:
            slave.receive_data(can_id, data, time.time())
        else:
            slave.receive_frame(sync_msg if can_id == 0x80 else rpdo_msg)

    costs = {}
    for name, step in steps.items():
        started = time.process_time()
        for _ in range(n):
            step()
        costs[name] = (time.process_time() - started) / n * 1e6
    valve.stop()
    started = time.process_time()
    for _ in range(n):
        valve.advance(0.001)
    costs["1 ms of the loop"] = (time.process_time() - started) / n * 1e6
    print(f"per frame ({'canopen_udp' if fast else 'can.Message'}): "
          + ", ".join(f"{k} {v:.1f} us" for k, v in costs.items()))  # fmt: skip
    for count, period_ms in ((16, 1.0), (32, 2.0)):
        frames_in = 1 + count  # one SYNC and an RPDO1 per valve each period
        asked = period_ms if fast else frames_in  # the hub asks each valve per ms / per frame
        need = (frames_in * costs["decode"] + count * (costs["SYNC (TPDO1 out)"] + costs["RPDO1"])
                + count * period_ms * (costs["1 ms of the loop"] + costs["hub: judged quiet"])
                + asked * count * costs["hub: wait asked"])  # fmt: skip
        print(f"  serving {count} valves @ {period_ms:g} ms needs {need:.0f} us of CPU per period "
              f"= {need / (period_ms * 10):.0f} % of one core")  # fmt: skip
    slave.stop()
    bus.shutdown()


def _plc_side(n: int) -> None:
    """A PLC's own cost per frame: python-can (``can.Message``, what a PLC script with the
    ``canopen`` package pays) against the lean path of this benchmark's PLC (canopen_udp)."""
    import can
    import can.interfaces.udp_multicast.utils as udp

    from prm9tool.device.emulator import canopen_udp

    bus = can.Bus(interface="udp_multicast", channel=PER_FRAME_GROUP)
    send = canopen_udp.sender(bus)
    assert send is not None
    msg = can.Message(arbitration_id=0x201, data=bytes(4), is_extended_id=False)
    packed = udp.pack_message(
        can.Message(arbitration_id=0x181, data=bytes(4), is_extended_id=False)
    )
    steps = {
        "python-can send": lambda: bus.send(msg),
        "lean send": lambda: send(0x201, b"\x0f\x00\x00\x00"),
        "python-can decode": lambda: udp.unpack_message(
            packed, replace={"timestamp": 1.0}, check=True
        ),
        "lean decode": lambda: canopen_udp.decode(packed),
    }
    costs = {}
    for name, step in steps.items():
        started = time.process_time()
        for _ in range(n):
            step()
        costs[name] = (time.process_time() - started) / n * 1e6
    print("PLC per frame: " + ", ".join(f"{k} {v:.1f} us" for k, v in costs.items()))
    for kind in ("python-can", "lean"):
        need = 16 * costs[f"{kind} decode"] + 17 * costs[f"{kind} send"]
        print(f"  a {kind} PLC at 16 valves @ 1 ms needs {need:.0f} us of CPU per ms "
              f"= {need / 10:.0f} % of one core (16 TPDO1 in, SYNC and 16 RPDO1 out)")  # fmt: skip
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


def run(
    count: int,
    period_ms: float,
    seconds: float,
    profile: str | None = None,
    tree: str = TREE,
    dump: str | None = None,
    lag: list[str] | None = None,
) -> Result:
    """Serve ``count`` valves (nodes 1…count) from ``tree``, commission them, run SYNC for
    ``seconds``."""
    import can

    with tempfile.TemporaryDirectory() as data:
        serve = _serve(count, data, profile, tree, lag or [])
        try:
            bus = can.Bus(interface="udp_multicast", channel=GROUP)
            enlarge_receive_buffer(bus)  # the PLC takes 2N + 1 frames a millisecond too
            try:
                _commission(bus, count)
                return _measure(bus, count, period_ms, seconds, serve, dump)
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


def _serve(count: int, data: str, profile: str | None, tree: str,
           lag: list[str]) -> subprocess.Popen[str]:  # fmt: skip
    if tree == FLOOR:
        floor = [sys.executable, str(Path(__file__).with_name("serve_floor.py")), GROUP, str(count)]
        return subprocess.Popen(floor, env={**os.environ, "PYTHONPATH": TREE},
                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                                stdin=subprocess.PIPE, text=True)  # fmt: skip
    sampler = [str(Path(__file__).with_name("stack_sampler.py")), profile] if profile else lag
    command = [sys.executable, *sampler, "-m", "prm9tool", "--can-interface", "udp_multicast",
               "--can-channel", GROUP]  # fmt: skip
    for node in range(1, count + 1):
        command += ["--serve-emulator", f"{E02}:{7000 + node}", "--node-id", str(node)]
    env = {**os.environ, "PRM9TOOL_DATA_DIR": data}
    env["PYTHONPATH"] = os.pathsep.join(filter(None, [tree, env.get("PYTHONPATH")]))
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


def _run_s(pid: int) -> tuple[float, float]:
    """(CPU seconds, seconds waited runnable for a CPU) of all threads of process ``pid``
    (/proc/PID/task/*/schedstat: the OS's share is the wait)."""
    cpu = wait = 0
    for task in Path(f"/proc/{pid}/task").iterdir():
        try:
            run_ns, wait_ns, _ = (task / "schedstat").read_text().split()
        except (OSError, ValueError):
            continue  # a thread that ended meanwhile
        cpu, wait = cpu + int(run_ns), wait + int(wait_ns)
    return cpu / 1e9, wait / 1e9


def _cpu_s(pid: int) -> float:
    """User + system CPU seconds of process ``pid`` so far (/proc/PID/stat)."""
    fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def _measure(bus, count: int, period_ms: float, seconds: float, serve, dump: str | None) -> Result:  # type: ignore[no-untyped-def]
    """The PLC's run, lean: datagrams decoded and sent without ``can.Message``
    (``canopen_udp``: a Python PLC's own per-frame cost would otherwise be measured too)."""
    from prm9tool.device.emulator import canopen_udp

    receive_frame, send = canopen_udp.receiver(bus), canopen_udp.sender(bus)
    assert receive_frame is not None and send is not None
    sync_times: list[float] = []
    tpdo: dict[int, list[float]] = {node: [] for node in range(1, count + 1)}
    emcy = [0]
    stop = threading.Event()

    def receive() -> None:
        while True:
            frame = receive_frame(0.05)
            if frame is None:
                if stop.is_set():
                    return
                continue
            can_id, data, timestamp = frame
            cob, node = can_id & 0x780, can_id & 0x7F
            if cob == 0x180 and node in tpdo:
                tpdo[node].append(timestamp)
            elif cob == 0x080 and node and not _caused(node, data, count):
                emcy[0] += 1  # an EMCY the PLC did not cause (the injected fault's are)

    def fault(verb: str) -> None:  # on the serve command's stdin (docs/plc-testing.md)
        if count >= FAULTY:
            serve.stdin.write(f"{verb} node:{FAULTY} COIL_A_OPEN\n")
            serve.stdin.flush()

    drops_before, plc_before = _udp_drops(), _socket_drops(bus)
    receiver = threading.Thread(target=receive, daemon=True)
    receiver.start()
    period = period_ms / 1000.0
    pid = serve.pid
    cpu_before = _cpu_s(pid)
    serve_before, plc_before_run = _run_s(pid), _run_s(os.getpid())
    injected = cleared = False
    start = time.monotonic()
    n = 0
    while time.monotonic() - start < seconds:
        n += 1
        delay = start + n * period - time.monotonic()
        if delay > 0:
            time.sleep(delay)
        sync_times.append(time.time())
        send(0x080, b"")
        if not injected and n * period >= seconds / 3:
            injected = True
            fault("inject")  # the valve faults: its TPDO1 shows FAULT_HOLD, 5411 is caused
        elif not cleared and n * period >= 2 * seconds / 3:
            cleared = True
            fault("clear")
        setpoint = (8000 if (n // 500) % 2 else -8000).to_bytes(2, "little", signed=True)
        rpdo = b"\x0f\x00" + setpoint  # RPDO1 every SYNC: control word 0Fh, a ±50 % square
        for node in range(1, count + 1):
            send(0x200 + node, rpdo)
    elapsed = time.monotonic() - start
    cpu = (_cpu_s(pid) - cpu_before) / elapsed
    serve_after, plc_after = _run_s(pid), _run_s(os.getpid())
    time.sleep(0.2)
    stop.set()
    receiver.join()
    if dump:
        Path(dump).write_text(json.dumps({"sync": sync_times, "tpdo1": tpdo}))
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
        (serve_after[1] - serve_before[1]) / elapsed,
        (plc_after[0] - plc_before_run[0]) / elapsed,
        (plc_after[1] - plc_before_run[1]) / elapsed,
    )


if __name__ == "__main__":
    sys.exit(main())

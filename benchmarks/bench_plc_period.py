"""The PLC rig's serving work in one process, without sockets: CPU per SYNC period and repeated
samples (docs/PERFORMANCE.md, "issue 30, third stop").

    .venv/bin/python benchmarks/bench_plc_period.py [--valves 16,32] [--compare OTHER_CHECKOUT]
        [--quick]

Per valve count (SYNC every 1 ms up to 16 valves, 2 ms above, as ``bench_plc_rig.py``): the
CPU time (``time.process_time``) of a SYNC period — N RPDO1, the SYNC with N TPDO1 out (sent
into a stub), and each valve's 2 ms batch every 2 ms, the pacer told it ran (so a SYNC runs no
cycles of its own and both trees do the same work) — best of 5 x 500 periods, paced to the
wall clock; then, for 4 valves paced in real time (their batches between the SYNCs, as the
serving process runs them), the share of SYNCs that found a valve at the same simulated
moment as the SYNC before while the simulation kept up. ``--compare`` runs each figure in the
other checkout and in this one in turn (the machine's load moves between runs).
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import time
from pathlib import Path

E02 = "PRM9-06.3Z11/30-24E02S02-CA"
NODE = 10  # every valve's node ID: each has a slave of its own here, no routing
TREE = os.environ.get("PRM9_BENCH_TREE") or str(Path(__file__).resolve().parent.parent)


class Stub:
    """A bus as far as a CANopen slave without a receive thread uses it."""

    def send(self, msg: object, timeout: float | None = None) -> None:
        pass

    def recv(self, timeout: float | None = None) -> None:
        return None


def _valves(count: int):  # type: ignore[no-untyped-def]
    sys.path.insert(0, TREE)
    from prm9tool.device.emulator import EmulatedValve

    valves = []
    for serial in range(1, count + 1):
        valve = EmulatedValve(E02, serial)
        slave = valve.connect_can(Stub(), receive=False)  # type: ignore[arg-type]
        valve.advance(2.0)
        for data in ("2F00180201000000", "230118018A020080", "2B17100000000000"):
            slave.receive_data(0x600 + NODE, bytes.fromhex(data), 0.0)  # as the rig commissions:
            # TPDO1 every SYNC, TPDO2 off, no heartbeat
        slave.receive_data(0, bytes((1, NODE)), time.time())
        for word in (8, 9, 11, 15):
            slave.receive_data(0x600 + NODE, bytes([0x2B, 0x40, 0x60, 0, word, 0, 0, 0]), 0.0)
        valve.paced_by_group(True)
        valves.append((valve, slave))
    return valves


def period_cpu(count: int, period_s: float, periods: int, repeats: int) -> float:
    """CPU µs per SYNC period of ``count`` served valves (best of ``repeats``)."""
    valves = _valves(count)
    rpdo = bytes([15, 0, 0x40, 0x1F])
    best = float("inf")
    for _ in range(repeats):
        cpu = 0.0
        for p in range(periods):
            next_due = time.monotonic() + period_s
            started = time.process_time()
            stamp = time.time()
            for _valve, slave in valves:
                slave.receive_data(0x200 + NODE, rpdo, stamp)
            for _valve, slave in valves:
                slave.receive_data(0x80, b"", stamp)
            if period_s >= 0.002 or p % 2:  # 2 ms batches, as the pacer runs them
                for valve, _slave in valves:
                    valve.advance(0.002)
                    pacer = valve.pacer  # told they ran: the same work in either tree
                    pacer.cycles_done = int((time.monotonic() - pacer.start) / pacer.cycle_s) + 20
            cpu += time.process_time() - started
            while time.monotonic() < next_due:
                time.sleep(0.0001)
        best = min(best, cpu / periods * 1e6)
    return best


def repeated_samples(count: int, periods: int) -> tuple[float, int]:
    """Share of 1 ms SYNCs (0.5 ms or more after the one before, the simulation no more than
    2 ms behind) that found a valve at the simulated moment of the SYNC before; SYNCs judged."""
    valves = _valves(count)
    last: list[float | None] = [None] * count
    repeats = judged = 0
    last_stamp = 0.0
    start = time.monotonic()
    for p in range(periods):
        stamp = time.time()
        apart = stamp - last_stamp >= 0.0005
        last_stamp = stamp
        for i, (valve, slave) in enumerate(valves):
            keeping_up = valve.pacer.lag_s() <= 0.002
            slave.receive_data(0x80, b"", stamp)
            if apart and keeping_up:
                judged += 1
                repeats += valve.time == last[i]
            last[i] = valve.time
        for valve, _slave in valves:
            valve.paced_step()
        while time.monotonic() < start + (p + 1) * 0.001:
            time.sleep(0.0001)
    return (repeats / judged if judged else 0.0), judged


def _inside(args: argparse.Namespace) -> None:
    if args.stale:
        share, judged = repeated_samples(4, args.periods * 6)
        print(f"repeated {100 * share:.1f} % of {judged}")
        return
    period_s = 0.001 if args.one <= 16 else 0.002
    print(f"cpu {period_cpu(args.one, period_s, args.periods, args.repeats):.0f}")


def _run(tree: str, extra: list[str]) -> str:
    env = dict(os.environ, PRM9_BENCH_TREE=tree)
    cmd = [sys.executable, __file__, *extra]
    return subprocess.run(cmd, env=env, capture_output=True, text=True, check=True).stdout.strip()


def main() -> int:
    """Parse the options; run every figure in a process of its own (per tree)."""
    parser = argparse.ArgumentParser()
    parser.add_argument("--valves", default="16,32")
    parser.add_argument("--compare", metavar="TREE")
    parser.add_argument("--quick", action="store_true", help="a smoke run: seconds, not figures")
    parser.add_argument("--one", type=int, help=argparse.SUPPRESS)
    parser.add_argument("--stale", action="store_true", help=argparse.SUPPRESS)
    parser.add_argument("--periods", type=int, default=500, help=argparse.SUPPRESS)
    parser.add_argument("--repeats", type=int, default=5, help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.one or args.stale:
        _inside(args)
        return 0
    counts = [2] if args.quick else [int(n) for n in args.valves.split(",")]
    size = ["--periods", "50", "--repeats", "1"] if args.quick else []
    trees = [("compare", args.compare), ("this", TREE)] if args.compare else [("this", TREE)]
    for count in counts:
        period = 1 if count <= 16 else 2
        for name, tree in trees:
            load = os.getloadavg()[0]
            cpu = _run(tree, ["--one", str(count), *size]).split()[1]
            print(f"{name:>7} {count:3d} valves @ {period} ms: {cpu} us CPU per period "
                  f"(best of {1 if args.quick else 5} x {50 if args.quick else 500}), load {load:.2f}")  # fmt: skip
    for name, tree in trees:
        load = os.getloadavg()[0]
        out = _run(tree, ["--stale", *size])
        print(f"{name:>7}   4 valves paced, SYNC 1 ms: {out} SYNCs found the moment of the one "
              f"before (the simulation keeping up), load {load:.2f}")  # fmt: skip
    return 0


if __name__ == "__main__":
    sys.exit(main())

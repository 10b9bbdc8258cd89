"""Emulator speed: both control-loop kernels, E02 and E04 with every feature on, paced valves.

Per kernel (compiled C, Python reference) the real-time factor of E02 and E04 with every
feature on; the reference, measured in the same run, is a minimal inline Python cascade
(threshold, ramp, PID, first-order coil, spring-mass spool) written below: the least any
pure-Python 200 µs loop has to do. Then the CPU share of 8 paced E04 -CA valves on one
(virtual) CAN bus, as ``--serve-emulator`` x8 runs them, per kernel.

    .venv/bin/python benchmarks/bench_emulator.py              # everything, ~1 min
    .venv/bin/python benchmarks/bench_emulator.py --quick      # smoke run, a few seconds
    .venv/bin/python benchmarks/bench_emulator.py --paced 10   # plus a 10 s paced run
    .venv/bin/python benchmarks/bench_emulator.py --generator  # plus the generator's sine
"""

from __future__ import annotations

import argparse
import cProfile
import inspect
import pstats
import sys
import time
from collections import Counter
from types import FrameType
from typing import Any

import can

from prm9tool.device.emulator import EmulatedValve, kernel, kernels

CYCLE_S = EmulatedValve.CYCLE_S
TYPE_KEYS = {
    "E02": "PRM9-06.3Z11/30-24E02S02-CA",
    "E04": "PRM9-06.3Z11/30-24E04S02-CA",
}


KERNELS = ("compiled", "python")
# The per-cycle figures are CPU time of this (single-threaded) process: on the shared machine
# the wall time of the same run varies several-fold with the other work; --wall measures that.
CLOCK = time.process_time


def new_valve(kernel_name: str, type_key: str, **kwargs: Any) -> EmulatedValve:
    """A valve whose loop runs ``kernel_name`` ("compiled" or "python")."""
    kernels.use(kernel_name)
    try:
        return EmulatedValve(type_key, **kwargs)
    finally:
        kernels.use(None)


def all_features(type_key: str, kernel_name: str = "compiled") -> EmulatedValve:
    """A booted valve in analog mode with ramps, linearizations, dither and a 3-channel capture."""
    valve = new_valve(kernel_name, type_key, switches=(0, 2))
    valve.write(0x6332, 1, 200)  # ramps
    valve.write(0x6335, 1, 200)
    valve.write(0x6333, 1, 200)
    valve.write(0x6336, 1, 200)
    valve.write(0x6346, 0, -1)  # setpoint linearization on
    if "E04" in type_key:
        valve.write(0x2008, 0, 1)  # sensor linearization on
        valve.write(0x2021, 2, 20)  # process Ki
    valve.advance(2.0)
    valve.capture_start(["position_actual", "current_a", "demand"])
    return valve


def emulator_cycle_s(type_key: str, seconds: float, repeat: int, kernel_name: str) -> float:
    """Best-of-repeat wall time per 200 µs cycle, a square-wave setpoint keeping everything moving."""
    valve = all_features(type_key, kernel_name)
    times = []
    for _ in range(repeat):
        start = CLOCK()
        for k in range(int(seconds / 0.1)):
            valve.set_input("setpoint", 5.0 if k % 2 else -5.0)
            valve.advance(0.1)
            valve.capture_read()
        times.append((CLOCK() - start) / (seconds / CYCLE_S))
    return min(times)


def generator_cycle_s(type_key: str, seconds: float, repeat: int, kernel_name: str) -> float:
    """Best-of-repeat wall time per cycle with the setpoint generator's sine (20 Hz, ±40 %)
    running on the override in the valve's loop: the value changes nearly every cycle."""
    from prm9tool.catalogue import CATALOGUE
    from prm9tool.scope import GeneratorSettings, Waveform

    valve = all_features(type_key, kernel_name)
    valve.write(*CATALOGUE["SETPOVRON"].key, 1)
    valve.drive_override(GeneratorSettings(Waveform.SINE, 40.0, 0.0, 0.05).raw_values)
    times = []
    for _ in range(repeat):
        start = CLOCK()
        for _ in range(int(seconds / 0.1)):
            valve.usb_activity()  # the override's watchdog
            valve.advance(0.1)
            valve.capture_read()
        times.append((CLOCK() - start) / (seconds / CYCLE_S))
    return min(times)


def reference_cycle_s(cycles: int, repeat: int) -> float:
    """Best-of-repeat wall time per cycle of a minimal inline cascade (same loop style, no features)."""
    times = []
    for _ in range(repeat):
        start = CLOCK()
        minimal_cascade(cycles)
        times.append((CLOCK() - start) / cycles)
    return min(times)


def minimal_cascade(cycles: int) -> float:
    """Threshold, ramp, PID, first-order coil, spring-mass spool: locals only, one loop."""
    dt = CYCLE_S
    setpoint, threshold, step = 8192.0, 819.0, 16384.0 * dt / 0.2
    kp, ki, kd = 0.4, 100.0 * dt, 0.0004 / dt
    a_coil, b_coil = 0.9737, 0.0066  # L/R = 7.5 ms, mA per V per cycle
    kf, ks, cd, im, xn = 0.03, 21600.0, 72.0, dt / 0.06, 16384.0 / 0.0025
    ramp = integ = prev = current = x = v = 0.0
    for k in range(cycles):
        raw = setpoint if k % 10000 < 5000 else -setpoint
        target = raw if abs(raw) >= threshold else 0.0
        if ramp < target:
            ramp = min(ramp + step, target)
        elif ramp > target:
            ramp = max(ramp - step, target)
        error = ramp - x * xn
        integ += ki * error
        u = kp * error + integ + kd * (error - prev)
        prev = error
        volts = min(max(u * 0.0015, 0.0), 24.0)
        current = a_coil * current + b_coil * volts * 1000.0
        force = kf * current
        v += (force - ks * x - cd * v) * im
        x += v * dt
    return x


def _operational_and_enabled(valve: EmulatedValve) -> None:
    """Booted, NMT OPERATIONAL, DEVICE_MODE_ACTIVE by the manual's 08h → 09h → 0Bh → 0Fh."""
    valve.advance(2.0)
    valve.nmt_command(1)
    for word in (0x08, 0x09, 0x0B, 0x0F):
        valve.write(0x6040, 0, word)


def can_valve_cycle_s(seconds: float, repeat: int, quiet: bool) -> float:
    """Best-of-repeat time per cycle of an E02 -CA valve OPERATIONAL on a (virtual) bus in
    simulated time, 0.1 s a step: the CANopen slave's quiet 1 ms tasks passed by the compiled
    kernel (``quiet``) or every one in Python (its listener's quiet check hidden, as before)."""
    bus = can.Bus(interface="virtual", channel=f"bench-emulator-quiet-{time.monotonic_ns()}")
    valve = new_valve("compiled", TYPE_KEYS["E02"])
    slave = valve.connect_can(bus, receive=False)
    _operational_and_enabled(valve)
    if not quiet:
        valve.firmware.cycle_quiet = {}
    times = []
    for _ in range(repeat):
        start = CLOCK()
        steps = max(1, round(seconds / 0.1))
        for k in range(steps):
            valve.write(0x6300, 1, 4000 if k % 2 else -4000)
            valve.advance(0.1)
        times.append((CLOCK() - start) / (steps * 0.1 / CYCLE_S))
    slave.stop()
    bus.shutdown()
    return min(times)


def paced_bus_share(count: int, seconds: float, kernel_name: str) -> tuple[float, float, int]:
    """(CPU share of one core, worst simulated/wall ratio, dropped cycles) of ``count`` paced
    E04 -CA valves on one virtual CAN bus, operational and enabled, following a setpoint."""
    channel = f"bench-emulator-{kernel_name}-{time.monotonic_ns()}"
    buses = [can.Bus(interface="virtual", channel=channel) for _ in range(count)]
    valves, slaves = [], []
    for position, bus in enumerate(buses, start=2):  # node switch 2…: node IDs 10, 15, ...
        valve = new_valve(kernel_name, TYPE_KEYS["E04"], switches=(6, position))
        slaves.append(valve.connect_can(bus))
        _operational_and_enabled(valve)
        valve.write(0x6300, 1, 4000)  # a setpoint, as an RPDO would bring it
        valves.append(valve)
    sims = [v.time for v in valves]
    cpu0, wall0 = time.process_time(), time.monotonic()
    for valve in valves:
        valve.start()
    time.sleep(seconds)
    for valve in valves:
        valve.stop()
    cpu, wall = time.process_time() - cpu0, time.monotonic() - wall0
    ratio = min((v.time - s0) / wall for v, s0 in zip(valves, sims, strict=True))
    dropped = sum(v.pacer.dropped_cycles for v in valves)
    for slave in slaves:
        slave.stop()
    for bus in buses:
        bus.shutdown()
    return cpu / wall, ratio, dropped


def paced_run(seconds: float) -> tuple[float, float, int]:
    """(simulated s, wall s, dropped cycles) of a real paced run with every feature on."""
    valve = all_features(TYPE_KEYS["E04"])
    sim0 = valve.time
    wall0 = time.monotonic()
    valve.start()
    time.sleep(seconds)
    valve.stop()
    wall = time.monotonic() - wall0
    return valve.time - sim0, wall, valve.pacer.dropped_cycles


def profile(type_key: str, kernel_name: str) -> None:
    """Print where the time of one simulated second goes (cProfile, by total time)."""
    valve = all_features(type_key, kernel_name)
    profiler = cProfile.Profile()
    profiler.enable()
    for k in range(10):
        valve.set_input("setpoint", 5.0 if k % 2 else -5.0)
        valve.advance(0.1)
        valve.capture_read()
    profiler.disable()
    pstats.Stats(profiler).sort_stats("tottime").print_stats(8)


def line_counts(type_key: str, cycles: int = 2000) -> dict[str, float]:
    """Python lines executed per cycle in each block of the loop (blocks: ``# ---`` comments)."""
    valve = all_features(type_key, "python")
    valve.set_input("setpoint", 5.0)
    valve.advance(0.05)
    code = kernel.control_loop.__code__
    lines, start = inspect.getsourcelines(kernel.control_loop)
    blocks = {}
    name = "setup"
    for number, text in enumerate(lines, start=start):
        if "# ---" in text:
            name = text.strip("# -\n").split(":")[0].strip()
        blocks[number] = name
    hits: Counter[str] = Counter()

    def tracer(frame: FrameType, event: str, arg: Any) -> Any:
        if frame.f_code is not code:
            return None
        if event == "line":
            hits[blocks.get(frame.f_lineno, "?")] += 1
        return tracer

    sys.settrace(tracer)
    try:
        valve.advance(cycles * CYCLE_S)  # the loop's frame is resumed with tracing on
    finally:
        sys.settrace(None)
    return {block: count / cycles for block, count in hits.most_common()}


def main() -> None:
    """Print the figures recorded in docs/PERFORMANCE.md."""
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--seconds", type=float, default=2.0, help="simulated s per repeat")
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--valves", type=int, default=8, help="paced valves on one bus")
    parser.add_argument("--bus-seconds", type=float, default=5.0, help="wall s of that run")
    parser.add_argument("--paced", type=float, default=0.0, help="also run paced for N s")
    parser.add_argument("--profile", action="store_true", help="print a cProfile summary")
    parser.add_argument("--lines", action="store_true", help="print lines per cycle per block")
    parser.add_argument(
        "--generator", action="store_true", help="also run with a sine on the setpoint override"
    )
    parser.add_argument("--quick", action="store_true", help="a smoke run: seconds, not figures")
    parser.add_argument("--wall", action="store_true", help="wall time instead of CPU time")
    args = parser.parse_args()
    if args.wall:
        global CLOCK
        CLOCK = time.perf_counter
    if args.quick:
        args.seconds, args.repeat, args.bus_seconds = 0.05, 1, 0.5
        args.paced = min(args.paced, 0.2)
    available = kernels.compiled_unavailable()
    names = KERNELS if available is None else ("python",)
    if available is not None:
        print(f"compiled kernel unavailable ({available}): python kernel only")
    cycles = int(args.seconds / CYCLE_S)
    reference = reference_cycle_s(cycles, args.repeat)
    print(f"minimal inline cascade (Python): {reference * 1e6:6.2f} µs/cycle ({CLOCK.__name__})")
    for name, type_key in TYPE_KEYS.items():
        costs = {}
        for kernel_name in names:
            cost = costs[kernel_name] = emulator_cycle_s(
                type_key, args.seconds, args.repeat, kernel_name
            )
            print(
                f"{name} all features, {kernel_name} kernel: {cost * 1e6:.3f} µs/cycle, "
                f"{CYCLE_S / cost:.1f} x real time, {cost / reference:.2f}x the minimal cascade"
            )
            if args.generator:
                _generator_line(name, type_key, args, kernel_name, cost)
            if args.profile:
                profile(type_key, kernel_name)
        if len(costs) == 2:
            print(
                f"{name}: the compiled kernel is {costs['python'] / costs['compiled']:.1f}x "
                "faster than the python kernel"
            )
        if args.lines:
            counts = line_counts(type_key)
            print(f"  Python lines per cycle: {sum(counts.values()):.1f}")
            for block, count in counts.items():
                print(f"    {count:5.1f}  {block}")
    if available is None:
        quiet, python = (can_valve_cycle_s(args.seconds, args.repeat, q) for q in (True, False))
        print(
            f"E02 -CA OPERATIONAL in simulated time, compiled kernel: {quiet * 1e6:.3f} µs/cycle "
            f"with its quiet 1 ms tasks passed, {python * 1e6:.3f} µs/cycle with every 1 ms "
            f"task in Python ({python / quiet:.1f}x)"
        )
    for kernel_name in names:
        share, ratio, dropped = paced_bus_share(args.valves, args.bus_seconds, kernel_name)
        print(
            f"{args.valves} paced E04 -CA valves on one bus, {kernel_name} kernel: "
            f"{share * 100:.1f} % of one core, slowest valve {ratio:.4f} s simulated per s, "
            f"dropped cycles: {dropped}"
        )
    if args.paced > 0:
        sim, wall, dropped = paced_run(args.paced)
        error = (sim - wall) / wall * 100
        print(
            f"paced E04 run: {sim:.4f} s simulated in {wall:.4f} s wall "
            f"({error:+.3f} %), dropped cycles: {dropped}"
        )


def _generator_line(
    name: str, type_key: str, args: argparse.Namespace, kernel_name: str, cost: float
) -> None:
    driven = generator_cycle_s(type_key, args.seconds, args.repeat, kernel_name)
    print(
        f"{name} with the generator's 20 Hz sine on the override, {kernel_name} kernel: "
        f"{driven * 1e6:.3f} µs/cycle, {CYCLE_S / driven:.1f} x real time, "
        f"{driven / cost:4.2f}x the square-wave run"
    )


if __name__ == "__main__":
    main()

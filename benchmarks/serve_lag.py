"""The serving process's own view of its SYNCs: how long after a SYNC reached its socket each
valve had handled it (its TPDO1 sent), by the kernel's reception time stamp of the SYNC.

The PLC side of bench_plc_rig.py matches each TPDO1 to the latest SYNC before it; when the
serving process falls behind by more than a period that hides the lag (a TPDO1 answering a
SYNC 13 ms old lands just after a newer one), which only its "FIFO" column shows. Here the
lag is measured where it arises, per SYNC and valve, whatever the matching:

    python benchmarks/serve_lag.py OUT.json [--toggle-min-batch A,B | --toggle-quiet-ticks] \
        -m prm9tool --serve-emulator …

bench_plc_rig.py ``--serve-lag`` runs the serving process under it and prints the figures.
``--toggle-min-batch A,B`` switches every valve's batch size (``Pacer.min_batch``, cycles)
between A and B every half second and keeps the figures and the receive thread's CPU per
state apart: a paired comparison inside one process, which the machine's minute-to-minute
noise (±10 % CPU, ±20 points on time between runs) does not blur (docs/PERFORMANCE.md).
``--toggle-quiet-ticks`` likewise switches between the compiled kernel passing the CANopen
slave's quiet 1 ms tasks (as served) and every 1 ms task in Python (as before issue 30's
sixth stop: the valves' cycle listeners say nothing of their quiet tasks).
"""

from __future__ import annotations

import atexit
import gc
import json
import runpy
import signal
import sys
import threading
import time
from collections.abc import Callable
from typing import Any

SETTLE_S = 0.05  # after a switch, before its window counts
WINDOW_S = 0.45
START_S = 5.0  # commissioning first (the benchmark's set-up takes about that)
HUB_THREAD = "prm9-canopen-hub"


Setting = tuple[str, Callable[[list[Any]], None]]  # its label; put it on every valve


def min_batch(size: int) -> Setting:
    """Every valve's batch size ``size`` cycles."""

    def apply(valves: list[Any]) -> None:
        for valve in valves:
            valve.pacer.min_batch = size

    return f"min_batch {size}", apply


def quiet_ticks(passed: bool) -> Setting:
    """The compiled kernel passes the slaves' quiet 1 ms tasks (True) or leaves every one to
    Python (False: the cycle listeners' quiet checks hidden)."""
    kept: dict[int, dict[Any, Any]] = {}

    def apply(valves: list[Any]) -> None:
        for valve in valves:
            fw = valve.firmware
            with valve.lock:
                if passed:
                    fw.cycle_quiet = kept.pop(id(valve), fw.cycle_quiet)
                elif id(valve) not in kept:
                    kept[id(valve)], fw.cycle_quiet = fw.cycle_quiet, {}

    return f"quiet ticks {'passed' if passed else 'in Python'}", apply


def start(out: str, settings: list[Setting] | None) -> None:
    """Record until the process exits; write the figures to ``out`` (JSON)."""
    from prm9tool.device.emulator import canopen_slave
    from prm9tool.device.emulator.valve import EmulatedValve

    state: list[int | None] = [None if settings else 0]  # the window a SYNC counts in
    lags: dict[int, list[float]] = {k: [] for k in range(len(settings or (0,)))}
    cpu: dict[int, list[float]] = {k: [] for k in lags}
    handle = canopen_slave.CanopenSlave.receive_data

    def receive_data(self, can_id: int, data: bytes, timestamp: float) -> None:  # type: ignore[no-untyped-def]
        handle(self, can_id, data, timestamp)
        window = state[0]
        if can_id == 0x080 and window is not None:
            lags[window].append(time.time() - timestamp)

    canopen_slave.CanopenSlave.receive_data = receive_data  # type: ignore[method-assign]

    def toggle(settings: list[Setting]) -> None:
        time.sleep(START_S)
        hub = next((t for t in threading.enumerate() if t.name == HUB_THREAD), None)
        if hub is None or hub.ident is None:
            return
        clock = time.pthread_getcpuclockid(hub.ident)
        valves = [o for o in gc.get_objects() if isinstance(o, EmulatedValve)]
        while True:
            for k, (_, apply) in enumerate(settings):
                state[0] = None
                apply(valves)
                time.sleep(SETTLE_S)
                state[0] = k
                used, began = time.clock_gettime(clock), time.monotonic()
                time.sleep(WINDOW_S)
                cpu[k].append((time.clock_gettime(clock) - used) / (time.monotonic() - began))

    if settings:
        threading.Thread(target=toggle, args=(settings,), daemon=True).start()

    def dump() -> None:
        state[0] = None
        windows = [
            {"setting": settings[k][0] if settings else None, "lags": lags[k], "hub_cpu": cpu[k]}
            for k in lags
        ]
        with open(out, "w", encoding="utf-8") as file:
            json.dump(windows, file)

    atexit.register(dump)


def summary(path: str) -> list[str]:
    """Lines for the benchmark's output from a file :func:`start` wrote."""
    with open(path, encoding="utf-8") as file:
        windows = json.load(file)
    lines = []
    cpus = [w["hub_cpu"] for w in windows]
    for k, window in enumerate(windows):
        lags = sorted(window["lags"])
        if not lags:
            continue
        n = len(lags)
        late = sum(lag > 0.001 for lag in lags) / n
        label = "" if window["setting"] is None else f"{window['setting']}: "
        line = (f"  serve's view, {label}{n} SYNCs x valves handled: over 1 ms {late:.2%}, p50 "
                f"{lags[n // 2] * 1e3:.2f} ms, p99 {lags[int(0.99 * (n - 1))] * 1e3:.2f} ms, max "
                f"{lags[-1] * 1e3:.1f} ms")  # fmt: skip
        if window["hub_cpu"] and k:
            pairs = sorted(a / b for a, b in zip(cpus[k], cpus[0], strict=False) if b)
            line += (f"; receive thread CPU {_median(cpus[k]):.2f} core, paired against "
                     f"{windows[0]['setting']}: {pairs[len(pairs) // 2]:.3f}x "
                     f"(IQR {pairs[len(pairs) // 4]:.3f}-{pairs[3 * len(pairs) // 4]:.3f})")  # fmt: skip
        elif window["hub_cpu"]:
            line += f"; receive thread CPU {_median(window['hub_cpu']):.2f} core"
        lines.append(line)
    return lines


def _median(values: list[float]) -> float:
    ordered = sorted(values)
    return ordered[len(ordered) // 2]


if __name__ == "__main__":
    out, rest = sys.argv[1], sys.argv[2:]
    settings = None
    if rest[0] == "--toggle-min-batch":
        settings = [min_batch(int(s)) for s in rest[1].split(",")]
        rest = rest[2:]
    elif rest[0] == "--toggle-quiet-ticks":
        settings = [quiet_ticks(True), quiet_ticks(False)]
        rest = rest[1:]
    start(out, settings)
    signal.signal(signal.SIGTERM, signal.default_int_handler)
    if rest[0] == "-m":
        sys.argv = [rest[1], *rest[2:]]
        runpy.run_module(sys.argv[0], run_name="__main__", alter_sys=True)

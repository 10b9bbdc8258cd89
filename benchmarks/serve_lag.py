"""The serving process's own view of its SYNCs: how long after a SYNC reached its socket each
valve had handled it (its TPDO1 sent), by the kernel's reception time stamp of the SYNC.

The PLC side of bench_plc_rig.py matches each TPDO1 to the latest SYNC before it; when the
serving process falls behind by more than a period that hides the lag (a TPDO1 answering a
SYNC 13 ms old lands just after a newer one), which only its "FIFO" column shows. Here the
lag is measured where it arises, per SYNC and valve, whatever the matching:

    python benchmarks/serve_lag.py OUT.json [--toggle-min-batch A,B] -m prm9tool --serve-emulator …

bench_plc_rig.py ``--serve-lag`` runs the serving process under it and prints the figures.
``--toggle-min-batch A,B`` switches every valve's batch size (``Pacer.min_batch``, cycles)
between A and B every half second and keeps the figures and the receive thread's CPU per
state apart: a paired comparison inside one process, which the machine's minute-to-minute
noise (±10 % CPU, ±20 points on time between runs) does not blur (docs/PERFORMANCE.md).
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

SETTLE_S = 0.05  # after a switch, before its window counts
WINDOW_S = 0.45
START_S = 5.0  # commissioning first (the benchmark's set-up takes about that)
HUB_THREAD = "prm9-canopen-hub"


def start(out: str, sizes: tuple[int, ...] | None) -> None:
    """Record until the process exits; write the figures to ``out`` (JSON)."""
    from prm9tool.device.emulator import canopen_slave
    from prm9tool.device.emulator.valve import EmulatedValve

    state: list[int | None] = [None if sizes else 0]  # the window a SYNC counts in
    lags: dict[int, list[float]] = {k: [] for k in range(len(sizes or (0,)))}
    cpu: dict[int, list[float]] = {k: [] for k in lags}
    handle = canopen_slave.CanopenSlave.receive_data

    def receive_data(self, can_id: int, data: bytes, timestamp: float) -> None:  # type: ignore[no-untyped-def]
        handle(self, can_id, data, timestamp)
        window = state[0]
        if can_id == 0x080 and window is not None:
            lags[window].append(time.time() - timestamp)

    canopen_slave.CanopenSlave.receive_data = receive_data  # type: ignore[method-assign]

    def toggle(sizes: tuple[int, ...]) -> None:
        time.sleep(START_S)
        hub = next((t for t in threading.enumerate() if t.name == HUB_THREAD), None)
        if hub is None or hub.ident is None:
            return
        clock = time.pthread_getcpuclockid(hub.ident)
        valves = [o for o in gc.get_objects() if isinstance(o, EmulatedValve)]
        while True:
            for k, size in enumerate(sizes):
                state[0] = None
                for valve in valves:
                    valve.pacer.min_batch = size
                time.sleep(SETTLE_S)
                state[0] = k
                used, began = time.clock_gettime(clock), time.monotonic()
                time.sleep(WINDOW_S)
                cpu[k].append((time.clock_gettime(clock) - used) / (time.monotonic() - began))

    if sizes:
        threading.Thread(target=toggle, args=(sizes,), daemon=True).start()

    def dump() -> None:
        state[0] = None
        windows = [
            {"min_batch": sizes[k] if sizes else None, "lags": lags[k], "hub_cpu": cpu[k]}
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
        label = "" if window["min_batch"] is None else f"min_batch {window['min_batch']}: "
        line = (f"  serve's view, {label}{n} SYNCs x valves handled: over 1 ms {late:.2%}, p50 "
                f"{lags[n // 2] * 1e3:.2f} ms, p99 {lags[int(0.99 * (n - 1))] * 1e3:.2f} ms, max "
                f"{lags[-1] * 1e3:.1f} ms")  # fmt: skip
        if window["hub_cpu"] and k:
            pairs = sorted(a / b for a, b in zip(cpus[k], cpus[0], strict=False) if b)
            line += (f"; receive thread CPU {_median(cpus[k]):.2f} core, paired against "
                     f"min_batch {windows[0]['min_batch']}: {pairs[len(pairs) // 2]:.3f}x "
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
    sizes = None
    if rest[0] == "--toggle-min-batch":
        sizes = tuple(int(s) for s in rest[1].split(","))
        rest = rest[2:]
    start(out, sizes)
    signal.signal(signal.SIGTERM, signal.default_int_handler)
    if rest[0] == "-m":
        sys.argv = [rest[1], *rest[2:]]
        runpy.run_module(sys.argv[0], run_name="__main__", alter_sys=True)

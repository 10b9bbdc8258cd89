"""USB link benchmark: upload efficiency and time, streaming capacity, parallel valves.

Run:  .venv/bin/python benchmarks/bench_usb.py [--realtime-stream]

1. Full E04 upload + verify + store over the emulated link held to one report per
   millisecond: reports sent against the minimum the payload needs (target ≤ 1.5×) and the
   elapsed time (target < 0.5 s), against the link-bound time measured in the same run.
2. Three measuring points at 5 kHz for 10 s: samples lost (must be 0) and the share of the
   link used. Simulated time by default (deterministic); ``--realtime-stream`` runs 10 s of
   wall-clock time with the valve in its real-time thread, as in the GUI.
3. One against eight emulated valves uploading in parallel: the throughput ratio, with the
   link paced (the issue's case: several valves on one PLC test rig in real time) and unpaced
   (CPU-bound), and the CPU time per upload that bounds the paced ratio.
"""

from __future__ import annotations

import argparse
import math
import os
import threading
import time

from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.device.emulator import EmulatedValve
from prm9tool.device.usb.session import UsbSession
from prm9tool.device.usb.transport.emulator import SLOT_S, EmulatorTransport

E04 = "PRM9-06.3Z11/30-24E04S02-CA"
REPORT = 64
KEYS = ["position_actual", "current_a", "demand"]
ROUNDS = 5


def tuned_values() -> dict[str, int | str]:
    """The E04 parameter set with every value changed (so each write really changes it)."""
    variant = TypeKey.parse(E04).variant
    values = {}
    for param in CATALOGUE.file_parameters(variant):
        default = param.default_for(variant)
        if "LINX" in param.mnemonic or "LINY" in param.mnemonic:  # curves must keep increasing
            assert isinstance(default, int)
            values[param.mnemonic] = default + 100 if default < param.raw_max else default - 100
            continue
        allowed = [code for code, _ in param.choices] or [param.raw_min, param.raw_max]
        values[param.mnemonic] = next(v for v in allowed if v != default)
    return values


def minimum_reports(values: dict[str, int | str]) -> tuple[int, int]:
    """(host→valve, both directions): each phase's payload bytes packed into 64-byte reports.

    Payload: write = address (3 bytes) + value per entry, plus a 1-byte acknowledgement;
    verify = the addresses, then the values; store = a 1-byte command and acknowledgement, then
    the values read back once more (the session's contract: stored = verified stored).
    """
    params = [CATALOGUE[m] for m in values]
    address_bytes = 3 * len(params)
    value_bytes = sum(p.dtype.size for p in params)

    def reports(n: int) -> int:
        return math.ceil(n / REPORT)

    read_back_out, read_back_in = reports(address_bytes), reports(value_bytes)
    out = reports(address_bytes + value_bytes) + 2 * read_back_out + reports(1)
    back = reports(1) + 2 * read_back_in + reports(1)
    return out, out + back


def bench_upload() -> None:
    values = tuned_values()
    valve = EmulatedValve(E04, 1)
    transport = EmulatorTransport(valve, paced=True)
    session = UsbSession(transport, "emulator:bench")
    out0, in0 = transport.stats.reports_out, transport.stats.reports_in
    start = time.perf_counter()
    result = session.upload(values)
    elapsed = time.perf_counter() - start
    assert result.stored and result.verified
    sent = transport.stats.reports_out - out0
    both = sent + transport.stats.reports_in - in0
    min_out, min_both = minimum_reports(values)
    link_bound = sent * SLOT_S  # request in frame k, answer in frame k+1 with the next request
    print("1. full E04 upload + verify + store, link at one report per ms")
    print(f"   parameters            {len(values)}")
    print(f"   reports sent          {sent} (minimum {min_out}) ratio {sent / min_out:.2f}")
    print(f"   both directions       {both} (minimum {min_both}) ratio {both / min_both:.2f}")
    print(f"   elapsed               {elapsed * 1000:.1f} ms (target < 500 ms)")
    print(f"   link-bound time       {link_bound * 1000:.1f} ms  ratio {elapsed / link_bound:.2f}")


def bench_stream(seconds: float, realtime: bool) -> None:
    valve = EmulatedValve(E04, 2)
    valve.set_input("setpoint", 5.0)
    reference = EmulatedValve(E04, 3)  # the same simulation without USB
    start = time.perf_counter()
    if not realtime:
        reference.advance(seconds)
    ref_cpu = time.perf_counter() - start
    if realtime:
        valve.start()
    transport = EmulatorTransport(valve, paced=realtime)
    session = UsbSession(transport, "emulator:stream")
    session.stream_start(KEYS)
    reports0, link0 = transport.stats.stream_reports, transport.link_time
    received = 0
    start = time.perf_counter()
    while (transport.link_time - link0) < seconds:
        if realtime:
            time.sleep(0.02)  # the GUI's worker reads about 50 times a second
        else:
            valve.advance(0.02)
        received += len(session.stream_read())
    elapsed = time.perf_counter() - start
    link = transport.link_time - link0
    session.stream_stop()
    valve.stop()
    expected = round(link * 5000)
    reports = transport.stats.stream_reports - reports0
    mode = "wall clock, valve thread" if realtime else "simulated time, stepped"
    print(f"2. 3 channels × 5 kHz for {link:.1f} s ({mode})")
    print(f"   samples received      {received} of ≈{expected} (the last ≤ 10 ms still queued)")
    print(f"   samples lost          {session.samples_lost}")
    print(f"   link used (IN)        {reports / (link / SLOT_S):.1%} of the report slots")
    print(
        f"   payload share (IN)    {received * 3 * 2 / (link / SLOT_S * REPORT):.1%} of the bytes"
    )
    if not realtime:
        print(
            f"   CPU time              {elapsed:.2f} s; valve alone {ref_cpu:.2f} s ratio "
            f"{elapsed / ref_cpu:.2f}"
        )


def open_valves(first_serial: int, count: int, paced: bool) -> list[UsbSession]:
    """Sessions to ``count`` fresh emulated valves (``paced``: link at one report per ms)."""
    sessions = []
    for serial in range(first_serial, first_serial + count):
        transport = EmulatorTransport(EmulatedValve(E04, serial), paced=paced)
        sessions.append(UsbSession(transport, f"emulator:{serial}"))
    return sessions


def upload_all(sessions: list[UsbSession], values: dict[str, int | str]) -> tuple[float, float]:
    """(wall s, process CPU s) to upload ``values`` into every session, one thread per valve."""

    def upload(session: UsbSession) -> None:
        for _ in range(ROUNDS):
            assert session.upload(values).stored

    threads = [threading.Thread(target=upload, args=(s,)) for s in sessions]
    cpu, start = time.process_time(), time.perf_counter()
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    return time.perf_counter() - start, time.process_time() - cpu


def bench_parallel(count: int, repeats: int) -> None:
    """1 against ``count`` valves, paced (the PLC rig's case) and unpaced (CPU-bound).

    Paced, each upload mostly waits for its link (one report per ms), so parallel valves
    overlap; only the Python per report is serialized (the GIL), and it sets the ceiling:
    one upload's elapsed time / its CPU time. Unpaced, an upload never waits: the uploads are
    pure Python, so threads in one process cannot beat one valve (the GIL), whatever the cores.
    Best of ``repeats`` runs each (the least disturbed by the machine's other load).
    """
    values = tuned_values()
    print(f"3. 1 vs {count} emulated valves uploading in parallel, {ROUNDS} uploads each")
    for paced in (True, False):
        serial = 100
        singles, many = [], []
        for _ in range(repeats):
            singles.append(upload_all(open_valves(serial, 1, paced), values))
            many.append(upload_all(open_valves(serial + 1, count, paced), values))
            serial += count + 1
        single, single_cpu = min(singles)
        parallel, parallel_cpu = min(many)
        one, rate = ROUNDS / single, count * ROUNDS / parallel
        pairs = sorted(count * s[0] / m[0] for s, m in zip(singles, many, strict=True))
        if paced:
            print("   link at one report per ms (real time, as on a PLC test rig):")
        else:
            print("   link unpaced (CPU-bound: no waiting, the GIL serializes the uploads):")
        print(f"   1 valve               {single * 1000:.0f} ms  ({one:.1f} uploads/s)")
        print(f"   {count} valves              {parallel * 1000:.0f} ms  ({rate:.1f} uploads/s)")
        print(
            f"   throughput ratio      {rate / one:.1f}× (ideal {count}×; best times of "
            f"{repeats} runs, the runs' own ratios {pairs[0]:.1f}–{pairs[-1]:.1f}×)"
        )
        per_upload = parallel_cpu / (count * ROUNDS)
        print(
            f"   CPU per upload        {single_cpu / ROUNDS * 1000:.2f} ms alone, "
            f"{per_upload * 1000:.2f} ms with {count} ({parallel_cpu / parallel:.0%} of one core)"
        )
        if paced:
            ceiling = single / ROUNDS / per_upload
            print(f"   GIL-bound ceiling     {ceiling:.1f}× (one upload's time / its CPU time)")
    print(f"   load average          {os.getloadavg()[0]:.1f} ({os.cpu_count()} cores)")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--realtime-stream", action="store_true")
    parser.add_argument("--seconds", type=float, default=10.0)
    parser.add_argument("--quick", action="store_true", help="a smoke run: seconds, not figures")
    args = parser.parse_args()
    if args.quick:
        args.seconds = 0.5
    bench_upload()
    bench_stream(args.seconds, args.realtime_stream)
    bench_parallel(8, 1 if args.quick else 5)


if __name__ == "__main__":
    main()

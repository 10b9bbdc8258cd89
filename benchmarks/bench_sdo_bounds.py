"""What an upload that never ends costs the CANopen master (issue 29, docs/can-link.md
"Bounded, exact SDO transfers").

A node on a python-can virtual bus (a thread on raw frames, in this process) answers every
segmented upload with full 7-byte segments and never the last one — with no size declared,
or declaring 0xFFFFFFFF bytes. Prints, for the firmware text 0x100A (a catalogue string:
bound ``STRING_MAX_BYTES``) and an object the catalogue does not know (``DEFAULT_MAX_BYTES``):
the segments the master asked for, the wall time until it aborted, the abort code and the
peak memory allocated during the transfer (tracemalloc; the figure includes what the bus's
receive thread allocates for the frames meanwhile, so it is an upper bound).

    .venv/bin/python benchmarks/bench_sdo_bounds.py [--quick]

Then, against an emulated valve on the virtual bus, what the master's own transfers cost
next to the ``canopen`` package's client it replaced: 500 uploads of 0x6041 (expedited) and of
0x100A (segmented), wall and CPU time per upload, alternating twice.

``--quick`` (a smoke run): the firmware text only, no size declared; 20 uploads each.
"""

from __future__ import annotations

import argparse
import threading
import time
import tracemalloc

import can
import canopen

from prm9tool.device.canlink.bus import CanOptions, acquire, release
from prm9tool.device.canlink.sdo import SdoChannel, SdoTransferError, max_bytes
from prm9tool.errors import Prm9Error

NODE = 11


class EndlessNode:
    """Answers every upload of 0x600+NODE segmented, with segments that never end."""

    def __init__(self, channel: str, declared: int | None) -> None:
        self.bus = can.Bus(interface="virtual", channel=channel)
        self.declared = declared
        self.segments = 0
        self.stop = threading.Event()
        self.thread = threading.Thread(target=self.serve, daemon=True)
        self.thread.start()

    def serve(self) -> None:
        while not self.stop.is_set():
            msg = self.bus.recv(0.05)
            if msg is None or msg.arbitration_id != 0x600 + NODE:
                continue
            data = bytes(msg.data)
            if data[0] == 0x40:
                size = self.declared
                head = bytes([0x40 if size is None else 0x41]) + data[1:4]
                answer = head + (size or 0).to_bytes(4, "little")
            elif data[0] & 0xE0 == 0x60:
                self.segments += 1
                answer = bytes([data[0] & 0x10]) + b"x" * 7
            else:
                continue
            self.bus.send(
                can.Message(arbitration_id=0x580 + NODE, data=answer, is_extended_id=False)
            )

    def close(self) -> None:
        self.stop.set()
        self.thread.join(5)
        self.bus.shutdown()


def measure(index: int, declared: int | None) -> str:
    channel = f"bench-sdo-bounds-{time.monotonic_ns()}"
    node = EndlessNode(channel, declared)
    shared = acquire(CanOptions("virtual", channel))
    remote = canopen.RemoteNode(NODE, canopen.ObjectDictionary())
    shared.network.add_node(remote)
    sdo = SdoChannel(remote, 0.5, shared)
    tracemalloc.start()
    started = time.monotonic()
    try:
        sdo.upload(index, 0)
        outcome = "no error (a defect)"
    except SdoTransferError as exc:
        outcome = f"abort 0x{int(exc.code):08X}"
    except Prm9Error as exc:
        outcome = type(exc).__name__
    took = time.monotonic() - started
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    release(shared)
    node.close()
    shown = "none" if declared is None else f"0x{declared:X}"
    return (
        f"0x{index:04X} (bound {max_bytes(index, 0)} B), declared {shown}: "
        f"{node.segments} segments, {took * 1000:.0f} ms, {outcome}, peak {peak / 1024:.1f} KiB"
    )


def round_trips(count: int) -> None:
    from prm9tool.device.emulator import EmulatedValve

    channel = f"bench-sdo-round-trip-{time.monotonic_ns()}"
    valve = EmulatedValve("PRM9-06.3Z11/30-24E04S02-CA", 4711)
    slave_bus = can.Bus(interface="virtual", channel=channel)
    slave = valve.connect_can(slave_bus)
    valve.advance(2.0)  # its boot
    shared = acquire(CanOptions("virtual", channel))
    remote = canopen.RemoteNode(valve.node_id, canopen.ObjectDictionary())
    shared.network.add_node(remote)
    sdo = SdoChannel(remote, 0.5, shared)
    remote.sdo.RESPONSE_TIMEOUT = 0.5
    for index in (0x6041, 0x100A, 0x6041, 0x100A):
        for name, upload in (("prm9tool", sdo.upload), ("canopen ", remote.sdo.upload)):
            wall, cpu = time.perf_counter(), time.process_time()
            for _ in range(count):
                upload(index, 0)
            wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
            print(
                f"{name} 0x{index:04X}: {wall / count * 1e3:.3f} ms wall, "
                f"{cpu / count * 1e3:.3f} ms CPU per upload"
            )
    release(shared)
    slave.stop()
    slave_bus.shutdown()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true", help="a smoke run")
    quick = parser.parse_args().quick
    cases = [(0x100A, None)] if quick else [
        (0x100A, None), (0x100A, 0xFFFFFFFF), (0x5FFF, None), (0x5FFF, 0xFFFFFFFF),
    ]  # fmt: skip
    for index, declared in cases:
        print(measure(index, declared))
    round_trips(20 if quick else 500)


if __name__ == "__main__":
    main()

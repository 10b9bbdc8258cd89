"""The floor of any serving process on this machine: N nodes that do nothing but the frames.

``bench_plc_rig.py --floor`` serves its runs with this instead of ``prm9tool --serve-emulator``:
one thread receiving on python-can's udp_multicast socket the way the served valves' hub does
(``canopen_udp``: the kernel's ID filter, ``MSG_DONTWAIT``, msgpack's C decoder) and answering
each SYNC with every node's TPDO1 from bytes made once — no valve, no object dictionary, no
simulation. Boot-up at start, every SDO download confirmed (the benchmark's commissioning),
RPDOs received and dropped. What the rig reaches with this is what a served valve's per-frame
path in C could reach at best here (the same system calls, no Python per valve): the
machine's own share of TPDO1 within 1 ms.

    python benchmarks/serve_floor.py GROUP NODES
"""

from __future__ import annotations

import signal
import sys
import threading

import can


def serve(group: str, nodes: int) -> None:
    """Answer on ``group`` until SIGTERM."""
    from prm9tool.device.emulator import canopen_hub, canopen_udp

    bus = can.Bus(interface="udp_multicast", channel=group)
    canopen_hub.enlarge_receive_buffer(bus)
    receive, send = canopen_udp.receiver(bus), canopen_udp.sender(bus)
    assert receive is not None and send is not None
    taken = {
        0x080,
        *(0x600 + n for n in range(1, nodes + 1)),
        *(0x200 + n for n in range(1, nodes + 1)),
    }
    canopen_udp.filter_ids(bus.fileno(), taken)
    tpdo1 = [(0x180 + n, b"\x37\x06\x00\x00") for n in range(1, nodes + 1)]  # status, actual
    stop = threading.Event()
    signal.signal(signal.SIGTERM, lambda *_: stop.set())
    threading.Thread(target=sys.stdin.read, daemon=True).start()  # the fault commands: read
    for node in range(1, nodes + 1):
        send(0x700 + node, b"\x00")  # boot-up
    while not stop.is_set():
        frame = receive(0.1)
        if frame is None:
            continue
        can_id, data, _ = frame
        if can_id == 0x080:
            for cob_id, payload in tpdo1:
                send(cob_id, payload)
        elif can_id & 0x780 == 0x600 and data[:1] in (b"\x2f", b"\x2b", b"\x27", b"\x23"):
            send(can_id - 0x80, b"\x60" + data[1:4] + b"\x00\x00\x00\x00")
    bus.shutdown()


if __name__ == "__main__":
    serve(sys.argv[1], int(sys.argv[2]))

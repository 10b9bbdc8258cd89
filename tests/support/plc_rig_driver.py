"""Runs inside a private network namespace (tests/test_plc_rig_processes.py): a PLC written from
docs/plc-testing.md alone, with the ``canopen`` package, against ``prm9tool --serve-emulator``
serving VALVES emulated valves (nodes 1…VALVES) in another process on a udp_multicast bus.

It commissions every valve (§7.6: heartbeat, TPDO1 every SYNC, NMT start, control word 08h →
09h → 0Bh → 0Fh), runs SYNC every PERIOD_MS with an RPDO1 setpoint square per SYNC for
SECONDS, injects a fault on node 2 through the serve command's stdin, clears it, resets the
fault with 08h → 09h → 0Bh → 0Fh, and writes what it saw to OUT/result.json.

Usage: ``python plc_rig_driver.py OUT GROUP VALVES PERIOD_MS SECONDS``
"""

from __future__ import annotations

import itertools
import json
import os
import signal
import socket
import subprocess
import sys
import threading
import time
import traceback
from pathlib import Path

import canopen

E02 = "PRM9-06.3Z11/30-24E02S02-CA"
FAULTY = 2  # the node the fault is injected on
CYCLE_FACTOR = 5  # 0x1006 = 5 SYNC periods: a margin for the PLC thread on a busy PC (--busy 2)
RECEIVE_BUFFER = 4 * 1024 * 1024  # bytes: a PLC taking 16 TPDO1 a millisecond needs more
SDO_RETRIES = 3  # and a request the PC's load dropped (the kernel, a full buffer) is sent again
SDO_TIMEOUT_S = 2.0  # canopen's 0.3 s is short for 16 emulated valves on a loaded 2-core PC
MIN_CYCLE_MS = 60  # and at least 60 ms: a PLC thread on a loaded 2-core PC stalls for 40 ms


def cycle_period_ms(period_ms: float) -> float:
    """What the PLC writes to 0x1006 (the valves report SYNC missing after 1.5 x this)."""
    return max(CYCLE_FACTOR * period_ms, MIN_CYCLE_MS)


def main() -> None:
    out, group = Path(sys.argv[1]), sys.argv[2]
    count, period_ms, seconds = int(sys.argv[3]), float(sys.argv[4]), float(sys.argv[5])
    result: dict[str, object] = {}
    command = [sys.executable, "-m", "prm9tool", "--can-interface", "udp_multicast",
               "--can-channel", group]  # fmt: skip
    for node in range(1, count + 1):
        command += ["--serve-emulator", f"{E02}:{8000 + node}", "--node-id", str(node)]
    serve = subprocess.Popen(command, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                             stderr=subprocess.STDOUT, text=True)  # fmt: skip
    lines: list[str] = []
    reader = threading.Thread(target=lambda: lines.extend(iter(serve.stdout.readline, "")))
    reader.start()
    eds = out / "prm9.eds"
    subprocess.run([sys.executable, "-m", "prm9tool", "--export-eds", E02, "-o", str(eds)],
                   check=True)  # fmt: skip
    network = canopen.Network()
    network.connect(interface="udp_multicast", channel=group)
    _enlarge_receive_buffer(network.bus)
    try:
        result.update(_plc(network, serve, lines, eds, count, period_ms, seconds))
    except Exception as exc:  # the test shows it
        result["driver_error"] = "".join(traceback.format_exception(exc)[-4:])
    finally:
        network.disconnect()
        serve.send_signal(signal.SIGTERM)
        try:
            serve.wait(timeout=60)
        except subprocess.TimeoutExpired:
            serve.kill()
        reader.join(10)
        result["serve"] = "".join(lines)
        (out / "result.json").write_text(json.dumps(result), encoding="utf-8")


def _plc(network, serve, lines, eds, count, period_ms, seconds):  # type: ignore[no-untyped-def]
    emcy: list[tuple[int, int]] = []
    nodes = {}
    for node_id in range(1, count + 1):
        node = network.add_node(node_id, str(eds))
        node.sdo.RESPONSE_TIMEOUT = SDO_TIMEOUT_S  # docs/plc-testing.md: a busy PC
        node.sdo.MAX_RETRIES = SDO_RETRIES
        node.emcy.add_callback(lambda e, n=node_id: emcy.append((n, e.code)))
        nodes[node_id] = node
    deadline = time.monotonic() + 60
    while not all(f"node {n}: NMT pre-operational" in "".join(lines) for n in nodes):
        assert time.monotonic() < deadline, "the served valves did not come up"
        time.sleep(0.1)
    for node_id, node in nodes.items():  # docs/plc-testing.md, "Commissioning"
        node.sdo[0x1017].raw = 0  # no heartbeat: the PLC watches the TPDOs
        node.sdo[0x1006].raw = int(cycle_period_ms(period_ms) * 1000)  # missing: 1.5 x this
        node.sdo[0x1800][1].raw = 0x180 + node_id
        node.sdo[0x1800][2].raw = 1  # TPDO1 every SYNC
        node.sdo[0x1801][1].raw = 0x80000280 + node_id  # TPDO2 off
    network.nmt.send_command(0x01)  # NMT start, all nodes
    time.sleep(0.1)
    for node in nodes.values():
        _enable(node)
    tpdo = dict.fromkeys(nodes, 0)
    actual: dict[int, list[int]] = {n: [0, 0] for n in nodes}  # lowest, highest 0x6301/1 seen
    for node_id in nodes:
        network.subscribe(
            0x180 + node_id, lambda can_id, data, ts: _count(tpdo, actual, can_id, data)
        )
    syncs: list[float] = []  # the bus's own record: our SYNCs as the socket received them
    network.subscribe(0x080, lambda can_id, data, ts: syncs.append(ts))
    network.sync.start(period_ms / 1000.0)
    stop = threading.Event()
    profile = threading.Thread(target=_setpoints, args=(network, nodes, period_ms, stop))
    profile.start()
    try:
        time.sleep(seconds / 2)
        before_fault = list(emcy)
        serve.stdin.write(f"inject node:{FAULTY} COIL_A_OPEN\n")
        serve.stdin.flush()
        _wait(lambda: (FAULTY, 0x5411) in emcy, 10)
        states_faulty = _settled_state(nodes[FAULTY])
        serve.stdin.write(f"clear node:{FAULTY} COIL_A_OPEN\n")
        serve.stdin.flush()
        time.sleep(0.5)
        stop.set()  # the RPDOs say 0Fh: pause them while the fault is reset by SDO
        profile.join()
        _enable(nodes[FAULTY])  # 08h resets the fault whose cause is gone (docs)
        after_reset = nodes[FAULTY].sdo[0x6041].raw & 0x0F
        stop.clear()
        profile = threading.Thread(target=_setpoints, args=(network, nodes, period_ms, stop))
        profile.start()
        time.sleep(seconds / 2)
        # read while SYNC runs: 16 SDO reads outlast 1.5 x 0x1006 once SYNC stops
        states = {n: node.sdo[0x6041].raw & 0x0F for n, node in nodes.items()}
    finally:
        stop.set()
        profile.join()
        during = list(emcy)  # stopping SYNC below is a real loss: its 8100 is caused
        network.sync.stop()
    return {
        "emcy": during,
        "sync_gap_ms": max((b - a for a, b in itertools.pairwise(syncs)), default=0) * 1e3,
        "syncs": len(syncs),
        "emcy_before_fault": before_fault,
        "faulty_state": states_faulty,
        "after_reset": after_reset,
        "states": states,
        "tpdo": tpdo,
        "actual": actual,
    }


def _enlarge_receive_buffer(bus) -> None:  # type: ignore[no-untyped-def]
    """docs/plc-testing.md: 16 TPDO1 a millisecond overflow the kernel's default socket buffer
    (~200 datagrams) whenever a busy PC holds up the PLC's receive thread for 10 ms or so; an
    SDO answer lost with them is an SDO timeout."""
    with socket.socket(fileno=os.dup(bus.fileno())) as sock:  # the bus's socket, a copy of it
        sock.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, RECEIVE_BUFFER)


def _settled_state(node) -> int:  # type: ignore[no-untyped-def]
    """Bits 0…3 of the status word once the fault reaction (a few ms) is over."""
    deadline = time.monotonic() + 5
    while (state := node.sdo[0x6041].raw & 0x0F) == 0b0111 and time.monotonic() < deadline:
        time.sleep(0.01)  # FAULT_REACTION: outputs being switched off
    return state


def _enable(node) -> None:  # type: ignore[no-untyped-def]
    for word in (0x08, 0x09, 0x0B, 0x0F):
        node.sdo[0x6040].raw = word


def _setpoints(network, nodes, period_ms, stop) -> None:  # type: ignore[no-untyped-def]
    """RPDO1 (control word 0Fh, setpoint) to every node each period: a ±25 % square, 0.5 s."""
    start, n = time.monotonic(), 0
    while not stop.is_set():
        n += 1
        value = 4096 if int((time.monotonic() - start) / 0.5) % 2 else -4096
        data = bytes([0x0F, 0]) + value.to_bytes(2, "little", signed=True)
        for node_id in nodes:
            network.send_message(0x200 + node_id, data)
        stop.wait(max(0.0, start + n * period_ms / 1000 - time.monotonic()))


def _count(tpdo, actual, can_id, data) -> None:  # type: ignore[no-untyped-def]
    """A TPDO1 (status word, actual value 0x6301/1): counted, the actual value's range kept."""
    node = can_id - 0x180
    tpdo[node] += 1
    if len(data) >= 4:
        value = int.from_bytes(data[2:4], "little", signed=True)
        seen = actual[node]
        seen[0], seen[1] = min(seen[0], value), max(seen[1], value)


def _wait(condition, timeout_s) -> None:  # type: ignore[no-untyped-def]
    deadline = time.monotonic() + timeout_s
    while not condition():
        assert time.monotonic() < deadline, "not in time"
        time.sleep(0.01)


if __name__ == "__main__":
    os.environ.setdefault("PYTHONUNBUFFERED", "1")
    main()

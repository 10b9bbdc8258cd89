"""Runs inside a private network namespace (tests/test_can_bad_nodes_processes.py): an
emulated -CA valve served at node 10 (``--serve-emulator``), misbehaving raw-frame nodes
(tests/support/bad_node.py) in processes of their own on the same udp_multicast bus, and
prm9tool's ``--list-devices`` and ``--batch`` in others. Writes what each printed to
OUT/result.json.

Usage: ``python bad_node_driver.py run OUT GROUP`` (GROUP: the multicast address, the bus);
``python bad_node_driver.py serve GROUP NODE:FAULT[:DELAY_MS[:SERIAL]] …`` serves bad nodes
until terminated.
"""

from __future__ import annotations

import json
import signal
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # tests/: the support package

E04 = "PRM9-06.3Z11/30-24E04S02-CA"
NODES = (  # one process each
    ("11:answers-1000-only",),
    ("12:none:0:777002",),  # two processes at node 12: two nodes at one ID, 3 ms apart
    ("12:none:3:777003",),
    ("13:endless-huge",),
)


def serve(group: str, specs: list[str]) -> None:
    """Serve the bad nodes ``specs`` until SIGTERM."""
    import can

    from support.bad_node import BadNode, Fault, prm9_objects

    bus = can.Bus(interface="udp_multicast", channel=group)
    nodes = []
    for spec in specs:
        node, fault, *rest = spec.split(":")
        delay_ms = rest[0] if rest else "0"
        serial = rest[1] if len(rest) > 1 else "777001"
        nodes.append(
            BadNode(
                bus, int(node), Fault(fault), prm9_objects(int(serial)), int(delay_ms) / 1000
            ).start()
        )
    print("serving", flush=True)
    signal.sigwait([signal.SIGTERM])
    for bad in nodes:
        bad.stop()
    bus.shutdown()


def tool(*args: str, timeout: float = 120) -> dict[str, object]:
    """Run prm9tool in a process of its own; its exit code and output."""
    done = subprocess.run(
        [sys.executable, "-m", "prm9tool", *args],
        capture_output=True,
        text=True,
        timeout=timeout,
        check=False,
    )
    return {"code": done.returncode, "out": done.stdout, "err": done.stderr}


def _started(command: list[str], ready: str) -> subprocess.Popen[str]:
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    assert process.stdout is not None
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline:
        line = process.stdout.readline()
        if ready in line or not line:
            break
    return process


def run(out: Path, group: str) -> None:
    """Serve, use, stop; write the outcome."""
    bus = ["--can-interface", "udp_multicast", "--can-channel", group]
    processes = [
        _started(
            [sys.executable, "-m", "prm9tool", "--serve-emulator", f"{E04}:4711", *bus],
            "on the bus",
        )
    ]
    result: dict[str, object] = {}
    try:
        processes += [
            _started([sys.executable, __file__, "serve", group, *specs], "serving")
            for specs in NODES
        ]
        result["list"] = tool("--list-devices", *bus)
        source = out / "tuned.prm"
        result["new"] = tool("--new", E04, "-o", str(source))
        source.write_text(
            source.read_text(encoding="utf-8").replace("MONDELAY = 1000", "MONDELAY = 1500"),
            encoding="utf-8",
        )
        result["batch"] = tool("--batch", str(source), "--device", "can:10", *bus)
        result["download12"] = tool(
            "--batch", "--download", str(out / "twelve.prm"), "--device", "can:12", *bus
        )
        result["twelve_saved"] = (out / "twelve.prm").exists()
        result["batch13"] = tool("--batch", str(source), "--device", "can:13", *bus)
    except Exception as exc:  # the test reports it
        result["driver_error"] = repr(exc)
    finally:
        for process in processes:
            process.terminate()
            try:
                process.wait(10)
            except subprocess.TimeoutExpired:
                process.kill()
        (out / "result.json").write_text(json.dumps(result), encoding="utf-8")


if __name__ == "__main__":
    if sys.argv[1] == "serve":
        serve(sys.argv[2], sys.argv[3:])
    else:
        run(Path(sys.argv[2]), sys.argv[3])

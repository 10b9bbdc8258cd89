"""Runs inside a private network namespace (tests/test_lss_processes.py): two emulated -CA
valves at node-ID switch 1 (LSS) in processes of their own on one udp_multicast bus; the tool,
in further processes, finds them (``--lss-scan``), gives them node IDs 21 and 22
(``--lss-assign``); the valves are power-cycled (their processes end and start again), then the
tool lists and uploads them (``--list-devices``, ``--batch --all``). Writes OUT/result.json.

Usage: ``python lss_processes_driver.py OUT GROUP`` (GROUP: the multicast address, the bus).
"""

from __future__ import annotations

import json
import signal
import subprocess
import sys
import time
from pathlib import Path

E04 = "PRM9-06.3Z11/30-24E04S02-CA"
SERIALS = (4711, 4712)


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


def serve(serial: int, bus: list[str], ready: str) -> tuple[subprocess.Popen[str], list[str]]:
    """One valve at switch 1 in a process of its own; returns once it printed ``ready``."""
    process = subprocess.Popen(
        [sys.executable, "-m", "prm9tool", "--serve-emulator", f"{E04}:{serial}",
         "--node-id", "lss", *bus],
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
    )  # fmt: skip
    lines: list[str] = []
    assert process.stdout is not None
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline:
        line = process.stdout.readline()
        lines.append(line)
        if ready in line or not line:
            break
    return process, lines


def stop(process: subprocess.Popen[str], lines: list[str]) -> str:
    """End a served valve (SIGTERM: its power goes off); everything it printed."""
    process.send_signal(signal.SIGTERM)
    process.wait(timeout=30)
    rest = process.stdout.read() if process.stdout is not None else ""
    return "".join(lines) + rest


def main() -> None:
    """Serve, commission, power-cycle, list and upload; write the outcome."""
    out, group = Path(sys.argv[1]), sys.argv[2]
    bus = ["--can-interface", "udp_multicast", "--can-channel", group]
    result: dict[str, object] = {}
    served = [serve(serial, bus, "waiting for an LSS master") for serial in SERIALS]
    try:
        result["list_before"] = tool("--list-devices", *bus)
        result["scan"] = tool("--lss-scan", "--json", *bus)
        result["assign"] = tool("--lss-assign", "4711=21", "4712=22", *bus)
        result["scan_after"] = tool("--lss-scan", *bus)
    finally:
        result["serve_first"] = [stop(*item) for item in served]
    served = [serve(serial, bus, "on the bus") for serial in SERIALS]  # power on again
    try:
        result["list"] = tool("--list-devices", *bus)
        source = out / "released.prm"
        result["new"] = tool("--new", E04, "-o", str(source))
        report = out / "report.json"
        result["batch"] = tool("--batch", str(source), "--all", *bus, "--report", str(report))
        result["report"] = (
            json.loads(report.read_text(encoding="utf-8")) if report.exists() else None
        )
    finally:
        result["serve_second"] = [stop(*item) for item in served]
        (out / "result.json").write_text(json.dumps(result, indent=1), encoding="utf-8")


if __name__ == "__main__":
    main()

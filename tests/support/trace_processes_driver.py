"""The two-process trace test's driver (runs inside a private network namespace): prm9tool
--serve-emulator with two valves (nodes 10 and 15) in one process, prm9tool --record in
another, and here a ``canopen``-package PLC that commissions both, runs setpoints at 1 kHz SYNC
and provokes an RPDO-deadline fault on node 10 (its RPDO1 stops). Writes result.json.

    python tests/support/trace_processes_driver.py OUT_DIR GROUP
"""

from __future__ import annotations

import json
import signal
import struct
import subprocess
import sys
import threading
import time
from pathlib import Path

E02 = "PRM9-06.3Z11/30-24E02S02-CA"
E04 = "PRM9-06.3Z11/30-24E04S02-CA"
DEADLINE_MS = 20


class Tool:
    """A prm9tool process whose output (standard output and error) is read as it comes."""

    def __init__(self, args: list[str]) -> None:
        self.process = subprocess.Popen(
            [sys.executable, "-m", "prm9tool", *args],
            stdout=subprocess.PIPE,
            stderr=subprocess.STDOUT,
            text=True,
        )
        self.lines: list[str] = []
        self._reader = threading.Thread(target=self._read, daemon=True)
        self._reader.start()

    def _read(self) -> None:
        assert self.process.stdout is not None
        for line in self.process.stdout:
            self.lines.append(line)

    def wait_for(self, text: str, timeout_s: float = 60) -> None:
        """Until a line of its output contains ``text``."""
        deadline = time.monotonic() + timeout_s
        while not any(text in line for line in self.lines):
            if time.monotonic() > deadline or self.process.poll() is not None:
                raise RuntimeError(f"no {text!r} from prm9tool: {''.join(self.lines)}")
            time.sleep(0.05)

    def stop(self) -> int:
        """SIGTERM, then its exit code (killed after 30 s)."""
        self.process.send_signal(signal.SIGTERM)
        try:
            self.process.wait(30)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()
        self._reader.join(5)
        return self.process.returncode


def _plc(group: str) -> None:
    import canopen

    network = canopen.Network()
    network.connect(interface="udp_multicast", channel=group)
    try:
        nodes = {
            n: network.add_node(canopen.RemoteNode(n, canopen.ObjectDictionary())) for n in (10, 15)
        }
        for node in nodes.values():
            node.sdo.upload(0x1018, 1)
            node.sdo.download(0x1800, 5, struct.pack("<H", 10))  # TPDO1 every 10 ms
        nodes[15].sdo.download(0x6043, 0, struct.pack("<b", 4))
        network.send_message(0x000, bytes([0x01, 0x00]))  # NMT start, all nodes
        time.sleep(0.2)
        for word in (0x08, 0x09, 0x0B, 0x0F):
            for node in nodes.values():
                node.sdo.download(0x6040, 0, struct.pack("<H", word))
            time.sleep(0.1)
        nodes[10].sdo.download(0x1400, 5, struct.pack("<H", DEADLINE_MS))
        _run(network, 1500, to=(10, 15))
        _run(network, 300, to=(15,))  # node 10's setpoints stop: its deadline passes
    finally:
        network.disconnect()


def _run(network: object, periods: int, to: tuple[int, ...]) -> None:
    """``periods`` SYNC periods of 1 ms: SYNC, then RPDO1 (control word 0Fh, setpoint)."""
    started = time.perf_counter()
    for k in range(periods):
        network.send_message(0x080, b"")  # type: ignore[attr-defined]
        for node in to:
            network.send_message(0x200 + node, struct.pack("<Hh", 0x0F, 4000))  # type: ignore[attr-defined]
        wait = started + (k + 1) * 0.001 - time.perf_counter()
        if wait > 0:
            time.sleep(wait)


def main() -> None:
    out, group = Path(sys.argv[1]), sys.argv[2]
    bus = ["--can-interface", "udp_multicast", "--can-channel", group]
    result: dict[str, object] = {}
    valves: Tool | None = None
    recorder: Tool | None = None
    try:
        valves = Tool(
            ["--serve-emulator", f"{E02}:3010", "--node-id", "10", "--serve-emulator",
             f"{E04}:3015", "--node-id", "15", *bus]
        )  # fmt: skip
        valves.wait_for("node 15: on the bus")
        recorder = Tool(["--record", str(out / "machine.blf"), *bus])
        recorder.wait_for("recording")
        _plc(group)
        time.sleep(0.5)
    except Exception as exc:
        result["driver_error"] = repr(exc)
    finally:
        if recorder is not None:
            result["recorder_code"] = recorder.stop()
            result["recorder_out"] = "".join(recorder.lines)
        if valves is not None:
            valves.stop()
            result["valves_out"] = "".join(valves.lines)
    result["trace"] = str(out / "machine.blf")
    (out / "result.json").write_text(json.dumps(result), encoding="utf-8")


if __name__ == "__main__":
    main()

"""Runs inside a private network namespace (tests/test_can_reconnect_processes.py): a valve
served by ``prm9tool --serve-emulator`` in another process as node 10; this process is the
tool (a ValveConnection, as the GUI has it) online with it. The serving process ends (the valve
drops off the bus), the connection looks for it; the valve is served again as node 15 (same
serial, same EEPROM image) and the connection must find it there. Writes OUT/result.json.

Usage: ``python can_reconnect_driver.py OUT GROUP``.
"""

from __future__ import annotations

import json
import signal
import subprocess
import sys
import time
from collections.abc import Callable
from pathlib import Path

E04 = "PRM9-06.3Z11/30-24E04S02-CA"
SERIAL = 4713
WAIT_S = 60.0  # an upper bound only: every wait ends as soon as its condition holds


def serve(group: str, node: int) -> subprocess.Popen[str]:
    """The valve on the bus as ``node``; returns once it says it is on the bus."""
    bus = ["--can-interface", "udp_multicast", "--can-channel", group]
    process = subprocess.Popen(
        [sys.executable, "-m", "prm9tool", "--serve-emulator", f"{E04}:{SERIAL}",
         "--node-id", str(node), *bus],
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
    )  # fmt: skip
    assert process.stdout is not None
    while line := process.stdout.readline():
        if "on the bus" in line:
            return process
    raise RuntimeError(f"the valve was not served as node {node}")


def end(process: subprocess.Popen[str]) -> None:
    """The valve drops off the bus (its process ends)."""
    process.send_signal(signal.SIGTERM)
    process.wait(timeout=WAIT_S)


def main() -> None:
    """Online, lose the valve, serve it at another node ID, found again; write the outcome."""
    from PySide6.QtCore import QCoreApplication

    from prm9tool.device import factory
    from prm9tool.device.canlink.bus import CanOptions
    from prm9tool.online.connection import ValveConnection
    from prm9tool.service.valve_listing import default_lister

    out, group = Path(sys.argv[1]), sys.argv[2]
    options = CanOptions("udp_multicast", group)
    qt = QCoreApplication([])
    result: dict[str, object] = {"events": []}
    events: list[object] = result["events"]  # type: ignore[assignment]
    connection = ValveConnection(
        opener=lambda entry: factory.open_session(entry, can_link=options),  # type: ignore[arg-type]
        lister=default_lister,
    )
    connection.lost.connect(lambda m: events.append(["lost", m]))
    connection.reconnected.connect(lambda i: events.append(["reconnected", i.device_id, i.serial]))
    connection.failed.connect(lambda m: events.append(["failed", m]))

    def until(condition: Callable[[], bool], what: str) -> None:
        deadline = time.monotonic() + WAIT_S
        while not condition():
            if time.monotonic() > deadline:
                raise TimeoutError(what)
            qt.processEvents()
            time.sleep(0.01)  # the worker and the loop post their results meanwhile

    first = serve(group, 10)
    second = None
    try:
        connection.go_online("can:10")
        until(lambda: connection.is_online, "online with node 10")
        result["first"] = [connection.device.device_id, connection.device.serial]  # type: ignore[union-attr]
        end(first)
        until(lambda: connection.is_reconnecting, "looking for the lost valve")
        result["looking_for"] = connection.lost_valve.serial  # type: ignore[union-attr]
        second = serve(group, 15)
        until(lambda: connection.is_online, "online again")
        result["second"] = [connection.device.device_id, connection.device.serial]  # type: ignore[union-attr]
    except Exception as exc:  # the outcome says what broke; the test shows it
        result["driver_error"] = repr(exc)
    finally:
        connection.shutdown()
        for process in (first, second):
            if process is not None and process.poll() is None:
                end(process)
        (out / "result.json").write_text(json.dumps(result, indent=1), encoding="utf-8")


if __name__ == "__main__":
    main()

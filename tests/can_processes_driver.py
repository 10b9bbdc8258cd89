"""Runs inside a private network namespace (tests/test_can_processes.py): one process serves an
emulated -CA valve on a udp_multicast bus, others use it: ``--list-devices``, ``--batch`` and
the GUI (offscreen) going online. Writes what each step printed to OUT/result.json.

Usage: ``python can_processes_driver.py OUT GROUP`` (GROUP: the multicast address, the bus).
"""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

E04 = "PRM9-06.3Z11/30-24E04S02-CA"
GUI = """
import os, sys, json
from PySide6.QtCore import QTimer
from prm9tool import app
from prm9tool.cli.main import build_parser
args = build_parser().parse_args(sys.argv[1:])
qt = app.create_application()
window = app.create_window(args)
window.show()
def online(is_online):
    if is_online:
        info = window.connection.device
        print(json.dumps({"online": True, "type_key": info.type_key, "serial": info.serial}))
        sys.stdout.flush()
        os._exit(0)
window.connection.online_changed.connect(online)
window.connection.failed.connect(lambda text: (print(json.dumps({"failed": text})), os._exit(1)))
QTimer.singleShot(20000, lambda: (print(json.dumps({"timeout": True})), os._exit(2)))
app.start(window, app.plan_from(args))
qt.exec()
"""


def tool(*args: str, timeout: float = 60) -> dict[str, object]:
    """Run prm9tool in a process of its own; its exit code and output."""
    done = subprocess.run(
        [sys.executable, "-m", "prm9tool", *args],
        capture_output=True,
        text=True,
        timeout=timeout,
        check=False,
    )
    return {"code": done.returncode, "out": done.stdout, "err": done.stderr}


def main() -> None:
    """Serve, use, stop; write the outcome."""
    out, group = Path(sys.argv[1]), sys.argv[2]
    bus = ["--can-interface", "udp_multicast", "--can-channel", group]
    serve = subprocess.Popen(
        [sys.executable, "-m", "prm9tool", "--serve-emulator", f"{E04}:4711", *bus],
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
    )
    result: dict[str, object] = {}
    lines: list[str] = []
    try:
        assert serve.stdout is not None
        deadline = time.monotonic() + 30
        while time.monotonic() < deadline:
            line = serve.stdout.readline()
            lines.append(line)
            if "on the bus" in line or not line:
                break
        result["list"] = tool("--list-devices", *bus)
        source = out / "tuned.prm"
        result["new"] = tool("--new", E04, "-o", str(source))
        report = out / "report.json"
        result["batch"] = tool(
            "--batch", str(source), "--device", "can:10", *bus, "--report", str(report)
        )
        result["report"] = (
            json.loads(report.read_text(encoding="utf-8")) if report.exists() else None
        )
        gui = subprocess.run(
            [sys.executable, "-c", GUI, "--device", "can:10", *bus],
            capture_output=True,
            text=True,
            timeout=60,
            check=False,
            env={**os.environ, "QT_QPA_PLATFORM": "offscreen"},
        )
        result["gui"] = {"code": gui.returncode, "out": gui.stdout, "err": gui.stderr[-2000:]}
    finally:
        serve.send_signal(signal.SIGTERM)
        serve.wait(timeout=20)
        rest = serve.stdout.read() if serve.stdout is not None else ""  # what readline buffered too
        result["serve"] = {"code": serve.returncode, "out": "".join(lines) + rest}
        (out / "result.json").write_text(json.dumps(result, indent=1), encoding="utf-8")


if __name__ == "__main__":
    main()

"""Runs inside a private network namespace (tests/test_can_processes.py): one process serves an
emulated -CA valve on a udp_multicast bus, others use it as a user would: ``--list-devices``,
``--batch`` upload and download, ``--diff``, the commissioning of §7.6 by a PLC (this
process, raw frames), ``--characterize``, the GUI (offscreen) going online with the live
diagram, the oscilloscope and the generator, and ``--history``. Writes what each step printed
to OUT/result.json.

Usage: ``python can_processes_driver.py OUT GROUP OD`` (GROUP: the multicast address, the bus;
OD: ``full`` or ``manual``, the served valve's object dictionary, ``--od``).
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
SHORT_PROFILE = """name = "short"
[test]
step_amplitudes_pct = [25]
step_duration_s = 0.1
bode_amplitude_pct = 10
bode_f_min_hz = 2
bode_f_max_hz = 20
bode_duration_s = 6.0
static_period_s = 8
"""
CHANGES = {  # the upload changes these (display units): a ramp, a monitoring delay
    "RAMPSETPOSUP = 0": "RAMPSETPOSUP = 20",
    "MONDELAY = 1000": "MONDELAY = 1500",
}
GUI = """
import os, sys, json, time
from PySide6.QtCore import QTimer
from prm9tool import app
from prm9tool.app import start_plan
from prm9tool.cli.main import build_parser
from prm9tool.scope.generator import GeneratorSettings, Waveform
args = build_parser().parse_args(sys.argv[1:])
qt = app.create_application()
window = app.create_window(args)
window.show()
connection = window.connection
seen = {"states": [], "signals": {}, "samples": 0, "moves": [], "failed": []}
def finish(**more):
    print(json.dumps({**seen, **more}))
    sys.stdout.flush()
    os._exit(0)
def status(s):
    seen["states"].append([s.nmt_state, str(s.device_state)])
def values(v):
    seen["signals"].update({k: float(x) for k, x in v.items()})
def samples(block):
    seen["samples"] += len(block)
    seen["moves"].extend(float(x) for x in block[:, 0])
def stop_all():
    connection.stop_generator()
    connection.stop_stream()
    QTimer.singleShot(500, lambda: finish(online=True, type_key=connection.device.type_key,
                                          serial=connection.device.serial))
def enough():
    # what the test checks, not a fixed 2.5 s: a loaded PC delivered no sample in that time
    moved = seen["moves"] and max(seen["moves"]) - min(seen["moves"]) > 1000
    if seen["samples"] > 100 and moved:
        checking.stop()
        stop_all()
checking = QTimer()
checking.timeout.connect(enough)
def scope():
    connection.start_stream(["position_actual"], 1000)
    QTimer.singleShot(300, lambda: connection.start_generator(
        GeneratorSettings(Waveform.STEP, amplitude=30.0, offset=0.0, period=0.6)))
    checking.start(100)
def online(is_online):
    if is_online:
        connection.watch_signals(["position_actual", "demand"])
        QTimer.singleShot(1500, scope)
connection.online_changed.connect(online)
connection.status_changed.connect(status)
connection.signal_values_changed.connect(values)
connection.samples_received.connect(samples)
connection.failed.connect(lambda text: seen["failed"].append(text))
QTimer.singleShot(80000, lambda: finish(timeout=True))
start_plan.start(window, start_plan.plan_from(args))
qt.exec()
"""

API = """
import json, sys, prm9tool
bus = {"can_interface": "udp_multicast", "can_channel": sys.argv[1]}
listed = [d.to_dict() for d in prm9tool.list_devices(**bus)]
with prm9tool.connect("can:10", type_key=sys.argv[2], **bus) as valve:
    values = valve.read("DYNFREQ", "MONDELAY")
    valve["DYNFREQ"] = 105
    values["DYNFREQ after"] = valve["DYNFREQ"]
    info = valve.info.to_dict()
print(json.dumps({"listed": listed, "values": values, "info": info}))
"""


def tool(*args: str, timeout: float = 90) -> dict[str, object]:
    """Run prm9tool in a process of its own; its exit code and output."""
    done = subprocess.run(
        [sys.executable, "-m", "prm9tool", *args],
        capture_output=True,
        text=True,
        timeout=timeout,
        check=False,
    )
    return {"code": done.returncode, "out": done.stdout, "err": done.stderr}


def commission(
    group: str, node: int = 10, words: tuple[int, ...] = (0x08, 0x09, 0x0B, 0x0F)
) -> list[str]:
    """The PLC's part of §7.6: NMT start, then control words 08h → 09h → 0Bh → 0Fh by SDO,
    each followed by the status word the next TPDO1 carries (``"0008"`` …). With 00h first
    the rising edge of R resets a fault that has gone (table 7-20).

    Like a PLC that wants the status soon, it first sets TPDO1's event timer (0x1800/5,
    read/write, 1388h = 5 s as delivered: table 7-13) to STATUS_PERIOD_MS, and puts the 5 s
    back at the end, so the steps after this one find the valve as delivered."""
    import can

    bus = can.Bus(interface="udp_multicast", channel=group)
    seen = []
    try:
        timer = _sdo_write(bus, node, 0x1800, 5, STATUS_PERIOD_MS)
        if timer:
            return [timer]
        bus.send(can.Message(arbitration_id=0, data=bytes([1, node]), is_extended_id=False))
        for word in words:
            request = bytes([0x2B, 0x40, 0x60, 0, word, 0, 0, 0])
            bus.send(can.Message(arbitration_id=0x600 + node, data=request, is_extended_id=False))
            seen.append(_next_status(bus, node, word))
        timer = _sdo_write(bus, node, 0x1800, 5, DELIVERED_PERIOD_MS)
        if timer:
            seen.append(timer)
    finally:
        bus.shutdown()
    return seen


STATUS_PERIOD_MS = 50  # TPDO1's event timer while the PLC commissions
DELIVERED_PERIOD_MS = 0x1388  # as delivered (table 7-13)


def _sdo_write(bus: object, node: int, index: int, sub: int, value: int) -> str:
    """Expedited SDO download of a U16; "" when the valve answered, else what it said."""
    import can

    request = bytes([0x2B, index & 0xFF, index >> 8, sub, *value.to_bytes(2, "little"), 0, 0])
    message = can.Message(arbitration_id=0x600 + node, data=request, is_extended_id=False)
    bus.send(message)  # type: ignore[attr-defined]
    deadline = time.monotonic() + 15
    while time.monotonic() < deadline:
        msg = bus.recv(0.5)  # type: ignore[attr-defined]
        if msg is None or msg.arbitration_id != 0x580 + node or msg.data[1:4] != request[1:4]:
            continue
        return "" if msg.data[0] == 0x60 else f"{index:04X}/{sub} refused {bytes(msg.data).hex()}"
    return f"no answer to {index:04X}/{sub}"


def _next_status(bus: object, node: int, word: int) -> str:
    """The status word of the first TPDO1 after the SDO answer to control word ``word``."""
    deadline, answered = time.monotonic() + 15, False
    while time.monotonic() < deadline:
        msg = bus.recv(0.5)  # type: ignore[attr-defined]
        if msg is None:
            continue
        if msg.arbitration_id == 0x580 + node and bytes(msg.data[1:3]) == b"\x40\x60":
            answered = msg.data[0] == 0x60
        elif answered and msg.arbitration_id == 0x180 + node and len(msg.data) >= 2:
            return f"{int.from_bytes(bytes(msg.data[:2]), 'little'):04X}"
        elif not answered and msg.arbitration_id == 0x580 + node and msg.data[0] == 0x80:
            return f"refused {bytes(msg.data).hex()} for {word:02X}"
    return f"no TPDO1 after {word:02X}"


def main() -> None:
    """Serve, use, stop; write the outcome."""
    out, group, od = Path(sys.argv[1]), sys.argv[2], sys.argv[3]
    bus = ["--can-interface", "udp_multicast", "--can-channel", group]
    serve = subprocess.Popen(
        [sys.executable, "-m", "prm9tool", "--serve-emulator", f"{E04}:4711", "--od", od, *bus],
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
        text = source.read_text(encoding="utf-8")
        for old, new in CHANGES.items():
            text = text.replace(old, new)
        source.write_text(text, encoding="utf-8")
        report = out / "report.json"
        device = ["--device", "can:10", *bus]
        result["batch"] = tool("--batch", str(source), *device, "--report", str(report))
        result["report"] = (
            json.loads(report.read_text(encoding="utf-8")) if report.exists() else None
        )
        downloaded = out / "downloaded.prm"
        result["download"] = tool("--batch", "--download", str(downloaded), *device)
        result["downloaded"] = (
            downloaded.read_text(encoding="utf-8") if downloaded.exists() else None
        )
        result["diff"] = tool("--diff", str(source), *device)
        result["commissioning"] = commission(group)
        profile = out / "short.toml"
        profile.write_text(SHORT_PROFILE, encoding="utf-8")
        characterized = out / "characterize.json"
        result["characterize"] = tool(
            "--characterize", *device, "--profile", str(profile), "--json", str(characterized),
            timeout=150,
        )  # fmt: skip
        result["characterized"] = (
            json.loads(characterized.read_text(encoding="utf-8"))
            if characterized.exists()
            else None
        )
        # the PLC enables the valve again (the test's steps may have ended in a fault reaction)
        result["recommissioning"] = commission(group, words=(0x00, 0x08, 0x09, 0x0B, 0x0F))
        gui = subprocess.run(
            [sys.executable, "-c", GUI, *device],
            capture_output=True,
            text=True,
            timeout=120,
            check=False,
            env={**os.environ, "QT_QPA_PLATFORM": "offscreen"},
        )
        result["gui"] = {"code": gui.returncode, "out": gui.stdout, "err": gui.stderr[-3000:]}
        result["history"] = tool("--history", "4711", "--json")
        # shell scripts and Python scripts on the same bus (docs/api.md), after everything else
        label = ["--type-key", E04]  # the manual valve does not tell its key
        result["set"] = tool("--set", "DYNFREQ=110", "--store", *device, *label)
        result["get"] = tool("--get", "DYNFREQ", "--json", *device, *label)
        api = subprocess.run(
            [sys.executable, "-c", API, group, E04],
            capture_output=True,
            text=True,
            timeout=90,
            check=False,
        )
        result["api"] = {"code": api.returncode, "out": api.stdout, "err": api.stderr[-3000:]}
    except Exception as exc:  # the outcome says what broke; the test shows it
        result["driver_error"] = repr(exc)
    finally:
        serve.send_signal(signal.SIGTERM)
        try:
            serve.wait(timeout=60)
        except subprocess.TimeoutExpired:
            serve.kill()
            serve.wait()
        rest = serve.stdout.read() if serve.stdout is not None else ""  # what readline buffered too
        result["serve"] = {"code": serve.returncode, "out": "".join(lines) + rest}
        (out / "result.json").write_text(json.dumps(result, indent=1), encoding="utf-8")


if __name__ == "__main__":
    main()

"""Two processes, one bus: ``prm9tool --serve-emulator`` in one process, the tool in others
(``--list-devices``, ``--batch``, the GUI going online), on python-can's udp_multicast bus.

Multicast must never leave the machine: everything runs in a private network namespace
(``unshare -n``) whose only interface is loopback, with the multicast route on it. Where
``unshare`` is not permitted (no root, no user namespaces) the test is skipped and says why;
CI runs as root and runs it.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

E04 = "PRM9-06.3Z11/30-24E04S02-CA"
DRIVER = Path(__file__).with_name("can_processes_driver.py")
NAMESPACE = "ip link set lo up && ip link set lo multicast on && ip route add 224.0.0.0/4 dev lo"
GROUP = "239.74.163.9"


def _namespace_problem() -> str | None:
    if shutil.which("unshare") is None or shutil.which("ip") is None:
        return "unshare or ip (iproute2) is not installed"
    probe = subprocess.run(
        ["unshare", "-n", "sh", "-c", NAMESPACE],
        capture_output=True,
        text=True,
        check=False,
        timeout=20,
    )
    if probe.returncode != 0:
        return f"a private network namespace is not permitted here: {probe.stderr.strip()}"
    return None


@pytest.fixture(scope="module")
def outcome(tmp_path_factory):
    problem = _namespace_problem()
    if problem:
        pytest.skip(f"two-process CAN test needs unshare -n (multicast must stay local): {problem}")
    out = tmp_path_factory.mktemp("two-processes")
    env = {**os.environ, "PRM9TOOL_DATA_DIR": str(out / "data")}
    command = f"{NAMESPACE} && exec {sys.executable} {DRIVER} {out} {GROUP}"
    subprocess.run(["unshare", "-n", "sh", "-c", command], env=env, timeout=240, check=False)
    return json.loads((out / "result.json").read_text(encoding="utf-8"))


@pytest.mark.timeout(300)
def test_list_devices_in_another_process_finds_the_served_valve(outcome):
    listed = outcome["list"]
    assert listed["code"] == 0, listed["err"]
    assert f"can:10\t{E04}\tserial 4711\tfirmware" in listed["out"]


@pytest.mark.timeout(300)
def test_batch_in_another_process_uploads_verifies_and_stores(outcome):
    assert outcome["batch"]["code"] == 0, outcome["batch"]["err"]
    record = outcome["report"]["valves"][0]
    assert (record["device_id"], record["result"], record["verification"]) == (
        "can:10",
        "ok",
        "passed",
    )


@pytest.mark.timeout(300)
def test_the_gui_in_another_process_goes_online_over_can(outcome):
    gui = outcome["gui"]
    assert gui["code"] == 0, gui["out"] + gui["err"]
    assert json.loads(gui["out"].strip().splitlines()[-1]) == {
        "online": True,
        "type_key": E04,
        "serial": 4711,
    }


@pytest.mark.timeout(300)
def test_the_served_valve_reports_its_life_and_stops_on_sigterm(outcome):
    serve = outcome["serve"]
    assert serve["code"] == 0
    text = serve["out"]
    assert f"serial 4711: {E04} starting as node 10 on udp_multicast channel {GROUP}" in text
    assert f"serial 4711 node 10: on the bus udp_multicast channel {GROUP}" in text
    assert "serial 4711 node 10: NMT pre-operational" in text
    assert text.rstrip().endswith("prm9tool: stopped")

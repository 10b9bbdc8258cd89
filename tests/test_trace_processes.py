"""Issue 32's "done means": a trace recorded by ``prm9tool --record`` in one process while a
``canopen``-package PLC (another process) commissions two emulated valves (``prm9tool
--serve-emulator``, a third), runs setpoints at 1 kHz SYNC and provokes an RPDO-deadline fault
decodes to the right sequence of states, values and the fault. On python-can's udp_multicast
bus inside a private network namespace (as tests/test_can_processes.py; skipped where
``unshare -n`` is not permitted)."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
from test_can_processes import NAMESPACE, _namespace_problem

import prm9tool.trace as trace
from prm9tool.trace.events import Kind

DRIVER = Path(__file__).parent / "support" / "trace_processes_driver.py"
GROUP = "239.74.163.12"


@pytest.fixture(scope="module")
def decoded(tmp_path_factory):
    problem = _namespace_problem()
    if problem:
        pytest.skip(f"two-process trace test needs unshare -n: {problem}")
    out = tmp_path_factory.mktemp("trace-processes")
    env = {**os.environ, "PRM9TOOL_DATA_DIR": str(out / "data")}
    command = f"{NAMESPACE} && exec {sys.executable} {DRIVER} {out} {GROUP}"
    subprocess.run(["unshare", "-n", "sh", "-c", command], env=env, timeout=300, check=False)
    result = json.loads((out / "result.json").read_text(encoding="utf-8"))
    assert "driver_error" not in result, result
    assert result["recorder_code"] == 0, result["recorder_out"]
    assert "frames recorded into" in result["recorder_out"]
    return trace.read(result["trace"])


def _states(decoded, node):
    return [
        e.text.split(" (")[0].split(" ")[-1]
        for e in decoded.events
        if e.node == node and e.kind is Kind.STATE and e.text.startswith("device state")
    ]


@pytest.mark.slow
def test_the_commissioning_decodes_to_its_states(decoded):
    for node in (10, 15):
        states = _states(decoded, node)
        assert states[:4] == ["INIT", "DISABLED", "HOLD", "DEVICE_MODE_ACTIVE"], (node, states)
    assert decoded.nodes == {10: "PRM9", 15: "PRM9"}
    assert decoded.not_understood == []


@pytest.mark.slow
def test_the_setpoints_and_the_mapping_in_force_decode(decoded):
    rpdo15 = [dict(e.values) for e in decoded.events if e.node == 15 and e.text.startswith("RPDO1")]
    assert rpdo15 and rpdo15[-1]["PRCSETP"] == pytest.approx(4000 * 100 / 16384)
    tpdo10 = [dict(e.values) for e in decoded.events if e.node == 10 and e.text.startswith("TPDO1")]
    assert max(v["POSACT"] for v in tpdo10) > 20.0
    assert 1500 <= decoded.sync.count <= 1800


@pytest.mark.slow
def test_the_rpdo_deadline_fault_is_an_incident(decoded):
    assert _states(decoded, 10)[-1] in ("FAULT_REACTION", "FAULT_HOLD", "FAULT")
    assert _states(decoded, 15)[-1] == "DEVICE_MODE_ACTIVE"
    found = [i.what for i in decoded.incidents if i.node == 10]
    assert any(w.startswith("node 10: EMCY 0x8100") for w in found), found
    assert any(w.startswith("node 10 left DEVICE_MODE_ACTIVE") for w in found), found

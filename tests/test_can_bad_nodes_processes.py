"""Misbehaving nodes in processes of their own beside a served valve (issue 29), on python-can's
udp_multicast bus in a private network namespace (as tests/test_can_processes.py): real
timing — two nodes at one node ID answering 3 ms apart, a node that never ends an upload —
and prm9tool's commands in further processes. The driver is tests/support/bad_node_driver.py."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
from test_can_processes import NAMESPACE, _namespace_problem

E04 = "PRM9-06.3Z11/30-24E04S02-CA"
DRIVER = Path(__file__).parent / "support" / "bad_node_driver.py"
GROUP = "239.74.163.29"


@pytest.fixture(scope="module")
def outcome(tmp_path_factory):
    problem = _namespace_problem()
    if problem:
        pytest.skip(f"two-process CAN test needs unshare -n (multicast must stay local): {problem}")
    out = tmp_path_factory.mktemp("bad-nodes")
    env = {**os.environ, "PRM9TOOL_DATA_DIR": str(out / "data")}
    command = f"{NAMESPACE} && exec {sys.executable} {DRIVER} run {out} {GROUP}"
    subprocess.run(["unshare", "-n", "sh", "-c", command], env=env, timeout=540, check=False)
    result = json.loads((out / "result.json").read_text(encoding="utf-8"))
    assert "driver_error" not in result, result["driver_error"]
    return result


def _clean(step: dict[str, object]) -> None:
    assert "Traceback" not in str(step["err"]), step["err"]


@pytest.mark.slow
@pytest.mark.timeout(600)
def test_list_devices_lists_the_healthy_valve_and_each_broken_node_as_such(outcome):
    listed = outcome["list"]
    _clean(listed)
    assert listed["code"] == 0, listed["err"]
    out = str(listed["out"])
    assert f"can:10\t{E04}\tserial 4711" in out
    assert "can:11\tnot identified\tnode 11: answers 0x1000 only: not identified" in out
    assert "can:12\tnot identified\tnode 12: two nodes answer at this ID" in out
    assert "can:13\tnot identified\tnode 13: not identified: 0x100A/0: the node declares" in out


@pytest.mark.slow
@pytest.mark.timeout(600)
def test_batch_to_the_healthy_valve_succeeds_and_the_broken_ones_are_refused(outcome):
    _clean(outcome["batch"])
    assert outcome["batch"]["code"] == 0, outcome["batch"]["err"]
    for step in ("download12", "batch13"):
        _clean(outcome[step])
        assert outcome[step]["code"] != 0
    assert "two nodes answer at this ID" in str(outcome["download12"]["err"])
    assert not outcome["twelve_saved"]
    assert "not identified" in str(outcome["batch13"]["err"])

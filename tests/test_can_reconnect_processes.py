"""Two processes, one bus: the valve served by ``--serve-emulator`` drops off the bus (its
process ends) and is served again at another node ID; the tool, in another process, finds it
by its serial number (0x1018/4) and is online with it there. udp_multicast inside a private
network namespace (``unshare -n``), as tests/test_can_processes.py."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
from test_can_processes import NAMESPACE, _namespace_problem

DRIVER = Path(__file__).parent / "support" / "can_reconnect_driver.py"
GROUP = "239.74.163.23"


def test_the_valve_served_again_at_another_node_id_is_found_by_its_serial(tmp_path):
    problem = _namespace_problem()
    if problem:
        pytest.skip(f"two-process CAN test needs unshare -n (multicast must stay local): {problem}")
    env = {**os.environ, "PRM9TOOL_DATA_DIR": str(tmp_path / "data")}
    command = f"{NAMESPACE} && exec {sys.executable} {DRIVER} {tmp_path} {GROUP}"
    subprocess.run(["unshare", "-n", "sh", "-c", command], env=env, timeout=300, check=False)
    result = json.loads((tmp_path / "result.json").read_text(encoding="utf-8"))
    assert "driver_error" not in result, result
    assert result["first"] == ["can:10", 4713]
    assert result["looking_for"] == 4713
    assert result["second"] == ["can:15", 4713]
    kinds = [event[0] for event in result["events"]]
    assert kinds[:1] == ["lost"] and "reconnected" in kinds
    assert ["reconnected", "can:15", 4713] in result["events"]

"""Commissioning two valves by LSS (CiA 305) across processes: two ``prm9tool
--serve-emulator … --node-id lss`` valves (node-ID switch at 1, manual table 7-17) with
different serials on one udp_multicast bus, the tool in other processes: ``--lss-scan`` finds
both, ``--lss-assign 4711=21 4712=22`` gives them their node IDs, an emulated power cycle keeps
them, ``--list-devices`` and ``--batch --all`` then reach them. In a private network namespace
(``unshare -n``) as tests/test_can_processes.py; skipped with the reason where not permitted.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
from test_can_processes import NAMESPACE, _namespace_problem

E04 = "PRM9-06.3Z11/30-24E04S02-CA"
DRIVER = Path(__file__).parent / "support" / "lss_processes_driver.py"
GROUP = "239.74.163.21"


@pytest.fixture(scope="module")
def outcome(tmp_path_factory):
    problem = _namespace_problem()
    if problem:
        pytest.skip(f"two-process CAN test needs unshare -n (multicast must stay local): {problem}")
    out = tmp_path_factory.mktemp("lss-processes")
    env = {**os.environ, "PRM9TOOL_DATA_DIR": str(out / "data")}
    command = f"{NAMESPACE} && exec {sys.executable} {DRIVER} {out} {GROUP}"
    subprocess.run(["unshare", "-n", "sh", "-c", command], env=env, timeout=600, check=False)
    return json.loads((out / "result.json").read_text(encoding="utf-8"))


@pytest.mark.timeout(700)
def test_valves_without_a_node_id_are_not_canopen_nodes_yet(outcome):
    listed = outcome["list_before"]
    assert listed["code"] == 4, listed
    assert "can:" not in listed["out"]
    for lines in outcome["serve_first"]:
        assert "without a node ID" in lines and "waiting for an LSS master" in lines


@pytest.mark.timeout(700)
def test_lss_scan_finds_both_valves_with_their_identity(outcome):
    scan = outcome["scan"]
    assert scan["code"] == 0, scan["err"]
    found = json.loads(scan["out"])
    assert sorted(d["serial"] for d in found) == [4711, 4712]
    assert all(d["prm9"] and d["vendor"] == 0xE6 for d in found)


@pytest.mark.timeout(700)
def test_lss_assign_gives_each_its_node_id_and_both_answer(outcome):
    assign = outcome["assign"]
    assert assign["code"] == 0, assign["err"]
    assert "serial 4711: node 21, stored; it answers as can:21" in assign["out"]
    assert "serial 4712: node 22, stored; it answers as can:22" in assign["out"]
    after = outcome["scan_after"]
    assert after["code"] == 4 and "no device without a node ID answered" in after["err"]


@pytest.mark.timeout(700)
def test_after_a_power_cycle_they_are_listed_and_uploaded_with_batch_all(outcome):
    for lines in outcome["serve_second"]:
        assert "starting as node 2" in lines
    listed = outcome["list"]
    assert listed["code"] == 0, listed["err"]
    assert f"can:21\t{E04}\tserial 4711" in listed["out"]
    assert f"can:22\t{E04}\tserial 4712" in listed["out"]
    batch = outcome["batch"]
    assert batch["code"] == 0, batch["err"]
    records = {r["device_id"]: r for r in outcome["report"]["valves"]}
    assert sorted(records) == ["can:21", "can:22"]
    assert all((r["result"], r["verification"]) == ("ok", "passed") for r in records.values())

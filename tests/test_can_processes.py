"""Two processes, one bus: ``prm9tool --serve-emulator`` in one process, the tool in others
(``--list-devices``, ``--batch`` upload and download, ``--diff``, ``--characterize``, the GUI
going online with the live diagram, oscilloscope and generator, ``--history``), on python-can's
udp_multicast bus — against the full emulated valve and against one with only the objects the
manual lists (``--od manual``: no 0x1010/0x1011, none of this project's objects, keeps what is
written), so every workflow is shown to work with a valve built from the manual alone.

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
DRIVER = Path(__file__).parent / "support" / "can_processes_driver.py"
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


@pytest.fixture(scope="module", params=["full", "manual"])
def outcome(request, tmp_path_factory):
    problem = _namespace_problem()
    if problem:
        pytest.skip(f"two-process CAN test needs unshare -n (multicast must stay local): {problem}")
    out = tmp_path_factory.mktemp(f"two-processes-{request.param}")
    env = {**os.environ, "PRM9TOOL_DATA_DIR": str(out / "data")}
    command = f"{NAMESPACE} && exec {sys.executable} {DRIVER} {out} {GROUP} {request.param}"
    subprocess.run(["unshare", "-n", "sh", "-c", command], env=env, timeout=540, check=False)
    result = json.loads((out / "result.json").read_text(encoding="utf-8"))
    assert "driver_error" not in result, result["driver_error"]
    result["od"] = request.param
    return result


@pytest.mark.timeout(600)
def test_list_devices_in_another_process_finds_the_served_valve(outcome):
    listed = outcome["list"]
    assert listed["code"] == 0, listed["err"]
    if outcome["od"] == "full":
        assert f"can:10\t{E04}\tserial 4711\tfirmware" in listed["out"]
    else:  # no 0x2041: its label tells (--type-key, the batch file's key), until remembered
        assert "can:10\t? (E04 -CA; type key unknown)\tserial 4711\tfirmware" in listed["out"]


@pytest.mark.timeout(600)
def test_batch_in_another_process_uploads_verifies_and_stores(outcome):
    assert outcome["batch"]["code"] == 0, outcome["batch"]["err"]
    record = outcome["report"]["valves"][0]
    assert (record["device_id"], record["result"], record["verification"]) == (
        "can:10",
        "ok",
        "passed",
    )
    kept = "kept by the valve as written (it has no store command)"
    assert record["store"] == {"full": "stored with 0x1010", "manual": kept}[outcome["od"]]


@pytest.mark.timeout(600)
def test_download_in_another_process_reads_what_the_upload_left(outcome):
    assert outcome["download"]["code"] == 0, outcome["download"]["err"]
    text = outcome["downloaded"]
    assert "RAMPSETPOSUP = 20" in text and "MONDELAY = 1500" in text


@pytest.mark.timeout(600)
def test_diff_against_the_valve_after_the_upload(outcome):
    diff = outcome["diff"]
    assert diff["code"] == 0, diff["out"] + diff["err"]


@pytest.mark.timeout(600)
def test_a_plc_commissions_the_valve_and_tpdo1_shows_the_cia_408_status_words(outcome):
    assert outcome["commissioning"] == ["0008", "0009", "000B", "000F"]


@pytest.mark.timeout(600)
def test_characterize_in_another_process(outcome):
    done = outcome["characterize"]
    if done["code"] == 6:  # a PC too loaded to keep the bus's pace: said, not hidden
        err = done["err"]
        assert "link lost" in err or "updated the valve's setpoint too seldom" in err, err
        assert "the test was stopped" in err, err  # nothing of it made up or kept
        return
    if "measure it over USB" in done["err"]:  # E04 flow test: no gains to set on this link
        assert done["code"] == 8 and "nothing was changed" in done["err"], done["err"]
        return
    if "the measurement cannot be analysed" in done["err"]:
        # SDO-polled samples on a loaded PC: too few for the static test ("choose a … period"),
        # or the E04 flow test's opening/velocity records of unequal length — said, exit 8;
        # sampling at the bus's pace (issue 20 items 5/6, another branch) removes both
        assert done["code"] == 8, done["err"]
        return
    assert done["code"] in (0, 8), done["err"]
    assert "device state" not in done["err"], done["err"]  # the valve is seen enabled
    report = outcome["characterized"]
    assert report is not None, done["err"]
    figures = {f["name"]: f["value"] for f in report["figures"]}
    assert 0.8 < figures["static_gain"] < 1.2, figures


@pytest.mark.timeout(600)
def test_history_lists_the_upload_and_download(outcome):
    history = outcome["history"]
    assert history["code"] == 0, history["err"]
    operations = [r["operation"] for r in json.loads(history["out"])["records"]]
    assert "batch-upload" in operations and "download" in operations, operations


@pytest.mark.timeout(600)
def test_the_gui_in_another_process_goes_online_over_can(outcome):
    gui = outcome["gui"]
    assert gui["code"] == 0, gui["out"] + gui["err"]
    seen = json.loads(gui["out"].strip().splitlines()[-1])
    assert {k: seen.get(k) for k in ("online", "type_key", "serial")} == {
        "online": True,
        "type_key": E04,
        "serial": 4711,
    }, seen
    assert outcome["recommissioning"][-1] == "000F", outcome["serve"]["out"]
    assert seen["failed"] == [], outcome["serve"]["out"]
    assert ["operational", "DEVICE_MODE_ACTIVE"] in seen["states"]  # the status poll
    assert "position_actual" in seen["signals"]  # the live diagram's values
    assert seen["samples"] > 100  # the oscilloscope
    assert max(seen["moves"]) - min(seen["moves"]) > 1000  # the generator moved the spool


@pytest.mark.timeout(600)
def test_the_served_valve_reports_its_life_and_stops_on_sigterm(outcome):
    serve = outcome["serve"]
    assert serve["code"] == 0
    text = serve["out"]
    assert f"serial 4711: {E04} starting as node 10 on udp_multicast channel {GROUP}" in text
    assert f"serial 4711 node 10: on the bus udp_multicast channel {GROUP}" in text
    assert "serial 4711 node 10: NMT pre-operational" in text
    assert text.rstrip().endswith("prm9tool: stopped")


@pytest.mark.timeout(600)
def test_get_set_and_the_python_api_in_other_processes(outcome):
    assert outcome["set"]["code"] == 0, outcome["set"]["err"]
    assert outcome["set"]["out"] == "DYNFREQ\t110\tHz\n"
    assert outcome["get"]["code"] == 0, outcome["get"]["err"]
    got = json.loads(outcome["get"]["out"])
    assert got["values"] == {"DYNFREQ": 110}
    assert (got["device"]["device_id"], got["device"]["link"]) == ("can:10", "can")
    assert outcome["api"]["code"] == 0, outcome["api"]["err"]
    api = json.loads(outcome["api"]["out"])
    assert [(d["device_id"], d["serial"]) for d in api["listed"]] == [("can:10", 4711)]
    assert api["values"] == {"DYNFREQ": 110, "MONDELAY": 1500, "DYNFREQ after": 105}
    assert api["info"]["type_key"] == E04

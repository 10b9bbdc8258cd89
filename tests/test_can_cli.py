"""The command line over CAN in one process: ``--list-devices`` and ``--batch`` reach the
emulated -CA valve on a virtual bus as ``can:10`` (the two-process run over udp_multicast is
tests/test_can_processes.py)."""

from __future__ import annotations

import json

import pytest
from support.can_link_rig import E04, make_link_rig, unique_channel
from support.canopen_rig import foreign_node

from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.cli.main import main
from prm9tool.files.prmfile import PrmContents, write_file


@pytest.fixture
def rig(tmp_path, request):
    rig = make_link_rig(request.node.name, tmp_path)
    yield rig
    rig.close()


def bus_args(rig) -> list[str]:
    return ["--can-interface", "virtual", "--can-channel", rig.options.channel]


def tuned_file(tmp_path) -> str:
    contents = PrmContents.factory(TypeKey.parse(E04))
    contents.values.update(LIMTA=1500, LIMTB=1600, POSKP=contents.values["POSKP"])
    path = tmp_path / "tuned.prm"
    write_file(contents, path)
    return str(path)


def test_list_devices_shows_the_valve_as_can_node(rig, data_dir, capsys):
    assert main(["--list-devices", *bus_args(rig)]) == 0
    out = capsys.readouterr().out
    assert f"can:10\t{E04}\tserial {rig.valve.serial}\tfirmware 1.0.0" in out


def test_batch_uploads_verifies_and_stores_with_a_report(rig, data_dir, tmp_path, capsys):
    source = tuned_file(tmp_path)
    report = tmp_path / "r.json"
    argv = ["--batch", source, "--device", "can:10", *bus_args(rig), "--report", str(report)]
    assert main(argv) == 0, capsys.readouterr().err
    record = json.loads(report.read_text(encoding="utf-8"))["valves"][0]
    assert (record["device_id"], record["kind"], record["result"]) == ("can:10", "can", "ok")
    assert record["verification"] == "passed" and record["backup"]
    assert rig.stored_set()["LIMTA"] == 1500


def test_batch_all_and_download(rig, data_dir, tmp_path, capsys):
    source = tuned_file(tmp_path)
    assert main(["--batch", source, "--all", *bus_args(rig)]) == 0
    out = tmp_path / "valve.prm"
    assert main(["--batch", "--download", str(out), "--device", "can:10", *bus_args(rig)]) == 0
    assert "LIMTA = 1500" in out.read_text(encoding="utf-8")


def test_a_node_that_is_not_a_prm9_is_listed_and_refused(data_dir, tmp_path, capsys):
    channel = unique_channel("cli-other")
    network = foreign_node(channel, vendor=0x42)
    args = ["--can-interface", "virtual", "--can-channel", channel]
    try:
        assert main(["--list-devices", *args]) == 4  # no PRM9 on the bus
        shown = capsys.readouterr()
        assert "can:5\tnot a PRM9\tnode 5: not a PRM9 (device type 0x191, vendor 0x42)" in shown.out
        code = main(["--batch", tuned_file(tmp_path), "--device", "can:5", *args])
        err = capsys.readouterr().err
    finally:
        network.disconnect()
    assert code == 4
    assert (
        "node 5: not a PRM9 (device type 0x191, vendor 0x42); prm9tool does not write to it" in err
    )


def test_a_missing_adapter_exits_6_naming_it_without_a_traceback(data_dir, capsys):
    code = main(["--list-devices", "--can-interface", "socketcan", "--can-channel", "prm9nosuch1"])
    err = capsys.readouterr().err
    assert code == 6
    assert "cannot open the CAN interface 'socketcan', channel 'prm9nosuch1'" in err
    assert "Traceback" not in err


def test_objects_a_real_valve_lacks_are_a_warning_in_the_report(data_dir, tmp_path, capsys):
    rig = make_link_rig("cli-real", tmp_path, real_valve=True)
    report = tmp_path / "r.json"
    try:
        argv = ["--batch", tuned_file(tmp_path), *bus_args(rig), "--report", str(report)]
        assert main(argv) == 0
    finally:
        rig.close()
    err = capsys.readouterr().err
    record = json.loads(report.read_text(encoding="utf-8"))["valves"][0]
    assert record["type_key"] == E04  # the file's key, checked against the objects
    assert "POSKP" in record["skipped"] and record["result"] == "ok"
    assert "warning: not available over CANopen on this valve, not uploaded: " in err
    assert all(not CATALOGUE[m].address_from_manual for m in record["skipped"])


def test_a_download_from_a_real_valve_leaves_its_missing_objects_empty(data_dir, tmp_path):
    rig = make_link_rig("cli-real-dl", tmp_path, real_valve=True)
    out = tmp_path / "valve.prm"
    try:
        argv = ["--batch", "--download", str(out), "--device", "can:10", *bus_args(rig)]
        argv_up = ["--batch", str(out), "--device", "can:10", *bus_args(rig)]
        assert main(["--batch", tuned_file(tmp_path), *bus_args(rig)]) == 0
        assert main(argv) == 0
        text = out.read_text(encoding="utf-8")
        assert main(["--check", str(out)]) == 0  # warnings only
        assert main(argv_up) == 0  # and it uploads back
    finally:
        rig.close()
    assert "LIMTA = 1500" in text
    assert "AINSETP =  # not available over CANopen on the valve this was read from" in text

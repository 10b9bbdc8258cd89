"""Uploading into a valve that has no store command (manual table 7-13 lists no 0x1010; §7.2.2:
it keeps what is written), into one whose 0x1010/1 says it cannot store, and what each leaves
in the valve when something goes wrong (prm9tool.device.canlink.storing)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from support.can_link_rig import E04, LinkRig, make_link_rig
from support.waiting import wait_for

from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.manual_od import NOT_KEPT_AFTER_RESTART
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.cli.main import main
from prm9tool.device.canlink.session import CanopenSession
from prm9tool.device.canlink.storing import (
    KEPT_AS_WRITTEN,
    STORED_WITH_1010,
    VERIFIED_RESTART,
    factory_values,
    safe_order,
)
from prm9tool.device.upload_outcome import KEPT_OUTCOME, RESTARTED_OUTCOME
from prm9tool.errors import DeviceTimeoutError, Prm9Error
from prm9tool.files.prmfile import read_file

NODE = 10
# the setpoint curve's points XB, XC move right past each other's old place: written in the
# catalogue's order, XB = -40 % would pass XC = -50 % and the valve would refuse it
MOVED = {"SETPLINXB": -6554, "SETPLINXC": -4915, "LIMTA": 1500, "DTAMP": 1000}


@pytest.fixture
def manual(request, tmp_path, data_dir):
    rig = make_link_rig(request.node.name, tmp_path, od="manual")
    rig.valve.start()
    yield rig
    rig.valve.stop()
    rig.close()


def held(rig: LinkRig, mnemonic: str) -> int | str:
    """What the valve holds after a power cycle (its non-volatile memory, else the default)."""
    return rig.stored_set().get(mnemonic, CATALOGUE[mnemonic].default)


def session_for(rig: LinkRig, **kwargs: object) -> CanopenSession:
    return CanopenSession(rig.options, NODE, type_key=E04, **kwargs)  # type: ignore[arg-type]


def test_a_valve_without_a_store_command_keeps_the_upload_written_in_a_safe_order(manual):
    with session_for(manual) as session:
        values = session.download() | MOVED
        result = session.upload(values)
    assert (result.stored, result.failed_step, result.store) == (True, None, KEPT_AS_WRITTEN)
    assert {m: held(manual, m) for m in MOVED} == MOVED  # kept without any store command


def test_safe_order_puts_limits_and_curve_points_before_what_they_would_pass():
    variant = TypeKey.parse(E04).variant
    holds = factory_values(variant)
    params = [CATALOGUE[m] for m in holds]
    order = [p.mnemonic for p in safe_order(variant, params, holds, holds | MOVED)]
    assert order.index("SETPLINXC") < order.index("SETPLINXB")
    back = [p.mnemonic for p in safe_order(variant, params, holds | MOVED, holds)]
    assert back.index("SETPLINXB") < back.index("SETPLINXC")


def test_a_store_capability_of_0_refuses_the_upload_before_writing(tmp_path, data_dir):
    rig = make_link_rig("capability", tmp_path)
    with rig.valve.lock:
        rig.valve.firmware.od.getters[(0x1010, 1)] = lambda: 0  # CiA 301: cannot store at all
    try:
        with session_for(rig) as session:
            before = session.download()
            with pytest.raises(Prm9Error) as caught:
                session.upload(before | MOVED)
            assert session.download() == before  # nothing was written
    finally:
        rig.close()
    assert str(caught.value) == (
        "the valve cannot store parameters: 0x1010/1 reads 0x00000000 (CiA 301: neither on "
        "command nor by itself); nothing was written"
    )


def test_a_valve_that_refuses_one_object_mid_upload_gets_the_backup_back(manual):
    manual.refuse(0x6361, 1)  # DTAMP, after SETPLINXB/XC and LIMTA in the write order
    with session_for(manual) as session:
        before = session.download()
        result = session.upload(before | MOVED)
        after = session.download()
    assert (result.stored, result.failed_step, result.store) == (False, "write", KEPT_AS_WRITTEN)
    assert result.reload_error is None  # the backup's values are back: the message says so
    assert after == before
    assert {m: held(manual, m) for m in MOVED} == {m: before[m] for m in MOVED}


def test_batch_report_and_history_say_which_store_happened(manual, tmp_path, capsys):
    source, report = tmp_path / "set.prm", tmp_path / "report.json"
    assert main(["--new", E04, "-o", str(source)]) == 0
    text = source.read_text(encoding="utf-8").replace("DTAMP = 15", "DTAMP = 20")
    source.write_text(text, encoding="utf-8")
    bus = ["--can-interface", "virtual", "--can-channel", manual.options.channel]
    code = main(["--batch", str(source), "--device", "can:10", *bus, "--report", str(report)])
    out = capsys.readouterr()
    assert code == 0, out.err
    record = json.loads(report.read_text(encoding="utf-8"))["valves"][0]
    assert (record["result"], record["store"]) == ("ok", KEPT_AS_WRITTEN)
    assert "kept by the valve as written (it has no store command)" in out.out + out.err
    assert main(["--history", str(manual.valve.serial), "--json"]) == 0
    records = json.loads(capsys.readouterr().out)["records"]
    upload = next(r for r in records if r["operation"] == "batch-upload")
    assert upload["details"]["store"] == KEPT_AS_WRITTEN


def test_power_lost_between_two_writes_the_backup_is_put_back(manual):
    with session_for(manual, timeout_s=0.2) as session:
        before = session.download()
        manual.reset_after(3)  # the valve restarts while the third write is on its way
        with pytest.raises(DeviceTimeoutError) as caught:
            session.upload(before | MOVED)
    message = str(caught.value)
    assert "upload failed while writing the parameters (step 1 of 3)" in message
    assert message.endswith(
        "every value the upload changed was put back from the backup and reads back so: the "
        "valve holds its previous set again (it keeps what is written)"
    )
    assert {m: held(manual, m) for m in MOVED} == {m: before[m] for m in MOVED}


def test_verification_by_restart_is_asked_for_and_said(manual):
    with session_for(manual) as session:
        session.verify_by_restart = True
        values = session.download() | MOVED
        result = session.upload(values)
    assert (result.stored, result.store) == (True, VERIFIED_RESTART)
    wait_for(lambda: manual.valve.status().nmt_state == "pre-operational", 5.0)
    assert {m: held(manual, m) for m in MOVED} == MOVED


def test_a_valve_with_0x1010_stores_with_it(tmp_path, data_dir):
    rig = make_link_rig("with-1010", tmp_path)
    try:
        with session_for(rig) as session:
            result = session.upload(session.download() | MOVED)
    finally:
        rig.close()
    assert (result.stored, result.store) == (True, STORED_WITH_1010)


def test_factory_values_without_0x1011_are_uploaded(manual):
    with session_for(manual) as session:
        session.upload(session.download() | MOVED)
        session.restore_factory()
        after = session.download()
    factory = factory_values(session.variant)
    assert {m: after[m] for m in MOVED} == {m: factory[m] for m in MOVED}
    assert {m: held(manual, m) for m in MOVED} == {m: factory[m] for m in MOVED}


def _batch_verify_losing_dtamp(rig: LinkRig, tmp_path, capsys, monkeypatch) -> tuple[dict, str]:
    """--batch --verify-by-restart (DTAMP 15 → 20 %) into ``rig``'s valve, whose non-volatile
    memory loses DTAMP (the restart brings back the old value): its report record and stderr."""
    nv = rig.valve.firmware.nv
    replace = nv.replace
    lost = {"DTAMP": nv.values.get("DTAMP", CATALOGUE["DTAMP"].default)}
    monkeypatch.setattr(nv, "replace", lambda values: replace({**values, **lost}))
    source, report = tmp_path / "set.prm", tmp_path / "report.json"
    assert main(["--new", E04, "-o", str(source)]) == 0
    text = source.read_text(encoding="utf-8").replace("DTAMP = 15", "DTAMP = 20")
    source.write_text(text, encoding="utf-8")
    bus = ["--can-interface", "virtual", "--can-channel", rig.options.channel]
    args = ["--batch", str(source), "--device", "can:10", *bus, "--verify-by-restart"]
    code = main([*args, "--report", str(report)])
    out = capsys.readouterr()
    assert code == 1, out.err
    record = json.loads(report.read_text(encoding="utf-8"))["valves"][0]
    assert (record["result"], record["failed_step"]) == ("store-failed", "store")
    assert record["mismatches"] == {"DTAMP": {"expected": 3277, "actual": 2458}}
    return record, out.err


def test_batch_verify_by_restart_says_what_the_valve_did_not_keep(
    manual, tmp_path, capsys, monkeypatch
):
    """--batch --verify-by-restart against a valve whose memory loses DTAMP: the report and
    the history say it with the same text as the GUI's Verify by restart…"""
    record, _ = _batch_verify_losing_dtamp(manual, tmp_path, capsys, monkeypatch)
    # the backup is back
    assert record["error"] == f"{NOT_KEPT_AFTER_RESTART} (DTAMP: 3277 → 2458); {KEPT_OUTCOME}"
    assert record["store"] == KEPT_AS_WRITTEN  # not "verified after a restart"
    assert held(manual, "DTAMP") == 2458 == manual.working("DTAMP")


def test_batch_verify_by_restart_on_a_valve_with_0x1010_says_it_runs_on_what_came_back(
    tmp_path, data_dir, capsys, monkeypatch
):
    """The same with a valve that stores with 0x1010: the restart put it on its stored set,
    which is not the upload; nothing is written after it, the backup file is named."""
    rig = make_link_rig("with-1010-lost", tmp_path)
    rig.valve.start()
    try:
        record, err = _batch_verify_losing_dtamp(rig, tmp_path, capsys, monkeypatch)
        working = rig.working("DTAMP")
    finally:
        rig.valve.stop()
        rig.close()
    backup = record["backup"]
    assert record["error"] == (
        f"{NOT_KEPT_AFTER_RESTART} (DTAMP: 3277 → 2458); {RESTARTED_OUTCOME}; the backup of "
        f"its values before the upload is kept in {backup}: upload it (--batch {backup}) to "
        "put them back"
    )
    assert "failed too" not in record["error"]  # nothing failed: it was just restarted
    assert record["error"] in err  # what the operator sees
    assert record["store"] == STORED_WITH_1010  # the store that happened, not verified
    assert held(rig, "DTAMP") == 2458 == working  # it runs on the set it came back with
    assert read_file(Path(backup)).values["DTAMP"] == 2458
    assert main(["--history", str(rig.valve.serial), "--json"]) == 0
    records = json.loads(capsys.readouterr().out)["records"]
    upload = next(r for r in records if r["operation"] == "batch-upload")
    assert (upload["outcome"], upload["details"]["store"]) == ("store-failed", STORED_WITH_1010)
    assert upload["details"]["error"] == record["error"]

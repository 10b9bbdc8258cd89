"""The public Python API (docs/api.md): the issue's snippet as written, on a real emulated
valve; a lazy, Qt-free import; each operation with its error a script author meets."""

from __future__ import annotations

import json
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest

import prm9tool
from prm9tool.api import EXPORTS, Valve
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.device import emulated_valves
from prm9tool.errors import AccessDeniedError, FileFormatError, TypeKeyError, ValueRangeError
from prm9tool.files.prmfile import PrmContents, write_file

ROOT = Path(__file__).resolve().parents[1]
KEY = "PRM9-06.3Z11/30-24E02S02-CA"
SNIPPET = textwrap.dedent(
    """
    import prm9tool
    prm9tool.list_devices(can_interface="virtual", can_channel="x")  # -> list of DeviceInfo (id, type key, serial, firmware, link)
    with prm9tool.connect("emulator:PRM9-06.3Z11/30-24E02S02-CA:4711") as valve:   # or "usb:…", "can:10" with can_interface=…, can_channel=…, can_bitrate=…
        valve.info                          # DeviceInfo
        valve["LIMTA"]                      # value in display units (mA); KeyError for an unknown mnemonic
        valve["LIMTA"] = 1800               # checked against the catalogue, written, read back; ValueRangeError when out of range
        params = prm9tool.read_prm("released.prm")      # a ParameterSet (mapping mnemonic -> value, with type key)
        result = valve.upload(params)       # transactional, returns the UploadResult
        valve.download()                    # -> ParameterSet; prm9tool.write_prm(path, params)
        data = valve.capture(["demand", "position_actual"], seconds=1.0)   # dict of numpy arrays at the valve's rate, plus "t"
        valve.status()                      # ValveStatus
    """
)


@pytest.fixture(autouse=True)
def _fresh_emulators():
    yield
    emulated_valves.forget_emulated_valves()


@pytest.fixture
def released(tmp_path: Path) -> Path:
    """released.prm: the factory set of KEY with LIMTA 1500 mA, DYNFREQ changed."""
    contents = PrmContents.factory(TypeKey.parse(KEY))
    contents.values.update(LIMTA=1500, DYNFREQ=120)
    path = tmp_path / "released.prm"
    write_file(contents, path)
    return path


@pytest.fixture
def valve():
    with prm9tool.connect(f"emulator:{KEY}:4711") as opened:
        yield opened


def test_the_snippet_runs_as_written(released, monkeypatch):
    monkeypatch.chdir(released.parent)
    scope: dict = {}
    exec(compile(SNIPPET, "snippet", "exec"), scope)
    valve, result, data = scope["valve"], scope["result"], scope["data"]
    assert valve.closed
    assert valve.info.serial == 4711 and valve.info.type_key == KEY
    assert valve.info.link == "emulator"
    assert result.stored and result.verified and result.failed_step is None
    assert set(data) == {"demand", "position_actual", "t"}
    assert len(data["t"]) == 5000 and data["t"][1] == pytest.approx(1 / 5000)
    assert all(len(column) == 5000 for column in data.values())
    with prm9tool.connect(f"emulator:{KEY}:4711") as again:  # the upload was stored
        assert again["LIMTA"] == 1500
        assert again["DYNFREQ"] == 120


def test_import_loads_no_qt_and_no_emulator():
    code = textwrap.dedent(
        """
        import sys
        import prm9tool
        prm9tool.connect, prm9tool.ParameterSet, prm9tool.list_devices, prm9tool.history.records
        bad = sorted(m for m in sys.modules
                     if m.partition(".")[0] in ("PySide6", "pyqtgraph")
                     or m.startswith("prm9tool.device.emulator"))
        print(bad)
        """
    )
    done = subprocess.run(
        [sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, check=True
    )
    assert done.stdout.strip() == "[]"


def test_the_package_namespace_is_lazy_and_complete():
    assert set(prm9tool.__all__) == set(EXPORTS) | {"__version__", "api", "history"}
    assert set(EXPORTS) <= set(dir(prm9tool))
    for name in EXPORTS:
        assert getattr(prm9tool, name) is getattr(prm9tool.api, name)
    with pytest.raises(AttributeError, match="no attribute 'conect'"):
        prm9tool.conect  # noqa: B018


def test_single_values_in_display_units(valve):
    assert valve["LIMTA"] == 2400  # mA, the factory value
    valve["LIMTA"] = 1800
    assert valve["LIMTA"] == 1800
    assert valve.read("LIMTA", "LIMTB") == {"LIMTA": 1800, "LIMTB": valve["LIMTB"]}
    with pytest.raises(KeyError, match="NOPE: no such parameter in the catalogue"):
        valve["NOPE"]
    with pytest.raises(ValueRangeError, match="LIMTA: 99999 mA is outside the allowed range"):
        valve["LIMTA"] = 99999
    assert valve["LIMTA"] == 1800  # nothing was sent
    with pytest.raises(ValueRangeError, match=r"LIMTA = 3000 mA is above .* CURNORM = 2600 mA"):
        valve["LIMTA"] = 3000  # within 0 … 4000 mA, above this valve's CURNORM (table 7-14)
    assert valve["LIMTA"] == 1800
    assert valve.check({"LIMTA": 2000, "DYNFREQ": 100}) == {"LIMTA": 2000, "DYNFREQ": 100}


def test_upload_refuses_another_variant_and_writes_nothing(valve):
    other = prm9tool.ParameterSet.factory("PRM9-06.3Z11/30-24E04S02-CA")
    other["LIMTA"] = 1000
    with pytest.raises(TypeKeyError, match="even force_type=True cannot upload it"):
        valve.upload(other, force_type=True)
    assert valve["LIMTA"] == 2400


def test_upload_of_display_values_and_its_history(valve):
    result = valve.upload({**valve.download(), "LIMTA": 1700}, backup=True)
    assert result.stored
    records = prm9tool.history.records(4711)
    assert [r["operation"] for r in records] == ["download", "backup", "upload"]
    assert records[-1]["outcome"] == "ok"
    assert records[-1]["details"]["command"] == "python API"


QUICK = "[test]\nstep_amplitudes_pct = [25.0]\nbode_duration_s = 0.5\nstatic_period_s = 1.0\n"


def test_a_characterization_is_recorded_as_the_command_line_records_it(valve, tmp_path):
    from prm9tool.history.recorder import Recorder
    from prm9tool.service.history import record_characterization

    (tmp_path / "quick.toml").write_text(QUICK, encoding="utf-8")
    valve.wait_booted()
    valve.nmt("start")
    valve.enable()  # a -CA valve follows its setpoint once its master enabled it
    result = valve.characterize(tmp_path / "quick.toml")
    (record,) = prm9tool.history.records(4711)
    verdict = "passed" if result.passed else "failed"
    assert (record["operation"], record["outcome"]) == ("characterization", verdict)
    assert record["device_id"] == f"emulator:{KEY}:4711" and record["link"] == "emulator"
    details = record["details"]
    assert details["command"] == "python API"
    # the same details as --characterize's record, into the same chain
    recorder = Recorder()
    record_characterization(recorder, result)
    cli = prm9tool.history.records(4711)[-1]
    assert {k: v for k, v in details.items() if k != "command"} == cli["details"]
    assert (cli["device_id"], cli["link"]) == (record["device_id"], record["link"])
    whole = recorder.store().record(record["id"])
    assert whole is not None and json.loads(whole["parameters"]) == result.parameters
    assert recorder.store().check_valve(4711) is None  # the chain holds both
    recorder.close()


def test_record_history_false_records_nothing(tmp_path):
    (tmp_path / "quick.toml").write_text(QUICK, encoding="utf-8")
    with prm9tool.connect(f"emulator:{KEY}:4712", record_history=False) as valve:
        valve.wait_booted()
        valve.nmt("start")
        valve.enable()
        valve.characterize(tmp_path / "quick.toml")
        valve.upload(valve.download(), backup=False)  # a backup file becomes a record when
        valve.store()  # a history is first opened (the import of old backups)
        valve.restore_factory(confirm_hydraulics_off=True, backup=False)
    assert prm9tool.history.records(4712) == []


@pytest.mark.parametrize("door", ["api", "cli"])
def test_a_factory_reset_on_a_fresh_history_records_its_backup_once(door, capsys):
    # the backup is the first record: opening the database imports old backup files, and it
    # took the one just written as well — two backup records of one file
    from prm9tool.cli.main import main

    if door == "api":
        with prm9tool.connect(f"emulator:{KEY}:4713") as valve:
            valve.restore_factory(confirm_hydraulics_off=True)
    else:
        assert main(["--emulator", f"{KEY}:4713", "--restore-factory", "--hydraulics-safe"]) == 0
    records = prm9tool.history.records(4713)
    assert [r["operation"] for r in records] == ["backup", "restore-factory"], records
    assert records[0]["details"]["file"] == records[1]["details"]["backup"]
    with prm9tool.connect(f"emulator:{KEY}:4713") as valve:  # the backup is there: none more
        valve.restore_factory(confirm_hydraulics_off=True)
    operations = [r["operation"] for r in prm9tool.history.records(4713)]
    assert operations == ["backup", "restore-factory", "restore-factory"], operations


def test_store_and_factory_reset_are_recorded_as_the_gui_records_them(valve):
    from prm9tool.history.recorder import Recorder

    valve["LIMTA"] = 1900
    valve.store()
    valve.restore_factory(only_reset=True)
    records = prm9tool.history.records(4711)
    assert [r["operation"] for r in records] == ["store", "backup", "restore-factory"]
    store = Recorder().store()
    stored = store.record(records[0]["id"])
    assert stored is not None and json.loads(stored["parameters"])["LIMTA"] == 1900  # read back
    backup = records[1]["details"]["file"]
    assert records[2]["details"] == {"backup": backup, "command": "python API"}
    backed_up = store.record(records[1]["id"])
    assert backed_up is not None and json.loads(backed_up["parameters"])["LIMTA"] == 1900
    store.close()


def test_a_refused_upload_is_recorded_with_its_failed_step(valve, monkeypatch):
    from prm9tool.device.records import UploadResult

    def refused(values, progress=None, cancel=None):
        return UploadResult(stored=False, written=3, verified=False, duration_s=0.1,
                            failed_step="write", failure="LIMTA: the valve refused it")  # fmt: skip

    monkeypatch.setattr(valve.session, "upload", refused)
    result = valve.upload(valve.download(), backup=False)
    assert not result.stored
    record = prm9tool.history.records(4711)[-1]
    assert (record["operation"], record["outcome"], record["failed_step"]) == (
        "upload", "verification-failed", "write")  # fmt: skip
    assert record["details"]["written"] == 3
    assert record["details"]["error"] == "LIMTA: the valve refused it"


def test_set_and_store_on_the_command_line_is_recorded_as_such(tmp_path, capsys):
    from prm9tool.cli.main import main

    assert main(["--emulator", f"{KEY}:4714", "--set", "LIMTA=1800", "--store"]) == 0
    (record,) = prm9tool.history.records(4714)
    assert (record["operation"], record["details"]["command"]) == ("store", "--set --store")


def test_parameter_set_checks_values_and_round_trips(tmp_path):
    params = prm9tool.ParameterSet.factory(KEY)
    with pytest.raises(ValueRangeError):
        params["LIMTA"] = -5
    with pytest.raises(KeyError, match="no such parameter"):
        params["NOPE"] = 1
    params["LIMTA"] = 1650
    prm9tool.write_prm(tmp_path / "a.prm", params)
    assert prm9tool.read_prm(tmp_path / "a.prm") == params
    assert "LIMTA=1650" in repr(params) or len(params) > 4
    assert "<table>" in params._repr_html_()
    (tmp_path / "bad.prm").write_text("nonsense\n", encoding="utf-8")
    with pytest.raises(FileFormatError):
        prm9tool.read_prm(tmp_path / "bad.prm")


def test_restart_needs_the_hydraulics_confirmed(valve):
    with pytest.raises(AccessDeniedError, match="confirm_hydraulics_off=True"):
        valve.restart()
    assert valve.restore_factory(only_reset=True) is None  # nothing moves: no question
    valve.restart(confirm_hydraulics_off=True)
    assert valve["LIMTA"] == 2400


def test_restore_factory_restarts_like_the_window_and_needs_the_hydraulics_confirmed(valve):
    # issue 28: the API's restore_factory() only reset, --restore-factory and the window
    # reset, restart and read the factory set back; now the API too, asking first
    valve["LIMTA"] = 1900
    valve.store()
    with pytest.raises(AccessDeniedError, match=r"restore_factory\(confirm_hydraulics_off=True\)"):
        valve.restore_factory()
    assert valve["LIMTA"] == 1900  # nothing sent
    assert [r["operation"] for r in prm9tool.history.records(4711)] == ["store"]
    factory = valve.restore_factory(confirm_hydraulics_off=True)
    assert factory is not None and factory["LIMTA"] == 2400 == valve["LIMTA"]  # effective now
    assert dict(factory.raw) == dict(valve.download().raw)


def test_nmt_enable_generator_and_capture(valve):
    assert not valve.wait_booted().booting
    valve.nmt("start")
    assert valve.status().nmt_state is prm9tool.NmtState.OPERATIONAL
    valve.enable()
    assert valve.status().device_state is prm9tool.DeviceState.DEVICE_MODE_ACTIVE
    with valve.generator("square", amplitude=20.0, period=0.2) as generator:
        data = valve.capture(["demand", "position_actual"], seconds=0.4)
    assert not generator.running
    assert data["demand"].max() == pytest.approx(20.0, abs=0.1)
    assert data["position_actual"].max() > 5.0  # the spool followed
    with pytest.raises(ValueError, match="unknown NMT command 'go'"):
        valve.nmt("go")
    with pytest.raises(ValueRangeError, match="'nope' is not a measuring point"):
        valve.capture(["nope"])


def test_diff_of_a_file_and_a_valve(valve, released):
    comparison = prm9tool.diff(released, valve)
    assert {row.mnemonic for row in comparison.changed} == {"LIMTA", "DYNFREQ"}
    assert not comparison.equal


def test_reprs_for_notebooks(valve):
    assert repr(valve).startswith(f"<Valve emulator:{KEY}:4711")
    for record in (valve.info, valve.status()):
        assert type(record).__name__ in record._repr_html_()
    assert isinstance(valve, Valve)
    assert isinstance(valve.capture(["demand"], 0.01)["t"], np.ndarray)


def test_a_valve_on_a_can_bus_is_listed_and_opened_by_its_node(tmp_path, request):
    from support.can_link_rig import E04, make_link_rig

    rig = make_link_rig(request.node.name, tmp_path, E04)
    try:
        bus = {"can_interface": "virtual", "can_channel": rig.options.channel}
        (found,) = prm9tool.list_devices(**bus)
        assert (found.device_id, found.type_key, found.link) == ("can:10", E04, "can")
        assert found.serial == rig.valve.serial
        assert found.can_bus == ("virtual", rig.options.channel, None)
        with prm9tool.connect("can:10", **bus) as valve:
            assert valve.info.serial == rig.valve.serial and valve.info.link == "can"
            valve["DYNFREQ"] = 125
            assert valve["DYNFREQ"] == 125
            assert valve.download()["DYNFREQ"] == 125
    finally:
        rig.close()


def test_an_unknown_device_id_is_a_clear_error():
    with pytest.raises(prm9tool.Prm9Error, match="unknown device 'com3'"):
        prm9tool.connect("com3")
    with pytest.raises(TypeKeyError, match="must start with 'PRM9-'"):
        prm9tool.connect("emulator:XYZ:1")


def test_a_test_on_a_ca_valve_waiting_for_its_master_says_to_commission_it():
    """A -CA valve as delivered waits for its master: the script is told what to call."""
    from prm9tool.characterize.rig import WaitsForMasterError

    with prm9tool.connect("emulator:PRM9-06.3Z11/30-24E02S02-CA:4791") as valve:
        valve.wait_booted()
        with pytest.raises(WaitsForMasterError, match=r"call valve\.commission\(\) first"):
            valve.characterize()

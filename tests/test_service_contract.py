"""The valve service behind every front door (issue 28): the same operation through the Python
API, the command line and the GUI's worker (ValveConnection) on the same emulated valves gives
the same result, the same words for the same refusal and the same history record."""

from __future__ import annotations

import json

import pytest
from support.gui_support import E02, E02_CA, emulator_connection
from support.waiting import wait_for

import prm9tool
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.cli.main import main
from prm9tool.device import emulated_valves, factory
from prm9tool.errors import AccessDeniedError, Prm9Error, ValueRangeError
from prm9tool.files.prmfile import PrmContents, write_file
from prm9tool.history.recorder import Recorder
from prm9tool.online.tuning_runner import ValveRunner
from prm9tool.scope.generator import GeneratorSettings, Waveform
from prm9tool.service.motion import MotionBusyError

TIMEOUT = 15_000
CAPPED_RANGE = "LIMTA: 99999 mA is outside the allowed range 0 … 2600 mA"


@pytest.fixture
def connection(qtbot):
    conn = emulator_connection()
    yield conn
    conn.shutdown()
    emulated_valves.forget_emulated_valves()


def _online(qtbot, connection, serial, type_key=E02):
    entry = factory.list_devices([f"{type_key}:{serial}"])[-1]
    with qtbot.waitSignals([connection.online_changed, connection.device_changed], timeout=TIMEOUT):
        connection.go_online(entry)


def _gui_refusal(qtbot, connection, mnemonic, raw):
    with qtbot.waitSignal(connection.failed, timeout=TIMEOUT) as failed:
        connection.write(mnemonic, raw)
    return failed.args[0]


def _api_refusal(serial, mnemonic, value):
    with prm9tool.connect(f"emulator:{E02}:{serial}", record_history=False) as valve:
        before = valve[mnemonic]
        with pytest.raises(Prm9Error) as refused:
            valve[mnemonic] = value
        assert valve[mnemonic] == before  # nothing was sent
    return refused.value


def _cli_refusal(capsys, serial, assignment):
    assert main(["--emulator", f"{E02}:{serial}", "--set", assignment]) == 2
    return capsys.readouterr().err


@pytest.mark.parametrize(
    ("mnemonic", "value", "words", "kind"),
    [
        ("CURNORM", 1000, "CURNORM: the parameter is read-only", AccessDeniedError),
        # the range every editor shows: 0 … CURNORM (2600 mA on this valve), not 0 … 4000 mA
        ("LIMTA", 99999, CAPPED_RANGE, ValueRangeError),
    ],
)
def test_a_refused_write_has_the_same_words_at_every_door(
    qtbot, connection, capsys, mnemonic, value, words, kind
):
    api = _api_refusal(7301, mnemonic, value)
    assert isinstance(api, kind) and str(api).startswith(words)
    cli = _cli_refusal(capsys, 7302, f"{mnemonic}={value}")
    assert (words in cli and "nothing was written" in cli) or "read-only" in cli
    _online(qtbot, connection, 7303)
    assert words in _gui_refusal(qtbot, connection, mnemonic, value)


def test_limta_beyond_its_cap_has_the_editors_words_at_every_door(qtbot, connection, capsys):
    # the parameter editors (model/editing.py) and the block dialogs refuse LIMTA = 99999 mA
    # with 0 … CURNORM; the command line, the API and the GUI's worker said 0 … 4000 mA
    from prm9tool.model.access import AccessModel
    from prm9tool.model.document import ParameterDocument
    from prm9tool.model.editing import apply_edit

    with prm9tool.connect(f"emulator:{E02_CA}:7306", record_history=False) as valve:
        doc = ParameterDocument(E02_CA)  # the factory values, as the valve's
        assert doc.value("CURNORM") == valve["CURNORM"] == 2600
        with pytest.raises(ValueRangeError) as api:
            valve.check({"LIMTA": 99999})
    with pytest.raises(ValueRangeError) as editor:
        apply_edit(doc, AccessModel(), "LIMTA", 99999)
    assert str(api.value) == str(editor.value) == CAPPED_RANGE
    assert main(["--emulator", f"{E02_CA}:7307", "--set", "LIMTA=99999"]) == 2
    assert f"--set: {CAPPED_RANGE}; nothing was written" in capsys.readouterr().err
    _online(qtbot, connection, 7308, E02_CA)
    assert CAPPED_RANGE in _gui_refusal(qtbot, connection, "LIMTA", 99999)


def test_not_a_number_has_the_same_words_in_the_api_and_on_the_command_line(capsys):
    api = _api_refusal(7304, "LIMTA", "abc")
    assert isinstance(api, ValueRangeError)
    assert str(api) in _cli_refusal(capsys, 7305, "LIMTA=abc")


def _history(serial):
    return [(r["operation"], r["outcome"]) for r in prm9tool.history.records(serial)]


def _parameters(record_id):
    recorder = Recorder()
    try:
        return recorder.store().record(record_id)["parameters"]
    finally:
        recorder.close()


def test_an_upload_runs_the_same_sequence_at_every_door(qtbot, connection, tmp_path):
    # the same file into three fresh valves: backup first (recorded), then the upload
    with prm9tool.connect(f"emulator:{E02}:7311", record_history=False) as valve:
        wanted = valve.download()
    values = {**wanted.raw, "LIMTA": 1700}
    path = tmp_path / "set.prm"
    write_file(PrmContents(wanted.type_key, values), path, backup=False)

    with prm9tool.connect(f"emulator:{E02}:7312") as valve:  # the API
        result = valve.upload(prm9tool.read_prm(path))
        assert result.stored
    assert main(["--batch", str(path), "--emulator", f"{E02}:7313"]) == 0  # the command line
    connection.set_recorder(Recorder())  # as the app does
    _online(qtbot, connection, 7314)  # the GUI's worker
    with qtbot.waitSignal(connection.operation_finished, timeout=TIMEOUT) as done:
        connection.upload(values)
    assert done.args[0] == "upload" and done.args[1].stored

    for serial in (7312, 7313, 7314):
        with prm9tool.connect(f"emulator:{E02}:{serial}", record_history=False) as valve:
            assert valve["LIMTA"] == 1700
    assert _history(7312) == _history(7314) == [("backup", "ok"), ("upload", "ok")]
    # the batch records its report's outcome (docs/batch.md), after the same backup
    assert _history(7313) == [("backup", "ok"), ("batch-upload", "ok")]
    api, gui = prm9tool.history.records(7312)[-1], prm9tool.history.records(7314)[-1]
    recorder = Recorder()
    store = recorder.store()
    assert store.record(api["id"])["parameters"] == store.record(gui["id"])["parameters"]
    recorder.close()
    same = {"written", "chosen", "mismatches"}
    assert {k: api["details"][k] for k in same} == {k: gui["details"][k] for k in same}
    # the batch's record has the upload's shape, with its batch context added (issue 28)
    batch = prm9tool.history.records(7313)[-1]
    assert set(batch["details"]) - set(api["details"]) == {"file", "verification"}
    assert set(api["details"]) <= set(batch["details"])  # "command": "python API", "--batch"
    assert {k: batch["details"][k] for k in same} == {k: api["details"][k] for k in same}
    assert batch["details"]["file"] == str(path) and batch["details"]["command"] == "--batch"
    assert _parameters(batch["id"]) == _parameters(api["id"])


def test_a_characterization_refuses_while_a_generator_runs_in_the_api_and_the_gui(
    qtbot, connection
):
    square = GeneratorSettings(Waveform.SQUARE, 10.0, 0.0, 0.5)
    with prm9tool.connect(f"emulator:{E02}:7321", record_history=False) as valve:
        with (
            valve.generator("square", amplitude=10, period=0.5),
            pytest.raises(MotionBusyError) as api,
        ):
            valve.characterize()
        assert valve.service.motion.running is None  # the generator gave it back
    assert str(api.value) == (
        "the characterization cannot start while the setpoint generator runs on this valve: "
        "stop the setpoint generator first; nothing was started"
    )
    _online(qtbot, connection, 7322)
    connection.start_generator(square)
    runner = ValveRunner(connection)
    with qtbot.waitSignal(runner.failed, timeout=TIMEOUT) as failed:
        runner.run("report", lambda rig: pytest.fail("the test must not start"))
    assert failed.args == ["report", str(api.value)]
    connection.stop_generator()


@pytest.mark.parametrize("od", ["full", "manual"])
def test_a_refused_write_has_the_same_words_over_canopen(qtbot, tmp_path, request, capsys, od):
    # the CAN valve, also the one with only the objects the manual lists (no type-key object)
    from support.can_link_rig import E04, make_link_rig
    from support.reconnect_links import can_connection

    rig = make_link_rig(request.node.name, tmp_path, E04, od=od)
    bus = {"can_interface": "virtual", "can_channel": rig.options.channel}
    cli_bus = ["--can-interface", "virtual", "--can-channel", rig.options.channel]
    words = "CURNORM: the parameter is read-only"
    connection = can_connection(rig)
    try:
        with prm9tool.connect("can:10", type_key=E04, record_history=False, **bus) as valve:
            with pytest.raises(AccessDeniedError) as api:
                valve["CURNORM"] = 1000
            with pytest.raises(ValueRangeError) as range_api:
                valve["LIMTA"] = 99999
        assert str(api.value) == words
        args = ["--device", "can:10", *cli_bus, "--type-key", E04, "--set"]
        assert main([*args, "CURNORM=1000"]) == 2
        assert words in capsys.readouterr().err
        assert main([*args, "LIMTA=99999"]) == 2
        assert str(range_api.value) in capsys.readouterr().err
        if od == "full":  # the window asks for a manual-only valve's type key first
            with qtbot.waitSignal(connection.online_changed, timeout=TIMEOUT):
                connection.go_online("can:10")
            assert words in _gui_refusal(qtbot, connection, "CURNORM", 1000)
            assert str(range_api.value) in _gui_refusal(qtbot, connection, "LIMTA", 99999)
    finally:
        connection.shutdown()
        rig.close()


LSS_TIMEOUT = 90_000  # a Fastscan, the checks of a node ID and the boot at it (busy PC)


def _lss_job(qtbot, lss, done, start):
    """The result of an LSS job of the CAN bus window's adapter (fails with its words)."""
    got, failed = [], []
    done.connect(got.append)
    lss.failed.connect(lambda _job, why: failed.append(why))
    start()
    qtbot.waitUntil(lambda: bool(got or failed), timeout=LSS_TIMEOUT)
    assert not failed, failed
    return got[0]


@pytest.mark.slow  # three buses of LSS searches (about 20 s)
def test_lss_is_one_operation_at_every_door(qtbot, request, capsys):
    # cli/lss.py, online/lss_commissioning.py and prm9tool.lss_* are the service's LSS
    from support.lss_rig import make_lss_rig

    from prm9tool.online.lss_commissioning import LssCommissioning

    rig = make_lss_rig(request.node.name)
    try:
        rig.add(4700, switches=(6, 2))  # node 10 by its switch
        for serial in (4711, 4712, 4713):
            rig.add(serial)  # switch 1: no node ID
        bus = {"can_interface": "virtual", "can_channel": rig.options.channel}
        cli_bus = ["--can-interface", "virtual", "--can-channel", rig.options.channel]
        gui_bus = {"interface": "virtual", "channel": rig.options.channel}
        lss = LssCommissioning()

        api_found = prm9tool.lss_scan(**bus)
        assert main(["--lss-scan", "--json", *cli_bus]) == 0
        cli_found = json.loads(capsys.readouterr().out)
        scanned = _lss_job(qtbot, lss, lss.scanned, lambda: lss.scan(gui_bus))
        assert [d.to_dict() for d in api_found] == cli_found
        assert scanned == api_found and {d.serial for d in api_found} == {4711, 4712, 4713}

        # the same refusal: node 10 answers already
        with pytest.raises(prm9tool.CommunicationError) as api:
            prm9tool.lss_assign({4711: 10}, **bus)
        assert main(["--lss-assign", "4711=10", *cli_bus]) == 2
        cli = capsys.readouterr().err
        with qtbot.waitSignal(lss.failed, timeout=LSS_TIMEOUT) as failed:
            lss.assign(gui_bus, api_found[0], 10)
        assert str(api.value).startswith("node ID 10 is taken: serial 4700 answers there")
        assert cli == f"prm9tool: {api.value}\n" and str(api.value) in failed.args[1]

        # the same result: stored, answering at the new node ID
        (given,) = prm9tool.lss_assign({4711: 21}, **bus)
        assert given.to_dict() == {"serial": 4711, "node_id": 21, "device": "can:21"}
        assert main(["--lss-assign", "4712=22", *cli_bus]) == 0
        assert capsys.readouterr().out == "serial 4712: node 22, stored; it answers as can:22\n"
        device = next(d for d in api_found if d.serial == 4713)
        assigned = _lss_job(qtbot, lss, lss.assigned, lambda: lss.assign(gui_bus, device, 23))
        assert assigned.device_id == "can:23"
        nodes = {v.firmware.nv.lss.get("node_id") for v in rig.valves[1:]}
        assert nodes == {21, 22, 23}
    finally:
        rig.close()


def test_an_autotune_refuses_while_a_generator_runs_in_the_api_and_the_gui(qtbot, connection):
    from prm9tool.service import autotune

    valve = prm9tool.connect(f"emulator:{E02}:7331", record_history=False)
    with (
        valve,
        valve.generator("square", amplitude=10, period=0.5),
        pytest.raises(MotionBusyError) as api,
    ):
        valve.autotune()
    assert str(api.value) == (
        "the autotune cannot start while the setpoint generator runs on this valve: "
        "stop the setpoint generator first; nothing was started"
    )
    _online(qtbot, connection, 7332)
    connection.start_generator(GeneratorSettings(Waveform.SQUARE, 10.0, 0.0, 0.5))
    runner = ValveRunner(connection)
    settings = autotune.AutotuneSettings()
    with qtbot.waitSignal(runner.failed, timeout=TIMEOUT) as failed:
        runner.run("autotune", lambda rig: autotune.run(rig, settings))
    assert failed.args == ["autotune", str(api.value)]
    connection.stop_generator()


@pytest.mark.slow  # three autotune runs (about 40 s)
def test_an_autotune_gives_the_same_result_and_record_at_every_door(
    qtbot, connection, capsys, tmp_path
):
    from prm9tool.service import autotune
    from prm9tool.views.history.notes import record_tuning_run

    with prm9tool.connect(f"emulator:{E02}:7333") as valve:  # the API
        api = valve.autotune()
    assert main(["--autotune", "--emulator", f"{E02}:7334", "--json"]) == 0  # the command line
    cli = json.loads(capsys.readouterr().out)
    connection.set_recorder(Recorder())
    _online(qtbot, connection, 7335)  # the GUI's worker, as the Tuning window runs it
    runner = ValveRunner(connection)
    with qtbot.waitSignal(runner.finished, timeout=120_000) as finished:
        runner.run("autotune", lambda rig: autotune.run(rig, autotune.AutotuneSettings()))
    gui = autotune.AutotuneOutcome(finished.args[1])
    record_tuning_run(connection, "autotune", finished.args[1])  # as the window does

    for outcome in (api.to_dict(), cli, gui.to_dict()):
        assert outcome["outcome"] == "proposed" and outcome["passes"] and not outcome["applied"]
        assert outcome["loop"] == "position" and outcome["method"] == "model"
        assert set(outcome["proposed"]) == {"POSKP", "POSKI", "POSKD", "POST1"}
    assert set(api.to_dict()) == set(cli) == set(gui.to_dict())
    qtbot.waitUntil(lambda: _history(7335) == [("autotune", "proposed")], timeout=TIMEOUT)
    assert _history(7333) == _history(7334) == [("autotune", "proposed")]
    records = [prm9tool.history.records(s)[-1]["details"] for s in (7333, 7334, 7335)]
    shapes = [set(r) - {"command"} for r in records]
    assert shapes[0] == shapes[1] == shapes[2] == set(cli) - {"outcome", "verdict"}
    for record, outcome in zip(records, (api.to_dict(), cli, gui.to_dict()), strict=True):
        assert record["proposed"] == outcome["proposed"]


def _gui_job(qtbot, connection, start, tag, timeout=TIMEOUT):
    """Start a job of the GUI's worker and return its result (operation_finished(tag, …))."""
    with qtbot.waitSignal(
        connection.operation_finished, timeout=timeout, check_params_cb=lambda n, _r: n == tag
    ) as done:
        start()
    return done.args[1]


def test_download_store_factory_values_and_restart_are_the_same_at_every_door(
    qtbot, connection, capsys, tmp_path
):
    from prm9tool.files.prmfile import read_file

    with prm9tool.connect(f"emulator:{E02}:7341") as valve:  # the API
        api_values = dict(valve.download().raw)
        valve["LIMTA"] = 1700
        valve.store()
        api_factory = dict(valve.restore_factory(confirm_hydraulics_off=True, backup=False).raw)
        valve.restart(confirm_hydraulics_off=True)
        api_after = dict(valve.download().raw)
    out = tmp_path / "7342.prm"  # the command line
    assert main(["--batch", "--download", str(out), "--emulator", f"{E02}:7342"]) == 0
    cli_values = dict(read_file(out).values)
    assert main(["--emulator", f"{E02}:7342", "--set", "LIMTA=1700", "--store"]) == 0
    capsys.readouterr()
    connection.set_recorder(Recorder())
    _online(qtbot, connection, 7343)  # the GUI's worker
    gui_values = _gui_job(qtbot, connection, connection.download, "download")
    connection.write("LIMTA", 1700)
    _gui_job(qtbot, connection, connection.store_valve, "store")
    gui_factory, _ = _gui_job(qtbot, connection, lambda: connection.factory_reset("f"), "f")
    gui_after = _gui_job(qtbot, connection, lambda: connection.restart_valve("restart"), "restart")

    assert api_values == cli_values == dict(gui_values)  # the same set, read three ways
    assert api_factory == dict(gui_factory) == api_values  # restarted and read back at both
    assert api_after == dict(gui_after) == api_values and api_after["LIMTA"] == 2400
    stores = {s: [r for r in prm9tool.history.records(s) if r["operation"] == "store"]
              for s in (7341, 7342, 7343)}  # fmt: skip
    assert [len(found) for found in stores.values()] == [1, 1, 1]
    assert {json.loads(_parameters(found[0]["id"]))["LIMTA"] for found in stores.values()} == {1700}
    # the service records the factory reset and the restart at both doors
    api_records, gui_records = (
        [
            r
            for r in prm9tool.history.records(serial)
            if r["operation"] in ("restore-factory", "restart")
        ]
        for serial in (7341, 7343)
    )
    assert [r["operation"] for r in api_records] == ["restore-factory", "restart"]
    assert [r["operation"] for r in gui_records] == ["restore-factory", "restart"]
    assert set(api_records[0]["details"]) - {"command"} == set(gui_records[0]["details"])
    assert _parameters(api_records[0]["id"]) == _parameters(gui_records[0]["id"])  # the set


def test_a_diff_against_a_file_is_the_same_in_the_api_and_on_the_command_line(capsys, tmp_path):
    from prm9tool.compare.export import as_json

    with prm9tool.connect(f"emulator:{E02}:7351", record_history=False) as valve:
        wanted = valve.download()
    path = tmp_path / "set.prm"
    write_file(PrmContents(wanted.type_key, {**wanted.raw, "LIMTA": 1700}), path, backup=False)
    with prm9tool.connect(f"emulator:{E02}:7352", record_history=False) as valve:
        api = as_json(prm9tool.diff(path, valve))
    assert main(["--diff", str(path), "--emulator", f"{E02}:7353", "--json"]) == 1
    cli = json.loads(capsys.readouterr().out)
    changed = lambda report: [r["mnemonic"] for r in report["differences"]]  # noqa: E731
    assert changed(api) == changed(cli) == ["LIMTA"]


def _gui_status(qtbot, connection):
    got = []
    connection.run("status", lambda s: connection.service(s).status(), got.append)
    qtbot.waitUntil(lambda: bool(got), timeout=TIMEOUT)
    return got[0]


def test_commissioning_a_ca_valve_gives_the_same_state_in_the_api_and_the_gui(qtbot, connection):
    # a -CA valve as delivered waits for its master: NMT start, then the enable sequence
    # (manual §7.2, §7.4), through the valve service at both doors
    from prm9tool.catalogue.commissioning import NmtCommand
    from prm9tool.online.valve_control import ValveControl

    with prm9tool.connect(f"emulator:{E02_CA}:7361", record_history=False) as valve:
        before = str(valve.wait_booted().device_state)
        valve.nmt("start")
        valve.enable()
        api = valve.status()
    _online(qtbot, connection, 7362, E02_CA)
    booted = []  # the valve boots about 2 s after power-up (manual §1.5): a job waits for it
    connection.run("boot", lambda s: wait_for(lambda: not s.status().booting, 10), booted.append)
    qtbot.waitUntil(lambda: bool(booted), timeout=TIMEOUT)
    control = ValveControl(connection)
    said = []
    connection.failed.connect(said.append)
    control.nmt(NmtCommand.START)
    control.enable()
    gui = _gui_status(qtbot, connection)  # the worker runs its jobs in order
    assert gui.device_state == api.device_state, said
    assert before == "INIT" and str(api.device_state) == "DEVICE_MODE_ACTIVE"
    assert str(gui.nmt_state) == str(api.nmt_state) == "operational"


def test_the_dcf_export_is_the_same_file_at_every_door(qtbot, capsys, tmp_path):
    from prm9tool.model.document import ParameterDocument
    from prm9tool.views.files.dcf_export import DcfExport

    with prm9tool.connect(f"emulator:{E02_CA}:7371", record_history=False) as valve:
        assert valve.export_dcf(tmp_path / "api.dcf") == valve.export_dcf(tmp_path / "api.dcf")
        values = valve.download().raw
    args = ["--emulator", f"{E02_CA}:7372", "--export-dcf", str(tmp_path / "cli.dcf")]
    assert main(args) == 0
    assert capsys.readouterr().out.startswith(f"DCF saved as {tmp_path / 'cli.dcf'} (node ")
    doc = ParameterDocument(E02_CA)  # the window's File → Export DCF writes the document
    doc.set_values(dict(values), "online")
    assert DcfExport(doc, None).export(tmp_path / "gui.dcf")
    texts = [
        (tmp_path / f"{door}.dcf").read_text(encoding="utf-8") for door in ("api", "cli", "gui")
    ]
    assert texts[0] == texts[1] == texts[2]


@pytest.mark.parametrize("od", ["full", "manual"])
def test_a_download_over_canopen_is_the_same_set_at_every_door(qtbot, tmp_path, request, od):
    # the CAN valve, also the one with only the objects the manual lists (no type-key object)
    from support.can_link_rig import E04, make_link_rig
    from support.reconnect_links import can_connection

    from prm9tool.files.prmfile import read_file

    rig = make_link_rig(request.node.name, tmp_path, E04, od=od)
    bus = {"can_interface": "virtual", "can_channel": rig.options.channel}
    cli_bus = ["--can-interface", "virtual", "--can-channel", rig.options.channel]
    connection = can_connection(rig)
    try:
        with prm9tool.connect("can:10", type_key=E04, **bus) as valve:
            api = dict(valve.download().raw)
        out = tmp_path / "can10.prm"
        args = ["--batch", "--download", str(out), "--device", "can:10", *cli_bus]
        assert main([*args, "--type-key", E04]) == 0
        assert dict(read_file(out).values) == api
        if od == "full":  # the window asks for a manual-only valve's type key first
            with qtbot.waitSignal(connection.online_changed, timeout=TIMEOUT):
                connection.go_online("can:10")
            assert dict(_gui_job(qtbot, connection, connection.download, "download")) == api
    finally:
        connection.shutdown()
        rig.close()


def test_the_eds_export_is_the_same_file_at_every_door(qtbot, tmp_path):
    from prm9tool.model.document import ParameterDocument
    from prm9tool.views.files.dcf_export import EdsExport

    with prm9tool.connect(f"emulator:{E02_CA}:7381", record_history=False) as valve:
        valve.export_eds(tmp_path / "api.eds")
    args = ["--export-eds", E02_CA, "-o", str(tmp_path / "cli.eds")]
    assert main(args) == 0
    # the window's File → Export EDS writes the document's type, offline too
    assert EdsExport(ParameterDocument(E02_CA), None).export(tmp_path / "gui.eds")
    # the same file but its creation time (CiA 306 [FileInfo], the minute it was written)
    texts = [
        [line for line in (tmp_path / f"{door}.eds").read_bytes().split(b"\r\n")
         if not line.startswith((b"CreationTime=", b"CreationDate="))]
        for door in ("api", "cli", "gui")
    ]  # fmt: skip
    assert texts[0] == texts[1] == texts[2] and b"[DeviceInfo]" in texts[0]
    with (
        prm9tool.connect(f"emulator:{E02}:7382", record_history=False) as valve,
        pytest.raises(prm9tool.TypeKeyError) as api,
    ):
        valve.export_eds(tmp_path / "no.eds")
    assert str(api.value).startswith(f"{E02} has no CANopen interface")


def test_a_diff_of_two_files_gives_the_same_differences_in_the_window_and_on_the_command_line(
    qtbot, monkeypatch, capsys, tmp_path
):
    # File → Compare with file… and --diff are one comparison (prm9tool.compare.model)
    from support.gui_support import main_window, record_prompts

    from prm9tool.compare.export import value
    from prm9tool.views.compare.view import CompareDialog

    first = PrmContents.factory(TypeKey.parse(E02))
    first.values.update(LIMTA=1700, POSKP=120)
    second = PrmContents.factory(TypeKey.parse(E02_CA))  # CANopen objects: missing
    second.values.update(LIMTA=1800, RAMPUPA=250)
    a, b = tmp_path / "a.prm", tmp_path / "b.prm"
    write_file(first, a, backup=False)
    write_file(second, b, backup=False)
    assert main(["--diff", str(a), str(b), "--json"]) == 1
    cli = [
        (d["mnemonic"], d["a"], d["b"]) for d in json.loads(capsys.readouterr().out)["differences"]
    ]

    record_prompts(monkeypatch)
    shown = []
    monkeypatch.setattr(CompareDialog, "exec", lambda dialog: shown.append(dialog) or 0)
    with main_window(qtbot, tmp_path, E02) as window:
        window.doc.set_values(dict(first.values), "a.prm")
        window.compare.compare_with_file(b)
        qtbot.waitUntil(lambda: bool(shown), timeout=TIMEOUT)
        rows = shown[0].model.comparison.rows
        gui = [(r.mnemonic, value(r, 0), value(r, 1)) for r in rows if r.differs]
    assert gui == cli
    assert {"LIMTA", "POSKP", "NODEID"} <= {mnemonic for mnemonic, _a, _b in cli}


def _records(serial, *operations):
    return [r for r in prm9tool.history.records(serial) if r["operation"] in operations]


def test_restart_and_factory_values_on_the_command_line_are_the_windows(qtbot, connection, capsys):
    # --restart and --restore-factory run the window's operations of the valve service
    # (restart_and_read, factory_reset_and_read) and record as the window does
    for serial in (7391, 7392, 7465):  # a value that the factory reset takes back
        assert main(["--emulator", f"{E02}:{serial}", "--set", "LIMTA=1700", "--store"]) == 0
    capsys.readouterr()
    cli = ["--emulator", f"{E02}:7391", "--hydraulics-safe", "--json"]
    assert main([*cli, "--restore-factory"]) == 0
    factory = json.loads(capsys.readouterr().out)
    assert main([*cli, "--restart"]) == 0
    restarted = json.loads(capsys.readouterr().out)
    connection.set_recorder(Recorder())
    _online(qtbot, connection, 7392)  # the GUI's worker
    gui_factory, _backup = _gui_job(qtbot, connection, lambda: connection.factory_reset("f"), "f")
    gui_restart = _gui_job(qtbot, connection, lambda: connection.restart_valve("r"), "r")

    assert factory["operation"] == "restore-factory" and restarted["operation"] == "restart"
    assert factory["values"]["LIMTA"] == restarted["values"]["LIMTA"] == 2400
    with prm9tool.connect(f"emulator:{E02}:7391", record_history=False) as valve:
        shown = {m: valve.parameter(m) for m in gui_factory}
        from prm9tool.api.params import display

        assert factory["values"] == {m: display(shown[m], v) for m, v in gui_factory.items()}
        assert restarted["values"] == {m: display(shown[m], v) for m, v in gui_restart.items()}
    cli_records = _records(7391, "restore-factory", "restart")
    gui_records = _records(7392, "restore-factory", "restart")
    assert [r["operation"] for r in cli_records] == ["restore-factory", "restart"]
    assert [r["operation"] for r in gui_records] == ["restore-factory", "restart"]
    for mine, theirs in zip(cli_records, gui_records, strict=True):
        assert set(mine["details"]) - {"command"} == set(theirs["details"]) - {"command"}
        assert _parameters(mine["id"]) == _parameters(theirs["id"])  # the set read back
    assert cli_records[1]["details"]["command"] == "--restart"
    # the API's restore_factory() is the same operation: reset, restart, the set read back
    with prm9tool.connect(f"emulator:{E02}:7465") as valve:
        with pytest.raises(AccessDeniedError, match="a restart moves the spool"):
            valve.restore_factory()  # the hydraulics question, as --hydraulics-safe
        assert valve["LIMTA"] == 1700  # nothing sent
        api_factory = valve.restore_factory(confirm_hydraulics_off=True)
    assert api_factory is not None and dict(api_factory.raw) == gui_factory
    (api_record,) = _records(7465, "restore-factory")
    assert set(api_record["details"]) - {"command"} == set(cli_records[0]["details"]) - {"command"}
    assert _parameters(api_record["id"]) == _parameters(cli_records[0]["id"])


@pytest.mark.parametrize(
    ("command", "words"),
    [
        ("--restart", "restarting the valve electronics is only allowed with the hydraulic "
         "circuit disconnected"),
        ("--restore-factory", "the valve's stored parameters are reset to the factory values"),
        ("--enable", "enabled, the valve follows its setpoint"),
        ("--disable", "disabled, the valve stops following its setpoint"),
    ],
)  # fmt: skip
def test_a_command_that_moves_the_spool_asks_the_hydraulics_question(capsys, command, words):
    # the window asks before a restart (RestartDialog); the command line refuses without the
    # answer, in the window's words, and sends nothing
    assert main(["--emulator", f"{E02_CA}:7393", command]) == 2
    err = capsys.readouterr().err
    assert f"error: {command}: {words}" in err and err.rstrip().endswith("add --hydraulics-safe")
    assert _history(7393) == []


def test_enable_and_disable_are_the_same_at_every_door(qtbot, connection, capsys):
    # --enable alone commissions a -CA valve (NMT start, 08h → 09h → 0Bh → 0Fh) as the API's
    # commission() and the status window's NMT start + Enable; --disable back to INIT
    from prm9tool.catalogue.commissioning import NmtCommand
    from prm9tool.online.valve_control import ValveControl

    with prm9tool.connect(f"emulator:{E02_CA}:7394", record_history=False) as valve:
        api = valve.commission()
        valve.disable()
        api_off = valve.status()
    cli = ["--emulator", f"{E02_CA}:7395", "--hydraulics-safe", "--json"]
    assert main([*cli, "--enable"]) == 0
    enabled = json.loads(capsys.readouterr().out)["status"]
    assert main([*cli, "--disable"]) == 0
    disabled = json.loads(capsys.readouterr().out)["status"]
    _online(qtbot, connection, 7396, E02_CA)
    booted = []
    connection.run("boot", lambda s: wait_for(lambda: not s.status().booting, 10), booted.append)
    qtbot.waitUntil(lambda: bool(booted), timeout=TIMEOUT)
    control = ValveControl(connection)
    control.nmt(NmtCommand.START)
    control.enable()
    gui = _gui_status(qtbot, connection)
    control.disable()
    gui_off = _gui_status(qtbot, connection)
    assert str(api.device_state) == enabled["device_state"] == str(gui.device_state)
    assert enabled["device_state"] == "DEVICE_MODE_ACTIVE" and enabled["nmt_state"] == "operational"
    assert str(api_off.device_state) == disabled["device_state"] == str(gui_off.device_state)
    assert disabled["device_state"] == "INIT"


def test_enable_of_a_valve_without_canopen_says_why_and_sends_nothing(capsys):
    assert main(["--emulator", f"{E02}:7397", "--enable", "--hydraulics-safe"]) == 2
    err = capsys.readouterr().err
    assert "this valve's CANopen is off" in err and "nothing was sent" in err
    assert "0x6040" not in err  # not the valve's SDO abort


@pytest.mark.parametrize("od", ["full", "manual"])
def test_restart_enable_and_disable_over_canopen_are_the_apis(tmp_path, request, capsys, od):
    # a -CA valve on a CAN bus (also the one with only the manual's objects): --enable,
    # --disable and --restart on the command line give the API's states; the restart comes
    # back in pre-operational (a restart over CAN drops the spool: hence --hydraulics-safe)
    from support.can_link_rig import E04, make_link_rig

    rig = make_link_rig(request.node.name, tmp_path, E04, od=od)
    rig.valve.start()  # real time: the restart's boot takes its ~2 s
    bus = {"can_interface": "virtual", "can_channel": rig.options.channel}
    cli = ["--device", "can:10", "--can-interface", "virtual", "--can-channel",
           rig.options.channel, "--type-key", E04, "--hydraulics-safe", "--json"]  # fmt: skip
    try:
        assert main([*cli, "--enable"]) == 0
        enabled = json.loads(capsys.readouterr().out)
        assert main([*cli, "--disable"]) == 0
        disabled = json.loads(capsys.readouterr().out)
        with prm9tool.connect("can:10", type_key=E04, **bus) as valve:
            api = valve.commission()
            valve.disable()
            api_off = valve.status()
            before = dict(valve.download().raw)
        assert enabled["status"]["device_state"] == str(api.device_state) == "DEVICE_MODE_ACTIVE"
        # the command line sent NMT start and saw it confirmed; the API found it operational
        # already (no heartbeat heard yet: "unknown" over a link that only asks)
        assert enabled["status"]["nmt_state"] == "operational", (enabled, api)
        assert disabled["status"]["device_state"] == str(api_off.device_state) == "INIT"
        assert main([*cli[:-1], "--restart"]) == 0
        out = capsys.readouterr().out
        assert out.startswith("the valve restarted; it runs with its stored parameters")
        assert "NMT pre-operational: it waits for its CANopen master" in out
        assert [r["operation"] for r in _records(rig.valve.serial, "restart")] == ["restart"]
        assert json.loads(_parameters(_records(rig.valve.serial, "restart")[0]["id"])) == before
    finally:
        rig.valve.stop()
        rig.close()


@pytest.mark.parametrize(
    ("serial", "command"),
    [
        (7398, []),  # --enable alone
        (7460, ["--characterize", "--json", "{tmp}/run.json"]),
        (7461, ["--autotune"]),
        (7462, ["--signature"]),
        (7463, ["--fit-twin", "{tmp}/twin.toml"]),
    ],
)
def test_an_enable_the_valve_refuses_has_the_same_words_and_code_at_every_door(
    capsys, tmp_path, serial, command
):
    # issue 28: --enable alone exited 1 when the valve refused, the same --enable before a
    # test 6 (communication); one rule (cli/enabling.py): the valve refused, exit 1
    from prm9tool.device.enabling import NotEnabledError

    with prm9tool.connect(f"emulator:{E02_CA}:{serial}", record_history=False) as valve:
        valve.commission()
        valve.session.emulator.set_fault("COIL_A_OPEN", True)
        wait_for(lambda: str(valve.status().device_state) == "FAULT_HOLD", 10)
        with pytest.raises(NotEnabledError) as api:
            valve.commission()
    args = [a.format(tmp=tmp_path) for a in command]
    assert main([*args, "--emulator", f"{E02_CA}:{serial}", "--enable", "--hydraulics-safe"]) == 1
    err = capsys.readouterr().err
    assert f"prm9tool: --enable: {api.value}" in err
    assert "error 0x5411 (Solenoid A disconnected) is still present" in err
    assert list(tmp_path.iterdir()) == []  # no test ran, no report, no twin


@pytest.mark.parametrize("command", [[], ["--characterize", "--json", "{tmp}/run.json"]])
def test_enable_of_a_valve_without_canopen_is_refused_alike_before_a_test(
    capsys, tmp_path, command
):
    args = [a.format(tmp=tmp_path) for a in command]
    assert main([*args, "--emulator", f"{E02}:7464", "--enable", "--hydraulics-safe"]) == 2
    err = capsys.readouterr().err
    assert "prm9tool: --enable: this valve's CANopen is off" in err and "nothing was sent" in err
    assert list(tmp_path.iterdir()) == []

"""End-to-end tests of the headless batch mode: real subprocesses, every exit code.

USB valves come from a stand-in ``hid`` module (tests/support/fake_hid) on PYTHONPATH, so the whole
path from the command line through discovery, hidapi backend, protocol and firmware runs.
"""

from __future__ import annotations

import json
import os
import re
import subprocess
from datetime import datetime
from pathlib import Path

import pytest
from support.python_process import run_python

from prm9tool import app
from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.cli import batch
from prm9tool.cli.main import main
from prm9tool.device import emulated_valves
from prm9tool.device.emulator import EmulatedValve
from prm9tool.device.usb.session import UsbSession
from prm9tool.device.usb.transport.emulator import EmulatorTransport, LinkFaults
from prm9tool.errors import AbortCode, ExitCode, SdoAbortError
from prm9tool.files.prmfile import PrmContents, read_file, write_file

E04 = "PRM9-06.3Z11/30-24E04S02-CA"
E02 = "PRM9-06.3Z11/30-24E02S02"
FAKE_HID = Path(__file__).parent / "support" / "fake_hid"


def run(tmp_path: Path, *args: str, fake_hid: str | None = None) -> subprocess.CompletedProcess:
    env = dict(os.environ, PRM9TOOL_DATA_DIR=str(tmp_path / "data"))
    env.pop("PRM9TOOL_USB_VID", None)
    env.pop("PRM9TOOL_USB_PID", None)
    if fake_hid is not None:
        env["PYTHONPATH"] = os.pathsep.join([str(FAKE_HID), env.get("PYTHONPATH", "")])
        env["PRM9TOOL_FAKE_HID"] = fake_hid
    return run_python("-m", "prm9tool", *args, env=env, cwd=tmp_path)


def tuned_file(tmp_path: Path, type_key: str = E04, name: str = "tuned.prm") -> Path:
    """A valid file whose values all differ from the factory defaults."""
    key = TypeKey.parse(type_key)
    contents = PrmContents.factory(key)
    contents.values.update(LIMTA=1500, LIMTB=1600, DYNFREQ=120, DTAMP=1000, AINSETP=5)
    path = tmp_path / name
    write_file(contents, path)
    return path


def report(tmp_path: Path, name: str = "report.json") -> dict:
    return json.loads((tmp_path / name).read_text(encoding="utf-8"))


def test_parallel_upload_with_report_and_backups(tmp_path):
    source = tuned_file(tmp_path)
    valves = [f"{E04}:{serial}" for serial in (21, 22, 23)]
    args = ["--batch", str(source), "--report", "report.json"]
    result = run(tmp_path, *args, *(a for v in valves for a in ("--emulator", v)))
    assert result.returncode == 0, result.stderr
    data = report(tmp_path)
    assert (data["schema"], data["mode"], data["exit_code"]) == (1, "upload", 0)
    records = data["valves"]
    assert [r["serial"] for r in records] == [21, 22, 23]
    for record in records:
        assert record["result"] == "ok" and record["verification"] == "passed"
        assert record["parameters_written"] == len(read_file(source).values)
        assert record["type_key"] == E04 and record["firmware"] == "1.0.0"
        backup = Path(record["backup"])
        assert backup.parent == tmp_path / "data" / "backups" / str(record["serial"])
        factory = PrmContents.factory(TypeKey.parse(E04)).values
        assert read_file(backup).values == factory  # taken before the upload
    total = 2 * len(read_file(source).values) + 1  # write + verify each, then store
    for serial in (21, 22, 23):
        lines = [line for line in result.stderr.splitlines() if line.startswith(f"[{serial}] ")]
        steps = [
            re.fullmatch(rf"\[{serial}\] (\w+) +(\d+) % \((\d+)/(\d+)\)", line) for line in lines
        ]
        shown = [(m[1], int(m[2]), int(m[3]), int(m[4])) for m in steps if m]
        assert [s for s, *_ in shown if s != "download"] == sorted(
            (s for s, *_ in shown if s != "download"), key=["write", "verify", "store"].index
        )
        assert {"write", "verify"} <= {s for s, *_ in shown}
        assert shown[-1] == ("store", 100, total, total)
        assert re.fullmatch(rf"\[{serial}\] ok \(\d+\.\d\d s\)", lines[-1])


def test_upload_in_one_process_download_in_the_next(tmp_path):
    source = tuned_file(tmp_path)
    assert run(tmp_path, "--batch", str(source), "--emulator", f"{E04}:5").returncode == 0
    result = run(tmp_path, "--batch", "--download", "out.prm", "--emulator", f"{E04}:5")
    assert result.returncode == 0, result.stderr
    downloaded = read_file(tmp_path / "out.prm")
    assert downloaded.values == read_file(source).values
    assert (downloaded.serial, downloaded.firmware) == (5, "1.0.0")


def test_second_upload_keeps_the_first_backup(tmp_path):
    e02 = tuned_file(tmp_path, E02, "e02.prm")
    for _ in range(2):
        args = ("--batch", str(e02), "--emulator", f"{E02}:8", "--report", "r.json")
        assert run(tmp_path, *args).returncode == 0
    backups = list((tmp_path / "data" / "backups" / "8").glob("*.prm"))
    assert len(backups) == 1
    assert report(tmp_path, "r.json")["valves"][0]["backup"] == str(backups[0])


def test_verification_failure_exits_1(tmp_path):
    source = tuned_file(tmp_path)
    fake = f"{E04},31,corrupt_reads_after_out=8"  # the reads of the backup are still clean
    result = run(tmp_path, "--batch", str(source), "--all", "--report", "r.json", fake_hid=fake)
    assert result.returncode == 1, result.stderr
    record = report(tmp_path, "r.json")["valves"][0]
    assert (record["result"], record["verification"], record["failed_step"]) == (
        "verification-failed",
        "failed",
        "verify",
    )
    count = len(record["mismatches"])
    noun = "parameter" if count == 1 else "parameters"
    assert f"{count} {noun} read back differently, nothing was stored" in record["error"]
    assert "working parameters were reset to its stored ones" in record["error"]
    assert record["mismatches"]


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--batch"], "--batch needs FILE.prm"),
        (["--batch", "x.prm", "--download", "y.prm"], "use either --batch FILE.prm or"),
        (
            ["--batch", "--download", "y.prm", "--emulator", E02, "--emulator", E04],
            "select exactly one",
        ),
        (["--batch", "x.prm", "--emulator", "PRM9-06.3Z11/31-24E02S02"], "flow '31'"),
        (["--bogus"], "unrecognized arguments"),
        (
            ["--batch", "x.prm", "--emulator", E02, "--can-interface", "socketcan"],
            "--batch with --emulator uses the emulated valve over USB; to put one on the CAN bus, "
            "run prm9tool --serve-emulator in another process",
        ),
        (["--check", "x.prm", "--can-channel", "can1"], "names a CAN bus; --check does not use"),
        (["--can-channel", "can1"], "use it with --device can:NODE, --list-devices, --batch"),
        (["--serve-emulator", E02], "--serve-emulator needs --can-interface"),
        (
            ["--serve-emulator", E02, "--can-interface", "virtual", "--list-devices"],
            "--serve-emulator and --list-devices are separate commands",
        ),
        (["--list-devices", "--node-id", "3"], "--node-id belongs to --serve-emulator"),
        (
            ["--serve-emulator", E02, "--can-interface", "virtual", "--node-id", "200"],
            "--node-id 200: CANopen node IDs are 1…127",
        ),
    ],
)
def test_usage_errors_exit_2(tmp_path, args, message):
    result = run(tmp_path, *args)
    assert result.returncode == 2
    assert message in result.stderr


def test_invalid_file_exits_3_and_uploads_nothing(tmp_path):
    source = tuned_file(tmp_path)
    text = source.read_text(encoding="utf-8").replace("LIMTA = 1500", "LIMTA = 99999")
    source.write_text(text, encoding="utf-8")
    result = run(tmp_path, "--batch", str(source), "--emulator", f"{E04}:3", "--report", "r.json")
    assert result.returncode == 3
    assert "is not a valid parameter file" in result.stderr
    assert "LIMTA" in result.stderr and f"{source.name}:" in result.stderr
    assert not (tmp_path / "data" / "emulator").exists()
    data = report(tmp_path, "r.json")  # written although the run stopped before any valve
    assert (data["mode"], data["file"], data["exit_code"], data["valves"]) == (
        "upload",
        str(source),
        3,
        [],
    )


def test_no_device_exits_4(tmp_path):
    source = tuned_file(tmp_path)
    result = run(tmp_path, "--batch", str(source), fake_hid="")
    assert result.returncode == 4
    assert "no valve found" in result.stderr
    result = run(tmp_path, "--batch", str(source), "--device", "999", fake_hid=f"{E04},41")
    assert result.returncode == 4
    assert "no valve '999' is connected (found: 41 (usb:/dev/hidraw0))" in result.stderr


def test_type_mismatch_exits_5_unless_forced(tmp_path):
    source = tuned_file(tmp_path)  # for .../30 l/min
    other_flow = "PRM9-06.3Z11/15-24E04S02-CA:6"
    result = run(tmp_path, "--batch", str(source), "--emulator", other_flow)
    assert result.returncode == 5
    assert "use --force-type" in result.stderr
    forced = run(tmp_path, "--batch", str(source), "--emulator", other_flow, "--force-type")
    assert forced.returncode == 0, forced.stderr
    result = run(tmp_path, "--batch", str(source), "--emulator", f"{E02}:7", "--force-type")
    assert result.returncode == 5
    assert "the parameter sets differ" in result.stderr


def test_communication_error_exits_6_and_names_the_step(tmp_path):
    source = tuned_file(tmp_path)
    fake = f"{E04},51;{E04},52,unplug_after_out=10"
    result = run(tmp_path, "--batch", str(source), "--all", "--report", "r.json", fake_hid=fake)
    assert result.returncode == 6, result.stderr
    first, second = report(tmp_path, "r.json")["valves"]
    assert first["result"] == "ok"
    assert (second["result"], second["failed_step"]) == ("communication-error", "write")
    assert "upload failed while writing the parameters (step 1 of 3)" in second["error"]
    assert "nothing was stored" in second["error"]
    assert "restart the valve, hydraulics off" in second["error"]  # the link is gone: no reload


def test_list_devices(tmp_path):
    result = run(tmp_path, "--list-devices", "--emulator", f"{E02}:9", fake_hid=f"{E04},61")
    assert result.returncode == 0, result.stderr
    assert result.stdout.splitlines() == [
        f"usb:/dev/hidraw0\t{E04}\tserial 61\tfirmware 1.0.0",
        f"emulator:{E02}:9\t{E02}\tserial 9\tfirmware 1.0.0",
    ]
    assert run(tmp_path, "--list-devices", fake_hid="").returncode == 4


def test_dry_run_writes_nothing(tmp_path):
    source = tuned_file(tmp_path)
    args = ("--batch", str(source), "--emulator", f"{E04}:4", "--dry-run", "--report", "r.json")
    result = run(tmp_path, *args)
    assert result.returncode == 0, result.stderr
    record = report(tmp_path, "r.json")["valves"][0]
    assert record["result"] == "dry-run"
    assert record["changes"] == 5
    assert not (tmp_path / "data" / "backups").exists()
    assert not (tmp_path / "data" / "emulator" / "4.json").exists()


def test_without_hidapi_the_emulator_still_works(tmp_path):
    broken = tmp_path / "broken"
    broken.mkdir()
    for name in ("hid", "hidraw"):
        (broken / f"{name}.py").write_text('raise ImportError("libhidapi.so.0: not found")\n')
    env = dict(os.environ, PRM9TOOL_DATA_DIR=str(tmp_path / "data"), PYTHONPATH=str(broken))
    result = run_python("-m", "prm9tool", "--list-devices", "--emulator", E02, env=env)
    assert result.returncode == 0, result.stderr
    assert f"emulator:{E02}:1" in result.stdout


def test_batch_mode_never_loads_the_qt_gui(tmp_path):
    source = tuned_file(tmp_path)
    code = (
        "import sys\n"
        "from prm9tool.cli.main import main\n"
        f"code = main(['--batch', {str(source)!r}, '--emulator', '{E04}:2', '--report', 'r.json'])\n"
        "gui = [m for m in ('PySide6.QtWidgets', 'PySide6.QtGui') if m in sys.modules]\n"
        "print(code, gui)\n"
    )
    env = dict(os.environ, PRM9TOOL_DATA_DIR=str(tmp_path / "data"))
    result = run_python("-c", code, env=env, cwd=tmp_path)
    assert result.stdout.strip() == "0 []", result.stderr


def test_every_parameter_of_the_report_schema_is_present(tmp_path):
    source = tuned_file(tmp_path)
    run(tmp_path, "--batch", str(source), "--emulator", f"{E04}:2", "--report", "r.json")
    record = report(tmp_path, "r.json")["valves"][0]
    documented = (Path(__file__).parents[1] / "docs" / "batch.md").read_text(encoding="utf-8")
    for name in record:
        assert f"`{name}`" in documented, f"report field {name} is not documented"


def test_several_valves_without_a_selection_exit_2(tmp_path):
    source = tuned_file(tmp_path)
    result = run(tmp_path, "--batch", str(source), fake_hid=f"{E04},71;{E04},72")
    assert result.returncode == 2
    assert "2 valves are connected: choose with --device or --all" in result.stderr
    result = run(tmp_path, "--batch", str(source), "--device", "72", fake_hid=f"{E04},71;{E04},72")
    assert result.returncode == 0, result.stderr


def test_unwritable_backup_exits_6_and_uploads_nothing(tmp_path):
    source = tuned_file(tmp_path)
    (tmp_path / "data").mkdir()
    (tmp_path / "data" / "backups").write_text("not a folder")
    args = ("--batch", str(source), "--emulator", f"{E04}:12", "--report", "r.json")
    result = run(tmp_path, *args)
    assert result.returncode == 6, result.stderr
    assert "Traceback" not in result.stderr
    record = report(tmp_path, "r.json")["valves"][0]
    assert (record["result"], record["failed_step"], record["backup"]) == (
        "communication-error",
        "backup",
        None,
    )
    assert "the backup could not be written, nothing was uploaded" in record["error"]
    assert not (tmp_path / "data" / "emulator" / "12.json").exists()  # nothing stored


def test_report_folder_is_checked_before_any_valve(tmp_path):
    source = tuned_file(tmp_path)
    args = ("--batch", str(source), "--emulator", f"{E04}:13", "--report", "no/such/r.json")
    result = run(tmp_path, *args)
    assert result.returncode == 2
    # the folder as the system writes paths (no\\such on Windows)
    assert f"--report no/such/r.json: there is no folder {Path('no/such')}" in result.stderr
    assert not (tmp_path / "data" / "emulator").exists()


def test_unwritable_report_after_a_good_run_exits_2(tmp_path):
    source = tuned_file(tmp_path)
    (tmp_path / "r.json").mkdir()  # a folder where the report should go
    result = run(tmp_path, "--batch", str(source), "--emulator", f"{E04}:14", "--report", "r.json")
    assert result.returncode == 2
    assert "cannot write the report r.json" in result.stderr


def test_download_failures_exit_6_and_3(tmp_path):
    args = ("--batch", "--download", "out.prm", "--report", "r.json")
    result = run(tmp_path, *args, fake_hid=f"{E04},81,unplug_after_out=3")
    assert result.returncode == 6
    assert "download failed" in result.stderr and "is gone" in result.stderr
    assert report(tmp_path, "r.json")["valves"][0]["error"]
    assert not (tmp_path / "out.prm").exists()
    (tmp_path / "out.prm").mkdir()  # the output cannot be written
    result = run(tmp_path, *args, "--emulator", f"{E04}:15")
    assert result.returncode == 3
    assert "cannot save out.prm" in result.stderr


def test_emulated_serial_of_another_type_exits_2(tmp_path):
    source = tuned_file(tmp_path)
    assert run(tmp_path, "--batch", str(source), "--emulator", f"{E04}:16").returncode == 0
    result = run(tmp_path, "--batch", str(source), "--emulator", f"{E02}:16")
    assert result.returncode == 2
    assert f"belongs to a {E04} valve, not to {E02}" in result.stderr


def test_a_valve_named_twice_is_uploaded_to_once(tmp_path):
    source = tuned_file(tmp_path)
    names = ("41", "/dev/hidraw0", "usb:/dev/hidraw0")
    args = ["--batch", str(source), "--all", "--report", "r.json"]
    result = run(
        tmp_path, *args, *(a for n in names for a in ("--device", n)), fake_hid=f"{E04},41"
    )
    assert result.returncode == 0, result.stderr
    records = report(tmp_path, "r.json")["valves"]
    assert [(r["device_id"], r["serial"], r["result"]) for r in records] == [
        ("usb:/dev/hidraw0", 41, "ok")
    ]
    lines = result.stderr.splitlines()
    assert sum(line.endswith(": backing up") for line in lines) == 1  # one upload, not two
    assert sum(line.startswith("[41] ok ") for line in lines) == 1


@pytest.mark.parametrize("wanted", ["/dev/hidraw1", "usb:/dev/hidraw1"])
def test_device_selects_a_valve_by_hid_path_or_device_id(tmp_path, wanted):
    source, fake = tuned_file(tmp_path), f"{E04},71;{E04},72"
    args = ("--batch", str(source), "--device", wanted, "--report", "r.json")
    result = run(tmp_path, *args, fake_hid=fake)
    assert result.returncode == 0, result.stderr
    records = report(tmp_path, "r.json")["valves"]
    assert [(r["device_id"], r["serial"], r["result"]) for r in records] == [
        ("usb:/dev/hidraw1", 72, "ok")
    ]
    download = ("--batch", "--download", "out.prm", "--device", wanted)
    result = run(tmp_path, *download, fake_hid=fake)
    assert result.returncode == 0, result.stderr
    assert read_file(tmp_path / "out.prm").serial == 72


def test_unplugged_at_the_store_step_the_report_keeps_what_was_written_and_verified(
    tmp_path, monkeypatch
):
    source = tuned_file(tmp_path)
    links: list[EmulatorTransport] = []
    die_after: list[int] = []

    def open_on_a_faulty_link(entry):
        transport = EmulatorTransport(emulated_valves.emulated_valve(entry.type_key, entry.serial))
        transport.faults = LinkFaults(die_after=die_after[0] if die_after else None)
        links.append(transport)
        return UsbSession(transport, entry.device_id)

    monkeypatch.setattr(batch, "open_valve", open_on_a_faulty_link)
    try:
        assert main(["--batch", str(source), "--emulator", f"{E04}:91"]) == ExitCode.OK
        die_after.append(links[0].reports_on_link - 2)  # lost: the last read-back after the store
        args = ["--batch", str(source), "--emulator", f"{E04}:92"]
        assert main([*args, "--report", str(tmp_path / "r.json")]) == ExitCode.COMMUNICATION
    finally:
        emulated_valves.forget_emulated_valves()
    record = report(tmp_path, "r.json")["valves"][0]
    assert (record["result"], record["failed_step"]) == ("communication-error", "store")
    assert record["parameters_written"] == len(read_file(source).values)
    assert record["verification"] == "passed"
    assert "upload failed while storing (step 3 of 3)" in record["error"]


def test_valves_are_uploaded_in_parallel(tmp_path):
    source = tuned_file(tmp_path)
    valves = [a for serial in (101, 102, 103, 104) for a in ("--emulator", f"{E04}:{serial}")]
    result = run(tmp_path, "--batch", str(source), *valves, "--report", "r.json")
    assert result.returncode == 0, result.stderr
    records = report(tmp_path, "r.json")["valves"]
    started = [datetime.fromisoformat(r["started"]) for r in records]
    finished = [datetime.fromisoformat(r["finished"]) for r in records]
    assert max(started) < min(finished)  # every valve was busy while every other one was
    wall = (max(finished) - min(started)).total_seconds()
    assert wall < 0.5 * sum(r["duration_s"] for r in records)


class _GuiStartedError(Exception):
    pass


@pytest.fixture
def gui(monkeypatch):
    """Stands in for the GUI: ``main`` raises _GuiStartedError instead of opening a window."""

    def start(args, spools_problem=None):
        raise _GuiStartedError(args, spools_problem)

    monkeypatch.setattr(app, "run", start)


@pytest.mark.parametrize(
    ("argv", "named"),
    [
        (["--download", "x.prm", "--emulator"], "--download"),
        (["--report", "r.json"], "--report"),
        (["--dry-run", "x.prm"], "--dry-run"),
        (["--force-type", "--emulator", E04], "--force-type"),
        (["--all"], "--all"),
        (["--device", "41", "--device", "/dev/hidraw1"], "--device"),
        (["--check", "x.prm", "--report", "r.json"], "--report"),
        (["--list-devices", "--batch", "x.prm"], "--batch"),
        (["--list-devices", "--report", "r.json"], "--report"),
        (["--list-devices", "--download", "out.prm"], "--download"),
        (["--list-devices", "--device", "41"], "--device"),
        (["--batch", "x.prm", "y.prm"], "y.prm"),
        (["--batch", "--download", "out.prm", "-o", "o.prm"], "-o/--output"),
        (["--batch", "x.prm", "--check", "x.prm"], "--check"),
        # issue 28: where argparse can say it, it does (mutually exclusive groups, choices)
        (["--lss-scan", "--find-bitrate", "--can-interface", "virtual"],
         "argument --find-bitrate: not allowed with argument --lss-scan"),
        (["--characterize", "--autotune", "--emulator"],
         "argument --autotune: not allowed with argument --characterize"),
        (["--new", E04, "--check", "x.prm"], "argument --check: not allowed with argument --new"),
        (["--autotune", "sideways", "--emulator"], "argument --autotune: invalid choice"),
        (["--apply", "--emulator"], "--apply belongs to --autotune"),
        (["--diff", "a.prm", "b.prm", "--history", "5"],
         "argument --history: not allowed with argument --diff"),
        (["--history-check", "--history-import"],
         "argument --history-import: not allowed with argument --history-check"),
    ],
)  # fmt: skip
def test_options_that_do_not_fit_the_command_exit_2(gui, capsys, argv, named):
    assert main(argv) == ExitCode.USAGE
    message = capsys.readouterr().err.splitlines()[-1]
    assert message.startswith("prm9tool: error: ") and named in message


@pytest.mark.parametrize(
    "argv",
    [
        [],
        ["valve.prm"],
        ["--emulator"],
        ["--emulator", f"{E04}:7", "--emulator", E02],
        [
            "--emulator",
            E04,
            "--can-interface",
            "virtual",
            "--can-channel",
            "x",
            "--can-bitrate",
            "250000",
        ],
        ["--device", "41"],
    ],
)
def test_gui_options_still_start_the_gui(gui, argv):
    with pytest.raises(_GuiStartedError):
        main(argv)


def test_help_lists_every_exit_code_and_the_readme_documents_them(capsys):
    assert main(["--help"]) == 0
    shown = capsys.readouterr().out
    readme = (Path(__file__).parents[1] / "README.md").read_text(encoding="utf-8")
    section = readme.split("## Headless production mode", 1)[1].split("\n## ", 1)[0]
    for code in ExitCode:
        assert re.search(rf"^  {int(code)}  \S", shown, re.MULTILINE), code
        assert re.search(rf"^\| {int(code)} \|", section, re.MULTILINE), code
    assert "docs/batch.md" in section and "docs/usb-protocol.md" in section


def test_a_refused_store_is_reported_truthfully_and_the_valve_reloaded(tmp_path, monkeypatch):
    source = tuned_file(tmp_path)
    valves = []

    def open_a_valve_that_refuses_to_store(entry):
        valve = emulated_valves.emulated_valve(entry.type_key, entry.serial)
        valve.store = refuse  # type: ignore[method-assign]
        valves.append(valve)
        return UsbSession(EmulatorTransport(valve), entry.device_id)

    def refuse():
        raise SdoAbortError(0x1010, 1, AbortCode.CANNOT_STORE)

    monkeypatch.setattr(batch, "open_valve", open_a_valve_that_refuses_to_store)
    try:
        args = ["--batch", str(source), "--emulator", f"{E04}:93"]
        assert main([*args, "--report", str(tmp_path / "r.json")]) == ExitCode.VERIFY_FAILED
        working = {m: valves[0].read(*CATALOGUE[m].key) for m in ("LIMTA", "DTAMP")}
    finally:
        emulated_valves.forget_emulated_valves()
    record = report(tmp_path, "r.json")["valves"][0]
    assert (record["result"], record["failed_step"]) == ("store-failed", "store")
    assert record["parameters_written"] == len(read_file(source).values)
    assert record["verification"] == "passed"
    assert "refused to store the parameters" in record["error"] and "0x08000020" in record["error"]
    assert "reset to its stored ones" in record["error"]
    assert working == {"LIMTA": 2400, "DTAMP": 2458}  # reloaded: the factory set it had stored


def test_a_long_firmware_text_is_cut_and_the_upload_goes_on(tmp_path, monkeypatch):
    source = tuned_file(tmp_path)
    long_text = "1.0.0-" + "x" * 40

    def open_a_valve_with_a_long_firmware_text(entry):
        valve = EmulatedValve(entry.type_key, entry.serial, long_text)
        return UsbSession(EmulatorTransport(valve), entry.device_id)

    monkeypatch.setattr(batch, "open_valve", open_a_valve_with_a_long_firmware_text)
    args = ["--batch", str(source), "--emulator", f"{E04}:94"]
    assert main([*args, "--report", str(tmp_path / "r.json")]) == ExitCode.OK
    assert report(tmp_path, "r.json")["valves"][0]["firmware"] == long_text[:25]


@pytest.mark.parametrize("mode", ["upload", "download"])
def test_whatever_goes_wrong_the_run_ends_with_its_report_and_exit_6(tmp_path, monkeypatch, mode):
    source = tuned_file(tmp_path)

    def open_a_valve_that_breaks_the_program(entry):
        raise ValueError("report of 75 bytes exceeds 64")

    monkeypatch.setattr(batch, "open_valve", open_a_valve_that_breaks_the_program)
    command = ["--batch", str(source)] if mode == "upload" else ["--batch", "--download", "o.prm"]
    args = [*command, "--emulator", f"{E04}:95", "--report", str(tmp_path / "r.json")]
    assert main(args) == ExitCode.COMMUNICATION
    written = report(tmp_path, "r.json")
    assert written["exit_code"] == ExitCode.COMMUNICATION
    error = written["valves"][0]["error"]
    assert "unexpected error (ValueError: report of 75 bytes exceeds 64)" in error
    assert not (tmp_path / "o.prm").exists()


def invalid_stored_set(tmp_path: Path, serial: int) -> Path:
    """The EEPROM image of an emulated valve that holds SETPLINXA = 10000 (XA above XB), as a
    real valve with older firmware may (--emulator TYPEKEY:SERIAL reads it from the data dir)."""
    folder = tmp_path / "data" / "emulator"
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / f"{serial}.json"
    image = {"format": "prm9tool-emulator-eeprom", "version": 1, "type_key": E04}
    path.write_text(json.dumps({**image, "serial": serial, "values": {"SETPLINXA": 10000}}))
    return path


def test_an_invalid_valve_is_backed_up_as_it_is_and_repaired_by_a_valid_upload(tmp_path):
    source = tuned_file(tmp_path)
    image = invalid_stored_set(tmp_path, 77)
    result = run(tmp_path, "--batch", str(source), "--emulator", f"{E04}:77", "--report", "r.json")
    assert result.returncode == 0, result.stderr
    record = report(tmp_path, "r.json")["valves"][0]
    assert (record["result"], record["backup_valid"]) == ("ok", False)
    backup = Path(record["backup"]).read_text(encoding="utf-8")
    assert "# NOT A VALID PARAMETER SET" in backup and "SETPLINXA = 61.035" in backup
    checked = run(tmp_path, "--check", record["backup"])
    assert checked.returncode == ExitCode.INVALID_FILE
    assert "SETPLIN linearization points must increase strictly" in checked.stdout + checked.stderr
    stored = json.loads(image.read_text(encoding="utf-8"))["values"]
    assert stored["SETPLINXA"] == read_file(source).values["SETPLINXA"]  # repaired


def test_download_of_an_invalid_valve_saves_what_it_holds_marked_invalid(tmp_path):
    invalid_stored_set(tmp_path, 78)
    result = run(tmp_path, "--batch", "--download", "out.prm", "--emulator", f"{E04}:78")
    assert result.returncode == 0, result.stderr
    assert "warning: the valve's set is not valid" in result.stderr
    text = (tmp_path / "out.prm").read_text(encoding="utf-8")
    assert "# NOT A VALID PARAMETER SET" in text and "SETPLINXA = 61.035" in text


@pytest.mark.parametrize("plugged_back", [True, False])
def test_a_valve_listed_again_after_its_link_broke_is_reported_not_retried(
    tmp_path, monkeypatch, capsys, plugged_back
):
    from prm9tool.device.emulated import plug_cable

    source = tuned_file(tmp_path)
    opened: list[EmulatorTransport] = []

    def open_and_pull_the_cable(entry):
        transport = EmulatorTransport(emulated_valves.emulated_valve(entry.type_key, entry.serial))
        transport.faults = LinkFaults(die_after=transport.reports_on_link + 30)  # in the run
        opened.append(transport)
        if not plugged_back:
            plug_cable(entry.serial, plugged=False)  # still out when the run ends
        return UsbSession(transport, entry.device_id)

    monkeypatch.setattr(batch, "open_valve", open_and_pull_the_cable)
    try:
        args = ["--batch", str(source), "--emulator", f"{E04}:93"]
        assert main([*args, "--report", str(tmp_path / "r.json")]) == ExitCode.COMMUNICATION
    finally:
        emulated_valves.forget_emulated_valves()
    record = report(tmp_path, "r.json")["valves"][0]
    assert record["result"] == "communication-error" and len(opened) == 1  # no retry
    if plugged_back:
        assert record["came_back"] == f"emulator:{E04}:93"
        assert "connected again" in capsys.readouterr().err  # the operator reads it
    else:
        assert record["came_back"] is None

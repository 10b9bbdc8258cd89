"""A CANopen valve that does not tell its type key (no 0x2041, as real valves): ``--type-key``
on the command line (``--batch --download`` and wherever a CAN valve is opened), the GUI asking
when going online with ``--device can:N``; the key is checked against what the objects tell and
remembered per serial number."""

from __future__ import annotations

import json

import pytest
from PySide6.QtWidgets import QInputDialog
from support.can_link_rig import E02, E04, make_link_rig

from prm9tool.cli.main import main
from prm9tool.device.canlink.typekeys import remembered


@pytest.fixture
def real(tmp_path):
    rig = make_link_rig("real-key", tmp_path, real_valve=True)
    yield rig
    rig.close()


def _bus(rig) -> list[str]:
    return [
        "--can-interface",
        "virtual",
        "--can-channel",
        rig.options.channel,
        "--device",
        "can:10",
    ]


def test_a_download_needs_the_key_and_takes_it_from_type_key(real, data_dir, tmp_path, capsys):
    out = tmp_path / "valve.prm"
    download = ["--batch", "--download", str(out), *_bus(real)]
    assert main(download) == 6
    assert "give the type key on its label (command line: --type-key KEY" in capsys.readouterr().err
    assert not out.exists()  # nothing half-written
    assert main([*download, "--type-key", E02]) == 6  # the valve's objects say E04
    assert "is an E02 valve, the valve's objects say E04" in capsys.readouterr().err
    assert main([*download, "--type-key", E04]) == 0
    assert out.read_text(encoding="utf-8").count(E04) >= 1
    assert remembered(data_dir, real.valve.serial) == E04  # next time without --type-key
    out.unlink()
    assert main(download) == 0 and out.exists()


@pytest.mark.parametrize(
    ("argv", "problem"),
    [
        (["--type-key", E04], "--type-key belongs to a valve on a CAN bus"),
        (["--device", "can:10", "--type-key", "PRM9-nonsense"], "--type-key: "),
        (["--device", "can:10", "--type-key", E04.removesuffix("-CA")], "is a -CA valve"),
    ],
)
def test_type_key_usage_errors(argv, problem, capsys):
    assert main(argv) == 2
    assert problem in capsys.readouterr().err


def test_the_gui_asks_for_the_key_when_going_online_with_device_can(
    qtbot, real, data_dir, tmp_path, monkeypatch
):
    from support.gui_support import settings_in

    from prm9tool.device import factory
    from prm9tool.model.access import AccessModel
    from prm9tool.model.document import ParameterDocument
    from prm9tool.model.undo import DocumentUndo
    from prm9tool.online.connection import ValveConnection
    from prm9tool.views.main_window import MainWindow

    asked: list[str] = []
    answers = [(E02, True), (E04, True)]  # a key that does not fit is asked again

    def answer(_parent, _title, label, text=""):
        asked.append(label)
        return answers.pop(0)

    monkeypatch.setattr(QInputDialog, "getText", staticmethod(answer))
    connection = ValveConnection(opener=lambda e: factory.open_session(e, can_link=real.options))
    doc = ParameterDocument(E04)
    win = MainWindow(doc, DocumentUndo(doc), AccessModel(), connection, settings_in(tmp_path))
    qtbot.addWidget(win)
    try:
        win.valve.go_online("can:10")  # as --device can:10 does
        qtbot.waitUntil(lambda: connection.is_online, timeout=10_000)
        assert connection.device.type_key == E04
        assert len(asked) == 2 and "its objects say E04 -CA" in asked[0]
        assert remembered(data_dir, real.valve.serial) == E04
    finally:
        connection.shutdown()


@pytest.fixture
def open_e02(tmp_path):
    """A real -CA E02 in spool position control: its objects leave E02/E04 open."""
    rig = make_link_rig("open-e02", tmp_path, E02, real_valve=True)
    yield rig
    rig.close()


def test_the_key_given_for_the_serial_goes_before_the_files_and_force_type_keeps_e04_out(
    open_e02, data_dir, tmp_path, capsys, caplog
):
    before = tmp_path / "before.prm"
    assert main(["--batch", "--download", str(before), *_bus(open_e02), "--type-key", E02]) == 0
    assert remembered(data_dir, open_e02.valve.serial) == E02
    e04 = tmp_path / "e04.prm"
    assert main(["--new", E04, "-o", str(e04)]) == 0
    capsys.readouterr()
    stored = open_e02.stored_set()
    report = tmp_path / "report.json"
    argv = ["--batch", str(e04), *_bus(open_e02), "--force-type", "--report", str(report)]
    assert main(argv) == 5  # another parameter set: refused even with --force-type
    assert f"{E04} taken from its label" not in caplog.text
    record = json.loads(report.read_text(encoding="utf-8"))["valves"][0]
    assert record["result"] == "type-mismatch" and record["type_key"] == E02
    assert record["parameters_written"] == 0 and open_e02.stored_set() == stored


def test_a_download_under_a_key_whose_objects_the_valve_lacks_is_refused_in_words(
    tmp_path, data_dir, capsys
):
    rig = make_link_rig("no-sensor", tmp_path, E02, real_valve=True)
    rig.missing |= {(index, 0xFF) for index in range(0x2005, 0x2009)}  # no external sensor
    out = tmp_path / "out.prm"
    try:
        argv = ["--batch", "--download", str(out), *_bus(rig), "--type-key", E04]
        assert main(argv) == 6  # "download failed: …", as for a key its objects contradict
    finally:
        rig.close()
    err = capsys.readouterr().err
    assert "Traceback" not in err and "KeyError" not in err
    assert "has no object for SENSTYPE" in err and E04 in err
    assert not out.exists()
    assert remembered(data_dir, rig.valve.serial) is None  # a key the valve contradicts


def test_an_upload_under_a_files_key_whose_objects_the_valve_lacks_writes_nothing(
    tmp_path, data_dir
):
    """Issue 34 item 5: an E04 file went into such a valve "ok", its E04 parameters skipped
    as "not available"."""
    from prm9tool.catalogue.typekey import TypeKey
    from prm9tool.device.canlink.session import CanopenSession
    from prm9tool.errors import TypeKeyError
    from prm9tool.files.prmfile import PrmContents

    rig = make_link_rig("upload-no-sensor", tmp_path, E02, real_valve=True)
    rig.missing |= {(index, 0xFF) for index in range(0x2005, 0x2009)}
    values = PrmContents.factory(TypeKey.parse(E04)).values | {"LIMTA": 1800}
    try:
        with (
            CanopenSession(rig.options, 10, type_key=E04) as session,  # the file's key
            pytest.raises(TypeKeyError, match="has no object for SENSTYPE"),
        ):
            session.upload(values)
        assert rig.working("LIMTA") != 1800 and rig.stored_set() == {}
    finally:
        rig.close()

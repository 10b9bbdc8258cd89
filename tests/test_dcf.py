"""The DCF export: the EDS with the configured values, readable by the canopen package."""

from __future__ import annotations

import io

import canopen
import pytest

from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.errors import TypeKeyError
from prm9tool.files.dcf import export_dcf

E04 = "PRM9-06.3Z11/30-24E04S02-CA"


def test_the_dcf_carries_the_configured_values_and_the_commissioning():
    values = CATALOGUE.defaults(TypeKey.parse(E04).variant)
    values.update(LIMTA=1500, HEARTBEAT=250)
    text = export_dcf(E04, values, node_id=12, bitrate_kbit=250, node_name="press 3")
    assert "[DeviceComissioning]\nNodeID=12\nNodeName=press 3\nBaudrate=250\n" in text
    source = io.StringIO(text)
    source.name = "valve.dcf"
    od = canopen.import_od(source, 12)
    assert od.node_id == 12 and od.bitrate == 250_000
    limta = CATALOGUE["LIMTA"]
    assert od[limta.index][limta.subindex].value == 1500
    assert od[limta.index][limta.subindex].default == limta.default
    assert od[0x1017].value == 250


def test_a_valve_without_canopen_has_no_dcf():
    with pytest.raises(TypeKeyError, match="an EDS exists only for -CA valves"):
        export_dcf("PRM9-06.3Z11/30-24E04S02", {}, 10, 500)


def test_file_export_dcf_writes_the_documents_valve(qtbot, tmp_path, monkeypatch):
    from PySide6.QtWidgets import QFileDialog
    from support.gui_support import E02_CA, main_window, record_prompts

    record_prompts(monkeypatch)
    target = tmp_path / "valve.dcf"
    monkeypatch.setattr(QFileDialog, "getSaveFileName", lambda *_a, **_k: (str(target), ""))
    with main_window(qtbot, tmp_path, E02_CA) as window:
        window.doc.set_values({"LIMTA": 1700}, "test")
        window.commands["export_dcf"].trigger()
        assert "DCF saved as" in window.status.currentMessage()
    text = target.read_text(encoding="ascii")
    assert "NodeID=10\n" in text and "Baudrate=500\n" in text  # delivery switches (table 7-22)
    limta = CATALOGUE["LIMTA"]
    section = text.split(f"[{limta.index:04X}sub{limta.subindex:X}]", 1)[1].split("\n\n", 1)[0]
    assert "ParameterValue=1700" in section


def test_file_export_eds_writes_the_documents_type_offline(qtbot, tmp_path, monkeypatch):
    # the window's EDS is the valve service's write_eds, as --export-eds writes it (issue 28)
    from PySide6.QtWidgets import QFileDialog
    from support.gui_support import E02_CA, main_window, record_prompts

    from prm9tool.service.export import eds_text

    record_prompts(monkeypatch)
    target = tmp_path / "valve.eds"
    monkeypatch.setattr(QFileDialog, "getSaveFileName", lambda *_a, **_k: (str(target), ""))
    with main_window(qtbot, tmp_path, E02_CA) as window:
        action = window.commands["export_eds"]
        assert action.isEnabled() and not window.connection.is_online
        assert action in window.commands.menus["file"].actions()
        action.trigger()
        assert window.status.currentMessage() == f"EDS saved as {target}"
    text = target.read_bytes().decode("ascii")
    expected = eds_text(E02_CA)
    same = lambda t: [x for x in t.split("\r\n") if not x.startswith("Creation")]  # noqa: E731
    assert same(text) == same(expected) and "[DeviceInfo]" in text


def test_file_export_eds_to_an_unwritable_path_says_so_and_writes_nothing(
    qtbot, tmp_path, monkeypatch
):
    from PySide6.QtWidgets import QFileDialog
    from support.gui_support import E02_CA, main_window, record_prompts

    asked = record_prompts(monkeypatch)
    folder = tmp_path / "no such folder"
    target = folder / "valve.eds"
    monkeypatch.setattr(QFileDialog, "getSaveFileName", lambda *_a, **_k: (str(target), ""))
    with main_window(qtbot, tmp_path, E02_CA) as window:
        window.commands["export_eds"].trigger()
        assert "EDS saved" not in window.status.currentMessage()
    assert not folder.exists() and not list(tmp_path.glob("*.eds*"))
    assert any(f"Export EDS: Cannot write “{target}”" in text for text in asked.asked), asked


def test_file_export_eds_is_off_for_a_valve_without_canopen(qtbot, tmp_path):
    from support.gui_support import E02, main_window

    with main_window(qtbot, tmp_path, E02) as window:
        assert not window.commands["export_eds"].isEnabled()

"""Emulator non-volatile memory: store, restart, factory restore and the image file."""

from __future__ import annotations

import json
import re

import pytest

from prm9tool.catalogue import CATALOGUE
from prm9tool.device.emulator import EmulatedValve, nvimage
from prm9tool.errors import FileFormatError, Prm9Error

E02_CA = "PRM9-06.3Z11/30-24E02S02-CA"
E04 = "PRM9-06.3Z11/30-24E04S02-CA"
RAMP_UP = (0x6332, 1)
RAMP_DOWN = (0x6335, 1)


def test_changes_not_stored_are_lost_on_restart():
    valve = EmulatedValve(E02_CA)
    valve.write(*RAMP_UP, 500)
    valve.store()
    valve.write(*RAMP_DOWN, 700)
    assert valve.read(*RAMP_DOWN) == 700
    valve.restart()
    assert valve.read(*RAMP_UP) == 500
    assert valve.read(*RAMP_DOWN) == 0


def test_store_through_object_1010_with_the_save_signature():
    valve = EmulatedValve(E02_CA)
    valve.write(*RAMP_UP, 321)
    valve.write(0x1010, 1, 0x65766173)  # "save"
    valve.restart()
    assert valve.read(*RAMP_UP) == 321


def test_restore_factory_is_effective_after_restart_only():
    valve = EmulatedValve(E02_CA)
    valve.write(*RAMP_UP, 500)
    valve.store()
    valve.restore_factory()
    assert valve.read(*RAMP_UP) == 500
    valve.restart()
    assert valve.read(*RAMP_UP) == 0


def test_image_file_survives_across_instances(tmp_path):
    path = tmp_path / "valve.eeprom"
    first = EmulatedValve(E02_CA, serial=7, nv_path=path)
    first.write(*RAMP_UP, 1234)
    first.write(0x1017, 0, 250)  # heartbeat: a communication object, kept too
    assert not path.exists()  # nothing stored yet
    first.store()
    first.write(*RAMP_DOWN, 999)  # not stored
    second = EmulatedValve(E02_CA, serial=7, nv_path=path)
    assert second.read(*RAMP_UP) == 1234
    assert second.read(0x1017, 0) == 250
    assert second.read(*RAMP_DOWN) == 0
    data = json.loads(path.read_text(encoding="utf-8"))
    assert data["type_key"] == E02_CA
    assert data["values"]["RAMPSETPOSUP"] == 1234
    assert [p.name for p in tmp_path.iterdir()] == ["valve.eeprom"]  # no temporary left


def test_restore_factory_rewrites_the_file(tmp_path):
    path = tmp_path / "valve.eeprom"
    valve = EmulatedValve(E02_CA, nv_path=path)
    valve.write(*RAMP_UP, 1234)
    valve.store()
    valve.restore_factory()
    assert EmulatedValve(E02_CA, nv_path=path).read(*RAMP_UP) == 0


def test_image_of_another_valve_type_is_refused(tmp_path):
    path = tmp_path / "valve.eeprom"
    EmulatedValve(E02_CA, nv_path=path).store()
    with pytest.raises(FileFormatError, match=re.escape("belongs to a " + E02_CA + " valve")):
        EmulatedValve("PRM9-06.3Z11/30-24E04S02-CA", nv_path=path)


def test_corrupt_image_is_reported(tmp_path):
    path = tmp_path / "valve.eeprom"
    path.write_text("{not json", encoding="utf-8")
    with pytest.raises(FileFormatError, match="unreadable EEPROM image"):
        EmulatedValve(E02_CA, nv_path=path)


def test_live_and_service_values_are_not_stored():
    valve = EmulatedValve(E02_CA)
    valve.write(0x6300, 1, 5000)  # setpoint: process data, not a parameter
    valve.write(0x2050, 2, 3000)
    valve.write(0x2050, 1, 1)  # setpoint override on
    valve.store()
    valve.restart()
    assert valve.read(0x6300, 1) == 0
    assert valve.read(0x2050, 1) == 0
    assert valve.read(0x2050, 2) == 0


def test_switches_are_read_at_power_up_only():
    valve = EmulatedValve(E02_CA)
    assert valve.node_id == 10
    assert valve.bitrate == 500_000
    valve.set_input("switch_node", 5)
    valve.set_input("switch_baud", 8)
    assert valve.node_id == 10
    assert valve.read(0x2031, 2) == 2
    valve.restart()
    assert valve.node_id == 25
    assert valve.bitrate == 1_000_000
    assert valve.read(0x2031, 1) == 8


def test_default_cob_ids_follow_the_node_id_unless_stored():
    valve = EmulatedValve(E02_CA)
    assert valve.read(0x1800, 1) == 0x180 + 10
    valve.store()
    valve.set_input("switch_node", 3)
    valve.restart()
    assert valve.read(0x1800, 1) == 0x180 + 15
    valve.write(0x1800, 1, 0x1A5)
    valve.store()
    valve.set_input("switch_node", 4)
    valve.restart()
    assert valve.read(0x1800, 1) == 0x1A5


def test_node_switch_zero_uses_the_stored_node_id():
    valve = EmulatedValve(E02_CA, switches=(6, 0))
    valve.write(0x2030, 1, 42)
    valve.store()
    valve.restart()
    assert valve.node_id == 42
    assert valve.read(0x1400, 1) == 0x40000200 + 42


def test_interface_switch_zero_switches_canopen_off():
    valve = EmulatedValve(E02_CA, switches=(0, 2))
    assert not valve.can_enabled
    assert valve.bitrate == 0
    assert valve.status().nmt_state == "off"


def test_restart_listener_runs_after_every_power_cycle():
    valve = EmulatedValve(E02_CA)
    calls: list[float] = []
    valve.add_restart_listener(lambda: calls.append(valve.time))
    valve.advance(0.5)
    valve.restart()
    assert calls == [0.0]


def test_a_failed_image_write_leaves_memory_and_file_on_the_old_set(tmp_path, monkeypatch):
    path = tmp_path / "nv.json"
    valve = EmulatedValve(E04, 5, nv_path=path)
    valve.write(*CATALOGUE["LIMTA"].key, 1500)
    valve.store()
    valve.write(*CATALOGUE["LIMTA"].key, 1700)

    def disk_full(*args, **kwargs):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(nvimage.os, "fsync", disk_full)
    with pytest.raises(Prm9Error):
        valve.store()
    monkeypatch.undo()
    valve.restart()  # a restart in the process …
    in_process = valve.read(*CATALOGUE["LIMTA"].key)
    later = EmulatedValve(E04, 5, nv_path=path)  # … and a restart of the process agree
    assert in_process == later.read(*CATALOGUE["LIMTA"].key) == 1500
    assert not list(tmp_path.glob("*.tmp"))


def test_the_refused_image_is_explained_in_the_program_language(qapp, tmp_path):
    from prm9tool import i18n
    from prm9tool.translate import error_text

    path = tmp_path / "valve.eeprom"
    EmulatedValve(E02_CA, nv_path=path).store()
    with pytest.raises(FileFormatError) as refused:
        EmulatedValve(E04, nv_path=path)
    try:
        i18n.set_language("de")
        assert f"das Abbild gehört zu einem Ventil {E02_CA}, nicht zu {E04}" in error_text(
            refused.value
        )
        i18n.set_language("cs")
        assert f"obraz patří ventilu {E02_CA}, ne {E04}" in error_text(refused.value)
    finally:
        i18n.set_language("en")
    assert f"belongs to a {E02_CA} valve, not to {E04}" in error_text(refused.value)


def test_the_valve_list_says_in_german_why_a_remembered_emulated_valve_cannot_be_used(
    qtbot, tmp_path, monkeypatch
):
    from PySide6.QtCore import QSettings

    from prm9tool import i18n
    from prm9tool.device import emulated_valves, factory
    from prm9tool.views.hid_dialog import HidConfigurationDialog

    monkeypatch.setenv("PRM9TOOL_DATA_DIR", str(tmp_path))
    emulated_valves.forget_emulated_valves()
    EmulatedValve(E02_CA, nv_path=emulated_valves.emulator_nv_path(7007)).store()
    _usable, unusable = factory.usable_emulators([f"{E04}:7007"])
    settings = QSettings(str(tmp_path / "s.ini"), QSettings.Format.IniFormat)
    try:
        i18n.set_language("de")
        dialog = HidConfigurationDialog(lambda _specs, deliver: deliver(unusable), settings)
        qtbot.addWidget(dialog)
        dialog.refresh()
        text = dialog.table.item(0, 4).text()
    finally:
        i18n.set_language("en")
        emulated_valves.forget_emulated_valves()
    assert f"das Abbild gehört zu einem Ventil {E02_CA}, nicht zu {E04}" in text

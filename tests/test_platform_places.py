"""Windows (and macOS) as a user meets them: data and settings folders, CAN adapters, HID paths.

Runs on Linux with the platform faked (``sys.platform``) and in the Windows stage under Wine
(tools/windows/ci.sh), where the last test checks the real settings file.
"""

from __future__ import annotations

import sys
from pathlib import Path

import pytest
from PySide6.QtCore import QSettings

from prm9tool import paths
from prm9tool.catalogue.can_adapters import adapters, default_adapter
from prm9tool.device.usb.transport.hidapi import shown_path

WINDOWS_PATH = (
    rb"\\?\HID#VID_0483&PID_5750&MI_00#7&2a0b0f6b&0&0000#{4d1e55b2-f16f-11cf-88cb-001111000030}"
)


@pytest.fixture
def home(tmp_path, monkeypatch):
    """A home folder of its own, without prm9tool's override of the data folder."""
    monkeypatch.setenv("HOME", str(tmp_path))
    monkeypatch.setenv("USERPROFILE", str(tmp_path))  # "~" on Windows (the Windows stage)
    monkeypatch.setattr(Path, "home", classmethod(lambda cls: tmp_path))
    monkeypatch.delenv("PRM9TOOL_DATA_DIR", raising=False)
    monkeypatch.delenv("XDG_DATA_HOME", raising=False)
    monkeypatch.delenv("XDG_CONFIG_HOME", raising=False)
    return tmp_path


@pytest.mark.skipif(sys.platform == "win32", reason="Linux's folders, read by platformdirs' Unix")
def test_linux_keeps_its_folders(home, monkeypatch):
    monkeypatch.setattr(sys, "platform", "linux")
    assert paths.user_data_dir() == home / ".local" / "share" / "prm9tool"
    assert paths.settings_dir() == home / ".config" / "prm9tool"  # where QSettings wrote before
    monkeypatch.setenv("XDG_DATA_HOME", str(home / "xdg"))
    assert paths.user_data_dir() == home / "xdg" / "prm9tool"


def test_windows_keeps_data_local_and_settings_roaming(home, monkeypatch):
    from prm9tool.app import settings_folder

    monkeypatch.setattr(sys, "platform", "win32")
    monkeypatch.setenv("WIN_PD_OVERRIDE_LOCAL_APPDATA", "C:\\Users\\Jana\\AppData\\Local")
    monkeypatch.setenv("WIN_PD_OVERRIDE_APPDATA", "C:\\Users\\Jana\\AppData\\Roaming")
    assert str(paths.user_data_dir()).replace("/", "\\") == (
        "C:\\Users\\Jana\\AppData\\Local\\prm9tool"
    )
    assert str(settings_folder()).replace("/", "\\") == "C:\\Users\\Jana\\AppData\\Roaming"
    monkeypatch.setattr(sys, "platform", "linux")
    assert settings_folder() is None  # Qt's native place: $XDG_CONFIG_HOME/prm9tool


def test_macos_moves_the_data_of_an_earlier_version_over_once(home, monkeypatch):
    monkeypatch.setattr(sys, "platform", "darwin")
    old = home / ".local" / "share" / "prm9tool"
    (old / "backups").mkdir(parents=True)
    (old / "backups" / "valve.prm").write_text("kept")
    new = home / "Library" / "Application Support" / "prm9tool"
    assert paths.user_data_dir() == new
    assert (new / "backups" / "valve.prm").read_text() == "kept"
    assert not old.exists()
    assert paths.user_data_dir() == new  # the second time: nothing to move


def test_macos_reads_the_old_folder_where_it_cannot_be_moved(home, monkeypatch):
    monkeypatch.setattr(sys, "platform", "darwin")
    old = home / ".local" / "share" / "prm9tool"
    old.mkdir(parents=True)

    def refuse(self, target):
        raise OSError("Invalid cross-device link")

    monkeypatch.setattr(Path, "rename", refuse)
    assert paths.user_data_dir() == old


def test_a_new_macos_user_gets_application_support(home, monkeypatch):
    monkeypatch.setattr(sys, "platform", "darwin")
    assert paths.user_data_dir() == home / "Library" / "Application Support" / "prm9tool"


def test_windows_offers_the_adapters_of_windows():
    names = [adapter.interface for adapter in adapters("win32")]
    assert "socketcan" not in names
    assert {"pcan", "kvaser", "vector", "ixxat", "slcan"} <= set(names)
    assert (default_adapter("win32").interface, default_adapter("win32").channel) == (
        "pcan",
        "PCAN_USBBUS1",
    )
    assert {a.interface: a.channel for a in adapters("win32")}["slcan"].startswith("COM")
    assert (default_adapter("linux").interface, default_adapter("linux").channel) == (
        "socketcan",
        "can0",
    )


def test_the_help_names_windows_adapters_on_windows(monkeypatch):
    from prm9tool.cli.parser import build_parser

    monkeypatch.setattr(sys, "platform", "win32")
    text = " ".join(build_parser().format_help().split())
    assert "pcan PCAN_USBBUS1" in text
    assert "slcan COM3" in text
    assert "socketcan" not in text


def test_the_can_bus_dialog_offers_windows_adapters_on_windows(qtbot, tmp_path, monkeypatch):
    from prm9tool.views.canbus.bus_dialog import CanBusDialog

    monkeypatch.setattr(sys, "platform", "win32")
    settings = QSettings(str(tmp_path / "settings.ini"), QSettings.Format.IniFormat)
    dialog = CanBusDialog(lambda _bus, _deliver: None, settings)
    qtbot.addWidget(dialog)
    offered = [dialog.interface.itemText(i) for i in range(dialog.interface.count())]
    assert offered[0] == "pcan" and "socketcan" not in offered
    assert (dialog.bus()["interface"], dialog.bus()["channel"]) == ("pcan", "PCAN_USBBUS1")
    dialog.interface.setCurrentText("slcan")  # the usual channel follows the adapter
    assert dialog.bus()["channel"] == "COM3"
    dialog.channel.setText("COM7")  # one the user typed stays
    dialog.interface.setCurrentText("pcan")
    assert dialog.bus()["channel"] == "COM7"


def test_hid_paths_are_shown_as_windows_shows_them():
    assert shown_path(WINDOWS_PATH, "win32") == "HID\\VID_0483&PID_5750&MI_00\\7&2A0B0F6B&0&0000"
    assert shown_path(b"/dev/hidraw3", "linux") == "/dev/hidraw3"
    assert shown_path(b"DevSrvsID:4294968125", "darwin") == "DevSrvsID:4294968125"


@pytest.mark.skipif(sys.platform != "win32", reason="the real settings file on Windows")
def test_windows_settings_go_to_an_ini_file_in_appdata(qapp, tmp_path, monkeypatch):
    from prm9tool.app import create_application

    monkeypatch.setenv("WIN_PD_OVERRIDE_APPDATA", str(tmp_path))
    create_application()
    try:
        assert Path(QSettings().fileName()) == tmp_path / "prm9tool" / "prm9tool.ini"
    finally:
        QSettings.setDefaultFormat(QSettings.Format.NativeFormat)


def test_the_slcan_adapter_offered_on_windows_can_be_opened():
    import can

    assert "slcan" in {adapter.interface for adapter in adapters("win32")}
    bus = can.Bus(interface="slcan", channel="loop://", bitrate=500_000)  # pyserial's loopback
    bus.shutdown()

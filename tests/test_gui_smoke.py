"""Offscreen smoke test: the whole program on emulated E02 and E04-CA valves, with screenshots.

The screenshots go to ``$PRM9TOOL_SCREENSHOTS`` when set (the README's tour is made with
``PRM9TOOL_SCREENSHOTS=docs/screenshots pytest tests/test_gui_smoke.py``), else to a
temporary folder. Every picture is checked to show something (not one flat colour).
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from gui_support import record_prompts
from PySide6.QtCore import QSettings
from PySide6.QtGui import QImage
from PySide6.QtWidgets import QWidget

from prm9tool import app, i18n
from prm9tool.catalogue import Access
from prm9tool.cli import build_parser
from prm9tool.device import factory
from prm9tool.views import prompts
from prm9tool.views.access_dialog import ChangePasswordDialog, PasswordDialog
from prm9tool.views.hid_dialog import EmulatorDialog, HidConfigurationDialog
from prm9tool.views.online_dialogs import OnlineDiffDialog, RestartDialog
from prm9tool.views.valve_selection import ValveSelectionDialog

TIMEOUT = 15_000
# Pictures for the README wait for live values to fill in; a plain test run does not need to.
FOR_PICTURES = bool(os.environ.get("PRM9TOOL_SCREENSHOTS"))
SETTLE_MS = 2000 if FOR_PICTURES else 200
E02 = "PRM9-06.3Z11/30-24E02S02"
E04_CA = "PRM9-10.3Z11/60-24E04S02-CA"


@pytest.fixture
def shots(tmp_path) -> Path:
    folder = Path(os.environ.get("PRM9TOOL_SCREENSHOTS") or tmp_path / "screenshots")
    folder.mkdir(parents=True, exist_ok=True)
    return folder


@pytest.fixture
def program(qtbot, tmp_path, monkeypatch):
    """Start prm9tool as ``prm9tool --emulator KEY`` would, on settings of its own."""
    record_prompts(monkeypatch)
    QSettings.setPath(QSettings.Format.NativeFormat, QSettings.Scope.UserScope, str(tmp_path))
    started = []

    def start(args):
        qapp = app.create_application()
        window = app.create_window(build_parser().parse_args(args))
        window.resize(1280, 800)
        qtbot.addWidget(window)
        window.show()
        app.start(window, app.plan_from(build_parser().parse_args(args)))
        started.append(window)
        return qapp, window

    yield start
    for window in started:
        window.connection.shutdown()
    factory.forget_emulated_valves()
    i18n.set_language("en")


def _save(widget: QWidget, folder: Path, name: str) -> Path:
    path = folder / f"window_{name}.png"
    image = widget.grab().toImage()
    assert image.save(str(path)), path
    _assert_shows_something(path)
    return path


def _assert_shows_something(path: Path) -> None:
    image = QImage(str(path))
    assert image.width() > 100 and image.height() > 80
    colours = {
        image.pixel(x, y) for x in range(0, image.width(), 7) for y in range(0, image.height(), 7)
    }
    assert len(colours) > 8, f"{path.name} is nearly blank"


def _online(qtbot, window):
    qtbot.waitUntil(lambda: window.sync.active, timeout=TIMEOUT)
    qtbot.waitUntil(lambda: window.status.status_label.text() != "Status: —", timeout=TIMEOUT)


def test_e02_valve_window_table_and_dialogs(qtbot, program, shots):
    _qapp, window = program(["--emulator", f"{E02}:3001"])
    _online(qtbot, window)
    assert window.status.mode_label.text() == "Mode: ONLINE"
    assert str(window.doc.type_key) == E02
    qtbot.wait(SETTLE_MS)  # let the measuring points of the diagram fill in
    _save(window, shots, "main_window_e02")
    window.show_view("parameters")
    window.doc.set_value("DTAMP", 2458 + 819)  # one changed value shows the highlighting
    window.parameter_view.select("DTAMP")
    _save(window, shots, "parameter_list_e02")
    edit = window.parameter_view.make_edit_dialog("DYNFREQ")
    edit.show()
    edit.set_text("70000")
    edit._buttons.accepted.emit()
    assert "outside the allowed range" in edit.error_label.text()
    _save(edit, shots, "dialog_parameter_refused")
    edit.close()
    for name, dialog in (
        ("dialog_valve_selection", ValveSelectionDialog(window.doc.type_key, window)),
        ("dialog_hid_configuration",
         HidConfigurationDialog(window.connection.list_devices, window.settings, window)),
        ("dialog_password", PasswordDialog(window.passwords, window)),
        ("dialog_change_password", ChangePasswordDialog(window.passwords, window)),
        ("dialog_add_emulated_valve", EmulatorDialog(window)),
        ("dialog_restart", RestartDialog(window)),
        ("dialog_online_differences", OnlineDiffDialog(
            {**window.doc.values, "LIMTA": 2000, "DTAMP": 3277, "RAMPSETPOSUP": 150},
            dict(window.doc.values), E02, E02, window)),
    ):  # fmt: skip
        dialog.show()
        _save(dialog, shots, name)
        dialog.close()
    about = prompts.make_box(window, prompts.Icon.Information, "About prm9tool", "")
    window.show_about = lambda: None
    about.setText(__import__("prm9tool.views.help_dialog", fromlist=["x"]).about_html(
        "prm9tool", "Parameterization of PRM9 proportional directional valves.", ""))  # fmt: skip
    about.show()
    _save(about, shots, "dialog_about")
    about.close()
    help_window = window.show_help()
    _save(help_window, shots, "dialog_help")


def test_e04_ca_valve_expert_status_canopen_scope_and_languages(qtbot, program, shots):
    _qapp, window = program(["--emulator", f"{E04_CA}:3002"])
    _online(qtbot, window)
    assert str(window.doc.type_key) == E04_CA
    window.access.set_level(Access.EXPERT)
    qtbot.wait(SETTLE_MS)
    _save(window, shots, "main_window_e04_ca_expert")
    window.show_view("parameters")
    _save(window, shots, "parameter_list_e04_ca_expert")
    status = window.show_status_window()
    qtbot.waitUntil(lambda: status.fields["state"].text() not in ("", "—"), timeout=TIMEOUT)
    _save(status, shots, "dialog_valve_status")
    status.close()
    canopen = window.show_canopen_window()
    qtbot.wait(300)
    _save(canopen, shots, "dialog_canopen")
    canopen.close()
    window.open_scope("position_actual")
    assert window.current_view() == "scope"
    scope = window.views["scope"]
    scope.preselect("demand")
    scope.start()
    qtbot.wait(SETTLE_MS)
    _save(window, shots, "oscilloscope_e04_ca")
    scope.stop()
    window.show_view("diagram")
    window.set_language("de")
    qtbot.wait(100)  # layouts follow the longer texts at the next turn of the event loop
    _save(window, shots, "main_window_german")
    window.set_language("cs")
    window.show_view("parameters")
    qtbot.wait(100)
    _save(window, shots, "parameter_list_czech")
    window.set_language("en")
    record = window.records.record()
    record.setTextWidth(900)
    image = QImage(940, int(record.size().height()) + 40, QImage.Format.Format_ARGB32)
    image.fill(0xFFFFFFFF)
    from PySide6.QtGui import QPainter

    painter = QPainter(image)
    record.drawContents(painter)
    painter.end()
    assert image.save(str(shots / "window_record.png"))
    _assert_shows_something(shots / "window_record.png")

"""Offscreen smoke test: the whole program on emulated E02 and E04-CA valves, with screenshots.

The screenshots go to ``$PRM9TOOL_SCREENSHOTS`` when set (the README's tour is made with
``PRM9TOOL_SCREENSHOTS=docs/screenshots pytest tests/test_gui_smoke.py``), else to a
temporary folder. Each picture is taken once the state it shows has arrived (live values,
the changed-file mark, a recorded time window) and no one-line label is cut short by a layout
that has not caught up; it is checked to show something (not one flat colour).
"""

from __future__ import annotations

import os
import shutil
import subprocess
import threading
import time
from pathlib import Path

import pytest
from PySide6.QtCore import QRect, QSettings, Qt
from PySide6.QtGui import QImage
from PySide6.QtWidgets import QLabel, QMessageBox, QWidget
from support.gui_support import record_prompts, session_of

from prm9tool import app, i18n
from prm9tool.app import start_plan
from prm9tool.catalogue import Access
from prm9tool.cli.main import build_parser
from prm9tool.device import emulated_valves
from prm9tool.online.connection_worker import PROGRESS_PERIOD_S
from prm9tool.scope.generator import GeneratorSettings, Waveform
from prm9tool.views import prompts
from prm9tool.views.access_dialog import ChangePasswordDialog, PasswordDialog
from prm9tool.views.hid_dialog import EmulatorDialog, HidConfigurationDialog
from prm9tool.views.online_dialogs import OnlineDiffDialog, RestartDialog
from prm9tool.views.parameters.dialog import ParameterEditDialog
from prm9tool.views.parameters.model import Column
from prm9tool.views.valve.selection import ValveSelectionDialog

TIMEOUT = 15_000
E02 = "PRM9-06.3Z11/30-24E02S02"
E04_CA = "PRM9-10.3Z11/60-24E04S02-CA"
REAL_ASK = prompts.ask  # the fixture replaces it; the About and unsaved-changes shots need it


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
        start_plan.start(window, start_plan.plan_from(build_parser().parse_args(args)))
        started.append(window)
        return qapp, window

    yield start
    for window in started:
        window.connection.shutdown()
    emulated_valves.forget_emulated_valves()
    i18n.set_language("en")


def _save(qtbot, widget: QWidget, folder: Path, name: str) -> Path:
    """Grab ``widget`` once its layout has caught up with its texts (no label cut short)."""
    qtbot.waitUntil(lambda: _cut_labels(widget) == [], timeout=TIMEOUT)
    path = folder / f"window_{name}.png"
    image = widget.grab().toImage()
    assert image.save(str(path)), path
    _assert_shows_something(path)
    return path


def _cut_labels(widget: QWidget) -> list[str]:
    """Texts of the visible plain-text labels of ``widget`` that do not fit their label."""
    cut = []
    for label in [widget, *widget.findChildren(QLabel)]:
        if not isinstance(label, QLabel) or not label.isVisibleTo(widget):
            continue
        text = label.text()
        if not text or label.textFormat() == Qt.TextFormat.RichText or "<" in text:
            continue
        room = label.contentsRect().adjusted(label.margin(), label.margin(), -label.margin(),
                                             -label.margin())  # fmt: skip
        wrap = label.wordWrap()
        needed = label.fontMetrics().boundingRect(
            QRect(0, 0, room.width() if wrap else 100_000, 100_000),
            int(Qt.TextFlag.TextWordWrap) if wrap else 0,
            text,
        )
        slack = label.fontMetrics().height() // 3  # a row squeezed by a pixel or two is legible
        if needed.width() > room.width() or needed.height() > room.height() + slack:
            cut.append(text)
    return cut


def _assert_shows_something(path: Path) -> None:
    image = QImage(str(path))
    assert image.width() > 100 and image.height() > 80
    colours = {
        image.pixel(x, y) for x in range(0, image.width(), 7) for y in range(0, image.height(), 7)
    }
    assert len(colours) > 8, f"{path.name} is nearly blank"


def _online(qtbot, window, state="DEVICE_MODE_ACTIVE"):
    """Online, compared, and the valve's device state machine has reached ``state``."""
    last = {}
    window.connection.status_changed.connect(lambda status: last.update(status=status))
    qtbot.waitUntil(lambda: window.sync.active, timeout=TIMEOUT)
    qtbot.waitUntil(lambda: window.status.status_label.text() != "Status: —", timeout=TIMEOUT)
    reached = lambda: str(getattr(last.get("status"), "device_state", "")) == state  # noqa: E731
    qtbot.waitUntil(reached, timeout=TIMEOUT)


def _diagram_live(qtbot, window):
    """Every measuring point of the diagram shows a value, the supply a real one."""
    dots = window.views["diagram"].diagram.dots

    def live():
        texts = [dot.value_text for dot in dots.values()]
        supply = dots["supply_voltage"].value_text
        return all(texts) and supply.endswith(" V") and not supply.startswith("0.00")

    qtbot.waitUntil(live, timeout=TIMEOUT)


def _table_value(window, mnemonic):
    model = window.parameter_view.model
    return model.data(model.index(model.row_of(mnemonic), Column.VALUE))


def _grab_modal(qtbot, monkeypatch, folder, name, answer):
    """The next modal message box is saved as a picture and answered with ``answer``."""
    grabbed = []

    def exec_(box):
        box.show()
        grabbed.append(_save(qtbot, box, folder, name))
        box.close()
        return answer

    monkeypatch.setattr(prompts, "ask", REAL_ASK)
    monkeypatch.setattr(QMessageBox, "exec", exec_)
    return grabbed


def test_e02_valve_window_table_and_dialogs(qtbot, program, shots, monkeypatch):
    _qapp, window = program(["--emulator", f"{E02}:3001"])
    _online(qtbot, window)
    assert window.status.mode_label.text() == "Mode: ONLINE"
    assert str(window.doc.type_key) == E02
    _diagram_live(qtbot, window)
    _save(qtbot, window, shots, "main_window_e02")
    window.show_view("parameters")
    window.doc.set_value("DTAMP", 2458 + 819)  # one changed value shows the highlighting
    qtbot.waitUntil(lambda: window.status.file_label.text() == "untitled *", timeout=TIMEOUT)
    qtbot.waitUntil(lambda: _table_value(window, "PWR") == "24.00", timeout=TIMEOUT)
    assert _table_value(window, "DTAMP") == "20"
    _save(qtbot, window, shots, "parameter_list_e02")
    _parameter_dialogs(qtbot, window, shots)
    _upload_progress(qtbot, window, shots, monkeypatch)
    for name, dialog in (
        ("dialog_valve_selection", ValveSelectionDialog(window.doc.type_key, window)),
        ("dialog_hid_configuration",
         HidConfigurationDialog(window.connection.list_devices_async, window.settings, window)),
        ("dialog_password", PasswordDialog(window.passwords, window)),
        ("dialog_change_password", ChangePasswordDialog(window.passwords, window)),
        ("dialog_add_emulated_valve", EmulatorDialog(window)),
        ("dialog_restart", RestartDialog(window)),
        ("dialog_restore_factory", RestartDialog(window, factory=True)),
        ("dialog_online_differences", OnlineDiffDialog(
            {**window.doc.values, "LIMTA": 2000, "DTAMP": 3277, "RAMPSETPOSUP": 150},
            dict(window.doc.values), E02, E02, window)),
    ):  # fmt: skip
        dialog.show()
        qtbot.waitUntil(lambda d=dialog: not getattr(d, "listing", False), timeout=TIMEOUT)
        _save(qtbot, dialog, shots, name)
        dialog.close()
    about = _grab_modal(qtbot, monkeypatch, shots, "dialog_about", QMessageBox.StandardButton.Ok)
    window.commands["about"].trigger()  # the real Help → About box
    assert len(about) == 1
    help_window = window.show_help()
    _save(qtbot, help_window, shots, "dialog_help")
    prompt = _grab_modal(
        qtbot, monkeypatch, shots, "dialog_unsaved_changes", QMessageBox.StandardButton.Cancel
    )
    assert not window.close()  # File → Exit with the changed DTAMP asks; Cancel keeps it open
    assert len(prompt) == 1 and window.isVisible()


def _parameter_dialogs(qtbot, window, shots):
    """A double-click in the table opens the edit dialog; a value out of range is refused."""
    view = window.parameter_view
    view.edit_parameter("DYNFREQ")
    edit = view.findChild(ParameterEditDialog)
    qtbot.waitUntil(edit.isVisible, timeout=TIMEOUT)
    edit.set_text("120")
    _save(qtbot, edit, shots, "dialog_parameter_edit")
    edit.set_text("70000")
    edit._buttons.accepted.emit()
    assert "outside the allowed range" in edit.error_label.text()
    _save(qtbot, edit, shots, "dialog_parameter_refused")
    edit.close()


def _upload_progress(qtbot, window, shots, monkeypatch):
    """Valve → Upload to valve: the progress dialog while the values are written."""
    session = session_of(window)
    real_upload, halfway = session.upload, threading.Event()
    release = threading.Event()

    def slow_upload(values, progress=None, cancel=None):
        def report(done, total, step):
            if progress is not None:
                progress(done, total, step)
            if 2 * done >= total > 0 and not halfway.is_set():
                time.sleep(PROGRESS_PERIOD_S * 1.5)  # the connection passes on a report
                if progress is not None:  # at most every PROGRESS_PERIOD_S: this one goes
                    progress(done, total, step)
                halfway.set()
                release.wait(TIMEOUT / 1000)  # the picture is taken meanwhile

        return real_upload(values, report, cancel)

    monkeypatch.setattr(session, "upload", slow_upload)
    with qtbot.waitSignal(window.connection.operation_finished, timeout=TIMEOUT) as done:
        window.commands["upload"].trigger()
        qtbot.waitUntil(halfway.is_set, timeout=TIMEOUT)
        dialog = window.valve.progress_dialog

        def writing():
            step = dialog.labelText().split("\n")[-1]
            return (
                dialog.isVisible() and 0 < dialog.value() < dialog.maximum() and step != "download"
            )

        qtbot.waitUntil(writing, timeout=TIMEOUT)
        _save(qtbot, dialog, shots, "dialog_upload_progress")
        release.set()
    assert done.args[0] == "upload" and done.args[1].stored


def test_e04_ca_valve_expert_status_canopen_scope_and_languages(qtbot, program, shots):
    _qapp, window = program(["--emulator", f"{E04_CA}:3002"])
    _online(qtbot, window, "INIT")  # a -CA valve waits for its CANopen master (NMT start)
    assert str(window.doc.type_key) == E04_CA
    window.access.set_level(Access.EXPERT)
    _diagram_live(qtbot, window)
    _save(qtbot, window, shots, "main_window_e04_ca_expert")
    window.show_view("parameters")
    qtbot.waitUntil(lambda: _table_value(window, "PWR") == "24.00", timeout=TIMEOUT)
    _save(qtbot, window, shots, "parameter_list_e04_ca_expert")
    status = window.show_status_window()
    leds = status._led_states
    qtbot.waitUntil(lambda: all(led.text() not in ("", "—") for led in leds), timeout=TIMEOUT)
    commissioning = status.commissioning
    assert commissioning is not None
    qtbot.waitUntil(lambda: "CANopen master" in commissioning.reason.text(), timeout=TIMEOUT)
    assert "waiting for a CANopen master" in window.status.status_label.text()
    _save(qtbot, status, shots, "dialog_valve_status")
    # What a new user does (issue 14): NMT start and Enable (08h → 09h → 0Bh → 0Fh), so that
    # the setpoint generator's square wave moves the process loop for the picture.
    commissioning.buttons["nmt_start"].click()
    commissioning.buttons["enable"].click()
    qtbot.waitUntil(lambda: "follows its setpoint" in commissioning.reason.text(), timeout=TIMEOUT)
    status.close()
    emulated_dialog = window.emulated_menu.show_dialog()
    qtbot.waitUntil(emulated_dialog.isEnabled, timeout=TIMEOUT)
    _save(qtbot, emulated_dialog, shots, "dialog_emulated_valve")
    emulated_dialog.close()
    canopen = window.show_canopen_window()
    qtbot.waitUntil(lambda: _shows(canopen, "read from the valve"), timeout=TIMEOUT)
    _save(qtbot, canopen, shots, "dialog_canopen")
    canopen.close()
    window.open_scope("position_actual")
    assert window.current_view() == "scope"
    scope = window.views["scope"]
    scope.preselect("demand")
    scope.preselect("process_actual")
    scope.start()
    panel = scope.generator_panel  # as the user would set it up (the confirmation is skipped)
    panel.waveform.setCurrentIndex(panel.waveform.findData(Waveform.SQUARE))
    panel.amplitude.setValue(40.0)
    panel.offset.setValue(-20.0)
    panel.period.setValue(0.8)
    assert panel.settings() == GeneratorSettings(Waveform.SQUARE, 40.0, -20.0, 0.8)
    scope.generator.start(panel.settings())
    qtbot.waitUntil(lambda: _recorded_s(scope) >= 2.4, timeout=TIMEOUT)  # a full time window
    _save(qtbot, window, shots, "oscilloscope_e04_ca")
    scope.generator.stop()
    scope.stop()
    window.show_view("diagram")
    window.set_language("de")
    assert window.status.currentMessage() == ""  # an English message would stay otherwise
    _save(qtbot, window, shots, "main_window_german")
    window.set_language("cs")
    window.show_view("parameters")
    _save(qtbot, window, shots, "parameter_list_czech")
    window.set_language("en")
    _save_record_page(window, shots)


def _save_record_page(window, shots: Path) -> None:
    """The record's first page as the PDF has it (rendered by poppler's pdftoppm, if there):
    the picture once drew the record itself, wider than the PDF's page (issue 14, item 3)."""
    pdf = shots / "record.pdf"
    assert window.records.export_pdf(pdf)
    if shutil.which("pdftoppm") is not None:
        stem = shots / "window_record"
        subprocess.run(
            [
                "pdftoppm",
                "-r",
                "110",
                "-png",
                "-singlefile",
                "-f",
                "1",
                "-l",
                "1",
                str(pdf),
                str(stem),
            ],
            check=True,
        )
        _assert_shows_something(shots / "window_record.png")
    pdf.unlink()


def _shows(widget: QWidget, fragment: str) -> bool:
    return any(fragment in label.text() for label in widget.findChildren(QLabel))


def _recorded_s(scope) -> float:
    capture = scope.capture
    return 0.0 if capture is None else capture.buffer.total / capture.rate_hz

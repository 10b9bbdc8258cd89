"""Helpers of the GUI tests: a main window on isolated settings and an unpaced emulator."""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import pytest
from PySide6.QtCore import QSettings
from PySide6.QtWidgets import QFileDialog

from prm9tool import i18n
from prm9tool.device import emulated_valves, factory
from prm9tool.model.access import AccessModel
from prm9tool.model.document import ParameterDocument
from prm9tool.model.undo import DocumentUndo
from prm9tool.online.connection import ValveConnection
from prm9tool.views import prompts

E02 = "PRM9-06.3Z11/30-24E02S02"
E02_CA = "PRM9-06.3Z11/30-24E02S02-CA"
E04_CA = "PRM9-10.3Z11/60-24E04S02-CA"


@dataclass
class Prompts:
    """Records message boxes and answers the modal ones with ``answers`` (in order)."""

    answers: list[prompts.Button] = field(default_factory=list)
    asked: list[str] = field(default_factory=list)
    informed: list[str] = field(default_factory=list)

    def ask(self, _parent: object, _icon: object, title: str, text: str, buttons: Any,
            default: Any = prompts.Button.NoButton, details: str = "") -> prompts.Button:  # fmt: skip
        self.asked.append(f"{title}: {text}\n{details}".strip())
        if self.answers:
            return self.answers.pop(0)
        for fallback in (prompts.Button.Discard, prompts.Button.No, prompts.Button.Ok):
            if buttons & fallback:
                return fallback
        return prompts.Button.Cancel

    def inform(self, _parent: object, _icon: object, title: str, text: str,
               details: str = "") -> None:  # fmt: skip
        self.informed.append(f"{title}: {text}\n{details}".strip())


def record_prompts(monkeypatch: pytest.MonkeyPatch) -> Prompts:
    """Every message box of the program is recorded and answered without blocking.

    A modal dialog a test did not expect fails the test instead of blocking it forever.
    """
    recorder = Prompts()
    monkeypatch.setattr(prompts, "ask", recorder.ask)
    monkeypatch.setattr(prompts, "inform", recorder.inform)
    for cls in _modal_dialogs():
        monkeypatch.setattr(cls, "exec", _unexpected(cls.__name__))
    for name in ("getOpenFileName", "getSaveFileName"):
        monkeypatch.setattr(QFileDialog, name, _unexpected(f"QFileDialog.{name}"))
    return recorder


def reject_all_dialogs(monkeypatch: pytest.MonkeyPatch) -> None:
    """Every modal dialog is cancelled at once and every file dialog returns no file."""
    for cls in _modal_dialogs():
        monkeypatch.setattr(cls, "exec", lambda *_a, **_k: 0)
    for name in ("getOpenFileName", "getSaveFileName"):
        monkeypatch.setattr(QFileDialog, name, lambda *_a, **_k: ("", ""))


def _modal_dialogs() -> list[type]:
    from PySide6.QtPrintSupport import QPrintDialog

    from prm9tool.views.access_dialog import ChangePasswordDialog, PasswordDialog
    from prm9tool.views.canbus.bus_dialog import CanBusDialog
    from prm9tool.views.hid_dialog import EmulatorDialog, HidConfigurationDialog
    from prm9tool.views.online_dialogs import OnlineDiffDialog, RestartDialog
    from prm9tool.views.valve.selection import ValveSelectionDialog

    return [
        QPrintDialog, ChangePasswordDialog, PasswordDialog, EmulatorDialog,
        HidConfigurationDialog, OnlineDiffDialog, RestartDialog, ValveSelectionDialog,
        CanBusDialog,
    ]  # fmt: skip


def _unexpected(name: str) -> Any:
    def fail(*_args: object, **_kwargs: object) -> Any:
        raise AssertionError(f"unexpected modal dialog {name}")

    return fail


def settings_in(folder: Path) -> QSettings:
    """QSettings in an ini file of its own (the real user settings stay untouched)."""
    return QSettings(str(folder / "prm9tool.ini"), QSettings.Format.IniFormat)


def emulator_connection(paced: bool = False, reconnect: bool = False) -> ValveConnection:
    """A connection to emulated valves, unpaced (as fast as the link asks) unless ``paced``;
    ``reconnect``: a lost valve is looked for (the program's default; off here, so that the
    tests of a lost link see it offline)."""
    connection = ValveConnection(
        opener=lambda entry: factory.open_session(entry, paced=paced),  # type: ignore[arg-type]
        lister=lambda emulators, can=None: factory.list_devices(emulators),
    )
    connection.auto_reconnect = reconnect
    return connection


@contextmanager
def main_window(
    qtbot: Any, folder: Path, type_key: str = E02, connection: ValveConnection | None = None
) -> Iterator[Any]:
    """A shown main window; offline, English, Basic level; ``connection`` (default: to
    emulated valves, :func:`emulator_connection`)."""
    from prm9tool.views.main_window import MainWindow

    i18n.set_language("en")
    doc = ParameterDocument(type_key)
    connection = connection or emulator_connection()
    window = MainWindow(doc, DocumentUndo(doc), AccessModel(), connection, settings_in(folder))
    qtbot.addWidget(window)
    window.show()
    try:
        yield window
    finally:
        window.connection.shutdown()
        emulated_valves.forget_emulated_valves()
        i18n.set_language("en")


def go_online(qtbot: Any, window: Any, spec: str = f"{E02}:4001") -> Any:
    """Put the window online with the emulated valve ``spec``; returns its entry."""
    entry = factory.list_devices([spec])[-1]
    with qtbot.waitSignal(window.connection.online_changed, timeout=10_000):
        window.valve.go_online(entry)
    return entry


def valve_value(qtbot: Any, window: Any, mnemonic: str) -> Any:
    """What the connected valve holds for ``mnemonic``, read through the window's connection."""
    result: dict[str, Any] = {}
    window.connection.operation_finished.connect(
        lambda name, values: result.update(values) if name == "probe" else None
    )
    window.connection.read_many([mnemonic], "probe")
    qtbot.waitUntil(lambda: mnemonic in result, timeout=10_000)
    return result[mnemonic]


def session_of(window: Any) -> Any:
    """The open valve session (tests only: it belongs to the worker thread)."""
    return window.connection._worker.session


def emulated(serial: int) -> Any:
    """The emulated valve with ``serial``."""
    return emulated_valves.EMULATED.valves[serial]


@contextmanager
def online_recording(qtbot: Any, tmp_path: Path, spec: str) -> Iterator[tuple[Any, Any]]:
    """A connection online with the emulated valve ``spec`` (unpaced: the link's reports step
    it), recording into a fresh history in ``tmp_path``: (connection, recorder)."""
    from prm9tool.history.recorder import Recorder

    connection = emulator_connection()
    recorder = Recorder(f"sqlite:///{tmp_path / 'history.db'}", queue=tmp_path / "q.jsonl")
    connection.set_recorder(recorder)
    try:
        entry = factory.list_devices([spec])[-1]
        with qtbot.waitSignal(connection.online_changed, timeout=10000):
            connection.go_online(entry)
        yield connection, recorder
    finally:
        connection.shutdown()
        recorder.close()
        emulated_valves.forget_emulated_valves()

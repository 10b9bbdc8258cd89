"""Offscreen screenshots of the signal-flow diagram (every variant) and of every block dialog.

Usage (from the repository root)::

    QT_QPA_PLATFORM=offscreen python tools/diagram_screenshots.py [OUTPUT_DIR]

Writes PNG files to ``docs/screenshots/`` (or OUTPUT_DIR). The online pictures come from an
emulated valve whose live measuring points feed the diagram's red dots. Dialogs are pictured
at the size they open with.
"""

from __future__ import annotations

import os
import sys
from collections.abc import Sequence
from pathlib import Path
from types import SimpleNamespace

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")

from PySide6.QtCore import QObject, Signal
from PySide6.QtWidgets import QApplication, QWidget

from prm9tool import i18n
from prm9tool.catalogue import CATALOGUE, Access
from prm9tool.device.emulator import EmulatedValve
from prm9tool.model.access import AccessModel
from prm9tool.model.document import ParameterDocument
from prm9tool.model.undo import DocumentUndo
from prm9tool.online.tuning import StepSimulator
from prm9tool.views.canbus.canopen_window import CanopenWindow
from prm9tool.views.diagram import DiagramView
from prm9tool.views.valve.selection import ValveSelectionDialog

VARIANTS = {
    "diagram_e02.png": "PRM9-06.3Z11/30-24E02S02",
    "diagram_e02_coil_a.png": "PRM9-06.2Z51/30-24E02S02",
    "diagram_e02_coil_b.png": "PRM9-06.2Z61/30-24E02S02",
    "diagram_e04.png": "PRM9-06.3Z11/30-24E04S02",
    "diagram_e04_ca.png": "PRM9-06.3Z11/30-24E04S02-CA",
}
DIALOG_KEY = "PRM9-06.3Z11/30-24E04S02-CA"
E02_KEY = "PRM9-06.3Z11/30-24E02S02"


class _EmulatorLink(QObject):
    """Just enough of ValveConnection to show an emulated valve's live values."""

    online_changed = Signal(bool)
    signal_values_changed = Signal(dict)
    operation_finished = Signal(str, object)

    def __init__(self, valve: EmulatedValve) -> None:
        super().__init__()
        self.valve, self.is_online, self.watched = valve, True, []

    @property
    def device(self) -> object:
        """What the valve reports of itself (its type key), as ValveConnection.device."""
        return SimpleNamespace(type_key=str(self.valve.type_key))

    def watch_signals(self, keys: Sequence[str]) -> None:
        self.watched = list(keys)

    def read_many(self, mnemonics: Sequence[str], tag: str = "read") -> None:
        values = {mn: self.valve.read(*CATALOGUE[mn].key) for mn in mnemonics}
        self.operation_finished.emit(tag, values)

    def store(self) -> None:
        self.valve.store()

    def show_switches(self, doc: ParameterDocument) -> None:
        """What the connection's live-value polling reads: the switch positions."""
        doc.set_live({mn: self.valve.read(*CATALOGUE[mn].key) for mn in ("SWBAUD", "SWNODE")})

    def poll(self) -> None:
        self.signal_values_changed.emit({k: self.valve.signal(k) for k in self.watched})


def _save(widget: QWidget, path: Path, app: QApplication) -> None:
    widget.show()
    for _ in range(3):
        app.processEvents()
    widget.grab().save(str(path))
    sys.stdout.write(f"wrote {path}\n")


def _diagram(key: str, level: Access, link: QObject | None = None) -> DiagramView:
    doc = ParameterDocument(key)
    DocumentUndo(doc, doc)
    view = DiagramView(doc, AccessModel(level), link, simulator_factory=StepSimulator.for_document)
    view.resize(1024, 640)
    return view


def diagrams(out: Path, app: QApplication) -> None:
    """One picture per variant (Basic level, offline) and one online with live values."""
    for name, key in VARIANTS.items():
        _save(_diagram(key, Access.BASIC), out / name, app)
    valve = EmulatedValve(DIALOG_KEY, switches=(0, 0))  # analog setpoint: runs without a master
    valve.advance(2.5)
    valve.set_input("setpoint", 3.0)
    valve.advance(0.7)
    link = _EmulatorLink(valve)
    view = _diagram(DIALOG_KEY, Access.EXPERT, link)
    link.show_switches(view.document)
    link.poll()
    _save(view, out / "diagram_e04_ca_online.png", app)
    i18n.set_language("de")
    german = _diagram(DIALOG_KEY, Access.EXPERT, link)
    link.show_switches(german.document)
    link.poll()
    _save(german, out / "diagram_e04_ca_online_german.png", app)
    i18n.set_language("en")


# Values that make the dialogs' curves worth looking at (a user's edits, not defaults).
_CURVE = (-16384, -9011, -4096, -1311, 0, 1311, 4096, 9011, 16384)
DEMO = {
    "SETPLINON": -1,
    **{f"SETPLINY{p}": y for p, y in zip("ABCDEFGHI", _CURVE, strict=True)},
    "RAMPSETPOSUP": 400,
    "RAMPSETPOSDOWN": 200,
    "RAMPSETNEGUP": 300,
    "RAMPSETNEGDOWN": 150,
    "GAINSETPOS": 19661,
    "OFFSETPOS": 1311,
    "OFFSETNEG": 1311,
}


def dialogs(out: Path, app: QApplication) -> None:
    """Every block dialog of an E04-CA valve at Expert level, and the E02 threshold window."""
    view = _diagram(DIALOG_KEY, Access.EXPERT)
    view.document.set_values(DEMO, "screenshot values")
    for block_id in view.block_ids():
        if block_id in ("supply", "canopen", "valve"):  # the main window's windows
            continue
        dialog = view.open_block(block_id)
        assert dialog is not None
        _settle(dialog, app)
        _save(dialog, out / f"diagram_dialog_{block_id}.png", app)
        dialog.close()
    # the valve block opens the main window's Valve → Valve selection
    _save(ValveSelectionDialog(view.document.type_key), out / "diagram_dialog_valve.png", app)
    e02 = _diagram(E02_KEY, Access.BASIC)
    ramps = ("RAMPSETPOSUP", "RAMPSETPOSDOWN", "RAMPSETNEGUP", "RAMPSETNEGDOWN")
    e02.document.set_values({**DEMO, **dict.fromkeys(ramps, 300)}, "screenshot values")
    for block_id in ("threshold", "ramps"):
        dialog = e02.open_block(block_id)
        assert dialog is not None
        _save(dialog, out / f"diagram_dialog_{block_id}_e02_basic.png", app)
    locked = e02.open_block("position_controller")
    assert locked is not None
    _settle(locked, app)
    _save(locked, out / "diagram_dialog_position_controller_basic_locked.png", app)


def _settle(dialog: QWidget, app: QApplication) -> None:
    """Wait for a controller dialog's first simulated step response."""
    simulator = getattr(dialog, "simulator", None)
    if simulator is None:
        return
    for _ in range(400):
        app.processEvents()
        if getattr(dialog, "_current", None) is not None and not simulator.busy:
            break
        simulator_thread_wait(0.01)
    app.processEvents()


def simulator_thread_wait(seconds: float) -> None:
    """Sleep briefly while the simulator's worker thread runs."""
    import time

    time.sleep(seconds)


def canopen(out: Path, app: QApplication) -> None:
    """The CANopen window of an emulated valve with its switches at 6 (500 kbit/s) and 0
    (node ID and bit rate by software: the switch's bit rate is struck through)."""
    valve = EmulatedValve(DIALOG_KEY, switches=(6, 0))
    doc = ParameterDocument(DIALOG_KEY)
    window = CanopenWindow(doc, _EmulatorLink(valve))
    _save(window, out / "diagram_canopen_window.png", app)


def main(argv: list[str]) -> int:
    """Write every screenshot; returns the exit code."""
    out = Path(argv[1]) if len(argv) > 1 else Path("docs/screenshots")
    out.mkdir(parents=True, exist_ok=True)
    app = QApplication.instance() or QApplication(argv)
    assert isinstance(app, QApplication)
    diagrams(out, app)
    dialogs(out, app)
    canopen(out, app)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

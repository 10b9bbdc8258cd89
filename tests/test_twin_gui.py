"""Issue 31 item 3 in the window: the emulated valve's choice picks a twin from the history of a
serial or a twin file, and the offline tuning (the controller dialogs' simulated step, the
Tuning window's tests) runs on the twin of the document's serial and says which plant it was."""

from __future__ import annotations

from dataclasses import replace

import pytest
from support.history_support import Valve

from prm9tool.device.emulator.constants import PLANT
from prm9tool.device.emulator.twinfile import write_twin
from prm9tool.history.recorder import make_entry
from prm9tool.history.store import HistoryStore
from prm9tool.online import twins
from prm9tool.online.tuning import simulate_step
from prm9tool.twin.identify import Fit, FittedConstant

E02 = "PRM9-06.3Z11/30-24E02S02"
SLOW = replace(PLANT, spool_mass_kg=0.12, force_n_per_a=20.0)  # a plant the step tells apart


def _twin_file(path, serial: int):
    mass = FittedConstant("spool_mass_kg", PLANT.spool_mass_kg, 0.12, 0.001, True)
    write_twin(path, Fit(SLOW, (mass,), 0.02, 0.06, 1.4, 20), serial, E02, "1.0.0", "steps", {})
    return path


@pytest.fixture
def history(tmp_path, monkeypatch):
    """A history database (the default the window uses) with a twin record of serial 4301
    whose file exists, and one of serial 4302 whose file is gone."""
    url = f"sqlite:///{tmp_path / 'history.db'}"
    monkeypatch.setenv("PRM9TOOL_HISTORY_DB", url)
    store = HistoryStore(url)
    good = _twin_file(tmp_path / "4301.toml", 4301)
    for serial, path in ((4301, good), (4302, tmp_path / "gone.toml")):
        details = {"twin_file": str(path), "rms_pct": 0.02, "start_rms_pct": 1.4}
        store.append(make_entry(Valve(serial, E02), "twin", "explained", {}, details))
    return good


def test_the_twins_of_a_serial_come_from_its_history(history):
    (choice,) = twins.twins_of(4301)
    assert choice.path == str(history) and not choice.problem
    assert choice.spec == f"twin:{history}"
    (gone,) = twins.twins_of(4302)
    assert "cannot read the twin file" in gone.problem  # listed with why, not used
    assert twins.twin_plant(4302) is None
    assert twins.twins_of(4399) == [] and twins.twin_plant(None) is None
    plant = twins.twin_plant(4301)
    assert plant is not None and plant.plant == SLOW and plant.serial == 4301
    assert twins.spec_serial(f"twin:{history}") == 4301
    assert twins.spec_serial(f"{E02}:1001") == 1001


def test_the_controller_dialogs_step_runs_on_the_twin_of_the_documents_serial(history, qapp):
    from prm9tool.model.document import ParameterDocument
    from prm9tool.online.tuning import StepSimulator

    document = ParameterDocument(E02)
    document.set_source(4301, "1.0.0")
    simulator = StepSimulator.for_document(document, "position")
    assert simulator.twin is not None and simulator.twin.plant == SLOW
    document.set_source(4399, "1.0.0")
    assert StepSimulator.for_document(document, "position").twin is None
    values = dict(document.values)
    on_twin = simulate_step(E02, values, "position", SLOW).actual
    on_emulator = simulate_step(E02, values, "position").actual
    # the slower twin lags the default plant by percent of the step, not by noise
    assert max(a - b for a, b in zip(on_emulator, on_twin, strict=True)) > 2.0


def test_the_emulator_dialog_offers_the_twins_of_the_serial(history, qapp):
    from prm9tool.views.hid_dialog import EmulatorDialog

    dialog = EmulatorDialog()
    assert dialog.spec().endswith(":1002")  # no twin: a plain emulated valve
    dialog.serial.setValue(4301)
    assert dialog.twin.count() == 2  # none, and the one twin
    dialog.twin.setCurrentIndex(1)
    assert dialog.spec() == f"twin:{history}"
    dialog.serial.setValue(4302)
    assert dialog.twin.itemData(1) == ""  # its file is gone: shown with why, not chosen
    assert "cannot be used" in dialog.twin.itemText(1)
    dialog.twin_file.setText("")
    assert dialog.spec().endswith(":4302")

"""The document model: validated edits, signals, modified flag, undo/redo through QUndoStack."""

from __future__ import annotations

import pytest

from prm9tool.errors import ValueRangeError
from prm9tool.model.document import ParameterDocument
from prm9tool.model.undo import DocumentUndo

KEY = "PRM9-06.3Z11/30-24E02S02"


@pytest.fixture
def doc(qapp):
    return ParameterDocument(KEY)


def test_new_document_holds_factory_defaults(doc):
    assert doc.display("THRESETP") == "5"
    assert doc.display("LIMTA") == "2400"
    assert not doc.modified
    assert "PRCKP" not in doc.values  # E02 has no process controller


def test_set_value_emits_and_marks_modified(doc, qtbot):
    with qtbot.waitSignals([doc.value_changed, doc.modified_changed]):
        doc.set_value("LIMTA", 2000)
    assert doc.value("LIMTA") == 2000
    assert doc.modified


def test_out_of_range_is_refused_with_the_reason_and_changes_nothing(doc):
    with pytest.raises(ValueRangeError, match="outside the allowed range"):
        doc.set_value("DYNFREQ", 70000)
    with pytest.raises(ValueRangeError, match="CURNORM"):
        doc.set_value("LIMTB", 3000)
    assert doc.value("DYNFREQ") == 80 and doc.value("LIMTB") == 2400
    assert not doc.modified


def test_undo_redo_one_command_per_edit_and_per_bulk_operation(doc):
    undo = DocumentUndo(doc)
    doc.set_value("LIMTA", 2000)
    doc.set_values(
        {"RAMPSETPOSUP": 100, "RAMPSETPOSDOWN": 100, "RAMPSETNEGUP": 100, "RAMPSETNEGDOWN": 100},
        "All ramps 100 ms",
    )
    assert undo.stack.count() == 2
    undo.stack.undo()
    assert doc.value("RAMPSETNEGDOWN") == 0 and doc.value("LIMTA") == 2000
    undo.stack.undo()
    assert doc.value("LIMTA") == 2400
    assert not doc.modified  # back at the saved state
    undo.stack.redo()
    undo.stack.redo()
    assert doc.value("RAMPSETPOSUP") == 100 and doc.modified


def test_type_key_change_is_one_undoable_step(doc, qtbot):
    undo = DocumentUndo(doc)
    doc.set_value("LIMTA", 2000)
    with qtbot.waitSignal(doc.type_key_changed):
        doc.set_type_key("PRM9-06.3Z11/30-24E04S02-CA")
    assert "PRCKP" in doc.values and doc.value("LIMTA") == 2400
    undo.stack.undo()
    assert str(doc.type_key) == KEY and doc.value("LIMTA") == 2000
    assert "PRCKP" not in doc.values


def test_mark_saved_clears_modified(doc, tmp_path):
    doc.set_value("DTAMP", 1000)
    doc.mark_saved(tmp_path / "x.prm")
    assert not doc.modified and doc.path == tmp_path / "x.prm"


def test_undo_and_redo_emit_the_signals_views_listen_to(doc, qtbot):
    undo = DocumentUndo(doc)
    doc.set_value("AINSETP", 6)  # 0…10 V on two coils: table 8-4 warning
    assert [p.mnemonics for p in doc.problems()] == [("AINSETP",)]
    changed: list[str] = []
    doc.value_changed.connect(changed.append)
    with qtbot.waitSignals([doc.validity_changed, doc.modified_changed]):
        undo.stack.undo()
    assert changed == ["AINSETP"] and doc.problems() == [] and not doc.modified
    with qtbot.waitSignals([doc.value_changed, doc.validity_changed, doc.modified_changed]):
        undo.stack.redo()
    assert doc.value("AINSETP") == 6 and doc.modified and doc.problems()


def test_a_bulk_edit_resets_views_once_instead_of_one_signal_per_value(doc, qtbot):
    undo = DocumentUndo(doc)
    changed: list[str] = []
    doc.value_changed.connect(changed.append)
    lin = {f"SETPLINY{c}": -16100 + 4000 * i for i, c in enumerate("ABCDEFGHI")}
    with qtbot.waitSignals([doc.values_reset, doc.validity_changed]):
        doc.set_values(lin, "Linearization")
    assert changed == []
    with qtbot.waitSignal(doc.values_reset):
        undo.stack.undo()
    assert changed == []

"""The progress dialog of a valve operation against signals that come late."""

from __future__ import annotations

import shiboken6
from PySide6.QtWidgets import QMainWindow

from prm9tool.views.operation_progress import OperationProgress


def _progress_in_a_deleted_window(qtbot) -> OperationProgress:
    window = QMainWindow()
    progress = OperationProgress(window, lambda: None)
    progress.start("upload", "Uploading the parameters to the valve…")
    assert progress.dialog is not None
    shiboken6.delete(window)  # closed with its window; its dialog went with it
    return progress


def test_a_step_arriving_after_the_dialog_was_deleted_is_ignored(qtbot):
    """Issue 25 item 17: the connection's queued progress signal reached show_step after the
    window (and the dialog, its child) had been deleted — "Internal C++ object
    (QProgressDialog) already deleted", an exception in a Qt slot. The old tests never let a
    step arrive that late; a busy PC did."""
    progress = _progress_in_a_deleted_window(qtbot)
    progress.show_step(3, 43, "LIMTA")  # raised RuntimeError
    assert progress.dialog is None
    progress.close()  # and closing it again is harmless


def test_closing_after_the_dialog_was_deleted_is_harmless(qtbot):
    progress = _progress_in_a_deleted_window(qtbot)
    progress.close()
    assert progress.dialog is None


def test_steps_show_in_the_dialog(qtbot):
    window = QMainWindow()
    qtbot.addWidget(window)
    progress = OperationProgress(window, lambda: None)
    progress.start("upload", "Uploading")
    progress.show_step(3, 43, "LIMTA")
    dialog = progress.dialog
    assert dialog is not None
    assert (dialog.value(), dialog.maximum()) == (3, 43)
    assert dialog.labelText() == "Uploading\nLIMTA"
    progress.close()
    assert progress.dialog is None

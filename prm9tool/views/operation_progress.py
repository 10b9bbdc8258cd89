"""The progress dialog of a valve operation (upload, download, restart …): window-modal,
shown after 300 ms, its Cancel button cancels the connection's running job.

The connection's signals are queued from its worker thread, so a step or the end of an
operation can arrive after the dialog went with its window (a window closed while the valve
still works, a busy PC): such a signal finds no dialog and changes nothing. A shown dialog's
``setValue`` processes events, in which the operation may end: the dialog is then closed at
once but deleted only after its ``setValue`` has returned (deleting it inside crashed Qt).
"""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtCore import QObject, Qt
from PySide6.QtWidgets import QProgressDialog, QWidget
from shiboken6 import isValid


class OperationProgress(QObject):
    """At most one progress dialog at a time, opened by :meth:`start`, closed by :meth:`close`."""

    def __init__(self, window: QWidget, cancel: Callable[[], None]) -> None:
        super().__init__(window)
        self._window = window
        self._cancel = cancel
        self.dialog: QProgressDialog | None = None
        self._label = ""
        self._stepping = False  # inside the dialog's setValue, which processes events
        self._closed_while_stepping: list[QProgressDialog] = []

    def start(self, operation: str, label: str, cancellable: bool = True) -> None:
        """Open the dialog of ``operation`` (its object name) with ``label``; the previous closes."""
        self.close()
        self._label = label
        dialog = QProgressDialog(label, self.tr("Cancel") if cancellable else "", 0, 0)
        dialog.setParent(self._window, dialog.windowFlags())
        dialog.setObjectName(f"progress_{operation}")
        dialog.setWindowTitle("prm9tool")
        dialog.setWindowModality(Qt.WindowModality.WindowModal)
        dialog.setMinimumDuration(300)
        dialog.setAutoClose(False)
        dialog.setAutoReset(False)
        if not cancellable:
            dialog.setCancelButton(None)
        dialog.canceled.connect(self._cancel)
        self.dialog = dialog

    def show_step(self, done: int, total: int, step: str) -> None:
        """The operation reached ``done`` of ``total`` steps, now at ``step``."""
        dialog = self._open_dialog()
        if dialog is None or self._stepping:  # a step that arrived while the last is shown
            return
        dialog.setMaximum(max(total, 1))
        dialog.setLabelText(f"{self._label}\n{step}")
        self._stepping = True
        try:
            dialog.setValue(min(done, total))  # last: a shown modal dialog processes events here
        finally:
            self._stepping = False
            closed, self._closed_while_stepping = self._closed_while_stepping, []
            for old in closed:  # deleted only now that its setValue has returned
                if isValid(old):
                    old.deleteLater()

    def close(self) -> None:
        """Close the dialog, if one is open."""
        dialog, self.dialog = self._open_dialog(), None
        if dialog is not None:
            dialog.canceled.disconnect(self._cancel)
            dialog.close()
            if self._stepping:  # the operation ended during a step's event processing
                self._closed_while_stepping.append(dialog)
            else:
                dialog.deleteLater()

    def _open_dialog(self) -> QProgressDialog | None:
        """The dialog, unless it was deleted with its window (then forgotten)."""
        if self.dialog is not None and not isValid(self.dialog):
            self.dialog = None
        return self.dialog

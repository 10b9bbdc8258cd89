"""The progress dialog of a valve operation (upload, download, restart …): window-modal,
shown after 300 ms, its Cancel button cancels the connection's running job."""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtCore import QObject, Qt
from PySide6.QtWidgets import QProgressDialog, QWidget


class OperationProgress(QObject):
    """At most one progress dialog at a time, opened by :meth:`start`, closed by :meth:`close`."""

    def __init__(self, window: QWidget, cancel: Callable[[], None]) -> None:
        super().__init__(window)
        self._window = window
        self._cancel = cancel
        self.dialog: QProgressDialog | None = None
        self._label = ""

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
        dialog = self.dialog
        if dialog is None:
            return
        dialog.setMaximum(max(total, 1))
        dialog.setValue(min(done, total))
        dialog.setLabelText(f"{self._label}\n{step}")

    def close(self) -> None:
        """Close the dialog, if one is open."""
        dialog, self.dialog = self.dialog, None
        if dialog is not None:
            dialog.canceled.disconnect(self._cancel)
            dialog.close()
            dialog.deleteLater()

"""The history setting: which database (empty: SQLite in the user data dir) and what to do
when it cannot be reached before an upload. Saved in ``<user data dir>/history.json``, which
the command line reads too (docs/history.md)."""

from __future__ import annotations

from PySide6.QtWidgets import (
    QComboBox,
    QDialog,
    QDialogButtonBox,
    QFormLayout,
    QLabel,
    QLineEdit,
    QWidget,
)

from prm9tool.history.config import database_url, default_url, save_settings, unreachable_policy


class HistorySettingsDialog(QDialog):
    """Edit the history setting; ``url`` is the chosen database after ``accept``."""

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setWindowTitle(self.tr("History database"))
        current = database_url()
        self.url = QLineEdit("" if current == default_url() else current)
        self.url.setPlaceholderText(default_url())
        self.policy = QComboBox()
        for value, label in (
            ("ask", self.tr("ask before uploading")),
            ("refuse", self.tr("refuse the upload (production line)")),
            ("queue", self.tr("upload and keep the record here until the database is back")),
        ):
            self.policy.addItem(label, value)
        self.policy.setCurrentIndex(self.policy.findData(unreachable_policy()))
        hint = QLabel(self.tr("Empty: SQLite on this computer. A line of stations: "
                              "postgresql+psycopg://user:password@server/database"))  # fmt: skip
        hint.setWordWrap(True)
        form = QFormLayout(self)
        form.addRow(self.tr("Database:"), self.url)
        form.addRow("", hint)
        form.addRow(self.tr("When it cannot be reached:"), self.policy)
        buttons = QDialogButtonBox(
            QDialogButtonBox.StandardButton.Save | QDialogButtonBox.StandardButton.Cancel
        )
        buttons.accepted.connect(self._save)
        buttons.rejected.connect(self.reject)
        form.addRow(buttons)
        self.resize(620, 160)

    def _save(self) -> None:
        save_settings(self.url.text().strip() or None, str(self.policy.currentData()))
        self.accept()

"""The oscilloscope's exports: the visible window or the whole recording as CSV, the plot with
its legend as a PNG image, each through a file dialog or to a given path."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from PySide6.QtCore import QObject
from PySide6.QtGui import QImageWriter
from PySide6.QtWidgets import QWidget

from prm9tool.scope import write_csv
from prm9tool.views import prompts
from prm9tool.views.files import dialogs as file_dialogs
from prm9tool.views.scope.display import ScopeDisplay
from prm9tool.views.scope.plot import ScopePlot


class ScopeExport(QObject):
    """Writes what ``display`` and ``plot`` show; ``say`` puts a message in the status line."""

    def __init__(
        self, display: ScopeDisplay, plot: ScopePlot, say: Callable[[str], None], parent: QWidget
    ) -> None:
        super().__init__(parent)
        self._display, self._plot, self._say, self._parent = display, plot, say, parent

    def csv(self, path: str | Path, whole: bool) -> int:
        """Write the visible window (or the whole recording) as CSV; returns the row count."""
        capture = self._display.capture
        if capture is None:
            raise ValueError(self.tr("Nothing recorded yet."))
        t, values = self._display.whole_data() if whole else self._display.visible_data()
        with open(path, "w", encoding="utf-8", newline="") as out:
            return write_csv(out, t, values, capture.signals)

    def png(self, path: str | Path) -> None:
        """Save the plot with its legend as a PNG image."""
        writer = QImageWriter(str(path), b"PNG")  # PNG whatever the file name ends with
        if not writer.write(self._plot.render_image()):
            raise OSError(self.tr("Could not write {0}.").format(path))

    def ask_csv(self, whole: bool) -> None:
        """Export CSV… : ask for the file, write it, say how it went."""
        path, _ = file_dialogs.save_file_name(
            self._parent, self.tr("Export CSV"), "scope.csv", self.tr("CSV files (*.csv)")
        )
        if path:
            self._report(lambda: self.csv(path, whole), path)

    def ask_png(self) -> None:
        """Export PNG… : ask for the file, write it, say how it went."""
        path, _ = file_dialogs.save_file_name(
            self._parent, self.tr("Export PNG"), "scope.png", self.tr("PNG images (*.png)")
        )
        if path:
            self._report(lambda: self.png(path), path)

    def _report(self, action: Callable[[], object], path: str) -> None:
        try:
            action()
        except (OSError, ValueError) as exc:
            prompts.inform(self._parent, prompts.Icon.Warning, self.tr("Export"), str(exc))
        else:
            self._say(self.tr("Saved {0}.").format(path))

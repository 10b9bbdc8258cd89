"""Print and Export PDF of the parameter record (File menu).

Printing support is imported when first used: it is not needed to start the program.
"""

from __future__ import annotations

from datetime import datetime
from pathlib import Path
from typing import TYPE_CHECKING

from PySide6.QtCore import QObject, Signal
from PySide6.QtWidgets import QDialog, QFileDialog

from prm9tool.catalogue import Access
from prm9tool.views import prompts

if TYPE_CHECKING:
    from PySide6.QtGui import QPageLayout, QTextDocument

    from prm9tool.views.main_window import MainWindow


class RecordActions(QObject):
    """Builds the record of the window's document and prints it or writes it as PDF."""

    message_posted = Signal(str)

    def __init__(self, window: MainWindow) -> None:
        super().__init__(window)
        self._window = window

    def record(self, layout: QPageLayout | None = None) -> QTextDocument:
        """The record of the current document (with the diagram picture when available).

        Laid out on the pages of ``layout`` (A4 with 15 mm margins unless given).
        """
        from prm9tool.views.record import A4_LAYOUT, RecordHeader, build_record

        w = self._window
        level = self.tr("Expert") if w.access.level is Access.EXPERT else self.tr("Basic")
        info = w.connection.device
        header = RecordHeader(
            access_level=level,
            serial=str(info.serial) if info else "",
            firmware=info.firmware if info else "",
            date=datetime.now(),
        )
        diagram = getattr(w.views.get("diagram"), "render_picture", None)
        return build_record(w.doc, header, diagram, layout or A4_LAYOUT)

    def print_record(self) -> bool:
        """Print through the print dialog."""
        from PySide6.QtPrintSupport import QPrintDialog, QPrinter

        printer = QPrinter(QPrinter.PrinterMode.HighResolution)
        printer.setDocName(self._title())
        dialog = QPrintDialog(printer, self._window)
        if dialog.exec() != QDialog.DialogCode.Accepted:
            return False
        self.record(printer.pageLayout()).print_(printer)
        self.message_posted.emit(self.tr("Parameter record printed"))
        return True

    def export_pdf_dialog(self) -> bool:
        """Ask for a file name and write the record as PDF."""
        doc = self._window.doc
        base = doc.path.with_suffix(".pdf") if doc.path else None
        folder = Path(self._window.files.last_folder())
        suggestion = base or folder / (str(doc.type_key).replace("/", "_") + ".pdf")
        path, _filter = QFileDialog.getSaveFileName(
            self._window, self.tr("Export PDF"), str(suggestion), self.tr("PDF files (*.pdf)")
        )
        if not path:
            return False
        target = Path(path)
        if target.suffix.lower() != ".pdf":
            target = target.with_name(target.name + ".pdf")
        return self.export_pdf(target)

    def export_pdf(self, path: Path) -> bool:
        """Write the record to ``path``; a failure is reported and returns False."""
        from prm9tool.views.record import write_pdf

        try:
            write_pdf(self.record(), path, self._title())
        except OSError as exc:
            prompts.ask(
                self._window,
                prompts.Icon.Critical,
                self.tr("Export PDF"),
                self.tr("Cannot write “{0}”: {1}").format(str(path), str(exc)),
                prompts.Button.Ok,
            )
            return False
        self.message_posted.emit(self.tr("Parameter record saved as {0}").format(str(path)))
        return True

    def _title(self) -> str:
        return self.tr("PRM9 parameter record {0}").format(str(self._window.doc.type_key))

"""Print and Export PDF of the parameter record (File menu).

Printing support is imported when first used: it is not needed to start the program.
"""

from __future__ import annotations

from collections.abc import Mapping
from datetime import datetime
from pathlib import Path
from typing import TYPE_CHECKING, Protocol

from PySide6.QtCore import QObject, Signal
from PySide6.QtWidgets import QDialog, QWidget

from prm9tool.catalogue import Access
from prm9tool.views import prompts
from prm9tool.views.files import dialogs as file_dialogs

if TYPE_CHECKING:
    from PySide6.QtGui import QPageLayout, QTextDocument

    from prm9tool.model.access import AccessModel
    from prm9tool.model.document import ParameterDocument
    from prm9tool.online.connection import ValveConnection
    from prm9tool.views.files.workflow import FileWorkflow
    from prm9tool.views.paged_print import PageFrame
    from prm9tool.views.record.document import RecordHeader


class RecordHost(Protocol):
    """What the record actions use of the main window (``MainWindow``, which holds them:
    typed by what they need, this module stays below the window)."""

    @property
    def doc(self) -> ParameterDocument: ...

    @property
    def access(self) -> AccessModel: ...

    @property
    def connection(self) -> ValveConnection: ...

    @property
    def views(self) -> Mapping[str, QWidget]: ...

    @property
    def files(self) -> FileWorkflow: ...


class RecordActions(QObject):
    """Builds the record of the window's document and prints it or writes it as PDF."""

    message_posted = Signal(str)

    def __init__(self, window: RecordHost, widget: QWidget) -> None:
        """``widget``: the window as a widget (the parent of the dialogs the actions open)."""
        super().__init__(widget)
        self._window, self._widget = window, widget

    def header(self) -> RecordHeader:
        """The record's facts besides the document's: access level, the valve online, now."""
        from prm9tool.views.record.document import RecordHeader

        w = self._window
        level = self.tr("Expert") if w.access.level is Access.EXPERT else self.tr("Basic")
        info = w.connection.device
        return RecordHeader(
            access_level=level,
            serial=str(info.serial) if info else "",
            firmware=info.firmware if info else "",
            date=datetime.now(),
        )

    def record(
        self, layout: QPageLayout | None = None, header: RecordHeader | None = None
    ) -> QTextDocument:
        """The record of the current document (with the diagram picture when available).

        Laid out on the pages of ``layout`` (A4 with 15 mm margins unless given).
        """
        from prm9tool.views.record.document import A4_LAYOUT, build_record

        w = self._window
        diagram = getattr(w.views.get("diagram"), "render_picture", None)
        return build_record(w.doc, header or self.header(), diagram, layout or A4_LAYOUT)

    def _frame(self, header: RecordHeader) -> PageFrame:
        from prm9tool.views.record.document import record_frame

        return record_frame(self._window.doc, header)

    def file_stem(self) -> str:
        """The name a record file is proposed under: type key and serial number."""
        from prm9tool.views.record.document import record_file_stem

        doc, info = self._window.doc, self._window.connection.device
        serial = info.serial if info else doc.source_serial
        return record_file_stem(str(doc.type_key), str(serial) if serial else "")

    def print_record(self) -> bool:
        """Print through the print dialog (15 mm margins proposed)."""
        from PySide6.QtCore import QMarginsF
        from PySide6.QtGui import QPageLayout
        from PySide6.QtPrintSupport import QPrintDialog, QPrinter

        from prm9tool.views.paged_print import MARGIN_MM, print_paged

        printer = QPrinter(QPrinter.PrinterMode.HighResolution)
        margins = QMarginsF(MARGIN_MM, MARGIN_MM, MARGIN_MM, MARGIN_MM)
        printer.setPageMargins(margins, QPageLayout.Unit.Millimeter)
        # the job's name; Qt's "print to file" proposes it up to its last dot, plus ".pdf"
        printer.setDocName(self.file_stem() + ".pdf")
        dialog = QPrintDialog(printer, self._widget)
        if dialog.exec() != QDialog.DialogCode.Accepted:
            return False
        header = self.header()
        print_paged(self.record(printer.pageLayout(), header), printer, self._frame(header))
        self.message_posted.emit(self.tr("Parameter record printed"))
        return True

    def export_pdf_dialog(self) -> bool:
        """Ask for a file name and write the record as PDF."""
        doc = self._window.doc
        base = doc.path.with_suffix(".pdf") if doc.path else None
        folder = Path(self._window.files.last_folder())
        suggestion = base or folder / (self.file_stem() + ".pdf")
        path, _filter = file_dialogs.save_file_name(
            self._widget, self.tr("Export PDF"), str(suggestion), self.tr("PDF files (*.pdf)")
        )
        if not path:
            return False
        target = Path(path)
        if target.suffix.lower() != ".pdf":
            target = target.with_name(target.name + ".pdf")
        return self.export_pdf(target)

    def export_pdf(self, path: Path) -> bool:
        """Write the record to ``path``; a failure is reported and returns False."""
        from prm9tool.views.record.document import write_pdf

        header = self.header()
        try:
            write_pdf(self.record(header=header), path, self._title(), self._frame(header))
        except OSError as exc:
            prompts.ask(
                self._widget,
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

"""File → Export DCF and File → Export EDS: the document's valve as a CiA 306 DCF
(prm9tool.files.dcf), and the EDS of its type (the valve service's ``write_eds``, as
``--export-eds`` and ``Valve.export_eds`` write it).

Online, the document holds the connected valve's values, so the DCF describes that valve as it
is configured; offline, the parameter set being edited. Node ID and bit rate are those the
valve runs with after power-up (switches and NODEID/BITRATE, manual table 7-17).
"""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import QObject, Signal
from PySide6.QtWidgets import QWidget

from prm9tool.errors import TypeKeyError
from prm9tool.model.document import ParameterDocument
from prm9tool.service.export import SETTINGS, write_dcf, write_eds
from prm9tool.views import prompts
from prm9tool.views.files import dialogs as file_dialogs


class DcfExport(QObject):
    """Asks for a file name and writes the DCF."""

    message_posted = Signal(str)

    def __init__(self, doc: ParameterDocument, window: QWidget) -> None:
        super().__init__(window)
        self._doc, self._window = doc, window

    def export_dialog(self, folder: str = "") -> bool:
        """Ask for the file and write it; False when cancelled or failed (said so)."""
        name = str(self._doc.type_key).replace("/", "_").replace(".", "_") + ".dcf"
        path, _filter = file_dialogs.save_file_name(
            self._window, self.tr("Export DCF"), str(Path(folder) / name),
            self.tr("CANopen device configuration (*.dcf)"),
        )  # fmt: skip
        if not path:
            return False
        return self.export(Path(path))

    def export(self, path: Path) -> bool:
        """Write the DCF of the document to ``path``."""
        doc = self._doc
        values = {m: doc.value(m) for m in doc.values}
        try:
            node = write_dcf(path, doc.type_key, values, {m: doc.value(m) for m in SETTINGS})
        except OSError as exc:
            prompts.ask(
                self._window,
                prompts.Icon.Critical,
                self.tr("Export DCF"),
                self.tr("Cannot write “{0}”: {1}").format(str(path), str(exc)),
                prompts.Button.Ok,
            )
            return False
        self.message_posted.emit(self.tr("DCF saved as {0} (node {1})").format(str(path), node))
        return True


class EdsExport(QObject):
    """Asks for a file name and writes the EDS of the document's type: it depends only on
    the type key, so it is the same online and offline."""

    message_posted = Signal(str)

    def __init__(self, doc: ParameterDocument, window: QWidget) -> None:
        super().__init__(window)
        self._doc, self._window = doc, window

    def export_dialog(self, folder: str = "") -> bool:
        """Ask for the file and write it; False when cancelled or failed (said so)."""
        name = str(self._doc.type_key).replace("/", "_").replace(".", "_") + ".eds"
        path, _filter = file_dialogs.save_file_name(
            self._window, self.tr("Export EDS"), str(Path(folder) / name),
            self.tr("CANopen electronic data sheet (*.eds)"),
        )  # fmt: skip
        if not path:
            return False
        return self.export(Path(path))

    def export(self, path: Path) -> bool:
        """Write the EDS of the document's type to ``path`` (atomically: a file that cannot
        be written leaves nothing half-written behind)."""
        try:
            write_eds(path, self._doc.type_key)
        except (OSError, TypeKeyError) as exc:
            prompts.ask(
                self._window,
                prompts.Icon.Critical,
                self.tr("Export EDS"),
                self.tr("Cannot write “{0}”: {1}").format(str(path), str(exc)),
                prompts.Button.Ok,
            )
            return False
        self.message_posted.emit(self.tr("EDS saved as {0}").format(str(path)))
        return True

"""File → Compare with file…, Valve → Compare with valve, and "choose per parameter" when
going online: build the comparison, show the compare view, apply what the user chose.

Applying to the document is one undo step; applying to the valve is a transactional upload
of exactly the chosen values (write, read back, store) through the valve workflow, which
also asks the history first. Going online, the user chooses per parameter which side keeps
its value: the document takes the valve's chosen values (one undo step, not written back),
the valve gets the document's chosen values, and then both agree.
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import TYPE_CHECKING

from PySide6.QtCore import QObject, QSettings, Signal
from PySide6.QtWidgets import QDialog, QWidget

from prm9tool.catalogue.typekey import TypeKey
from prm9tool.compare.model import NOT_ON_SOURCE_VALVE, Comparison, Side
from prm9tool.errors import FileFormatError
from prm9tool.model.access import AccessModel
from prm9tool.model.document import ParameterDocument, Raw
from prm9tool.model.undo import DocumentUndo
from prm9tool.online.connection import ValveConnection
from prm9tool.online.sync import ValveSync
from prm9tool.translate import error_text, translated
from prm9tool.views import prompts
from prm9tool.views.files import dialogs as file_dialogs
from prm9tool.views.files.reader import read_in_background
from prm9tool.views.files.workflow import FOLDER_KEY
from prm9tool.views.history.notes import record_online_change
from prm9tool.views.valve.workflow import ValveWorkflow

if TYPE_CHECKING:  # the compare view is imported when first shown, not at start-up
    from prm9tool.views.compare.view import CompareDialog

COMPARE_VIEW = "compare_view"  # the download behind Valve → Compare with valve


class CompareWorkflow(QObject):
    """Opens the compare view from the menus and from the going-online prompt."""

    dialog_created = Signal(object)  # the CompareDialog, before it runs (tests answer it)
    message_posted = Signal(str)

    def __init__(
        self,
        window: QWidget,
        doc: ParameterDocument,
        undo: DocumentUndo,
        access: AccessModel,
        connection: ValveConnection,
        sync: ValveSync,
        valve: ValveWorkflow,
        settings: QSettings | None = None,
    ) -> None:
        super().__init__(window)
        self._window, self._doc, self._undo, self._access = window, doc, undo, access
        self._connection, self._sync, self._valve = connection, sync, valve
        self._settings = settings if settings is not None else QSettings()
        valve.choose_per_parameter = self.choose_going_online
        connection.operation_finished.connect(self._on_connection_operation_finished)
        connection.history_problem.connect(self._on_connection_history_problem)

    def _on_connection_history_problem(self, text: str) -> None:
        self.message_posted.emit(self.tr("History: {0}").format(text))

    # --- sides ----------------------------------------------------------------------------
    def _document(self) -> Side:
        return Side(self.tr("Document"), self._doc.type_key, dict(self._doc.values))

    def _valve_side(self, values: Mapping[str, Raw]) -> Side:
        info = self._connection.device
        key = self._doc.type_key if info is None else TypeKey.parse(info.type_key)
        label = self.tr("Valve {0}").format("" if info is None else info.serial)
        return Side(label, key, dict(values))

    def _factory(self, key: TypeKey) -> Side:
        return Side.factory(key, self.tr("Factory defaults"))

    def _run(
        self, comparison: Comparison, targets: tuple[int, ...], valve: bool = True
    ) -> CompareDialog:
        """The compare view of ``comparison``: side 0 the document, side 1 the valve (or,
        not ``valve``, a file)."""
        from prm9tool.views.compare.view import DOCUMENT, VALVE, CompareDialog

        roles = {0: DOCUMENT, 1: VALVE} if valve else {0: DOCUMENT}
        dialog = CompareDialog(comparison, targets, self._access.level, self._window, roles)
        self.dialog_created.emit(dialog)
        dialog.exec()
        return dialog

    # --- File → Compare with file… ----------------------------------------------------------
    def compare_with_file(self, path: Path | None = None) -> None:
        """Compare the document with a *.prm file; the file's chosen values can be taken."""
        if path is None:
            folder = str(self._settings.value(FOLDER_KEY, str(Path.home())))
            name, _filter = file_dialogs.open_file_name(
                self._window, self.tr("Compare with file"), folder,
                self.tr("Parameter files (*.prm);;All files (*)"),
            )  # fmt: skip
            if not name:
                return
            path = Path(name)
            self._settings.setValue(FOLDER_KEY, str(path.parent))  # the last folder used
        contents = read_in_background(self._window, path)  # the window keeps working
        if contents is None:
            return  # the user cancelled the reading
        if isinstance(contents, FileFormatError):
            lead = self.tr("{0} cannot be compared.").format(path.name)
            if contents.problems:  # the first one in the box, as File → Open says it
                lead = f"{lead}\n{translated(contents.problems[0].located(path.name))}"
            prompts.inform(self._window, prompts.Icon.Warning, self.tr("Compare with file"),
                           lead, error_text(contents))  # fmt: skip
            return
        file_side = Side(path.name, contents.type_key, contents.values, NOT_ON_SOURCE_VALVE())
        comparison = Comparison((self._document(), file_side), self._factory(self._doc.type_key))
        dialog = self._run(comparison, (0,), valve=False)
        if dialog.applied is not None and dialog.applied[1]:
            if not self._valve.confirms_online_values(dialog.applied[1]):
                return
            label = self.tr("Values taken from {0}").format(path.name)
            before = dict(self._doc.values)
            self._doc.set_values(dialog.applied[1], label)
            record_online_change(self._connection, "compare-apply", before, self._doc.values,
                                 source=path.name)  # fmt: skip
            self.message_posted.emit(label)

    # --- Valve → Compare with valve ---------------------------------------------------------
    def compare_with_valve(self) -> None:
        """Read the valve, then compare it with the document (apply to either side)."""
        if not self._connection.is_online:
            prompts.inform(self._window, prompts.Icon.Information, self.tr("Compare with valve"),
                           self.tr("Go online with the valve first (Communication → Online mode)."))  # fmt: skip
            return
        self._connection.download(COMPARE_VIEW)

    def _on_connection_operation_finished(self, name: str, result: object) -> None:
        if name == COMPARE_VIEW and isinstance(result, Mapping):
            self._show_valve_comparison(result)

    def _show_valve_comparison(self, values: Mapping[str, Raw]) -> None:
        valve = self._valve_side(values)
        comparison = Comparison((self._document(), valve), self._factory(valve.type_key))
        same_variant = valve.type_key.variant == self._doc.variant
        dialog = self._run(comparison, (0, 1) if same_variant else (0,))
        if dialog.applied is None or not dialog.applied[1]:
            return
        target, chosen = dialog.applied
        if target == 0:
            label = self.tr("Values taken from the valve")
            with self._sync.suspended():  # they are the valve's already
                self._doc.set_values(chosen, label, validate=False)
            self.message_posted.emit(label)
        else:
            self._valve.upload_values(chosen, "compare: values chosen from the document")

    # --- going online: choose per parameter --------------------------------------------------
    def choose_going_online(self, values: Mapping[str, Raw]) -> None:
        """The document and the valve differ: the user chooses per parameter; cancel goes
        offline (as in the differences prompt)."""
        valve = self._valve_side(values)
        comparison = Comparison((self._document(), valve), self._factory(valve.type_key))
        comparison.choose_all(1)  # the valve's values unless the user picks the document's
        from prm9tool.views.compare.view import BOTH

        dialog = self._run(comparison, (BOTH,))
        if dialog.result() != QDialog.DialogCode.Accepted or dialog.applied is None:
            self._valve.go_offline()
            return
        to_document, to_valve = comparison.to_apply(0), comparison.to_apply(1)
        if to_document:
            with self._sync.suspended():
                self._doc.set_values(to_document, self.tr("Values chosen from the valve"), False)
        if to_valve:
            # the sync starts when it is stored
            self._valve.upload_values(to_valve, "going online: values chosen per parameter")
        else:
            self._sync.start(values)
            self.message_posted.emit(self.tr("Online: document and valve agree"))

    # --- Valve → History ----------------------------------------------------------------------
    def show_history(self) -> QDialog | None:
        """The history of the connected valve (or of a serial number typed in)."""
        from prm9tool.views.history.window import HistoryWindow

        hook = self._connection.history
        if hook is None:
            return None
        info = self._connection.device
        serial = None if info is None else info.serial
        window = HistoryWindow(hook.recorder, serial, self.restore_into_document,
                               self.restore_to_valve, self._window,
                               None if info is None else info.type_key)  # fmt: skip
        window.database_changed.connect(self._connection.set_recorder)
        self.dialog_created.emit(window)
        window.show()
        return window

    def restore_into_document(self, key: TypeKey | None, values: Mapping[str, Raw]) -> None:
        """A record's parameter set becomes the document's, type key included (``key``), or
        the values ticked in two records (``key`` None: the document keeps its type key):
        one undo step (online it goes to the valve as any edit does)."""
        if not self._valve.confirms_online_values(values):
            return
        label = self.tr("Parameters restored from the history")
        if key is None:
            label = self.tr("%n value(s) taken from the history", "", len(values))
        before = dict(self._doc.values)
        self._undo.stack.beginMacro(label)
        if key is not None:
            self._doc.set_type_key(key)
        self._doc.set_values(values, label, validate=False)
        self._undo.stack.endMacro()
        whole = "record" if key is not None else "ticked values"
        record_online_change(self._connection, "history-restore", before, self._doc.values,
                             source=whole)  # fmt: skip
        self.message_posted.emit(label)

    def restore_to_valve(self, serial: int, values: Mapping[str, Raw]) -> bool:
        """Upload a record's set into the valve it came from (False: that valve is not online)."""
        info = self._connection.device
        if info is None or info.serial != serial or not self._connection.is_online:
            return False
        if self._valve.confirms_online_values(values):  # (a No: nothing sent, and said so)
            self._valve.upload_values(values, "history: a record's values restored")
        return True

"""The main window (manual §8.4): menus, toolbar, the three views, status bar.

The window composes the workflows (files, valve) and views; it holds no parameter state of its
own. It keeps one document object for its whole life, so every view stays connected to it.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from PySide6.QtCore import QByteArray, QEvent, QLocale, QSettings, Qt
from PySide6.QtGui import QCloseEvent, QDragEnterEvent, QDropEvent
from PySide6.QtWidgets import QApplication, QMainWindow, QWidget

from prm9tool import i18n
from prm9tool.catalogue import Access
from prm9tool.model.access import AccessModel
from prm9tool.model.document import ParameterDocument
from prm9tool.model.password import PasswordStore
from prm9tool.model.undo import DocumentUndo
from prm9tool.online.connection import ValveConnection
from prm9tool.online.sync import ValveSync
from prm9tool.online.valve_control import ValveControl
from prm9tool.views import prompts
from prm9tool.views.access_dialog import ChangePasswordDialog, PasswordDialog
from prm9tool.views.action_state import enabled_actions
from prm9tool.views.actions import MainActions
from prm9tool.views.compare.workflow import CompareWorkflow
from prm9tool.views.emulated_valve import EmulatedValveMenu
from prm9tool.views.files.dcf_export import DcfExport, EdsExport
from prm9tool.views.files.workflow import FileWorkflow
from prm9tool.views.help_dialog import HelpWindow, about_html, open_homepage, show_help_page
from prm9tool.views.icons import icon
from prm9tool.views.link_guard import LinkGuard
from prm9tool.views.page_stack import PageStack
from prm9tool.views.parameters.view import ParameterListView
from prm9tool.views.record.actions import RecordActions
from prm9tool.views.screen_fit import fit_to_screen
from prm9tool.views.status_bar import MainStatusBar
from prm9tool.views.valve.selection import ValveSelectionDialog
from prm9tool.views.valve.status import ValveStatusWindow
from prm9tool.views.valve.workflow import ValveWorkflow

if TYPE_CHECKING:  # imported when first shown: it loads pyqtgraph
    from prm9tool.views.scope.widget import ScopeWidget

VIEWS = ("diagram", "parameters", "scope")
VIEW_KEY = "window/view"


class MainWindow(QMainWindow):
    """prm9tool's main window."""

    def __init__(
        self,
        doc: ParameterDocument,
        undo: DocumentUndo,
        access: AccessModel,
        connection: ValveConnection,
        settings: QSettings,
        parent: QWidget | None = None,
    ) -> None:
        super().__init__(parent)
        self.doc, self.undo, self.access = doc, undo, access
        self.connection, self.settings = connection, settings
        for model in (doc, undo, access, connection):
            if model.parent() is None:
                model.setParent(self)  # the models live exactly as long as the window
        self.passwords = PasswordStore(settings)
        self.sync = ValveSync(doc, connection, self)
        self.files = FileWorkflow(self, doc, undo, settings)
        self.valve = ValveWorkflow(self, doc, undo, connection, self.sync, settings, access)
        self.control = ValveControl(connection, self)
        self.records = RecordActions(self, self)
        self.compare = CompareWorkflow(
            self, doc, undo, access, connection, self.sync, self.valve, settings
        )
        self.dcf = DcfExport(doc, self)
        self.eds = EdsExport(doc, self)
        self.link_guard = LinkGuard(doc, connection, self)
        self.commands = MainActions(self)
        self.commands.build_menus(self.menuBar())
        self.emulated_menu = EmulatedValveMenu(self.control, doc, self).attach(self.commands)
        self.commands.build_toolbar(self.addToolBar("toolbar"))
        self.status = MainStatusBar(self)
        self.setStatusBar(self.status)
        self.parameter_view = ParameterListView(doc, access, self)
        self.stack = PageStack(VIEWS, self._build_view, self)
        self.views = self.stack.views
        self._scope: ScopeWidget | None = None  # built when first shown
        self.stack.add("diagram", self._make_diagram_view())
        self.stack.add("parameters", self.parameter_view)
        self.setCentralWidget(self.stack)
        self.status_window: ValveStatusWindow | None = None
        self.help_window: HelpWindow | None = None
        self.canopen_window: QWidget | None = None
        self.trace_window: QWidget | None = None
        self.setWindowIcon(icon("app"))
        self.setAcceptDrops(True)
        self._connect_actions()
        self._connect_models()
        self._restore_settings()
        self.retranslate()
        self._update_actions()

    # --- view factories (filled in by the diagram and oscilloscope work) ---------------------------
    def _make_diagram_view(self) -> QWidget:
        from prm9tool.views.diagram import DiagramView

        view = DiagramView(self.doc, self.access, self.connection, self)
        view.measuring_point_clicked.connect(self.open_scope)
        view.valve_selection_requested.connect(self.new_document)  # asks about unsaved changes
        view.canopen_requested.connect(self.show_canopen_window)
        view.tuning_requested.connect(self.show_tuning_window)
        return view

    def _make_scope_view(self) -> QWidget:
        from prm9tool.views.scope.widget import ScopeWidget

        self._scope = ScopeWidget(self.connection, self.doc, self, control=self.control)
        self._scope.tuning_requested.connect(lambda: self.show_tuning_window(None))
        return self._scope

    def _build_view(self, name: str) -> QWidget:
        """The oscilloscope is built when first needed: it loads pyqtgraph, which would
        otherwise cost a quarter of the start-up time."""
        if name != "scope":
            raise KeyError(name)
        view = self._make_scope_view()
        self.stack.add(name, view)
        return view

    def show_tuning_window(self, loop: str | None = None) -> None:
        """Open (or raise) the Tuning window on ``loop`` (``position`` or ``process``; None:
        the loop it shows, a new window the one the valve's control mode closes)."""
        from prm9tool.views.tuning.window import TuningWindow

        window = getattr(self, "tuning_window", None)
        if window is None or window.doc is not self.doc:
            window = TuningWindow(self.doc, self.connection, self, self.control, self.access)
            window.addAction(self.commands["valve_status"])  # Ctrl+I there too
            self.tuning_window = window
        index = window.loop.findData(loop)
        if index >= 0 and not window.runner.busy:
            window.loop.setCurrentIndex(index)
        window.show()
        window.raise_()

    def open_scope(self, key: str | None = None) -> None:
        """Switch to the oscilloscope (online only) and preselect measuring point ``key``."""
        if not self.connection.is_online:
            self.status.showMessage(self.tr("The oscilloscope works in online mode only."), 5000)
            return
        self.show_view("scope")
        if key and self._scope is not None:
            self._scope.preselect(key)

    def show_view(self, name: str) -> None:
        """Show ``diagram``, ``parameters`` or ``scope`` in the main area."""
        if name == "scope" and not self.connection.is_online:
            name = "parameters" if self.current_view() == "scope" else self.current_view()
        self.stack.show_page(name)
        self.commands[f"view_{name}"].setChecked(True)
        self.settings.setValue(VIEW_KEY, name)
        self._note_background_recording(name)

    def _note_background_recording(self, view: str) -> None:
        """The valve streams three measuring points at a time: while the oscilloscope records
        them, the diagram's others read "—" (said, not only in their tooltips; issue 34)."""
        note = self.tr(
            "The oscilloscope records in the background: the valve sends three measuring "
            "points at a time, so the diagram's other points show — until the recording stops."
        )
        if view == "diagram" and self._scope is not None and self._scope.running:
            self.status.showMessage(note, 15000)
        elif self.status.currentMessage() == note:
            self.status.clearMessage()  # stopped since: the note would mislead

    def current_view(self) -> str:
        """Name of the view shown."""
        return self.stack.current_name()

    # --- wiring --------------------------------------------------------------------------------------
    def _connect_actions(self) -> None:
        a = self.commands
        handlers = {
            "new": self.new_document,
            "open": self.files.open_dialog,
            "save": self.files.save,
            "save_as": self.files.save_as,
            "save_copy": self.files.save_backup_copy,
            "undo": self.undo.stack.undo,
            "redo": self.undo.stack.redo,
            "print": self.records.print_record,
            "export_pdf": self.records.export_pdf_dialog,
            "export_dcf": lambda: self.dcf.export_dialog(self.files.last_folder()),
            "export_eds": lambda: self.eds.export_dialog(self.files.last_folder()),
            "od_browser": self.show_object_dictionary,
            "exit": self.close,
            "view_diagram": lambda: self.show_view("diagram"),
            "view_parameters": lambda: self.show_view("parameters"),
            "view_scope": lambda: self.open_scope(),
            "canopen": self.show_canopen_window,
            "level_basic": lambda: self.access.set_level(Access.BASIC),
            "level_expert": self.request_expert,
            "change_password": self.change_password,
            "valve_selection": self.new_document,
            "valve_status": self.show_status_window,
            "upload": self.valve.upload,
            "download": self.valve.download,
            "store": self.valve.store,
            "restore_factory": self.valve.restore_factory,
            "restart": self.valve.restart,
            "verify_restart": self.valve.verify_by_restart,
            "hid_configuration": self.valve.configure_hid,
            "can_bus": self.valve.configure_can_bus,
            "can_trace": self.show_trace_window,
            "online": lambda: self.valve.go_online(),
            "offline": self.valve.go_offline,
            "help": self.show_help,
            "homepage": lambda: open_homepage(self),
            "about": self.show_about,
            "compare_file": self.compare.compare_with_file,
            "compare_valve": self.compare.compare_with_valve,
            "history": self.compare.show_history,
        }
        for name, handler in handlers.items():
            a[name].triggered.connect(lambda _checked=False, h=handler: h())
        for language, action in a.language_actions.items():
            action.triggered.connect(lambda _checked=False, lang=language: self.set_language(lang))
        recent = a.menus["recent"]
        self.files.recent_changed.connect(lambda: self.files.fill_recent_menu(recent))
        self.files.fill_recent_menu(recent)

    def _connect_models(self) -> None:
        c, d, s = self.connection, self.doc, self.status
        for signal in (c.online_changed, c.busy_changed, c.operation_finished,
                       d.modified_changed, d.type_key_changed):  # fmt: skip
            signal.connect(self._update_actions)
        self.undo.stack.canUndoChanged.connect(self._update_actions)
        self.undo.stack.canRedoChanged.connect(self._update_actions)
        self.access.level_changed.connect(self._update_actions)
        s.observe(c, d, self.sync, self.access)
        c.online_changed.connect(self.commands.set_online)
        c.online_changed.connect(self._on_connection_online_changed)
        c.live_values_changed.connect(self.parameter_view.model.show_live)
        c.reconnect_ended.connect(self._update_actions)
        c.lost.connect(self._update_actions)  # Go offline stops the search
        for signal in (d.modified_changed, d.path_changed):
            signal.connect(self._show_file)
        self.files.about_to_replace.connect(self.sync.stop)
        self.files.document_replaced.connect(self.valve.compare_again)
        for source in (self.files, self.valve, self.records, self.compare, self.dcf,
                       self.eds, self.parameter_view):  # fmt: skip
            source.message_posted.connect(lambda text: s.showMessage(text, 8000))

    def show_object_dictionary(self) -> None:
        """View → Object dictionary (online): every object, read and at Expert level write."""
        from prm9tool.views.od_browser import ObjectDictionaryDialog

        dialog = ObjectDictionaryDialog(self.connection, self.access, self.doc.variant, self)
        dialog.setAttribute(Qt.WidgetAttribute.WA_DeleteOnClose)
        self.connection.online_changed.connect(dialog.close)
        dialog.show()
        dialog.read_all()

    def _on_connection_online_changed(self, online: bool) -> None:
        if online:
            return
        self.parameter_view.model.forget_live_values()  # offline, live values would be stale
        if self.current_view() == "scope" and not self.connection.is_reconnecting:
            self.show_view("parameters")

    def _update_actions(self, *_args: object) -> None:
        a = self.commands
        uploaded = self.valve.verifier.available
        enabled = enabled_actions(self.doc, self.undo, self.access, self.connection, uploaded)
        for name, value in enabled.items():
            a[name].setEnabled(value)
        a["level_expert" if self.access.level is Access.EXPERT else "level_basic"].setChecked(True)
        a.language_actions[i18n.current_language()].setChecked(True)
        self.status.set_type_key(str(self.doc.type_key))

    def _show_file(self, *_args: object) -> None:
        self.status.set_file(self.doc.path, self.doc.modified)
        name = self.doc.path.name if self.doc.path else self.tr("untitled")
        self.setWindowTitle(f"{name}[*] – prm9tool")
        self.setWindowModified(self.doc.modified)

    # --- commands ------------------------------------------------------------------------------------
    def new_document(self) -> bool:
        """Valve selection: a new document with the factory defaults of the chosen type key."""
        dialog = ValveSelectionDialog(self.doc.type_key, self)
        if dialog.exec() != ValveSelectionDialog.DialogCode.Accepted:
            return False
        return self.files.new_document(dialog.selected_type_key())

    def request_expert(self) -> bool:
        """Switch to Expert after the password dialog; stays at Basic if cancelled."""
        accepted = PasswordDialog.DialogCode.Accepted
        if self.access.level is not Access.EXPERT and self._ask_password() == accepted:
            self.access.set_level(Access.EXPERT)
        self._update_actions()
        return self.access.level is Access.EXPERT

    def _ask_password(self) -> int:
        return PasswordDialog(self.passwords, self).exec()

    def change_password(self) -> None:
        """Change the Expert password (Expert level only)."""
        if self.access.level is Access.EXPERT:
            ChangePasswordDialog(self.passwords, self).exec()

    def set_language(self, language: str) -> None:
        """Switch the program language now and remember it."""
        i18n.set_language(language)
        for window in QApplication.topLevelWidgets():  # children without a locale of their own
            window.setLocale(QLocale(language))  # follow: spin boxes take the new decimal comma
        self.settings.setValue("language", language)
        self.status.clearMessage()  # a message of the language before would stay
        self._update_actions()

    def show_status_window(self) -> ValveStatusWindow:
        """Show the (non-modal) valve status window."""
        if self.status_window is None:
            self.status_window = ValveStatusWindow(self.connection, self, self.control)
        self.status_window.show()
        self.status_window.raise_()
        return self.status_window

    def show_canopen_window(self) -> QWidget:
        """Show the CANopen window of a -CA valve."""
        if self.canopen_window is None:
            from prm9tool.views.canbus.canopen_window import CanopenWindow

            self.canopen_window = CanopenWindow(
                self.doc, self.connection, self, access=self.access, sync=self.sync
            )
        self.canopen_window.show()
        self.canopen_window.raise_()
        return self.canopen_window

    def show_trace_window(self) -> QWidget:
        """Communication → CAN trace: decode a trace file, record the bus of the CAN bus
        dialog (docs/trace.md)."""
        if self.trace_window is None:
            from prm9tool.views.canbus.bus_dialog import saved_bus
            from prm9tool.views.trace.window import TraceWindow

            finder = self.valve.finder
            self.trace_window = TraceWindow(
                finder.recording, lambda: saved_bus(self.settings), self.settings, self
            )
        self.trace_window.show()
        self.trace_window.raise_()
        return self.trace_window

    def show_help(self) -> HelpWindow:
        """Show the help page of this program."""
        self.help_window = show_help_page(self)
        return self.help_window

    def show_about(self) -> None:
        """Versions and contact."""
        text = about_html(
            self.tr("prm9tool"),
            self.tr("Parameterization of PRM9 proportional directional valves."),
            self.tr("Free software under the GNU General Public License v3 or later."),
        )
        prompts.ask(
            self, prompts.Icon.Information, self.tr("About prm9tool"), text, prompts.Button.Ok
        )

    # --- language, settings, events ------------------------------------------------------------------
    def retranslate(self) -> None:
        """Set every text in the current language."""
        self.commands.retranslate()
        self._show_file()

    def changeEvent(self, event: QEvent) -> None:
        """Retranslate when the program language changes."""
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate()
        super().changeEvent(event)

    def _restore_settings(self) -> None:
        geometry = self.settings.value("window/geometry")
        if isinstance(geometry, QByteArray) and not geometry.isEmpty():
            self.restoreGeometry(geometry)
        else:
            fit_to_screen(self, 1200, 800)
        state = self.settings.value("window/state")
        if isinstance(state, QByteArray):
            self.restoreState(state)
        view = str(self.settings.value(VIEW_KEY, "diagram"))
        self.show_view(view if view in VIEWS and view != "scope" else "diagram")

    def _save_settings(self) -> None:
        self.settings.setValue("window/geometry", self.saveGeometry())
        self.settings.setValue("window/state", self.saveState())

    def closeEvent(self, event: QCloseEvent) -> None:
        """Ask about unsaved changes, go offline, remember the window."""
        if self._scope is not None:
            self._scope.stop()  # switches the setpoint generator off while still online
        tuning = getattr(self, "tuning_window", None)
        if not self.files.maybe_save():
            event.ignore()
            return
        if tuning is not None and tuning.runner.busy:
            tuning.stop()  # the test ends and puts the valve back before the link closes
        if not self.valve.go_offline():
            event.ignore()
            return
        self._save_settings()
        self.connection.shutdown()
        event.accept()

    def dragEnterEvent(self, event: QDragEnterEvent) -> None:
        """Accept *.prm files."""
        if _dropped_prm(event) is not None:
            event.acceptProposedAction()

    def dropEvent(self, event: QDropEvent) -> None:
        """Open a dropped *.prm file."""
        path = _dropped_prm(event)
        if path is not None:
            event.acceptProposedAction()
            self.files.open_path(path)


def _dropped_prm(event: QDragEnterEvent | QDropEvent) -> Path | None:
    mime = event.mimeData()
    for url in mime.urls() if mime.hasUrls() else []:
        if url.isLocalFile() and url.toLocalFile().lower().endswith(".prm"):
            return Path(url.toLocalFile())
    return None

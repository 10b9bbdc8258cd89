"""Valve and Communication workflows: online/offline with the diff prompt, upload, download,
and what happens when the valve is lost; it composes the parts that have their own module
(finding the valve, the upload, factory values and restart, verify by restart).

Nothing here touches the device: it drives the ValveConnection (which runs the I/O in its
worker thread) and the document, and reacts to their signals.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping

from PySide6.QtCore import QObject, QSettings, QTime, Signal
from PySide6.QtWidgets import QProgressDialog, QWidget

from prm9tool.catalogue.typekey import TypeKey
from prm9tool.errors import TypeKeyError
from prm9tool.model.access import AccessModel
from prm9tool.model.document import ParameterDocument, Raw
from prm9tool.model.undo import DocumentUndo
from prm9tool.online.connection import ValveConnection
from prm9tool.online.connection_protocol import ListedValves, ValveListing
from prm9tool.online.sync import ValveSync
from prm9tool.translate import error_text
from prm9tool.views import prompts
from prm9tool.views.online_dialogs import DiffChoice, OnlineDiffDialog
from prm9tool.views.operation_progress import OperationProgress
from prm9tool.views.valve.finder import ValveFinder
from prm9tool.views.valve.restart_check import VERIFY_RESTART, RestartVerifier
from prm9tool.views.valve.restarts import ValveRestarts
from prm9tool.views.valve.upload import ValveUpload

COMPARE = "compare"  # download made on going online, to compare with the document


class ValveWorkflow(QObject):
    """What the Valve and Communication menus do."""

    message_posted = Signal(str)  # a short status-bar message
    diff_dialog_created = Signal(object)  # OnlineDiffDialog, before it is shown (tests, help)

    def __init__(
        self,
        window: QWidget,
        doc: ParameterDocument,
        undo: DocumentUndo,
        connection: ValveConnection,
        sync: ValveSync,
        settings: QSettings,
        access: AccessModel | None = None,
    ) -> None:
        super().__init__(window)
        self._window = window
        self._doc = doc
        self._undo = undo
        self._connection = connection
        self._sync = sync
        self._settings = settings
        self.progress = OperationProgress(window, connection.cancel)
        self.uploads = ValveUpload(
            window, doc, connection, sync, self.progress, self.message_posted.emit, access
        )
        self.finder = ValveFinder(window, connection, settings, self.message_posted.emit)
        self.verifier = RestartVerifier(window, doc, connection, sync, self.uploads,
                                        self.progress, self.message_posted.emit,
                                        self._on_compare_finished)  # fmt: skip
        self.restarts = ValveRestarts(window, doc, connection, sync, settings, self.uploads,
                                      self.progress, self.message_posted.emit,
                                      self.take_valve_values, self._on_compare_finished)  # fmt: skip
        # "choose per parameter" in the going-online dialog (the compare workflow sets it)
        self.choose_per_parameter: Callable[[Mapping[str, Raw]], None] | None = None
        connection.online_changed.connect(self._on_connection_online_changed)
        connection.operation_finished.connect(self._on_connection_operation_finished)
        connection.progress.connect(self._on_connection_progress)
        connection.failed.connect(self._on_connection_failed)
        connection.lost.connect(self._on_connection_lost)
        connection.reconnected.connect(self._on_connection_reconnected)
        connection.other_valve.connect(self._on_connection_other_valve)
        connection.generator_undone.connect(self._on_generator_undone)
        self._back = False  # the valve came back by itself: the comparison says "back online"
        connection.live_values_changed.connect(doc.set_live)
        connection.write_failed.connect(sync.forget)
        connection.backup_written.connect(self._on_connection_backup_written)

    @property
    def progress_dialog(self) -> QProgressDialog | None:
        """The progress dialog of the running operation, if any."""
        return self.progress.dialog

    # --- communication -----------------------------------------------------------------------
    def configure_hid(self) -> ValveListing | None:
        """Show the HID configuration; returns the chosen device entry (or None)."""
        return self.finder.configure_hid()

    def configure_can_bus(self) -> None:
        """Communication → CAN bus: choose the bus and a valve on it, then go online with it."""
        self.finder.configure_can_bus()

    def chosen_entry(self, entries: ListedValves) -> ValveListing | None:
        """The valve to go online with among the listed ``entries`` (``ValveFinder``)."""
        return self.finder.chosen_entry(entries)

    def go_online(self, entry: ValveListing | str | None = None) -> None:
        """Connect to ``entry`` (a listed valve or a device id), else find the valve first."""
        self.finder.go_online(entry)

    def go_offline(self) -> bool:
        """Disconnect (offering to store values changed online); False if the user cancelled."""
        if self._connection.is_online and self._sync.unstored:
            answer = prompts.ask(
                self._window,
                prompts.Icon.Question,
                self.tr("Store changes in the valve"),
                self.tr(
                    "Values changed online are active in the valve but not stored: a restart "
                    "of the valve would undo them. Store them in the valve now?"
                ),
                prompts.Button.Yes | prompts.Button.No | prompts.Button.Cancel,
                prompts.Button.Yes,
            )
            if answer == prompts.Button.Cancel:
                return False
            if answer == prompts.Button.Yes:
                self._connection.store(self._doc.values)
        scope = getattr(self._window, "views", {}).get("scope")
        if scope is not None:  # the setpoint generator switches its override off while online
            scope.stop()
        self._sync.stop()
        self._connection.go_offline()
        return True

    def _on_connection_online_changed(self, online: bool) -> None:
        if not online:
            self._sync.stop()
            self.progress.close()
            self.message_posted.emit(self.tr("Offline"))
            return
        self.progress.start(COMPARE, self.tr("Reading the valve's parameters…"), cancellable=False)
        self._connection.download(COMPARE)

    def compare_again(self) -> None:
        """The document was replaced while online: compare it with the valve again (the
        differences prompt decides what is written), instead of writing it unasked."""
        if self._connection.is_online:
            self._sync.stop()
            self.progress.start(
                COMPARE, self.tr("Reading the valve's parameters…"), cancellable=False
            )
            self._connection.download(COMPARE)

    # --- the diff prompt --------------------------------------------------------------------------
    def _on_compare_finished(self, values: Mapping[str, Raw]) -> None:
        valve_key = self._valve_key()
        if valve_key is None:
            return
        back, self._back = self._back, False
        same_key = valve_key == self._doc.type_key
        differs = any(self._doc.values.get(mn) != value for mn, value in values.items())
        pristine = self._doc.path is None and not self._doc.modified
        if pristine and not (back and same_key and not differs):
            self._adopt_valve(valve_key, values)
            return
        if not self._same_valve_or_confirmed():
            self.go_offline()
            return
        if same_key and not differs:
            self._stamp(self._doc)  # it holds this valve's set: it is this valve's document
            self._sync.start(values)
            self.message_posted.emit(
                self.tr("Back online: document and valve agree")
                if back
                else self.tr("Online: document and valve agree")
            )
            return
        self._ask_about_differences(valve_key, values)

    def _same_valve_or_confirmed(self) -> bool:
        """A document read from one valve (its serial number) meets another: say so first,
        before anything is compared, taken or sent; No goes offline."""
        info, source = self._connection.device, self._doc.source_serial
        if info is None or not source or int(source) == int(info.serial):
            return True
        answer = prompts.ask(
            self._window,
            prompts.Icon.Warning,
            self.tr("Another valve"),
            self.tr(
                "The document was read from valve {0}; you are online with valve {1} "
                "(serial numbers). Continue with this document on valve {1}?\n\n"
                "Yes compares the two as usual (nothing is written unasked); "
                "No goes offline."
            ).format(source, info.serial),
            prompts.Button.Yes | prompts.Button.No,
            prompts.Button.No,
        )
        return answer == prompts.Button.Yes

    def _ask_about_differences(self, valve_key: TypeKey, values: Mapping[str, Raw]) -> None:
        dialog = OnlineDiffDialog(
            dict(self._doc.values), values, str(self._doc.type_key), str(valve_key), self._window
        )
        self.diff_dialog_created.emit(dialog)
        dialog.exec()
        if dialog.choice is DiffChoice.TAKE_VALVE:
            self.take_valve_values(values, self.tr("Values read from the valve"))
        elif dialog.choice is DiffChoice.SEND_DOCUMENT:
            if not self.upload(values):
                self.go_offline()  # as Cancel: nothing was written
        elif dialog.choice is DiffChoice.CHOOSE and self.choose_per_parameter is not None:
            self.choose_per_parameter(values)
        else:
            self.go_offline()

    def _adopt_valve(self, key: TypeKey, values: Mapping[str, Raw]) -> None:
        """An untouched new document simply becomes the valve's parameter set."""
        fresh = ParameterDocument(key)
        fresh.set_values(values, "valve", validate=False)
        self._stamp(fresh)
        fresh.mark_saved(None)
        with self._sync.suspended():
            self._doc.replace_with(fresh)
        self._undo.stack.clear()
        self._sync.start(values)
        self.message_posted.emit(self.tr("Online: parameters read from the valve"))

    def take_valve_values(self, values: Mapping[str, Raw], label: str) -> None:
        """The document takes the valve's type key and values as one undo step."""
        key = self._valve_key()
        if key is None:
            return
        other_type = self._doc.path if key != self._doc.type_key else None
        with self._sync.suspended():
            self._undo.stack.beginMacro(label)
            self._doc.set_type_key(key)
            self._doc.set_values(values, label, validate=False)
            self._undo.stack.endMacro()
        self._stamp(self._doc)
        self._sync.start(values)
        if other_type is not None:  # another valve type: the file keeps what it holds
            self._doc.detach_file()
            label = self.tr(
                "{0}: the valve is a {1}, so the document is a new, unsaved one "
                "({2} stays as it is)"
            ).format(label, key, other_type.name)
        self.message_posted.emit(label)

    def _stamp(self, doc: ParameterDocument) -> None:
        info = self._connection.device
        doc.set_source(
            None if info is None else info.serial, None if info is None else info.firmware
        )

    def _valve_key(self) -> TypeKey | None:
        info = self._connection.device
        text = "" if info is None else info.type_key
        try:
            return TypeKey.parse(text)
        except TypeKeyError as exc:
            self._on_connection_failed(
                self.tr("The valve reports an unknown type key: {0}").format(error_text(exc))
            )
            self.go_offline()
            return None

    # --- valve commands ---------------------------------------------------------------------------
    def upload(self, valve_values: Mapping[str, Raw] | None = None) -> bool:
        """Write the document into the valve (``ValveUpload.upload``); False when nothing
        is sent."""
        key = self._valve_key()
        return key is not None and self.uploads.upload(key, valve_values)

    def upload_values(self, values: Mapping[str, Raw], purpose: str = "") -> None:
        """Upload exactly ``values`` (``ValveUpload.upload_values``)."""
        self.uploads.upload_values(values, purpose)

    def expert_differences(self, valve_values: Mapping[str, Raw]) -> list[str]:
        """The Expert-level parameters whose document value differs from the valve's."""
        return self.uploads.expert_differences(valve_values)

    def confirms_online_values(self, values: Mapping[str, Raw]) -> bool:
        """Online, ``values`` about to go into the document, and so to the valve (a compared
        file's, a history record's): at Basic level Expert-level changes need a Yes, as an
        upload's do. Offline True (an upload asks later)."""
        if not self._connection.is_online:
            return True
        if self.uploads.basic_user_confirms_expert_values(self._doc.values, values):
            return True
        self.message_posted.emit(self.tr("Nothing was sent to the valve"))
        return False

    def store(self) -> None:
        """Valve → Store: the valve keeps what it works with now (also after a restart)."""
        self.progress.start("store", self.tr("Storing the parameters in the valve…"), False)
        self._connection.store_valve()

    def download(self) -> None:
        """Read the valve's parameters into the document (one undo step)."""
        self.progress.start("download", self.tr("Downloading the parameters from the valve…"))
        self._connection.download()

    def restore_factory(self) -> None:
        """Valve → Restore factory values (``ValveRestarts.restore_factory``)."""
        self.restarts.restore_factory()

    def restart(self) -> None:
        """Valve → Restart valve (``ValveRestarts.restart``)."""
        self.restarts.restart()

    def verify_by_restart(self) -> bool:
        """Valve → Verify by restart… (``RestartVerifier.start``)."""
        return self.verifier.start()

    # --- results ------------------------------------------------------------------------------------
    def _on_connection_operation_finished(self, name: str, result: object) -> None:
        self.progress.close()
        if name == COMPARE and isinstance(result, Mapping):
            self._on_compare_finished(result)
        elif name == "download" and isinstance(result, Mapping):
            self.take_valve_values(result, self.tr("Download from valve"))
            self.message_posted.emit(self.tr("The valve's parameters are in the document; File → "
                                             "Save backup copy… keeps a copy of them"))  # fmt: skip
        elif self.restarts.finished(name, result):
            pass
        elif name == "upload":
            self.uploads.finished(result)
        elif name == VERIFY_RESTART:
            self.verifier.finished(result)
        elif name == "store":
            self._sync.unstored = False
            at = QTime.currentTime().toString("HH:mm:ss")
            self.message_posted.emit(self.tr("The valve stored its parameters at {0}").format(at))

    def _on_connection_progress(self, done: int, total: int, step: str) -> None:
        self.progress.show_step(done, total, step)

    def _on_connection_failed(self, message: str) -> None:
        self.progress.close()
        self.verifier.failed()
        self.message_posted.emit(message)
        prompts.inform(self._window, prompts.Icon.Warning, self.tr("Valve communication"), message)

    def _on_connection_lost(self, message: str) -> None:
        busy = self._connection.lost_during_operation  # an upload, download, … was cut off
        self.progress.close()
        if self.verifier.lost(message):
            return
        if self._connection.is_reconnecting and not busy:
            self.message_posted.emit(
                self.tr("Connection to the valve lost; looking for it… ({0})").format(message)
            )
            return
        text = self.tr(
            "The connection to the valve was lost; prm9tool is offline now.\n"
            "Every value is kept in the document: save it, or go online again and send it."
        )
        if self._connection.is_reconnecting:
            text = self.tr(
                "The connection to the valve was lost; prm9tool is offline now and looks for "
                "the valve. When it is back, prm9tool compares it with the document and you "
                "decide what to do; nothing is sent again by itself.\n"
                "Every value is kept in the document."
            )
        prompts.inform(
            self._window,
            prompts.Icon.Critical,
            self.tr("Connection to the valve lost"),
            text,
            message,
        )

    def _on_connection_reconnected(self, info: object) -> None:
        self._back = True
        self.message_posted.emit(
            self.tr("The valve {0} is back online; reading its parameters…").format(
                getattr(info, "serial", "")
            )
        )

    def _on_generator_undone(self, names: list[str]) -> None:
        self.message_posted.emit(
            self.tr(
                "The valve is open again: what the setpoint generator cut off with the link had "
                "changed is as before ({0})"
            ).format(", ".join(names))
        )

    def _on_connection_other_valve(self, lost: int, found: int, device_id: str) -> None:
        text = self.tr(
            "Another valve (serial number {0}) is where the lost valve {1} was ({2}). prm9tool "
            "does not connect to it by itself: it is a new valve. Go online to work with it."
        ).format(found, lost, device_id)
        self.message_posted.emit(text)
        prompts.inform(self._window, prompts.Icon.Information, self.tr("Another valve"), text)

    def _on_connection_backup_written(self, path: str) -> None:
        self.message_posted.emit(
            self.tr("Backup of the valve's parameters saved: {0}").format(path)
        )

"""File workflows: new, open, save, save as, save a backup copy, recent files, unsaved-changes
prompt."""

from __future__ import annotations

from datetime import datetime
from pathlib import Path

from PySide6.QtCore import QObject, QSettings, Signal
from PySide6.QtWidgets import QMenu, QWidget

from prm9tool.catalogue.typekey import TypeKey
from prm9tool.errors import FileFormatError, FileProblem
from prm9tool.model.document import ParameterDocument
from prm9tool.model.undo import DocumentUndo
from prm9tool.translate import translated
from prm9tool.views import prompts
from prm9tool.views.files import dialogs as file_dialogs
from prm9tool.views.files.reader import read_in_background

MAX_RECENT = 8
MAX_LISTED_PROBLEMS = 200  # a message box lists at most this many, then says how many more
RECENT_KEY = "files/recent"
FOLDER_KEY = "files/last_folder"
BACKUP_FOLDER_KEY = "files/backup_folder"  # where the last backup copy went


class FileWorkflow(QObject):
    """Everything the File menu does with the one document of the window."""

    recent_changed = Signal()
    message_posted = Signal(str)  # a short status-bar message
    about_to_replace = Signal()  # the document's contents are about to be replaced
    document_replaced = Signal()  # … and have been (a file opened, a new valve type)

    def __init__(
        self,
        window: QWidget,
        doc: ParameterDocument,
        undo: DocumentUndo,
        settings: QSettings,
    ) -> None:
        super().__init__(window)
        self._window = window
        self._doc = doc
        self._undo = undo
        self._settings = settings
        self._reading: Path | None = None  # the file being read on a worker thread

    # --- settings ----------------------------------------------------------------------------
    def last_folder(self) -> str:
        """The folder of the last file opened or saved (home at first)."""
        return str(self._settings.value(FOLDER_KEY, str(Path.home())))

    def recent_files(self) -> list[str]:
        """Most recently used files, newest first."""
        value = self._settings.value(RECENT_KEY, [])
        if isinstance(value, str):
            value = [value]
        if not isinstance(value, list | tuple):  # e.g. a number in a hand-edited settings file
            return []
        return [str(v) for v in value]

    def _remember(self, path: Path) -> None:
        self._settings.setValue(FOLDER_KEY, str(path.parent))
        files = [str(path)] + [f for f in self.recent_files() if f != str(path)]
        self._settings.setValue(RECENT_KEY, files[:MAX_RECENT])
        self.recent_changed.emit()

    def _forget(self, path: str) -> None:
        self._settings.setValue(RECENT_KEY, [f for f in self.recent_files() if f != path])
        self.recent_changed.emit()

    def fill_recent_menu(self, menu: QMenu) -> None:
        """Rebuild the "Open recent" submenu."""
        menu.clear()
        for number, path in enumerate(self.recent_files(), start=1):
            action = menu.addAction(f"&{number} {Path(path).name}")
            action.setToolTip(path)
            action.setStatusTip(path)
            action.triggered.connect(lambda _checked=False, p=path: self.open_recent(p))
        menu.setEnabled(bool(self.recent_files()))

    # --- unsaved changes ---------------------------------------------------------------------------
    def maybe_save(self) -> bool:
        """Ask what to do with unsaved changes; False means the user cancelled."""
        if not self._doc.modified:
            return True
        name = self._doc.path.name if self._doc.path else self.tr("untitled")
        answer = prompts.ask(
            self._window,
            prompts.Icon.Warning,
            self.tr("Unsaved changes"),
            self.tr("The parameters in “{0}” have been changed. Save the changes?").format(name),
            prompts.Button.Save | prompts.Button.Discard | prompts.Button.Cancel,
            prompts.Button.Save,
        )
        if answer == prompts.Button.Save:
            return self.save()
        return answer == prompts.Button.Discard

    # --- commands ------------------------------------------------------------------------------------
    def new_document(self, type_key: TypeKey) -> bool:
        """Replace the document by the factory defaults of ``type_key`` (asks first)."""
        if not self.maybe_save():
            return False
        self._replace(ParameterDocument(type_key))
        self.message_posted.emit(self.tr("New parameter set for {0}").format(str(type_key)))
        return True

    def open_dialog(self) -> bool:
        """Ask for a file and open it."""
        if not self.maybe_save():
            return False
        path, _filter = file_dialogs.open_file_name(
            self._window,
            self.tr("Open parameter file"),
            self.last_folder(),
            self.tr("Parameter files (*.prm);;All files (*)"),
        )
        return bool(path) and self.open_path(Path(path), ask=False)

    def open_recent(self, path: str) -> bool:
        """Open a file of the recent-files menu (forgotten if it no longer exists)."""
        if not Path(path).exists():
            self._forget(path)
            prompts.inform(
                self._window,
                prompts.Icon.Warning,
                self.tr("File not found"),
                self.tr("“{0}” no longer exists; it was removed from the list.").format(path),
            )
            return False
        return self.open_path(Path(path))

    def open_path(self, path: Path, ask: bool = True) -> bool:
        """Open ``path``; a broken file is reported with every problem and changes nothing.

        While a file is being read (the window keeps working), opening another one is refused.
        """
        if self._reading is not None:
            self.message_posted.emit(self.tr("Still reading {0}").format(self._reading.name))
            return False
        if ask and not self.maybe_save():
            return False
        from prm9tool.files import prmdocument  # imported when first needed: faster start-up

        self._reading = path
        try:
            contents = read_in_background(self._window, path)
        finally:
            self._reading = None
        if contents is None:
            self.message_posted.emit(self.tr("Opening {0} cancelled").format(path.name))
            return False
        if isinstance(contents, FileFormatError):
            self._report_file_error(self.tr("Cannot open “{0}”").format(path.name), contents)
            return False
        self._replace(prmdocument.document_from(contents, path))
        self._remember(path)
        self.message_posted.emit(self.tr("Opened {0}").format(str(path)))
        if contents.warnings:
            prompts.inform(
                self._window,
                prompts.Icon.Information,
                self.tr("Opened with warnings"),
                self.tr(
                    "“{0}” was opened; %n warning(s) were found.", "", len(contents.warnings)
                ).format(path.name),
                self._problem_lines(path.name, contents.warnings),
            )
        return True

    def save(self) -> bool:
        """Save to the current file, or ask for a name if there is none — or if the file is
        of another valve type than the document now (a valve's values taken, another valve
        selected): that file is never overwritten unasked."""
        if self._doc.path is None or self._doc.file_type_key != self._doc.type_key:
            return self.save_as()
        return self.save_to(self._doc.path)

    def save_as(self) -> bool:
        """Ask for a file name and save there."""
        current = self._doc.path
        if current is not None and self._doc.file_type_key == self._doc.type_key:
            suggestion = current
        else:  # beside the file of another type, not over it
            folder = current.parent if current is not None else Path(self.last_folder())
            suggestion = folder / self._suggested_name()
        path, _filter = file_dialogs.save_file_name(
            self._window,
            self.tr("Save parameter file"),
            str(suggestion),
            self.tr("Parameter files (*.prm)"),
        )
        if not path:
            return False
        target = Path(path)
        if target.suffix.lower() != ".prm":
            target = target.with_name(target.name + ".prm")
        return self.save_to(target)

    def save_backup_copy(self, path: Path | None = None) -> Path | None:
        """File → Save backup copy: write the document's values to another file and keep
        working on the document as it was (its file, its unsaved changes: a later Save or
        Exit never writes into the copy). Asks for the name unless ``path`` is given; returns
        the file written, None when cancelled or when it cannot be written (then said so)."""
        if path is None:
            path = self._ask_backup_name()
            if path is None:
                return None
        from prm9tool.files.backup import write_device_file
        from prm9tool.files.prmdocument import contents_of

        try:  # what the document holds, also when it breaks a rule (the file then says so)
            problems = write_device_file(contents_of(self._doc), path)
        except FileFormatError as exc:
            self._report_file_error(self.tr("Cannot save “{0}”").format(path.name), exc)
            return None
        self._settings.setValue(BACKUP_FOLDER_KEY, str(path.parent))
        message = self.tr("Backup copy saved as {0}; {1} stays the open document").format(
            str(path), self._doc.path.name if self._doc.path else self.tr("untitled")
        )
        if problems:
            message += " " + self.tr("(marked: %n rule(s) broken)", "", len(problems))
        self.message_posted.emit(message)
        return path

    def _ask_backup_name(self) -> Path | None:
        folder = self._settings.value(BACKUP_FOLDER_KEY, self.last_folder())
        stamp = datetime.now().strftime("%Y%m%d-%H%M")
        name = self._suggested_name().removesuffix(".prm") + f"_{stamp}.prm"
        path, _filter = file_dialogs.save_file_name(
            self._window,
            self.tr("Save backup copy"),
            str(Path(str(folder)) / name),
            self.tr("Parameter files (*.prm)"),
        )
        if not path:
            return None
        target = Path(path)
        return target if target.suffix.lower() == ".prm" else target.with_name(target.name + ".prm")

    def save_to(self, path: Path) -> bool:
        """Save atomically to ``path``; errors are reported and nothing is lost."""
        from prm9tool.files import prmdocument

        try:
            prmdocument.save_document(self._doc, path)
        except FileFormatError as exc:
            self._report_file_error(self.tr("Cannot save “{0}”").format(path.name), exc)
            return False
        self._remember(path)
        self.message_posted.emit(self.tr("Saved {0}").format(str(path)))
        return True

    def _suggested_name(self) -> str:
        key = str(self._doc.type_key).replace("/", "_")
        serial = f"_{self._doc.source_serial}" if self._doc.source_serial else ""
        return f"{key}{serial}.prm"

    def _replace(self, new: ParameterDocument) -> None:
        self.about_to_replace.emit()
        self._doc.replace_with(new)
        self._undo.stack.clear()
        self.document_replaced.emit()

    def _problem_lines(self, path: str, problems: list[FileProblem]) -> str:
        """``FILE:LINE: problem`` for each problem, in the program language (the first
        ``MAX_LISTED_PROBLEMS``, then how many more: a file can hold 60 000)."""
        lines = [translated(problem.located(path)) for problem in problems[:MAX_LISTED_PROBLEMS]]
        more = len(problems) - MAX_LISTED_PROBLEMS
        if more > 0:
            lines.append(self.tr("… and %n more problem(s).", "", more))
        return "\n".join(lines)

    def _report_file_error(self, title: str, exc: FileFormatError) -> None:
        problems = exc.problems
        first = translated(problems[0].located(Path(exc.path).name)) if problems else str(exc)
        more = (
            self.tr("%n more problem(s) in the details.", "", len(problems) - 1)
            if len(problems) > 1
            else ""
        )
        prompts.ask(
            self._window,
            prompts.Icon.Critical,
            title,
            f"{first}\n{more}".strip(),
            prompts.Button.Ok,
            details=self._problem_lines(exc.path, problems) if len(problems) > 1 else "",
        )

"""The program's file dialogs: Qt's own, with the files' dates in the program language.

Qt's file dialog (the one it shows where the desktop offers none, as on a bare X server)
formats the "Date Modified" column with the *system* locale: with ``LANG=C`` it read
"1 12 2026 21:24" in every program language (issue 34 item 20). While one of these functions
runs, a file dialog that shows gets a delegate for that column that formats the date with
``QLocale()``, the program language's locale (``i18n.set_language``): "01.12.26 21:24" in
German and Czech, "12/1/26 9:24 PM" in English. A native dialog (Windows, macOS, a desktop's
portal) formats its dates itself.

The functions take and return what ``QFileDialog.getOpenFileName`` and
``QFileDialog.getSaveFileName`` do, and call them (so tests that replace those still see every
dialog the program opens).
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

from PySide6.QtCore import (
    QAbstractProxyModel,
    QEvent,
    QLocale,
    QModelIndex,
    QObject,
    QPersistentModelIndex,
)
from PySide6.QtWidgets import (
    QApplication,
    QFileDialog,
    QFileSystemModel,
    QStyledItemDelegate,
    QStyleOptionViewItem,
    QTreeView,
)

DATE_COLUMN = 3  # QFileSystemModel: name, size, type, date modified


class DateDelegate(QStyledItemDelegate):
    """Shows a file's modification date in the program language's short format."""

    def initStyleOption(
        self, option: QStyleOptionViewItem, index: QModelIndex | QPersistentModelIndex
    ) -> None:
        """The cell's text: the date as ``QLocale()`` writes it (the rest as Qt does)."""
        super().initStyleOption(option, index)
        model = index.model()
        source = model.index(index.row(), index.column(), index.parent()) if model else index
        while isinstance(model, QAbstractProxyModel):
            source = model.mapToSource(source)
            model = model.sourceModel()
        if isinstance(model, QFileSystemModel) and source.isValid():
            modified = model.lastModified(source)
            option.text = QLocale().toString(modified, QLocale.FormatType.ShortFormat)  # type: ignore[attr-defined]


def date_in_program_language(dialog: QFileDialog) -> None:
    """Give the detail views of ``dialog`` the :class:`DateDelegate` (once)."""
    for view in dialog.findChildren(QTreeView):
        if not isinstance(view.itemDelegateForColumn(DATE_COLUMN), DateDelegate):
            view.setItemDelegateForColumn(DATE_COLUMN, DateDelegate(view))


class _ShownDialogs(QObject):
    """An application event filter that dates every file dialog as it shows."""

    def eventFilter(self, watched: QObject, event: QEvent) -> bool:
        """Date a file dialog that shows; every event goes on."""
        if event.type() == QEvent.Type.Show and isinstance(watched, QFileDialog):
            date_in_program_language(watched)
        return False


@contextmanager
def dates_in_program_language() -> Iterator[None]:
    """While inside, every file dialog that shows has its dates in the program language
    (the filter is on the application only this long: it sees every event)."""
    app = QApplication.instance()
    watcher = _ShownDialogs()
    if app is not None:
        app.installEventFilter(watcher)
    try:
        yield
    finally:
        if app is not None:
            app.removeEventFilter(watcher)


def _from_home(args: tuple[Any, ...], kwargs: dict[str, Any]) -> tuple[Any, ...]:
    """The dialog's folder argument (the third, or ``dir``): a bare file name or none starts in
    the home folder, not in the folder prm9tool was started from; a path is kept."""
    if "dir" in kwargs:
        kwargs["dir"] = _in_home(kwargs["dir"])
        return args
    if len(args) >= 3:
        return (*args[:2], _in_home(args[2]), *args[3:])
    return args


def _in_home(folder: Any) -> Any:
    if not isinstance(folder, str) or Path(folder).is_absolute():
        return folder
    return str(Path.home() / folder) if folder else str(Path.home())


def open_file_name(*args: Any, **kwargs: Any) -> tuple[str, str]:
    """``QFileDialog.getOpenFileName(...)``, dates in the program language; a relative folder
    is taken from the home folder."""
    args = _from_home(args, kwargs)
    with dates_in_program_language():
        return QFileDialog.getOpenFileName(*args, **kwargs)


def save_file_name(*args: Any, **kwargs: Any) -> tuple[str, str]:
    """``QFileDialog.getSaveFileName(...)``, dates in the program language; a suggested bare
    file name is put in the home folder."""
    args = _from_home(args, kwargs)
    with dates_in_program_language():
        return QFileDialog.getSaveFileName(*args, **kwargs)

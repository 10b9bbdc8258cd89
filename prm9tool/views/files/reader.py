"""Reading a *.prm file off the GUI thread, for File → Open and File → Compare with file.

A file may be up to 1 MiB of lines to check (``prm9tool.files.prmfile.MAX_FILE_SIZE``); while a
worker thread reads it, a local event loop keeps the window working (repainting, the valve's
live values) and, after half a second, a window-modal dialog offers Cancel. The caller builds
its document or comparison from the result on the GUI thread.
"""

from __future__ import annotations

import threading
from pathlib import Path
from typing import TYPE_CHECKING

from PySide6.QtCore import QCoreApplication, QEventLoop, QObject, Qt, Signal
from PySide6.QtWidgets import QProgressDialog, QWidget

from prm9tool.errors import FileFormatError

if TYPE_CHECKING:
    from prm9tool.files.prmfile import PrmContents

BUSY_DIALOG_AFTER_MS = 500  # reading a file that takes longer shows a dialog with Cancel

translate = QCoreApplication.translate  # the name pyside6-lupdate looks for


class _Finished(QObject):
    """Tells the GUI thread that the worker thread is done."""

    done = Signal()


def read_in_background(parent: QWidget, path: Path) -> PrmContents | FileFormatError | None:
    """Read and check ``path`` on a worker thread; None when the user pressed Cancel.

    Returns the contents, or the ``FileFormatError`` listing every problem; any other
    exception of the reader (a bug) is raised again on the GUI thread, never lost.
    """
    from prm9tool.files import prmfile  # imported when first needed: faster start-up

    outcome: list[PrmContents | BaseException] = []
    finished = _Finished()
    loop = QEventLoop()
    finished.done.connect(loop.quit)  # queued: emitted on the worker thread

    def read() -> None:
        try:
            outcome.append(prmfile.read_file(path))
        except BaseException as exc:  # handed to the GUI thread
            outcome.append(exc)
        finally:
            finished.done.emit()

    busy = QProgressDialog(
        translate("FileWorkflow", "Reading “{0}”…").format(path.name),
        translate("FileWorkflow", "Cancel"),
        0,
        0,
        parent,
    )
    busy.setWindowModality(Qt.WindowModality.WindowModal)
    busy.setMinimumDuration(BUSY_DIALOG_AFTER_MS)
    busy.canceled.connect(loop.quit)
    threading.Thread(target=read, name=f"read {path.name}", daemon=True).start()
    loop.exec()
    busy.canceled.disconnect(loop.quit)
    busy.reset()
    busy.deleteLater()
    if not outcome:
        return None
    result = outcome[0]
    if isinstance(result, BaseException) and not isinstance(result, FileFormatError):
        raise result  # read_file raises nothing else
    return result

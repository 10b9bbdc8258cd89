"""The Tuning window's Twin page off the GUI thread (issue 31 item 2, QtCore only): a valve's
twin fitted from its characterization or from a characterization's JSON report, through
:func:`prm9tool.service.twin.fit_proven` as ``--fit-twin`` does.

On the connected valve it is a tuning job like the others (:func:`valve_procedure` for the
window's runner: the characterization recorded, the twin fitted, written, recorded and
characterized as the valve was). From a report nothing touches a valve: :class:`ReportFit`
runs it in a thread of its own and reports ``finished(ProvenTwin)`` or ``failed(message)`` on
the GUI thread.
"""

from __future__ import annotations

import os
import threading
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any

from PySide6.QtCore import QObject, Signal

from prm9tool.errors import Prm9Error
from prm9tool.translate import error_text

if TYPE_CHECKING:
    from prm9tool.analysis.profile import Profile
    from prm9tool.characterize.rig import Rig
    from prm9tool.service.history import HistoryHook
    from prm9tool.service.twin import ProvenTwin


def history_of(connection: Any | None) -> HistoryHook | None:
    """Where a twin is recorded: the connection's history (the window's), else the configured
    database (a report fitted with no connection at hand)."""
    hook = getattr(connection, "history", None)
    if hook is not None:
        return hook  # type: ignore[no-any-return]
    from prm9tool.service.history import open_history

    return open_history(command="Tuning window: fit twin")


def valve_procedure(
    connection: Any, path: str | os.PathLike[str], profile: Profile
) -> Callable[[Rig], ProvenTwin]:
    """The job the window's runner plays on the valve: ``--fit-twin OUT --device ID``'s."""
    from prm9tool.characterize.run import characterize
    from prm9tool.service.history import run_with_history
    from prm9tool.service.twin import fit_proven

    def procedure(rig: Rig) -> ProvenTwin:
        run = run_with_history(connection, lambda: characterize(rig, profile))
        return fit_proven(run, path, getattr(connection, "history", None))

    return procedure


class ReportFit(QObject):
    """``--fit-twin OUT --from RUN.json`` in a thread: one at a time."""

    finished = Signal(object)  # ProvenTwin
    failed = Signal(str)
    busy_changed = Signal(bool)

    def __init__(self, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self._thread: threading.Thread | None = None

    @property
    def busy(self) -> bool:
        """True while a fit runs."""
        return self._thread is not None and self._thread.is_alive()

    def start(
        self, report: str | os.PathLike[str], out: str | os.PathLike[str], history: Any
    ) -> None:
        """Fit the twin of the run ``report`` describes and write it to ``out`` (ignored while
        another fit runs)."""
        if self.busy:
            return
        self.busy_changed.emit(True)

        def work() -> None:
            from prm9tool.service.twin import fit_proven
            from prm9tool.twin.report import run_of_report

            try:
                proven = fit_proven(run_of_report(report), out, history)
            except Prm9Error as exc:
                self._done(None, error_text(exc))
            except OSError as exc:
                self._done(None, f"{Path(out)}: {exc.strerror or exc}")
            except ValueError as exc:
                self._done(None, str(exc))
            else:
                self._done(proven, "")

        self._thread = threading.Thread(target=work, name="twin-fit", daemon=True)
        self._thread.start()

    def _done(self, proven: ProvenTwin | None, message: str) -> None:
        self.busy_changed.emit(False)  # queued to the GUI thread (this object lives there)
        if proven is not None:
            self.finished.emit(proven)
        else:
            self.failed.emit(message)

    def wait(self, timeout: float = 120.0) -> None:
        """Wait for a running fit (closing the window, tests)."""
        if self._thread is not None:
            self._thread.join(timeout)

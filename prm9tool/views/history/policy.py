"""Before an upload: may it go ahead while the history database cannot be reached?

The setting (``unreachable`` in the history setting, docs/history.md) says ``ask`` (the
default on a service laptop), ``refuse`` (a production line: no record, no upload) or
``queue`` (upload; the record waits in the local queue until the database is back).
"""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication
from PySide6.QtWidgets import QWidget

from prm9tool.history.config import unreachable_policy
from prm9tool.translate import error_text
from prm9tool.views import prompts


def may_upload(parent: QWidget | None, problem: object) -> bool:
    """True when the upload may start (``problem``: None or the HistoryError)."""
    if problem is None:
        return True
    policy = unreachable_policy()
    if policy == "queue":
        return True
    reason = error_text(problem) if isinstance(problem, Exception) else str(problem)
    if policy == "refuse":
        prompts.inform(
            parent,
            prompts.Icon.Warning,
            QCoreApplication.translate("HistoryPolicy", "Upload refused"),
            QCoreApplication.translate("HistoryPolicy", "The history database cannot record this upload, and the "
               "setting says to refuse uploads then. Nothing was written to the valve."),
            reason,
        )  # fmt: skip
        return False
    answer = prompts.ask(
        parent,
        prompts.Icon.Warning,
        QCoreApplication.translate("HistoryPolicy", "History database unavailable"),
        QCoreApplication.translate("HistoryPolicy", "The history database cannot record this upload. Upload anyway "
           "and keep the record on this computer until the database is back?\n\n"
           "Yes uploads and queues the record; No uploads nothing."),
        prompts.Button.Yes | prompts.Button.No,
        prompts.Button.No,
        reason,
    )  # fmt: skip
    return answer == prompts.Button.Yes

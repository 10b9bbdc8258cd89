"""Valve → Verify by restart…: the worker job that restarts the valve after an upload and reads
back whether it kept the values (issue 20 item 2; ``--batch --verify-by-restart`` does the same
inside the upload, prm9tool.device.canlink.upload_steps).

Runs in the connection's worker thread, only after the user confirmed in the GUI that the
hydraulics are disconnected (a restart drops the spool to its rest position). The restart is
the link's own: NMT reset node over CANopen, the restart command over USB. Then every file
parameter is read back (the valve's whole set, for the history) and those the upload wrote are
compared with what the document says the valve holds. The history gets one ``restart-verify``
record whatever happens; a valve that does not come back is recorded, then the link error goes
on (the connection goes offline and the GUI says what the valve holds as far as known).
QtCore-free.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from prm9tool.catalogue.manual_od import NOT_KEPT_AFTER_RESTART, VERIFIED_RESTART
from prm9tool.errors import CommunicationError

if TYPE_CHECKING:
    from prm9tool.device.session import ValveSession
    from prm9tool.history.recorder import Details
    from prm9tool.service.history import HistoryHook

Raw = int | str
Progress = Callable[[int, int, str], None]
OPERATION = "restart-verify"  # its history operation (docs/history.md)


@dataclass(frozen=True)
class RestartVerification:
    """What the valve read back after the restart.

    ``values``: its whole parameter set now; ``mismatches``: ``{mnemonic: (expected, read
    back)}`` of the uploaded values it did not keep; ``store``: ``"verified after a restart"``
    when it kept every one, else how the upload stored them (None: the link's store command).
    """

    values: dict[str, Raw]
    checked: int
    mismatches: dict[str, tuple[Raw, Raw]] = field(default_factory=dict)
    store: str | None = None

    @property
    def verified(self) -> bool:
        """The valve kept every uploaded value through the restart."""
        return not self.mismatches


def verify_by_restart(
    session: ValveSession,
    expected: Mapping[str, Raw],
    upload_store: str | None,
    history: HistoryHook | None,
    progress: Progress | None = None,
) -> RestartVerification:
    """Restart the valve, read its set back and compare it with ``expected`` (the values the
    last upload wrote, as the document holds them now); ``upload_store`` is how that upload
    stored them. The outcome goes into ``history``; CommunicationError when the valve does not
    come back (recorded first)."""
    details: Details = {"upload_store": upload_store, "checked": len(expected)}
    try:
        session.restart()
        values = dict(session.download(progress))
    except CommunicationError as exc:
        if history is not None:
            details |= {"store": upload_store, "error": str(exc)}
            history.add(session, OPERATION, "communication-error", None, details, "restart")
        raise
    compared = {m: v for m, v in expected.items() if m in values}
    mismatches = {m: (v, values[m]) for m, v in compared.items() if values[m] != v}
    store = upload_store if mismatches else VERIFIED_RESTART
    result = RestartVerification(values, len(compared), mismatches, store)
    if history is not None:
        details |= {"store": store, "checked": len(compared)}
        if mismatches:
            details |= {"error": NOT_KEPT_AFTER_RESTART, "mismatches": {
                m: [str(want), str(got)] for m, (want, got) in mismatches.items()}}  # fmt: skip
        outcome = "verification-failed" if mismatches else "ok"
        history.add(session, OPERATION, outcome, values, details, "verify" if mismatches else None)
    return result

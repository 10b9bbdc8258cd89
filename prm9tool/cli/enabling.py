"""The command line's one ``--enable``: what its CANopen master does to a -CA valve (NMT start
when it waits, then the control word 08h → 09h → 0Bh → 0Fh, the valve service's
``commission``), and one rule for the exit code of an enable that fails, whether ``--enable``
runs alone or before ``--characterize``, ``--autotune``, ``--signature`` or ``--fit-twin``:

- 2 (usage): the valve's CANopen is off (no -CA, or switched off): it enables itself and takes
  no control word (manual §7.4), so nothing is sent;
- 1 (the valve refused): the valve answered but did not reach DEVICE_MODE_ACTIVE (a fault
  still present: :class:`~prm9tool.device.enabling.NotEnabledError` says which) or refused the
  control word (an SDO abort) — a refusal is not a communication error;
- 6 (communication): no answer, a link lost (:class:`~prm9tool.errors.CommunicationError`).

The words are the service's, after ``--enable:`` (docs/api.md). No Qt.
"""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING

from prm9tool.cli.batch_devices import BatchError
from prm9tool.errors import CommunicationError, ExitCode, Prm9Error

if TYPE_CHECKING:
    from prm9tool.device.records import ValveStatus
    from prm9tool.service.valve import ValveService

__all__ = ["ENABLING", "NO_CONTROL_WORD", "NoControlWordError", "commission", "exit_code_of"]

NO_CONTROL_WORD = (
    "this valve's CANopen is off (a valve without -CA, or CANopen switched off): it enables "
    "itself when it is ready and takes no control word (manual §7.4); nothing was sent"
)
ENABLING = "enabling the valve: NMT start, control word 08h → 09h → 0Bh → 0Fh"


class NoControlWordError(Prm9Error):
    """``--enable``/``--disable`` of a valve that is not a CANopen slave (NMT off)."""


def exit_code_of(exc: Prm9Error) -> ExitCode:
    """The exit code of an ``--enable`` (or ``--disable``) that failed with ``exc``."""
    if isinstance(exc, NoControlWordError):
        return ExitCode.USAGE
    if isinstance(exc, CommunicationError):
        return ExitCode.COMMUNICATION
    return ExitCode.VERIFY_FAILED  # the valve refused: not enabled (a fault), an SDO abort


def takes_control_word(service: ValveService) -> None:
    """NoControlWordError when the valve, booted, has CANopen off (nothing sent to it)."""
    if str(service.commissioning.wait_booted().nmt_state) in ("off", ""):
        raise NoControlWordError(NO_CONTROL_WORD)


def commission(service: ValveService, say: bool = True) -> ValveStatus:
    """``--enable`` on the valve of ``service``: refused (nothing sent) when its CANopen is
    off, else NMT start when it waits and the enable sequence; the status after. ``say``:
    state on standard error what is sent. A failure raises BatchError with the rule's exit
    code and ``--enable: <the service's words>``."""
    try:
        takes_control_word(service)
        if say:
            print(f"prm9tool: {ENABLING}", file=sys.stderr)
        return service.commissioning.commission()
    except Prm9Error as exc:
        raise BatchError(exit_code_of(exc), f"--enable: {exc}") from exc

"""What an upload reports (the contract is :class:`~prm9tool.device.session.ValveSession`'s):
its result, the values that read back differently, what a failed upload left in the valve, and
the communication error that names the failed step and how far the upload got. No Qt.
"""

from __future__ import annotations

import time
from collections.abc import Mapping, Sequence

from prm9tool.catalogue import Parameter
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.device.records import STEPS, Value
from prm9tool.errors import CommunicationError, SdoAbortError

RESTARTED_BEFORE_STORE = (
    "the valve's values changed after the store was acknowledged (it restarted before the "
    "store?): its stored set is not the upload"
)


def differences(
    params: Sequence[Parameter],
    values: Mapping[str, Value],
    actual: Mapping[str, Value | SdoAbortError],
) -> dict[str, tuple[Value, Value]]:
    """``{mnemonic: (uploaded, read back)}`` of every value that reads back differently."""
    return {
        p.mnemonic: (values[p.mnemonic], shown(actual[p.mnemonic]))
        for p in params
        if actual[p.mnemonic] != values[p.mnemonic]
    }


def shown(value: Value | SdoAbortError) -> Value:
    """A value read back as the report shows it (a refusal as its text)."""
    return str(value) if isinstance(value, SdoAbortError) else value


def since(start: float) -> float:
    """Seconds since ``start`` (``time.monotonic``)."""
    return time.monotonic() - start


KEPT_OUTCOME = (
    "every value the upload changed was put back from the backup and reads back so: the valve "
    "holds its previous set again (it keeps what is written)"
)


RESTARTED_OUTCOME = (
    "it runs on the set it came back with from the restart, its stored set: the upload's values "
    "except those; nothing was written to it after the restart"
)


def reload_outcome(problem: str | None, kept: bool = False, restarted: bool = False) -> str:
    """What a failed upload left in the valve, given why the reload failed (None: it worked).
    ``kept``: a valve that keeps every write (no store command): the backup's values were
    written back instead, and ``problem`` says what it holds where that failed. ``restarted``
    (a valve with a store command whose verification by restart found the upload not kept):
    the restart put its stored set into its working values, nothing is put back."""
    if restarted and not kept:
        return RESTARTED_OUTCOME
    if kept:
        return KEPT_OUTCOME if problem is None else f"putting the backup back failed: {problem}"
    if problem is None:
        return "the valve's working parameters were reset to its stored ones (no restart)"
    return (
        "resetting its working parameters to the stored ones failed too "
        f"({problem}): restart the valve, hydraulics off, to return to them"
    )


def step_error(
    exc: CommunicationError,
    step: str,
    problem: str | None,
    written: int,
    verified: bool,
    kept: bool = False,
) -> CommunicationError:
    """``exc`` with the failed step and the valve's state named; ``problem``: reload failure.

    ``written`` and ``verified`` say how far the upload got; they travel as attributes.
    """
    number = list(STEPS).index(step) + 1
    if kept:
        outcome = reload_outcome(problem, kept=True)
    elif step != "store":
        outcome = f"nothing was stored; {reload_outcome(problem)}"
    elif problem is None:
        outcome = (
            "the store may not have completed: the valve now holds either its previous "
            "parameters or the complete new set, working and stored alike — download to check"
        )
    else:
        outcome = (
            "the store may not have completed: after a restart the valve holds either its "
            "previous parameters or the complete new set — download to check "
            f"(resetting its working parameters failed too: {problem})"
        )
    error = type(exc)(f"upload failed while {STEPS[step]} (step {number} of 3): {exc}; {outcome}")
    error.step = step  # type: ignore[attr-defined]
    error.reloaded = problem is None  # type: ignore[attr-defined]
    error.written = written  # type: ignore[attr-defined]
    error.verified = verified  # type: ignore[attr-defined]
    return error


def type_problem(
    file_key: TypeKey, valve_key: TypeKey, force: bool, option: str = "--force-type"
) -> str | None:
    """Why a parameter set of ``file_key`` must not go into a ``valve_key`` valve (None: it
    may). Another variant never (its parameter set differs); another type key of the same
    variant only with ``force``, which the message names as ``option``."""
    if file_key == valve_key:
        return None
    if file_key.variant != valve_key.variant:
        return (
            f"the file is for {file_key} ({file_key.variant.label}) but the valve is "
            f"{valve_key} ({valve_key.variant.label}): the parameter sets differ, even "
            f"{option} cannot upload it"
        )
    if force:
        return None
    return (
        f"the file is for {file_key} but the valve is {valve_key} (use {option} to upload anyway)"
    )

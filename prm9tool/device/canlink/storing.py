"""How a -CA valve keeps its parameters, and writing so that it never holds a refused set.

The manual's object list (table 7-13) has no store object 0x1010 and §7.2.2 (figure 7-3,
point B) says the valve keeps the parameters once set; a valve that does have 0x1010 tells
its abilities in sub-index 1 (CiA 301: bit 0 = stores on command, bit 1 = stores by itself).
So a valve is one of:

* :data:`STORED_WITH_1010` — 0x1010/1 with bit 0: the upload ends with "save" (CiA 301);
* :data:`KEPT_AS_WRITTEN` — no 0x1010, or one that stores by itself only (bit 1): every write
  is durable as it lands, nothing to send at the end;
* neither (0x1010/1 reads 0): it cannot keep an upload at all — :class:`CannotStoreError`
  before anything is written.

On a valve that keeps each write, no intermediate combination may break a rule of the
catalogue (a limit below the value it bounds, a curve that turns back), because a power loss
can freeze any of them: :func:`safe_order` orders the writes so that every step leaves a set
the rules accept, as far as one exists (limits before the values they bound, curve points in
the direction they move).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING

from prm9tool.catalogue import CATALOGUE, Parameter
from prm9tool.catalogue.manual_od import KEPT_AS_WRITTEN, STORED_WITH_1010, VERIFIED_RESTART
from prm9tool.catalogue.variant import Variant
from prm9tool.device.canlink.sdo import MISSING, SdoChannel
from prm9tool.errors import Prm9Error, SdoAbortError

if TYPE_CHECKING:
    from prm9tool.device.session import ValveSession

Value = int | str
__all__ = ["KEPT_AS_WRITTEN", "STORED_WITH_1010", "VERIFIED_RESTART", "safe_order", "store_kind"]
STORE_ON_COMMAND, STORE_AUTONOMOUSLY = 0x01, 0x02  # CiA 301, 0x1010 sub-index 1


class CannotStoreError(Prm9Error):
    """The valve has 0x1010 but can neither store on command nor by itself."""


def store_kind(sdo: SdoChannel) -> str:
    """:data:`STORED_WITH_1010` or :data:`KEPT_AS_WRITTEN`, from 0x1010/1 (CiA 301)."""
    try:
        capability = sdo.read_u32(0x1010, 1)
    except SdoAbortError as exc:
        if exc.code in MISSING:
            return KEPT_AS_WRITTEN  # manual table 7-13, §7.2.2
        raise
    if capability & STORE_ON_COMMAND:
        return STORED_WITH_1010
    if capability & STORE_AUTONOMOUSLY:
        return KEPT_AS_WRITTEN
    raise CannotStoreError(
        f"the valve cannot store parameters: 0x1010/1 reads 0x{capability:08X} (CiA 301: "
        "neither on command nor by itself); nothing was written"
    )


def _errors(variant: Variant, values: Mapping[str, Value]) -> set[str]:
    return {str(p.text) for p in CATALOGUE.check_rules(variant, values) if p.severity == "error"}


def safe_order(
    variant: Variant,
    params: Sequence[Parameter],
    holds: Mapping[str, Value],
    target: Mapping[str, Value],
) -> list[Parameter]:
    """``params`` in an order whose every step leaves a set the catalogue's rules accept,
    starting from what the valve ``holds``; values it holds already keep their place. Where no
    such order exists the rest follow in their given order (the valve may refuse one; the
    upload then puts the backup back)."""
    state = dict(holds)
    pending = [p for p in params if holds.get(p.mnemonic, holds) != target[p.mnemonic]]
    ordered = [p for p in params if p not in pending]
    refused = _errors(variant, state)
    while pending:
        for param in pending:
            trial = {**state, param.mnemonic: target[param.mnemonic]}
            problems = _errors(variant, trial)
            if problems <= refused:
                break
        else:
            return ordered + pending
        pending.remove(param)
        ordered.append(param)
        state, refused = trial, problems
    return ordered


def factory_values(variant: Variant) -> dict[str, Value]:
    """The catalogue's factory set of the *.prm parameters of ``variant``."""
    return {p.mnemonic: p.default_for(variant) for p in CATALOGUE.file_parameters(variant)}


def factory_upload(session: ValveSession) -> None:
    """Restore factory values on a valve without 0x1011: the catalogue's factory set uploaded
    (write in a safe order, read back, kept as written); Prm9Error when it failed."""
    values = {
        m: v for m, v in factory_values(session.variant).items() if m not in session.unavailable
    }
    result = session.upload(values)
    if not result.stored:
        from prm9tool.device.upload_outcome import reload_outcome

        shown = "; ".join(f"{m}: {w} → {g}" for m, (w, g) in result.mismatches.items())
        why = result.failure or shown
        kept = result.store == KEPT_AS_WRITTEN
        raise Prm9Error(
            f"restoring the factory values failed ({why}); "
            f"{reload_outcome(result.reload_error, kept, result.restarted)}"
        )

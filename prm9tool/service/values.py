"""One validation of a user's value, for every front door.

The window, the command line (``--set``) and a script's ``valve["LIMTA"] = …`` hand what the
user typed or passed to :func:`user_value`: its type (a number for a numeric parameter — not
``True``, not ``None`` —, text for a text one), a display text parsed as the catalogue parses
it, the value rounded to the parameter's resolution, its catalogue range and whether the
object dictionary accepts writes at all. A refusal is a :class:`~prm9tool.errors.Prm9Error`
that names the mnemonic, in the same words at every door, before anything is sent.
:func:`check_rules` adds the rules between parameters (LIMTA/LIMTB at most CURNORM, manual
table 7-14) with the valve's own caps. No Qt.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping
from numbers import Real
from typing import TYPE_CHECKING

from prm9tool.catalogue import CAPPED_BY, CATALOGUE, Parameter
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.errors import AccessDeniedError, ValueRangeError
from prm9tool.messages import QT_TRANSLATE_NOOP, Message

if TYPE_CHECKING:
    from prm9tool.device.records import Value
    from prm9tool.device.session import ValveSession

__all__ = ["ReadOnlyError", "caps_held", "check_rules", "read_only_text", "user_value"]


EXPECTED_NUMBER = QT_TRANSLATE_NOOP("Service", "{0}: expected a number in {1}, got {2}")


class ReadOnlyError(AccessDeniedError):
    """The parameter is read-only (the valve's object dictionary refuses every write)."""


def read_only_text(mnemonic: str) -> Message:
    """The refusal of a write to a read-only parameter (every door says it so)."""
    return QT_TRANSLATE_NOOP("Service", "{0}: the parameter is read-only")(mnemonic)


def user_value(param: Parameter, value: object, caps: Mapping[str, Value] | None = None) -> Value:
    """The raw value of ``value`` for ``param``, checked; raises before anything is sent.

    ``value``: a display value (``1800`` mA, ``12.5`` %), a display text as typed
    (``"1800"``, ``"0,4"``, a choice's label) or, for a text parameter, the text. Rounds to
    the parameter's resolution (the nearest raw value). ReadOnlyError for a read-only
    parameter, ValueRangeError for a value of the wrong type, not a number or outside the
    range (each names the mnemonic). ``caps``: what the valve holds of the parameters that
    cap others (:func:`caps_held`): LIMTA beyond its catalogue range is then refused with the
    range the window's editors show, ``0 … 2600 mA`` on a valve with CURNORM 2600 mA.
    """
    if not param.writable:
        raise ReadOnlyError(read_only_text(param.mnemonic))
    if param.is_string:
        param.check_raw(value)  # type: ignore[arg-type]  # "LIMTA: expected text, got 5"
        return str(value)
    if isinstance(value, str):
        raw = param.parse_display(value)  # "abc": "LIMTA: 'abc' is not a number"
    elif isinstance(value, bool) or not isinstance(value, Real):
        unit = f" in {param.unit}" if param.unit else ""
        raise ValueRangeError(f"{param.mnemonic}: expected a number{unit}, got {value!r}")
    elif not math.isfinite(float(value)):
        raise ValueRangeError(f"{param.mnemonic}: {value!r} is not a number")
    else:
        raw = param.to_raw(float(value))
    cap = CAPPED_BY.get(param.mnemonic)
    param.check_raw(raw, (caps or {}).get(cap) if cap else None)
    return raw


def caps_held(session: ValveSession, mnemonics: Iterable[str]) -> dict[str, Value]:
    """What the valve holds of the parameters that cap ``mnemonics`` (LIMTA, LIMTB: its
    CURNORM, manual table 7-14); reads them, nothing when none is capped or the valve lacks
    the object (it then checks the cap itself)."""
    from prm9tool.device.session import NotAvailableError

    caps = {CAPPED_BY[m] for m in mnemonics if m in CAPPED_BY}
    try:
        return session.read_many(sorted(caps)) if caps else {}
    except NotAvailableError:
        return {}


def check_rules(
    session: ValveSession, values: Mapping[str, Value], held: Mapping[str, Value] | None = None
) -> None:
    """ValueRangeError naming every cross-parameter rule ``values`` break together with the
    valve's own caps (LIMTA/LIMTB at most its CURNORM, manual table 7-14); reads the caps
    unless ``held`` (:func:`caps_held`) gives them."""
    if held is None:
        held = caps_held(session, values)
    variant = TypeKey.parse(session.info.type_key).variant
    problems = CATALOGUE.check_rules(variant, {**values, **held})  # the valve's caps count
    errors = [p.message for p in problems if p.severity == "error"]
    if errors:
        raise ValueRangeError("; ".join(errors))

"""User edits that depend on the access level (shared by the parameter list and the diagram).

At Basic access level the four setpoint ramps are set together (manual §8.7.2, "Rampová
funkce"): changing one ramp sets every ramp of the valve to that value as one undo step.
"""

from __future__ import annotations

import math

from prm9tool.catalogue import CAPPED_BY, CATALOGUE, Access, Parameter
from prm9tool.errors import AccessDeniedError
from prm9tool.i18n import format_value
from prm9tool.messages import QT_TRANSLATE_NOOP, Message, Number
from prm9tool.model.access import AccessModel
from prm9tool.model.document import ParameterDocument, Raw

RAMPS: tuple[str, ...] = ("RAMPSETPOSUP", "RAMPSETPOSDOWN", "RAMPSETNEGUP", "RAMPSETNEGDOWN")

_ROUNDED = QT_TRANSLATE_NOOP("Edits", "{0}{1} rounded to {2}{1} (resolution {3}{1})")


def linked_mnemonics(doc: ParameterDocument, access: AccessModel, mnemonic: str) -> list[str]:
    """The parameters an edit of ``mnemonic`` changes at the current level (itself, or all ramps)."""
    if mnemonic in RAMPS and access.level is Access.BASIC:
        return [mn for mn in RAMPS if mn in doc.values]
    return [mnemonic]


def allowed_range(param: Parameter, doc: ParameterDocument | None) -> tuple[int, int, str | None]:
    """Lowest and highest raw value ``param`` may take in ``doc``, and the parameter that caps
    it (LIMTA and LIMTB: at most CURNORM, manual table 7-14), None when only its own range
    does. Without a document: the catalogue range."""
    cap = CAPPED_BY.get(param.mnemonic) if doc is not None else None
    if doc is None or cap is None:
        return param.raw_min, param.raw_max, None
    return param.raw_min, min(param.raw_max, int(doc.value(cap))), cap


def range_text(param: Parameter, doc: ParameterDocument | None, *, unit: bool = True) -> str:
    """The allowed range as every editor shows it: ``0 … 2600 mA (CURNORM)``, ``0 … 100 %``;
    the codes of a choice parameter. ``doc`` None: the catalogue range; ``unit``: with the unit.
    """
    if param.choices:
        return ", ".join(str(code) for code, _label in param.choices)
    low, high, cap = allowed_range(param, doc)
    suffix = f" {param.unit}" if unit and param.unit else ""
    capped = f" ({cap})" if cap is not None else ""
    return f"{format_value(param, low)} … {format_value(param, high)}{suffix}{capped}"


def rounding_note(param: Parameter, entered: str, raw: Raw) -> Message | None:
    """What to tell the user when ``entered`` (a number as typed, point or comma) is finer than
    ``param``'s resolution and became ``raw``: ``2100.7 mA rounded to 2101 mA (resolution
    1 mA)``, short enough for the status bar beside its fields at 1024 pixels; None when the
    value is kept as typed (or is not a number)."""
    if param.is_string or param.choices or not isinstance(raw, int):
        return None
    typed_text = entered.strip()
    if typed_text.count(",") == 1:
        typed_text = typed_text.replace(",", ".")
    try:
        typed = float(typed_text)
    except ValueError:
        return None
    shown = param.format_display(raw)  # as every editor, the list and the file show it
    if float(shown) == typed:  # "7 %" of 0.0061 % steps is 7.0007 %, shown as the 7 typed
        return None
    unit = f" {param.unit}" if param.unit else ""
    return _ROUNDED(Number(typed_text), unit, Number(shown), Number(resolution_text(param)))


def resolution_text(param: Parameter) -> str:
    """One step of ``param`` to two significant digits (``0.0061``, ``0.01``, ``1``): its
    shortest display text ("0.006") would read back as the step but is not its size."""
    decimals = max(0, 1 - math.floor(math.log10(param.scale)))
    text = f"{param.scale:.{decimals}f}"
    return text.rstrip("0").rstrip(".") if "." in text else text


def _refuse_beyond_cap(param: Parameter, doc: ParameterDocument, raw: Raw) -> None:
    """A capped value (LIMTA ≤ CURNORM) beyond even the catalogue's range is refused with the
    range the editors show (0 … 2600 mA), not the catalogue's 0 … 4000 mA that contradicts it;
    within the catalogue's range the document's rule names the cap. The one check every door
    makes (``Parameter.check_raw`` with the cap, as the valve service's)."""
    cap = CAPPED_BY.get(param.mnemonic)
    if cap is None or not isinstance(raw, int) or param.raw_min <= raw <= param.raw_max:
        return
    param.check_raw(raw, doc.value(cap))


def apply_edit(
    doc: ParameterDocument, access: AccessModel, mnemonic: str, raw: Raw, entered: str | None = None
) -> Message | None:
    """Set ``mnemonic`` as the user at the current access level would; one undo step.

    Raises AccessDeniedError if the level may not change it, ValueRangeError with the reason
    if the value is not allowed. Nothing changes when an error is raised. ``entered``: the
    text the user typed; the value is then set and the note returned if it was rounded to
    the parameter's resolution (:func:`rounding_note`), which the editor shows. Else None.
    """
    param = CATALOGUE[mnemonic]
    reason = access.lock_reason(param)
    if reason is not None:
        raise AccessDeniedError(reason)
    _refuse_beyond_cap(param, doc, raw)
    targets = linked_mnemonics(doc, access, mnemonic)
    for target in targets:
        doc.validate(target, raw)
    if len(targets) == 1:
        doc.set_value(mnemonic, raw)
    else:
        unit = f" {param.unit}" if param.unit else ""
        label = QT_TRANSLATE_NOOP("Edits", "All ramps = {0}{1}")(
            Number(param.format_display(raw)), unit
        )
        doc.set_values(dict.fromkeys(targets, raw), label)
    return rounding_note(param, entered, raw) if entered is not None else None

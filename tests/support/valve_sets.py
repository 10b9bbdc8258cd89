"""Parameter sets for upload tests: complete, different from a given set in every entry, and
valid — the valve refuses to store a set that breaks a cross-parameter rule (docs/emulator.md),
so the linearization points move by a small step and keep increasing."""

from __future__ import annotations

import re
from collections.abc import Mapping

from prm9tool.catalogue import CATALOGUE, Parameter
from prm9tool.catalogue.variant import Variant

CURVE_POINT = re.compile(r"(SETPLIN|SENSLIN)[XY][A-I]")
CURVE_STEP = 100  # far below the 4096 between neighbouring factory points


def moved(param: Parameter, current: int | str) -> int | str:
    """A valid value of ``param`` other than ``current``."""
    assert isinstance(current, int)
    if CURVE_POINT.fullmatch(param.mnemonic):
        return (
            current + CURVE_STEP if current + CURVE_STEP <= param.raw_max else current - CURVE_STEP
        )
    allowed = [code for code, _ in param.choices] or [param.raw_min, param.raw_max]
    return next(v for v in allowed if v != current)


def changed_set(
    variant: Variant, base: Mapping[str, int | str] | None = None
) -> dict[str, int | str]:
    """Every file parameter of ``variant`` moved away from ``base`` (default: factory)."""
    params = CATALOGUE.file_parameters(variant)
    start = base if base is not None else {p.mnemonic: p.default_for(variant) for p in params}
    return {p.mnemonic: moved(p, start[p.mnemonic]) for p in params}

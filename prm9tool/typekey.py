"""PRM9 type keys: parse, validate, format, and derive the electronics variant.

Layout (SPEC §2.2, inference from the manual's examples)::

    PRM9-06.3Z11/30-24E02S02-CA
    │    │  │    │  │ │  │   └─ optional CANopen interface
    │    │  │    │  │ │  └───── S02 (electronics series)
    │    │  │    │  │ └──────── E02 (position feedback) or E04 (plus process feedback)
    │    │  │    │  └────────── supply voltage, V
    │    │  │    └───────────── nominal flow at Δp 10 bar, l/min
    │    │  └────────────────── spool code (decides the coil layout)
    │    └───────────────────── nominal size Dn
    └────────────────────────── series
"""

from __future__ import annotations

import json
import re
from dataclasses import dataclass
from pathlib import Path

from prm9tool.errors import TypeKeyError
from prm9tool.variant import Coils, Config, Variant

FLOWS: dict[str, tuple[str, ...]] = {"06": ("05", "08", "15", "30"), "10": ("30", "60")}
SUPPLIES = ("24",)


@dataclass(frozen=True)
class Spool:
    """A spool code and what it means for the electronics."""

    code: str
    coils: Coils
    description: str
    from_manual: bool  # True: named in the manual; False: an assumption of ours


SPOOLS: dict[str, Spool] = {
    s.code: s
    for s in (
        Spool("3Z11", Coils.AB, "3 positions, two solenoids A and B", True),
        Spool("3Z12", Coils.AB, "3 positions, two solenoids A and B", False),
        Spool("3Y11", Coils.AB, "3 positions, two solenoids A and B", False),
        Spool("2Z51", Coils.A, "2 positions, one solenoid on side A", False),
        Spool("2Y51", Coils.A, "2 positions, one solenoid on side A", False),
        Spool("2Z61", Coils.B, "2 positions, one solenoid on side B", False),
        Spool("2Y61", Coils.B, "2 positions, one solenoid on side B", False),
    )
}


def load_extra_spools(path: Path) -> None:
    """Add spool codes from a JSON file ``[{"code":..., "coils": "AB|A|B", "description":...}]``.

    Raises TypeKeyError naming the entry that is wrong; nothing is added in that case.
    """
    try:
        entries = json.loads(path.read_text(encoding="utf-8"))
        new = {
            e["code"]: Spool(
                str(e["code"]), Coils(e["coils"]), str(e.get("description", "")), False
            )
            for e in entries
        }
    except (OSError, ValueError, KeyError, TypeError) as exc:
        raise TypeKeyError(f"spool catalogue {path}: {exc}") from exc
    SPOOLS.update(new)


_PATTERN = re.compile(
    r"^(?P<series>[^-]*)-(?P<size>[^.]*)\.(?P<spool>[^/]*)/(?P<flow>[^-]*)-"
    r"(?P<supply>\d*)(?P<config>E\d\d)?(?P<series2>S\d\d)?(?P<tail>.*)$"
)


@dataclass(frozen=True)
class TypeKey:
    """A validated type key."""

    size: str
    spool: str
    flow: str
    supply: str
    config: Config
    canopen: bool

    @property
    def coils(self) -> Coils:
        """Coil layout derived from the spool code."""
        return SPOOLS[self.spool].coils

    @property
    def variant(self) -> Variant:
        """The electronics variant of this valve."""
        return Variant(self.config, self.coils, self.canopen)

    def __str__(self) -> str:
        suffix = "-CA" if self.canopen else ""
        return (
            f"PRM9-{self.size}.{self.spool}/{self.flow}-{self.supply}{self.config.value}S02{suffix}"
        )

    @classmethod
    def parse(cls, text: str) -> TypeKey:
        """Parse and validate ``text``; raises TypeKeyError naming the wrong part."""
        key = text.strip().upper()
        m = _PATTERN.match(key)
        if not key.startswith("PRM9-"):
            raise TypeKeyError(f"type key {text!r}: must start with 'PRM9-'")
        if m is None:
            raise TypeKeyError(
                f"type key {text!r}: expected the form PRM9-<size>.<spool>/<flow>-<supply>"
                "<E02|E04>S02[-CA], e.g. PRM9-06.3Z11/30-24E02S02"
            )
        return cls._from_match(text, m)

    @classmethod
    def _from_match(cls, text: str, m: re.Match[str]) -> TypeKey:
        size, spool, flow = m["size"], m["spool"], m["flow"]
        if size not in FLOWS:
            raise TypeKeyError(f"type key {text!r}: nominal size {size!r} must be 06 or 10")
        if spool not in SPOOLS:
            known = ", ".join(sorted(SPOOLS))
            raise TypeKeyError(f"type key {text!r}: unknown spool {spool!r} (known: {known})")
        if flow not in FLOWS[size]:
            allowed = ", ".join(FLOWS[size])
            raise TypeKeyError(
                f"type key {text!r}: flow {flow!r} l/min does not exist for Dn{size} "
                f"(allowed: {allowed})"
            )
        if m["supply"] not in SUPPLIES:
            raise TypeKeyError(f"type key {text!r}: supply voltage {m['supply']!r} must be 24")
        if m["config"] not in ("E02", "E04"):
            raise TypeKeyError(
                f"type key {text!r}: configuration {m['config'] or '(missing)'!r} "
                "must be E02 or E04"
            )
        if m["series2"] != "S02":
            raise TypeKeyError(
                f"type key {text!r}: electronics series {m['series2'] or '(missing)'!r} must be S02"
            )
        if m["tail"] not in ("", "-CA"):
            raise TypeKeyError(f"type key {text!r}: suffix {m['tail']!r} must be empty or -CA")
        return cls(size, spool, flow, m["supply"], Config(m["config"]), m["tail"] == "-CA")


def all_type_keys() -> list[TypeKey]:
    """Every valid combination (for pickers and tests)."""
    return [
        TypeKey(size, spool, flow, "24", config, ca)
        for size, flows in FLOWS.items()
        for spool in SPOOLS
        for flow in flows
        for config in Config
        for ca in (False, True)
    ]

"""PRM9 type keys: parse, validate, format, and derive the electronics variant.

Layout (inference from the manual's examples: §8.7.1 valve selection, §7.7, the status bar
of §8.8)::

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
from dataclasses import dataclass
from enum import StrEnum
from pathlib import Path
from typing import NoReturn

from prm9tool.catalogue.variant import Coils, Config, Variant
from prm9tool.errors import TypeKeyError
from prm9tool.messages import QT_TRANSLATE_NOOP, Arg, Message, Template

FLOWS: dict[str, tuple[str, ...]] = {"06": ("05", "08", "15", "30"), "10": ("30", "60")}
# ``--emulator`` without a type key (GUI, --batch, --list-devices, --help, docs): the
# manual's valve, an E02 with CANopen (manual §8.7.2, the CANopen window of figure 8-21).
DEFAULT_EMULATOR_TYPE_KEY = "PRM9-06.3Z11/30-24E02S02-CA"
SUPPLIES = ("24",)


class SpoolSource(StrEnum):
    """Where the program knows a spool code from."""

    MANUAL = "manual"  # named in the valve manual
    ASSUMED = "assumed"  # shipped with prm9tool, an assumption of ours
    USER = "user"  # the user's spools.json


@dataclass(frozen=True)
class Spool:
    """A spool code and what it means for the electronics."""

    code: str
    coils: Coils
    description: str
    source: SpoolSource

    @property
    def from_manual(self) -> bool:
        """True for a spool the manual names (it cannot be redefined)."""
        return self.source is SpoolSource.MANUAL


_ASSUMED = SpoolSource.ASSUMED
SPOOLS: dict[str, Spool] = {
    s.code: s
    for s in (
        Spool("3Z11", Coils.AB, "3 positions, two solenoids A and B", SpoolSource.MANUAL),
        Spool("3Z12", Coils.AB, "3 positions, two solenoids A and B", _ASSUMED),
        Spool("3Y11", Coils.AB, "3 positions, two solenoids A and B", _ASSUMED),
        Spool("2Z51", Coils.A, "2 positions, one solenoid on side A", _ASSUMED),
        Spool("2Y51", Coils.A, "2 positions, one solenoid on side A", _ASSUMED),
        Spool("2Z61", Coils.B, "2 positions, one solenoid on side B", _ASSUMED),
        Spool("2Y61", Coils.B, "2 positions, one solenoid on side B", _ASSUMED),
    )
}


USER_SPOOLS_FILE = "spools.json"  # in the user data dir: the user's own spool codes


def load_user_spools(data_dir: Path) -> list[str]:
    """Add the spool codes of ``<data_dir>/spools.json`` if that file exists; the codes added.

    The program calls it at start (``prm9tool.cli.main``), with the user data dir
    (``PRM9TOOL_DATA_DIR`` overrides it). Raises TypeKeyError like :func:`load_extra_spools`.
    """
    path = data_dir / USER_SPOOLS_FILE
    return load_extra_spools(path) if path.is_file() else []


def load_extra_spools(path: Path) -> list[str]:
    """Add spool codes from a JSON file ``[{"code":..., "coils": "AB|A|B", "description":...}]``.

    A code may replace one of our assumptions, never a spool the manual names. Returns the
    codes added; raises TypeKeyError naming the entry that is wrong (nothing is added then).
    """
    try:
        entries = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError) as exc:
        raise TypeKeyError(_SPOOL_FILE(str(path), str(exc))) from exc
    if not isinstance(entries, list):
        raise TypeKeyError(_SPOOL_FILE(str(path), _NOT_A_LIST()))
    new: dict[str, Spool] = {}
    for number, entry in enumerate(entries, 1):
        try:
            spool = _user_spool(entry)
        except _SpoolError as exc:
            raise TypeKeyError(_SPOOL_ENTRY(str(path), number, exc.args[0])) from None
        new[spool.code] = spool
    SPOOLS.update(new)
    return list(new)


class _SpoolError(Exception):
    """What is wrong with one entry of a spools.json (a Message)."""


def _user_spool(entry: object) -> Spool:
    if not isinstance(entry, dict):
        raise _SpoolError(_NOT_AN_OBJECT())
    for key in ("code", "coils"):
        if key not in entry:
            raise _SpoolError(_NO_KEY(repr(key)))
    code = str(entry["code"]).strip().upper()
    if not code or any(c not in _CODE for c in code):
        raise _SpoolError(_BAD_CODE(repr(code)))
    known = SPOOLS.get(code)
    if known is not None and known.from_manual:
        raise _SpoolError(_MANUAL_SPOOL(code))
    coils = entry["coils"]
    if not isinstance(coils, str) or coils not in {c.value for c in Coils}:
        raise _SpoolError(_BAD_COILS(repr(coils)))
    return Spool(code, Coils(coils), str(entry.get("description", "")), SpoolSource.USER)


_SPOOL_FILE = QT_TRANSLATE_NOOP("TypeKey", "spool catalogue {0}: {1}")
_SPOOL_ENTRY = QT_TRANSLATE_NOOP("TypeKey", "spool catalogue {0}: entry {1}: {2}")
_NOT_A_LIST = QT_TRANSLATE_NOOP("TypeKey", "expected a list of spools")
_NOT_AN_OBJECT = QT_TRANSLATE_NOOP("TypeKey", "expected an object with code, coils and description")
_NO_KEY = QT_TRANSLATE_NOOP("TypeKey", "{0} is missing")
_BAD_CODE = QT_TRANSLATE_NOOP("TypeKey", "code {0} must be letters and digits only")
_MANUAL_SPOOL = QT_TRANSLATE_NOOP(
    "TypeKey", "spool {0} is named in the manual and cannot be redefined"
)
_BAD_COILS = QT_TRANSLATE_NOOP("TypeKey", "coils {0} must be AB, A or B")


@dataclass(frozen=True)
class TypeKey:
    """A validated type key."""

    size: str
    spool: str
    flow: str
    supply: str
    config: Config
    canopen: bool

    def __post_init__(self) -> None:
        """Refuse a configuration that is not a :class:`Config` (a plain ``"E02"`` included).

        A Qt combo box hands an enum stored as item data back as ``str``; such a key would
        only fail later, when it is formatted, far from the slot that made it.
        """
        if not isinstance(self.config, Config):
            raise TypeError(f"TypeKey.config must be a Config, not {type(self.config).__name__}")

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
        return _Parser(text).type_key()


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


# --- parsing ---------------------------------------------------------------------------------
_DIGITS = "0123456789"
_CODE = _DIGITS + "ABCDEFGHIJKLMNOPQRSTUVWXYZ"
_SEPARATORS = ".-/"


def _span(text: str, start: int, allowed: str) -> int:
    """End of the run of ``allowed`` characters of ``text`` from ``start``."""
    end = start
    while end < len(text) and text[end] in allowed:
        end += 1
    return end


def _span_until(text: str, start: int, stops: str) -> int:
    """End of the run of characters of ``text`` from ``start`` that are not in ``stops``."""
    end = start
    while end < len(text) and text[end] not in stops:
        end += 1
    return end


class _Parser:
    """Reads a type key part by part, so that an error names the part or separator that is wrong.

    Structure first (every separator where it belongs), then the values in reading order.
    """

    def __init__(self, text: str) -> None:
        self._text = text
        self._key = text.strip().upper()
        self._pos = 0

    def type_key(self) -> TypeKey:
        if not self._key.startswith("PRM9-"):
            self._fail(QT_TRANSLATE_NOOP("TypeKey", "type key {0}: must start with 'PRM9-'"))
        self._pos = len("PRM9-")
        size = self._part(_DIGITS, ".", _PART_SIZE, _EXPECTED_DOT)
        spool = self._part(_CODE, "/", _PART_SPOOL, _EXPECTED_SLASH)
        flow = self._part(_DIGITS, "-", _PART_FLOW, _EXPECTED_DASH)
        supply, config, series, suffix = self._electronics()
        self._check_values(size, spool, flow)
        self._check_electronics(supply, config, series, suffix)
        return TypeKey(size, spool, flow, supply, Config(config), suffix == "-CA")

    def _fail(self, template: Template, *args: Arg) -> NoReturn:
        raise TypeKeyError(template(repr(self._text), *args))

    def _part(self, allowed: str, separator: str, name: Message, wrong: Template) -> str:
        """The part at the cursor (a run of ``allowed``) and the ``separator`` after it."""
        end = _span(self._key, self._pos, allowed)
        if end == self._pos:  # e.g. 'DN06': take it whole, so that the value check names it
            end = _span_until(self._key, self._pos, _SEPARATORS)
        part, found = self._key[self._pos : end], self._key[end : end + 1]
        if not part:
            self._fail(_MISSING, name)
        if found != separator:
            self._fail(wrong, repr(part), repr(found) if found else _END_OF_KEY)
        self._pos = end + 1
        return part

    def _electronics(self) -> tuple[str, str, str, str]:
        """``24E02S02[-CA]`` split into supply, configuration, series and suffix."""
        end = _span_until(self._key, self._pos, "-")
        block, suffix = self._key[self._pos : end], self._key[end:]
        supply_end = _span(block, 0, _DIGITS)
        config_end = supply_end
        if block[supply_end : supply_end + 1] not in ("", "S"):  # E02, E04 or a wrong letter
            config_end = _span(block, supply_end + 1, _DIGITS)
        supply, config = block[:supply_end], block[supply_end:config_end]
        return supply, config, block[config_end:], suffix

    def _check_values(self, size: str, spool: str, flow: str) -> None:
        if size not in FLOWS:
            self._fail(
                QT_TRANSLATE_NOOP("TypeKey", "type key {0}: nominal size {1} must be 06 or 10"),
                repr(size),
            )
        if spool not in SPOOLS:
            self._fail(
                QT_TRANSLATE_NOOP("TypeKey", "type key {0}: unknown spool {1} (known: {2})"),
                repr(spool),
                ", ".join(sorted(SPOOLS)),
            )
        if flow not in FLOWS[size]:
            self._fail(
                QT_TRANSLATE_NOOP(
                    "TypeKey",
                    "type key {0}: flow {1} l/min does not exist for Dn{2} (allowed: {3})",
                ),
                repr(flow),
                size,
                ", ".join(FLOWS[size]),
            )

    def _check_electronics(self, supply: str, config: str, series: str, suffix: str) -> None:
        if not supply:
            self._fail(_MISSING, _PART_SUPPLY)
        if supply not in SUPPLIES:
            self._fail(
                QT_TRANSLATE_NOOP("TypeKey", "type key {0}: supply voltage {1} must be 24"),
                repr(supply),
            )
        if not config:
            self._fail(_MISSING, _PART_CONFIG)
        if config not in ("E02", "E04"):
            self._fail(
                QT_TRANSLATE_NOOP("TypeKey", "type key {0}: configuration {1} must be E02 or E04"),
                repr(config),
            )
        self._check_series(series)
        if suffix not in ("", "-CA"):
            self._fail(
                QT_TRANSLATE_NOOP("TypeKey", "type key {0}: suffix {1} must be empty or -CA"),
                repr(suffix),
            )

    def _check_series(self, series: str) -> None:
        if not series:
            self._fail(_MISSING, _PART_SERIES)
        if series != "S02" and series.startswith("S02"):  # PRM9-…-24E02S02CA
            self._fail(
                QT_TRANSLATE_NOOP(
                    "TypeKey",
                    "type key {0}: expected '-' between the electronics series S02 and {1}",
                ),
                repr(series[3:]),
            )
        if series != "S02":
            self._fail(
                QT_TRANSLATE_NOOP("TypeKey", "type key {0}: electronics series {1} must be S02"),
                repr(series),
            )


_EXPECTED_DOT = QT_TRANSLATE_NOOP(
    "TypeKey", "type key {0}: expected '.' between the nominal size {1} and the spool, found {2}"
)
_EXPECTED_SLASH = QT_TRANSLATE_NOOP(
    "TypeKey", "type key {0}: expected '/' between the spool {1} and the nominal flow, found {2}"
)
_EXPECTED_DASH = QT_TRANSLATE_NOOP(
    "TypeKey",
    "type key {0}: expected '-' between the nominal flow {1} and the supply voltage, found {2}",
)
_END_OF_KEY = QT_TRANSLATE_NOOP("TypeKey", "the end of the key")()
_MISSING = QT_TRANSLATE_NOOP("TypeKey", "type key {0}: the {1} is missing")
_PART_SIZE = QT_TRANSLATE_NOOP("TypeKey", "nominal size (06 or 10)")()
_PART_SPOOL = QT_TRANSLATE_NOOP("TypeKey", "spool")()
_PART_FLOW = QT_TRANSLATE_NOOP("TypeKey", "nominal flow")()
_PART_SUPPLY = QT_TRANSLATE_NOOP("TypeKey", "supply voltage (24)")()
_PART_CONFIG = QT_TRANSLATE_NOOP("TypeKey", "configuration (E02 or E04)")()
_PART_SERIES = QT_TRANSLATE_NOOP("TypeKey", "electronics series (S02)")()

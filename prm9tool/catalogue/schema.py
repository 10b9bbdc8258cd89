"""Typed description of one valve parameter (object-dictionary entry)."""

from __future__ import annotations

import math
import re
import struct
from dataclasses import dataclass, field
from enum import IntEnum, StrEnum
from functools import cached_property

from prm9tool.catalogue.variant import Coils, Config, Variant
from prm9tool.errors import ValueRangeError
from prm9tool.messages import QT_TRANSLATE_NOOP, SHOWN_CHARACTERS, Number, quoted


class DataType(IntEnum):
    """CiA 301 data types used by the PRM9 (the numbers are the CiA 301 type codes)."""

    BOOLEAN = 0x01
    INTEGER8 = 0x02
    INTEGER16 = 0x03
    INTEGER32 = 0x04
    UNSIGNED8 = 0x05
    UNSIGNED16 = 0x06
    UNSIGNED32 = 0x07
    VISIBLE_STRING = 0x09

    @property
    def size(self) -> int:
        """Encoded size in bytes (0 for variable-length strings)."""
        return _SIZES[self]

    @cached_property
    def is_string(self) -> bool:
        """True for the variable-length string type."""
        return self is DataType.VISIBLE_STRING

    @property
    def natural_range(self) -> tuple[int, int]:
        """The full range the type can hold."""
        return _RANGES[self]

    @property
    def codec(self) -> struct.Struct | None:
        """The little-endian struct of a number type (None for strings)."""
        return _STRUCTS.get(self)

    def encode(self, value: int | str) -> bytes:
        """Encode a raw value little-endian as on the CAN bus."""
        codec = _STRUCTS.get(self)
        if codec is None:
            return str(value).encode("latin-1", errors="replace")
        return codec.pack(int(value))

    def decode(self, data: bytes) -> int | str:
        """Decode little-endian bytes; raises ``struct.error``/``ValueError`` on wrong length."""
        codec = _STRUCTS.get(self)
        if codec is None:
            return data.decode("latin-1")
        return int(codec.unpack(data)[0])


_SIZES = {
    DataType.BOOLEAN: 1,
    DataType.INTEGER8: 1,
    DataType.INTEGER16: 2,
    DataType.INTEGER32: 4,
    DataType.UNSIGNED8: 1,
    DataType.UNSIGNED16: 2,
    DataType.UNSIGNED32: 4,
    DataType.VISIBLE_STRING: 0,
}
_FORMATS = {
    DataType.BOOLEAN: "B",
    DataType.INTEGER8: "b",
    DataType.INTEGER16: "h",
    DataType.INTEGER32: "i",
    DataType.UNSIGNED8: "B",
    DataType.UNSIGNED16: "H",
    DataType.UNSIGNED32: "I",
}
_STRUCTS = {dtype: struct.Struct("<" + fmt) for dtype, fmt in _FORMATS.items()}  # not strings
_RANGES = {
    DataType.BOOLEAN: (0, 1),
    DataType.INTEGER8: (-128, 127),
    DataType.INTEGER16: (-32768, 32767),
    DataType.INTEGER32: (-(2**31), 2**31 - 1),
    DataType.UNSIGNED8: (0, 255),
    DataType.UNSIGNED16: (0, 65535),
    DataType.UNSIGNED32: (0, 2**32 - 1),
    DataType.VISIBLE_STRING: (0, 0),
}


class Access(StrEnum):
    """Who may change a parameter in the program."""

    BASIC = "basic"  # visible and editable at Basic level
    EXPERT = "expert"  # visible and editable only at Expert level
    READ_ONLY = "read-only"  # live or identity values, never written by the program


class ObjAccess(StrEnum):
    """Object-dictionary access as seen over SDO/USB (CiA 301 notation)."""

    RO = "ro"
    RW = "rw"
    WO = "wo"
    CONST = "const"


@dataclass(frozen=True)
class Texts:
    """A text in the three program languages."""

    en: str
    de: str
    cs: str

    def get(self, language: str) -> str:
        """The text in ``language`` (``en``, ``de`` or ``cs``), English as fallback."""
        return getattr(self, language, None) or self.en


@dataclass(frozen=True)
class Applies:
    """The variants a parameter belongs to (calling it: the variant's parameter set).

    ``every_canopen``: the object is in the object dictionary of every -CA valve, also where
    it is not part of the parameter set (the external sensor objects of manual table 7-14 on
    an E02 -CA, which has no sensor input): :meth:`on_device` says where the object exists.
    """

    configs: frozenset[Config] = frozenset(Config)
    coils: frozenset[Coils] = frozenset(Coils)
    canopen_only: bool = False
    every_canopen: bool = False

    def __call__(self, variant: Variant) -> bool:
        return (
            variant.config in self.configs
            and variant.coils in self.coils
            and (variant.canopen or not self.canopen_only)
        )

    def on_device(self, variant: Variant) -> bool:
        """True if ``variant``'s object dictionary has the object (over CANopen and USB)."""
        return self(variant) or (self.every_canopen and variant.canopen)

    def describe(self) -> str:
        """Human-readable list of the variants, e.g. ``E04, coils AB/A, -CA only``."""
        parts = ["/".join(sorted(c.value for c in self.configs))]
        if self.coils != frozenset(Coils):
            parts.append("coils " + "/".join(sorted(c.value for c in self.coils)))
        if self.canopen_only:
            parts.append("-CA only")
        if self.every_canopen and self.configs != frozenset(Config):
            others = "/".join(sorted(c.value for c in set(Config) - self.configs))
            parts.append(f"object also on {others} -CA")
        return ", ".join(parts)


EVERY_VARIANT = Applies()


@dataclass(frozen=True)
class Parameter:
    """One object-dictionary entry with everything the program needs to know about it.

    ``display = raw * scale``; ``decimals`` is the number of decimals an edit field offers.
    ``default_e04`` overrides ``default`` on E04 valves, ``default_one_coil`` on valves with
    one coil (A or B only); ``node_relative`` means the real
    default is ``default + node ID`` (CANopen COB-IDs, written ``$NODEID+...`` in an EDS).
    ``in_file`` parameters form the parameter set that *.prm files and uploads carry.
    """

    mnemonic: str
    index: int
    subindex: int
    dtype: DataType
    raw_min: int
    raw_max: int
    default: int | str
    text: Texts
    group: str
    access: Access = Access.EXPERT
    obj_access: ObjAccess = ObjAccess.RW
    unit: str = ""
    scale: float = 1.0
    decimals: int = 0
    applies: Applies = EVERY_VARIANT
    in_file: bool = True
    choices: tuple[tuple[int, Texts], ...] = ()
    default_e04: int | None = None
    default_one_coil: int | None = None
    node_relative: bool = False
    help: Texts | None = None
    source: str = ""
    extra: dict[str, str] = field(default_factory=dict, compare=False, hash=False)

    # --- identity -----------------------------------------------------------------
    @cached_property
    def key(self) -> tuple[int, int]:
        """``(index, subindex)``."""
        return (self.index, self.subindex)

    @property
    def address(self) -> str:
        """``0x6345/1`` style address."""
        return f"0x{self.index:04X}/{self.subindex}"

    @property
    def address_from_manual(self) -> bool:
        """False when the object address is this project's decision (``source`` says so): a
        real valve may lack that object, so over CANopen the parameter may be unavailable."""
        return not _DECIDED_ADDRESS.search(self.source)

    @cached_property
    def is_string(self) -> bool:
        """True for string parameters (type key, firmware version, device name)."""
        return self.dtype.is_string

    def on_device(self, variant: Variant) -> bool:
        """True if ``variant``'s object dictionary has this object; it may still not be part
        of the variant's parameter set (``applies``): see :class:`Applies`."""
        return self.applies.on_device(variant)

    @cached_property
    def writable(self) -> bool:
        """True if the object dictionary accepts writes."""
        return self.obj_access in (ObjAccess.RW, ObjAccess.WO)

    def default_for(self, variant: Variant, node_id: int = 0) -> int | str:
        """Factory default raw value on ``variant`` (``node_id`` for node-relative COB-IDs)."""
        value = self.default
        if variant.config is Config.E04 and self.default_e04 is not None:
            value = self.default_e04
        if variant.coils is not Coils.AB and self.default_one_coil is not None:
            value = self.default_one_coil
        if self.node_relative and isinstance(value, int):
            value += node_id
        return value

    # --- raw <-> display --------------------------------------------------------------
    def to_display(self, raw: int | str) -> float | int | str:
        """Convert a raw value to display units (int when the scale is 1)."""
        if self.is_string or isinstance(raw, str):
            return raw
        if self.scale == 1.0:
            return int(raw)
        return raw * self.scale

    def to_raw(self, display: float | int | str) -> int | str:
        """Convert a display value to the nearest raw value (no range check)."""
        if self.is_string:
            return str(display)
        value = float(display)
        if not math.isfinite(value):
            raise ValueRangeError(
                QT_TRANSLATE_NOOP("Problems", "{0}: {1} is not a number")(
                    self.mnemonic, quoted(display) if isinstance(display, str) else repr(display)
                )
            )
        if not math.isfinite(value / self.scale):  # e.g. 1e308 % overflows the raw value
            raise ValueRangeError(
                QT_TRANSLATE_NOOP("Problems", "{0}: {1} is far outside the range")(
                    self.mnemonic, quoted(display) if isinstance(display, str) else repr(display)
                )
            )
        return round(value / self.scale)

    def format_display(self, raw: int | str) -> str:
        """Shortest decimal text that reads back to exactly ``raw`` (used by files and tables)."""
        if self.is_string or isinstance(raw, str):
            return str(raw)
        if self.scale == 1.0:
            return str(int(raw))
        value = raw * self.scale
        for decimals in range(9):
            text = f"{value:.{decimals}f}"
            if round(float(text) / self.scale) == raw:
                return _tidy(text)
        return repr(value)

    def parse_display(self, text: str, decimal: str = ".") -> int | str:
        """Parse a display text to a raw value; raises ValueRangeError with the reason.

        A number is ASCII digits with an optional sign, one decimal point and an exponent
        (``-2.5``, ``1e3``); ``decimal`` is a second decimal separator taken as well (``,``:
        the program language writes ``0,4``). A comma where only the point is the separator
        (a file, the English program) is refused in words, not read as a point. Other digits
        (``２４００``, ``٢٤٠٠``), ``2_400``, ``inf`` and ``nan`` are not numbers, whatever
        Python's ``float()`` would accept.
        """
        if self.is_string:
            return text
        cleaned = text.strip()
        if decimal != "." and cleaned.count(decimal) == 1:
            cleaned = cleaned.replace(decimal, ".")
        elif cleaned.count(",") == 1 and _is_number(cleaned.replace(",", ".")):
            raise ValueRangeError(
                QT_TRANSLATE_NOOP(
                    "Problems", "{0}: {1} is not a number: the decimals follow a point ({2})"
                )(self.mnemonic, quoted(cleaned), cleaned.replace(",", "."))
            )
        if self.choices and not _is_number(cleaned):
            for code, label in self.choices:
                if cleaned.lower() in (label.en.lower(), label.de.lower(), label.cs.lower()):
                    return code
        if not _is_number(cleaned):
            raise ValueRangeError(
                QT_TRANSLATE_NOOP("Problems", "{0}: {1} is not a number")(
                    self.mnemonic, quoted(text.strip())
                )
            )
        raw = self.to_raw(cleaned)
        assert isinstance(raw, int)
        return raw

    # --- validation --------------------------------------------------------------------
    def check_raw(self, raw: int | str, cap: int | str | None = None) -> None:
        """Raise ValueRangeError with a user-facing message if ``raw`` is not allowed.

        ``cap``: the raw value of the parameter that caps this one (LIMTA and LIMTB: the
        valve's CURNORM, manual table 7-14), when known; a value outside the catalogue's range
        is then refused with the range every editor shows (``0 … 2600 mA``), not the
        catalogue's ``0 … 4000 mA`` that contradicts it. Within the catalogue's range the rule
        between parameters names the cap (``CATALOGUE.check_rules``)."""
        if self.is_string:
            if not isinstance(raw, str):
                raise ValueRangeError(
                    QT_TRANSLATE_NOOP("Problems", "{0}: expected text, got {1}")(
                        self.mnemonic, repr(raw)
                    )
                )
            return
        if isinstance(raw, (str, bool)):
            raise ValueRangeError(
                QT_TRANSLATE_NOOP("Problems", "{0}: expected a number, got {1}")(
                    self.mnemonic, repr(raw)
                )
            )
        if self.choices and raw not in {code for code, _ in self.choices}:
            allowed = ", ".join(str(code) for code, _ in self.choices)
            raise ValueRangeError(
                QT_TRANSLATE_NOOP("Problems", "{0}: {1} is not one of the allowed codes {2}")(
                    self.mnemonic, _short_number(str(raw)), allowed
                )
            )
        if not self.raw_min <= raw <= self.raw_max:
            high = min(self.raw_max, cap) if isinstance(cap, int) else self.raw_max
            lo, hi = self.format_display(self.raw_min), self.format_display(high)
            unit = f" {self.unit}" if self.unit else ""
            raise ValueRangeError(
                QT_TRANSLATE_NOOP(
                    "Problems", "{0}: {1}{2} is outside the allowed range {3} … {4}{2}"
                )(
                    self.mnemonic,
                    Number(_short_number(self.format_display(raw))),
                    unit,
                    Number(lo),
                    Number(hi),
                )
            )

    def choice_text(self, raw: int, language: str = "en") -> str:
        """The label of an enumerated value (or the number if it is not enumerated)."""
        for code, label in self.choices:
            if code == raw:
                return label.get(language)
        return str(raw)


# "object 0x2041: decision", "object and scaling: decision", "decision (tuning generator)",
# "not in 7-13: decision" (a CiA 301 object the manual's table does not list)
_DECIDED_ADDRESS = re.compile(r"object[^:;)]*: decision|^decision \(|not in 7-13: decision")
# Unambiguous: digits, then a fraction only after a point. "[0-9]+\.?[0-9]*" split a run of
# digits between its two parts in every way before failing on a trailing letter: a check time
# quadratic in the number's length (20 000 digits and an "x": 15 s).
_NUMBER = re.compile(r"[+-]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][+-]?[0-9]+)?")


def _short_number(text: str) -> str:
    """A number's text for a message: as it is, or in powers of ten when it is longer than a
    message should repeat (``1e+149``, not its 150 digits)."""
    return text if len(text) <= SHOWN_CHARACTERS else f"{float(text):.6g}"


def _is_number(text: str) -> bool:
    """True for an ASCII decimal number (``re`` with ``[0-9]``, not ``\\d``, which is Unicode)."""
    return _NUMBER.fullmatch(text) is not None


def _tidy(text: str) -> str:
    if "." in text:
        text = text.rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text

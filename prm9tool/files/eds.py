"""The CANopen view of the parameter catalogue: object layout, CiA 306 EDS export, docs table.

Everything here is derived from :data:`prm9tool.catalogue.CATALOGUE`; the only additions are
the structure CiA 301 requires around the catalogue entries (object type, a synthesized
sub-index 0 "highest sub-index supported" where the catalogue lists only the data entries).
The emulated valve's CANopen slave uses :func:`od_objects` too, so the EDS and the slave
describe the same objects.
"""

from __future__ import annotations

import unicodedata
from collections import defaultdict
from collections.abc import Iterable
from dataclasses import dataclass
from datetime import datetime
from enum import IntEnum

from prm9tool._version import __version__
from prm9tool.catalogue import CAPPED_BY, CATALOGUE, DataType, ObjAccess, Parameter
from prm9tool.catalogue.pdo import mapping_for_control_mode
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.catalogue.variant import ALL_VARIANTS, Config, Variant
from prm9tool.errors import TypeKeyError

BIT_RATES_KBIT = (10, 20, 50, 125, 250, 500, 800, 1000)
UNSUPPORTED_BIT_RATES_KBIT = frozenset({10})  # manual table 7-1
MANDATORY = (0x1000, 0x1001, 0x1018)  # CiA 301
VENDOR_NAME = "ARGO-HYTOS"


class ObjectKind(IntEnum):
    """CiA 301 object codes as used in an EDS ``ObjectType``."""

    VAR = 0x7
    ARRAY = 0x8
    RECORD = 0x9


@dataclass(frozen=True)
class OdObject:
    """One object (index) of a valve's dictionary: its catalogue entries and CiA 301 structure."""

    index: int
    name: str
    kind: ObjectKind
    entries: tuple[Parameter, ...]  # catalogue entries, by sub-index

    @property
    def highest_subindex(self) -> int:
        """The value sub-index 0 of a structured object reports."""
        return max(p.subindex for p in self.entries)

    @property
    def synthesized_sub0(self) -> bool:
        """True if sub-index 0 is not in the catalogue and is added here (structured objects)."""
        return self.kind is not ObjectKind.VAR and all(p.subindex != 0 for p in self.entries)


def od_objects(variant: Variant) -> list[OdObject]:
    """Every object of ``variant``'s dictionary, by index."""
    by_index: dict[int, list[Parameter]] = defaultdict(list)
    for param in CATALOGUE.for_variant(variant):
        by_index[param.index].append(param)
    objects = []
    for index in sorted(by_index):
        entries = tuple(sorted(by_index[index], key=lambda p: p.subindex))
        kind = _kind(index, entries)
        objects.append(OdObject(index, _object_name(entries, kind), kind, entries))
    return objects


def raw_limits(param: Parameter, variant: Variant) -> tuple[int, int]:
    """The raw values ``variant`` accepts for ``param`` (its range, capped by ``CAPPED_BY``).

    The capping parameter (CURNORM) is read-only, so its default is the limit a master can rely on.
    """
    high = param.raw_max
    cap = CAPPED_BY.get(param.mnemonic)
    if cap is not None:
        high = min(high, int(CATALOGUE[cap].default_for(variant)))
    return param.raw_min, high


def pdo_mappable(variant: Variant) -> set[tuple[int, int]]:
    """``(index, subindex)`` of every object that appears in a fixed PDO mapping."""
    result = set()
    for param in CATALOGUE.for_variant(variant):
        if param.group == "canopen_comm" and "MAP" in param.mnemonic and param.subindex > 0:
            for mode in (2, 4):
                value = mapping_for_control_mode(param, mode)
                result.add((value >> 16, (value >> 8) & 0xFF))
    return result


def _kind(index: int, entries: tuple[Parameter, ...]) -> ObjectKind:
    if 0x1400 <= index < 0x1C00:  # PDO parameters: records, also a mapping with no entries
        return ObjectKind.RECORD
    if len(entries) == 1 and entries[0].subindex == 0:
        return ObjectKind.VAR
    data = [p for p in entries if p.subindex > 0]
    contiguous = [p.subindex for p in data] == list(range(1, len(data) + 1))
    homogeneous = len({p.dtype for p in data}) == 1
    if index == 0x1003 or (index >= 0x2000 and len(data) > 1 and contiguous and homogeneous):
        return ObjectKind.ARRAY
    return ObjectKind.RECORD


def _object_name(entries: tuple[Parameter, ...], kind: ObjectKind) -> str:
    texts = [p.text.en for p in entries]
    if kind is ObjectKind.VAR or (len(entries) == 1 and entries[0].subindex == 1):
        return texts[0]
    if entries[0].subindex == 0:
        return texts[0].split(":")[0]
    prefix = _common_prefix(texts).rstrip(" :,(")
    if len(prefix) >= 4:
        return prefix
    return "/".join(p.mnemonic for p in entries)


def _common_prefix(texts: list[str]) -> str:
    length = 0
    for chars in zip(*texts, strict=False):
        if len(set(chars)) != 1:
            break
        length += 1
    return texts[0][:length]


# --- EDS ------------------------------------------------------------------------------------
def export_eds(type_key: str | TypeKey, created: datetime | None = None) -> str:
    """A CiA 306 EDS for the valve ``type_key`` (raises TypeKeyError on a bad or non -CA key)."""
    key = type_key if isinstance(type_key, TypeKey) else TypeKey.parse(type_key)
    if not key.canopen:
        raise TypeKeyError(
            f"{key} has no CANopen interface: an EDS exists only for -CA valves (e.g. {key}-CA)"
        )
    variant = key.variant
    objects = od_objects(variant)
    when = created or datetime.now()
    lines = _file_info(key, when) + _device_info(key) + _object_lists(objects)
    mappable = pdo_mappable(variant)
    for obj in objects:
        lines += _object_section(obj, variant, key, mappable)
    return "\n".join(lines) + "\n"


def _file_info(key: TypeKey, when: datetime) -> list[str]:
    stamp = [when.strftime("%I:%M%p"), when.strftime("%m-%d-%Y")]
    return [
        "[FileInfo]",
        f"FileName={eds_file_name(key)}",
        "FileVersion=1",
        "FileRevision=0",
        "EDSVersion=4.0",
        f"Description={key} proportional valve, CiA 301 / CiA 408",
        f"CreationTime={stamp[0]}",
        f"CreationDate={stamp[1]}",
        f"CreatedBy=prm9tool {__version__}",
        f"ModificationTime={stamp[0]}",
        f"ModificationDate={stamp[1]}",
        f"ModifiedBy=prm9tool {__version__}",
        "",
    ]


def _device_info(key: TypeKey) -> list[str]:
    defaults = CATALOGUE.defaults(key.variant)
    lines = [
        "[DeviceInfo]",
        f"VendorName={VENDOR_NAME}",
        f"VendorNumber=0x{defaults['VENDORID']:X}",
        f"ProductName={key}",
        f"ProductNumber=0x{defaults['PRODCODE']:X}",
        f"RevisionNumber=0x{defaults['REVISION']:X}",
        f"OrderCode={key}",
    ]
    for rate in BIT_RATES_KBIT:
        lines.append(f"BaudRate_{rate}={0 if rate in UNSUPPORTED_BIT_RATES_KBIT else 1}")
    lines += [
        "SimpleBootUpMaster=0",
        "SimpleBootUpSlave=1",
        "Granularity=0",
        "DynamicChannelsSupported=0",
        "CompactPDO=0",
        "GroupMessaging=0",
        "NrOfRXPDO=2",
        "NrOfTXPDO=2",
        "LSS_Supported=1",  # node-ID switch 1: LSS (manual table 7-17, CiA 305)
        "",
        "[DummyUsage]",
        *(f"Dummy{i:04d}=0" for i in range(1, 8)),
        "",
        "[Comments]",
        "Lines=2",
        "Line1=Generated by prm9tool from its parameter catalogue.",
        "Line2=PDO mappings are fixed; RPDO1/TPDO1 entry 2 follow the control mode 0x6043.",
        "",
    ]
    return lines


def _object_lists(objects: list[OdObject]) -> list[str]:
    mandatory = [o.index for o in objects if o.index in MANDATORY]
    manufacturer = [o.index for o in objects if 0x2000 <= o.index < 0x6000]
    optional = [o.index for o in objects if o.index not in mandatory + manufacturer]
    lines: list[str] = []
    for title, indices in (
        ("MandatoryObjects", mandatory),
        ("OptionalObjects", optional),
        ("ManufacturerObjects", manufacturer),
    ):
        lines += [f"[{title}]", f"SupportedObjects={len(indices)}"]
        lines += [f"{n}=0x{index:04X}" for n, index in enumerate(indices, start=1)]
        lines.append("")
    return lines


def _object_section(
    obj: OdObject, variant: Variant, key: TypeKey, mappable: set[tuple[int, int]]
) -> list[str]:
    if obj.kind is ObjectKind.VAR:
        return _variable(f"{obj.index:04X}", obj.entries[0], obj.name, variant, key, mappable)
    subs = len(obj.entries) + (1 if obj.synthesized_sub0 else 0)
    lines = [
        f"[{obj.index:04X}]",
        f"ParameterName={_parameter_name(obj.name)}",
        f"ObjectType=0x{obj.kind.value:X}",
        f"SubNumber=0x{subs:X}",
        "",
    ]
    if obj.synthesized_sub0:
        lines += [
            f"[{obj.index:04X}sub0]",
            "ParameterName=Highest sub-index supported",
            "ObjectType=0x7",
            f"DataType=0x{DataType.UNSIGNED8.value:04X}",
            "AccessType=ro",
            f"DefaultValue={obj.highest_subindex}",
            "PDOMapping=0",
            "",
        ]
    for param in obj.entries:
        section = f"{obj.index:04X}sub{param.subindex:X}"
        lines += _variable(section, param, param.text.en, variant, key, mappable)
    return lines


def _variable(
    section: str,
    param: Parameter,
    name: str,
    variant: Variant,
    key: TypeKey,
    mappable: set[tuple[int, int]],
) -> list[str]:
    lines = [
        f"[{section}]",
        f"ParameterName={_parameter_name(name)}",
        "ObjectType=0x7",
        f"DataType=0x{param.dtype.value:04X}",
        f"AccessType={param.obj_access.value}",
        f"DefaultValue={_default_text(param, variant, key)}",
        f"PDOMapping={1 if param.key in mappable else 0}",
    ]
    limits = raw_limits(param, variant)
    if not param.is_string and limits != param.dtype.natural_range:
        lines += [f"LowLimit={limits[0]}", f"HighLimit={limits[1]}"]
    lines.append("")
    return lines


def _default_text(param: Parameter, variant: Variant, key: TypeKey) -> str:
    if param.mnemonic == "PCODE":
        return str(key)
    value = param.default_for(variant)
    if isinstance(value, str):
        return _ascii(value)
    if param.node_relative:
        return f"$NODEID+0x{value:X}"
    if param.dtype is DataType.UNSIGNED32:
        return f"0x{value:X}"
    return str(value)


def eds_file_name(key: TypeKey) -> str:
    """A file name for ``key``'s EDS (``/`` and ``.`` of the type key replaced)."""
    return str(key).replace("/", "_").replace(".", "_") + ".eds"


_ASCII = {"Ω": "Ohm", "µ": "u", "°": "deg", "±": "+/-", "…": "...", "–": "-", "→": "->"}


def _parameter_name(text: str) -> str:
    """A ParameterName value every EDS reader can take: ASCII, and none of ``=`` (naive
    ``key=value`` readers split at every one), ``;`` or ``#`` (comments in some INI readers)."""
    text = _ascii(text).replace(" = ", ": ")
    return text.replace("=", "-").replace(";", ",").replace("#", "No.")


def _ascii(text: str) -> str:
    for char, replacement in _ASCII.items():
        text = text.replace(char, replacement)
    return unicodedata.normalize("NFKD", text).encode("ascii", "ignore").decode("ascii")


# --- documentation table -----------------------------------------------------------------------
def markdown_table(parameters: Iterable[Parameter] | None = None) -> str:
    """The object-dictionary table of docs/canopen.md (every object of a -CA valve)."""
    params = list(parameters) if parameters is not None else _canopen_parameters()
    mappable = pdo_mappable(Variant(Config.E04, canopen=True))
    rows = [
        "| index | sub | mnemonic | name | type | access | default (raw) | range (raw) "
        "| unit (raw × scale) | variants | PDO |",
        "|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for p in sorted(params, key=lambda q: q.key):
        rows.append(
            f"| 0x{p.index:04X} | {p.subindex} | {p.mnemonic} | {_md(p.text.en)} "
            f"| {p.dtype.name} | {p.obj_access.value} | {_md_default(p)} | {_md_range(p)} "
            f"| {_md_unit(p)} | {p.applies.describe()} | {'yes' if p.key in mappable else ''} |"
        )
    return "\n".join(rows) + "\n"


def _canopen_parameters() -> list[Parameter]:
    """Every catalogue entry that exists on at least one -CA variant."""
    ca_variants = [v for v in ALL_VARIANTS if v.canopen]
    return [p for p in CATALOGUE if any(p.on_device(v) for v in ca_variants)]


def _md(text: str) -> str:
    return text.replace("|", "\\|")


def _md_default(p: Parameter) -> str:
    if p.is_string:
        return f'"{p.default}"' if p.default else "(device)"
    assert isinstance(p.default, int)
    text = f"0x{p.default:X}" if p.dtype is DataType.UNSIGNED32 else str(p.default)
    if p.node_relative:
        text = f"{text} + node ID"
    if p.default_e04 is not None:
        e04 = f"0x{p.default_e04:X}" if p.dtype is DataType.UNSIGNED32 else str(p.default_e04)
        text += f" (E04: {e04})"
    return text


def _md_unit(p: Parameter) -> str:
    if p.scale == 1.0 or not p.unit:
        return p.unit
    return f"{p.unit} (× {p.scale:.6g})"


def _md_range(p: Parameter) -> str:
    if p.is_string or (p.raw_min, p.raw_max) == p.dtype.natural_range:
        return ""
    if p.obj_access is ObjAccess.CONST:
        return ""
    if p.mnemonic in CAPPED_BY:
        high = raw_limits(p, Variant(Config.E04, canopen=True))[1]
        return f"{p.raw_min} … {high} ({CAPPED_BY[p.mnemonic]})"
    return f"{p.raw_min} … {p.raw_max}"

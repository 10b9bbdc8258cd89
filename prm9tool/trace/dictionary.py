"""What a node's objects are called and how their bytes read, per node: a PRM9 valve by the
catalogue (the single source of truth), another node by the EDS a user gives (the ``canopen``
package reads it), else raw. No Qt."""

from __future__ import annotations

import struct
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Protocol

from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.pdo import mapping_for_control_mode
from prm9tool.errors import FileFormatError, FileProblem

PdoDefault = tuple[int, int, tuple[int, ...]]  # COB-ID entry (0x1400/1 …), number, mapping entries
DEVICE_TYPE = CATALOGUE["DEVTYPE"].default  # 0x1000 of a PRM9 (CiA 408)
VENDOR_ID = CATALOGUE["VENDORID"].default  # 0x1018/1


@dataclass(frozen=True)
class Reading:
    """An object's value read from bytes: its name, the value in display units, its text."""

    name: str
    value: float | int | str
    text: str


class NodeDictionary(Protocol):
    """How one node's objects are named and read."""

    kind: str  # "PRM9", "EDS FILE", "raw"

    def read(self, index: int, subindex: int, data: bytes) -> Reading | None:
        """The object at ``index``/``subindex`` read from ``data`` (None: unknown object)."""

    def pdo_defaults(self, node: int, receive: bool, control_mode: int) -> list[PdoDefault]:
        """The node's PDOs at power-up: (COB-ID, number, mapping entries)."""


class Prm9Dictionary:
    """A PRM9 valve: the catalogue's names, scaling and PDO mappings (manual table 7-13)."""

    kind = "PRM9"
    CACHED = 200_000  # readings kept (a trace repeats its values: one Reading serves them all)

    def __init__(self) -> None:
        self._cache: dict[tuple[int, int, bytes], Reading | None] = {}

    def read(self, index: int, subindex: int, data: bytes) -> Reading | None:
        key = (index, subindex, data)
        cache = self._cache
        if key in cache:
            return cache[key]
        if len(cache) >= self.CACHED:
            cache.clear()
        reading = cache[key] = self._read(index, subindex, data)
        return reading

    def _read(self, index: int, subindex: int, data: bytes) -> Reading | None:
        param = CATALOGUE.by_address(index, subindex)
        if param is None:
            return None
        size = param.dtype.size
        try:
            raw = param.dtype.decode(data if param.is_string else data[:size])
        except (ValueError, TypeError, struct.error):  # fewer bytes than the type
            return None
        if param.is_string:
            return Reading(param.mnemonic, str(raw), f"{param.text.en} = {raw!r}")
        value = param.to_display(raw)
        shown = param.format_display(raw)
        unit = f" {param.unit}" if param.unit else ""
        hexed = (
            f" (0x{int(raw) & 0xFFFFFFFF:X})"
            if param.scale == 1.0 and not unit and not param.choices
            else ""
        )
        return Reading(
            param.mnemonic, value, f"{param.text.en} {param.mnemonic} = {shown}{unit}{hexed}"
        )

    def pdo_defaults(self, node: int, receive: bool, control_mode: int) -> list[PdoDefault]:
        kind = "RPDO" if receive else "TPDO"
        result = []
        for n in (1, 2):
            cob = _cob(kind, n, node)
            count = int(CATALOGUE[f"{kind}{n}MAPN"].default)
            entries = tuple(
                mapping_for_control_mode(CATALOGUE[f"{kind}{n}MAP{sub}"], control_mode)
                for sub in range(1, count + 1)
            )
            result.append((cob, n, entries))
        return result


def _cob(kind: str, n: int, node: int) -> int:
    param = CATALOGUE[f"{kind}{n}COBID"]
    assert isinstance(param.default, int)
    return param.default + node if param.node_relative else param.default


class EdsDictionary:
    """A node described by an EDS file (CiA 306), read with the ``canopen`` package."""

    def __init__(self, path: str | Path, node: int) -> None:
        import canopen

        self.kind = f"EDS {Path(path).name}"
        try:
            self._od: Any = canopen.import_od(str(path), node)
        except Exception as exc:  # canopen's parser raises what configparser meets
            raise FileFormatError(str(path), [FileProblem(0, f"not a usable EDS: {exc}")]) from exc

    def _variable(self, index: int, subindex: int) -> Any:
        import canopen

        try:
            obj = self._od[index]
        except KeyError:
            return None
        if isinstance(obj, canopen.objectdictionary.ODVariable):
            return obj if subindex == 0 else None
        try:
            return obj[subindex]
        except KeyError:
            return None

    def read(self, index: int, subindex: int, data: bytes) -> Reading | None:
        var = self._variable(index, subindex)
        if var is None:
            return None
        try:
            value = var.decode_phys(var.decode_raw(data))
        except Exception:
            return None
        unit = f" {var.unit}" if getattr(var, "unit", "") else ""
        return Reading(var.name, value, f"{var.name} = {value}{unit}")

    def pdo_defaults(self, node: int, receive: bool, control_mode: int) -> list[PdoDefault]:
        comm, maps = (0x1400, 0x1600) if receive else (0x1800, 0x1A00)
        result = []
        for n in range(512):
            cob_var, count_var = self._variable(comm + n, 1), self._variable(maps + n, 0)
            if cob_var is None or count_var is None:
                continue
            count = int(count_var.default or 0)
            entries = []
            for sub in range(1, count + 1):
                entry = self._variable(maps + n, sub)
                entries.append(int(entry.default or 0) if entry is not None else 0)
            result.append((int(cob_var.default or 0), n + 1, tuple(entries)))
        return result


class RawDictionary:
    """A node nothing is known of: its frames shown as bytes."""

    kind = "raw"

    def read(self, index: int, subindex: int, data: bytes) -> Reading | None:
        return None

    def pdo_defaults(self, node: int, receive: bool, control_mode: int) -> list[PdoDefault]:
        return []

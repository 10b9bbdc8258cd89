"""A valve's parameter set for scripts: :class:`ParameterSet`, :func:`read_prm`, :func:`write_prm`.

Values are in display units (mA, %, Hz … as the catalogue and the *.prm file give them); the
raw object-dictionary values stay inside (:attr:`ParameterSet.raw`). No Qt.
"""

from __future__ import annotations

import html
import os
from collections.abc import Iterator, Mapping, MutableMapping

from prm9tool.catalogue import CATALOGUE, Parameter
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.device.records import Value
from prm9tool.files.prmfile import PrmContents, read_file, write_file

Display = float | int | str
"""A value in display units: a number (int when the catalogue's scale is 1) or a text."""

__all__ = ["Display", "ParameterSet", "display", "lookup", "read_prm", "write_prm"]


class ParameterSet(MutableMapping[str, Display]):
    """The parameters of one valve type: ``mnemonic -> value`` in display units.

    ``params["LIMTA"]`` is the value in mA; ``params["LIMTA"] = 1700`` checks it against the
    catalogue's range first (ValueRangeError, the set unchanged); an unknown mnemonic is a
    KeyError. ``type_key`` says which valve the set is for; ``serial`` and ``firmware`` which
    valve it was read from (None for a set that was not).
    """

    def __init__(
        self,
        type_key: TypeKey | str,
        raw: Mapping[str, Value] | None = None,
        *,
        serial: int | None = None,
        firmware: str | None = None,
    ) -> None:
        self.type_key = TypeKey.parse(type_key) if isinstance(type_key, str) else type_key
        self.serial, self.firmware = serial, firmware
        self._params = {p.mnemonic: p for p in CATALOGUE.file_parameters(self.type_key.variant)}
        if raw is None:
            raw = PrmContents.factory(self.type_key).values
        self._raw: dict[str, Value] = {}
        for mnemonic, value in raw.items():
            self._parameter(mnemonic).check_raw(value)
            self._raw[mnemonic] = value

    @classmethod
    def factory(cls, type_key: TypeKey | str) -> ParameterSet:
        """The factory defaults of ``type_key``."""
        return cls(type_key)

    @classmethod
    def from_contents(cls, contents: PrmContents) -> ParameterSet:
        """The set a *.prm file's contents hold."""
        return cls(
            contents.type_key, contents.values, serial=contents.serial, firmware=contents.firmware
        )

    def to_contents(self) -> PrmContents:
        """The set as *.prm file contents."""
        return PrmContents(self.type_key, dict(self._raw), self.serial, self.firmware)

    @property
    def raw(self) -> dict[str, Value]:
        """A copy of the raw values (as the object dictionary holds them)."""
        return dict(self._raw)

    def parameter(self, mnemonic: str) -> Parameter:
        """The catalogue entry of ``mnemonic`` (unit, range, text); KeyError if the set has none."""
        return self._parameter(mnemonic)

    def text(self, mnemonic: str) -> str:
        """The value as the *.prm file and the table write it (``"1800"``, ``"12.5"``)."""
        return self._parameter(mnemonic).format_display(self._raw[mnemonic])

    def copy(self) -> ParameterSet:
        """An independent copy."""
        return ParameterSet(self.type_key, self._raw, serial=self.serial, firmware=self.firmware)

    # --- the mapping ------------------------------------------------------------------------
    def __getitem__(self, mnemonic: str) -> Display:
        param = self._parameter(mnemonic)
        return display(param, self._raw[mnemonic])

    def __setitem__(self, mnemonic: str, value: Display) -> None:
        param = self._parameter(mnemonic)
        raw = param.to_raw(value)
        param.check_raw(raw)
        self._raw[mnemonic] = raw

    def __delitem__(self, mnemonic: str) -> None:
        del self._raw[mnemonic]

    def __iter__(self) -> Iterator[str]:
        return iter(self._raw)

    def __len__(self) -> int:
        return len(self._raw)

    def __eq__(self, other: object) -> bool:
        if isinstance(other, ParameterSet):
            return self.type_key == other.type_key and self._raw == other._raw
        return super().__eq__(other)

    __hash__ = None  # type: ignore[assignment]

    def __repr__(self) -> str:
        shown = ", ".join(f"{m}={self.text(m)}" for m in list(self._raw)[:4])
        more = ", …" if len(self._raw) > 4 else ""
        origin = f", serial={self.serial}" if self.serial is not None else ""
        return f"<ParameterSet {self.type_key}{origin}: {len(self)} parameters ({shown}{more})>"

    def _repr_html_(self) -> str:
        rows = "".join(
            f"<tr><td>{m}</td><td style='text-align:right'>{html.escape(self.text(m))}</td>"
            f"<td>{html.escape(self._params[m].unit)}</td>"
            f"<td style='text-align:left'>{html.escape(self._params[m].text.en)}</td></tr>"
            for m in self._raw
        )
        return f"<table><caption>{html.escape(repr(self))}</caption>{rows}</table>"

    def _parameter(self, mnemonic: str) -> Parameter:
        where = f"in the parameter set of a {self.type_key.variant.label} valve"
        return lookup(self._params, mnemonic, where)


def display(param: Parameter, raw: Value) -> Display:
    """``raw`` in display units: an int when the scale is 1, else the shortest decimal that
    reads back to exactly ``raw`` (``12.5``, not ``12.500000000000002``); a text as it is."""
    if param.is_string or isinstance(raw, str):
        return raw
    if param.scale == 1.0:
        return int(raw)
    return float(param.format_display(raw))


def lookup(params: Mapping[str, Parameter], mnemonic: str, where: str) -> Parameter:
    """``params[mnemonic]``, or a KeyError that says whether the catalogue knows it at all."""
    param = params.get(mnemonic)
    if param is None:
        known = "" if mnemonic in CATALOGUE else " in the catalogue"
        raise KeyError(f"{mnemonic}: no such parameter{known} {where}")
    return param


def read_prm(path: str | os.PathLike[str]) -> ParameterSet:
    """Read a *.prm file; FileFormatError lists every problem with its line."""
    return ParameterSet.from_contents(read_file(path))


def write_prm(path: str | os.PathLike[str], params: ParameterSet, backup: bool = True) -> None:
    """Write ``params`` to a *.prm file atomically (the old file kept as ``<name>.bak`` unless
    ``backup`` is False); FileFormatError when it cannot be written (the old file untouched)."""
    write_file(params.to_contents(), path, backup=backup)


def as_parameter_set(values: Mapping[str, Display], type_key: TypeKey) -> ParameterSet:
    """``values`` as a ParameterSet: itself, or display values for ``type_key`` checked here."""
    if isinstance(values, ParameterSet):
        return values
    params = ParameterSet(type_key, {})
    params.update(values)
    return params

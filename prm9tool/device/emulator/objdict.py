"""The emulated valve's object dictionary: RAM values, live getters, write hooks, abort codes.

Every entry comes from the parameter catalogue. The only entries added here are the CiA 301
"highest sub-index" entries (sub 0) of records and arrays, derived from the catalogue's own
sub-indices. Errors are raised as :class:`SdoAbortError` with the CiA 301 abort code.
"""

from __future__ import annotations

import struct
from collections.abc import Callable, Iterable
from operator import itemgetter
from typing import Any

from prm9tool.catalogue import CATALOGUE, Catalogue, DataType, ObjAccess, Parameter, Texts
from prm9tool.catalogue.variant import Variant
from prm9tool.errors import AbortCode, SdoAbortError

Value = int | str
Key = tuple[int, int]
Getter = Callable[[], Value]
Hook = Callable[[Value], None]

_READABLE = (ObjAccess.RO, ObjAccess.RW, ObjAccess.CONST)
# CiA 301: 0x1003/0 takes only 0 (clear the history); another value is invalid, not out of range
ZERO_CLEARS: frozenset[Key] = frozenset({(0x1003, 0)})


def _sub0(index: int, highest: int) -> Parameter:
    return Parameter(
        f"SUB0_{index:04X}",
        index,
        0,
        DataType.UNSIGNED8,
        highest,
        highest,
        highest,
        Texts("Highest sub-index supported", "Höchster Subindex", "Nejvyšší subindex"),
        group="od_structure",
        obj_access=ObjAccess.CONST,
        in_file=False,
        source="CiA 301 (derived from the catalogue's sub-indices)",
    )


def _no_reader(values: dict[Key, Value]) -> Any:
    """read_all's mark for addresses read one at a time (never called)."""
    raise NotImplementedError


def abort(key: Key, code: AbortCode) -> SdoAbortError:
    """An SdoAbortError for ``key`` with ``code``."""
    return SdoAbortError(key[0], key[1], int(code))


class ObjectDictionary:
    """RAM image of one valve's object dictionary, with access rules and hooks.

    ``getters`` supply live values (read-only process data); ``hooks`` replace the plain store
    of a validated write (commands such as 0x1010 "save"); ``checks`` validate a value beyond
    the catalogue range (cross-parameter limits, device-state rules) and refuse it by raising
    :class:`SdoAbortError`; ``on_change`` is told the mnemonic after every accepted write that
    ran a hook or changed the stored value.
    """

    def __init__(self, variant: Variant, catalogue: Catalogue = CATALOGUE) -> None:
        self.variant = variant
        self.entries: dict[Key, Parameter] = {p.key: p for p in catalogue.for_variant(variant)}
        self.by_mnemonic: dict[str, Parameter] = {p.mnemonic: p for p in self.entries.values()}
        subs: dict[int, list[int]] = {}
        for index, sub in self.entries:
            subs.setdefault(index, []).append(sub)
        for index, sub_list in subs.items():
            if 0 not in sub_list:
                self.entries[(index, 0)] = _sub0(index, max(sub_list))
        self.indices = set(subs)
        self.values: dict[Key, Value] = {}
        self.getters: dict[Key, Getter] = {}
        self.hooks: dict[Key, Hook] = {}
        self.checks: dict[Key, Hook] = {}
        self.on_change: Callable[[str], None] | None = None
        # PDO mappings' entries resolved once: ((index, subindex, bits), ...) -> (param, bytes)
        self._mapped: dict[tuple[tuple[int, int, int], ...], tuple[tuple[Parameter, int], ...]]
        self._mapped = {}
        # and for writing: (index, subindex, bytes, (param, struct unpack) or None: write_bytes)
        self._written: dict[tuple[tuple[int, int, int], ...], tuple[_Written, ...]] = {}
        self._readers: dict[tuple[Key, ...], Callable[[dict[Key, Value]], Any]] = {}

    # --- lookups -----------------------------------------------------------------------
    def entry(self, index: int, subindex: int) -> Parameter:
        """The catalogue entry at the address, or an abort (no such object / sub-index)."""
        param = self.entries.get((index, subindex))
        if param is None:
            code = AbortCode.NO_SUCH_SUBINDEX if index in self.indices else AbortCode.NO_SUCH_OBJECT
            raise abort((index, subindex), code)
        return param

    def param(self, mnemonic: str) -> Parameter:
        """The entry with ``mnemonic`` (KeyError if it does not exist on this variant)."""
        return self.by_mnemonic[mnemonic]

    def has(self, mnemonic: str) -> bool:
        """True if the parameter exists on this variant."""
        return mnemonic in self.by_mnemonic

    def get(self, mnemonic: str) -> Value:
        """Current RAM value of a stored parameter (no access check; for the firmware)."""
        return self.values[self.by_mnemonic[mnemonic].key]

    # --- access ------------------------------------------------------------------------
    def read(self, index: int, subindex: int) -> Value:
        """Read with CiA 301 access rules."""
        param = self.entries.get((index, subindex))  # entry()'s look-up, its abort if absent
        return self._read(param if param is not None else self.entry(index, subindex))

    def _read(self, param: Parameter) -> Value:
        key = param.key
        if param.obj_access not in _READABLE:
            raise abort(key, AbortCode.WRITE_ONLY)
        getter = self.getters.get(key)
        if getter is not None:
            return getter()
        value = self.values.get(key)
        return param.default if value is None else value

    def write(self, index: int, subindex: int, value: Value) -> None:
        """Write with CiA 301 access and range rules; runs the check and hook of the entry."""
        self._write(self.entry(index, subindex), value)

    def _write(self, param: Parameter, value: Value) -> None:
        key = param.key
        if not param.writable:
            raise abort(key, AbortCode.READ_ONLY)
        validate(param, value)
        check = self.checks.get(key)
        if check is not None:
            check(value)
        hook = self.hooks.get(key)
        if hook is not None:
            hook(value)
        else:
            old = self.values.get(key)
            if old is not None and type(old) is type(value) and old == value:
                return  # the same value again (an RPDO each SYNC): nothing downstream changes
            self.values[key] = value
        if self.on_change is not None:
            self.on_change(param.mnemonic)

    def read_all(self, addresses: tuple[Key, ...]) -> tuple[Value, ...]:
        """:meth:`read` of each address: those stored plainly (readable, no getter) by one
        C-level look-up of them all (the CANopen slave's poll every 10 ms, its heartbeat time
        every 1 ms), the others, or a value not stored, through :meth:`read`."""
        get = self._readers.get(addresses)
        if get is None:
            plain = all(
                (p := self.entries.get(key)) is not None
                and p.obj_access in _READABLE
                and key not in self.getters
                for key in addresses
            )
            get = itemgetter(*addresses) if plain and len(addresses) > 1 else _no_reader
            self._readers[addresses] = get
        if get is not _no_reader:
            try:
                return get(self.values)  # type: ignore[no-any-return]
            except KeyError:  # not stored: read() answers the default
                pass
        return tuple([self.read(index, subindex) for index, subindex in addresses])

    def read_bytes(self, index: int, subindex: int) -> bytes:
        """Read and encode per the catalogue data type (little-endian)."""
        param = self.entry(index, subindex)
        return param.dtype.encode(self._read(param))

    def read_mapped(self, entries: tuple[tuple[int, int, int], ...]) -> bytes:
        """What a PDO mapping ``(index, subindex, bits)`` entries carries: :meth:`read_bytes`
        of each, cut to its bits, joined (an entry that does not exist aborts)."""
        plan = self._mapped.get(entries)
        if plan is None:
            plan = tuple((self.entry(index, sub), bits // 8) for index, sub, bits in entries)
            self._mapped[entries] = plan
        read = self._read
        return b"".join([param.dtype.encode(read(param))[:size] for param, size in plan])

    def write_mapped(
        self, entries: tuple[tuple[int, int, int], ...], data: bytes
    ) -> list[SdoAbortError]:
        """:meth:`write_bytes` of each entry's bytes of ``data`` in turn (long enough: the
        caller checked); the entries that refused their value, as their aborts."""
        plan = self._written.get(entries)
        if plan is None:  # resolved once per mapping, as read_mapped's: an RPDO each SYNC
            plan = tuple(
                _write_plan(self.entries.get((i, s)), i, s, bits) for i, s, bits in entries
            )
            self._written[entries] = plan
        refused: list[SdoAbortError] = []
        offset = 0
        write = self._write
        for index, sub, size, direct in plan:
            chunk = data[offset : offset + size]
            offset += size
            try:
                if direct is None or len(chunk) != size:  # the general path and its aborts
                    self.write_bytes(index, sub, chunk)
                else:  # write_bytes' checks passed already: a writable entry of this size
                    write(direct[0], int(direct[1](chunk)[0]))
            except SdoAbortError as exc:
                refused.append(exc)
        return refused

    def read_encoded(self, addresses: Iterable[Key], room: int) -> list[bytes | int]:
        """:meth:`read_bytes` of ``addresses`` in order, a refused entry as its abort code, as
        many as fit ``room`` bytes at a length byte each (an abort code takes 5 bytes)."""
        values: list[bytes | int] = []
        entries = self.entries
        for key in addresses:
            param = entries.get(key)
            try:
                if param is None:
                    param = self.entry(*key)  # raises the abort
                value: bytes | int = param.dtype.encode(self._read(param))
            except SdoAbortError as exc:
                value = exc.code
            size = 5 if isinstance(value, int) else 1 + len(value)
            if size > room:
                break
            values.append(value)
            room -= size
        return values

    def write_bytes(self, index: int, subindex: int, data: bytes) -> None:
        """Decode per the catalogue data type and write; wrong lengths abort."""
        param = self.entry(index, subindex)
        if not param.writable:
            raise abort(param.key, AbortCode.READ_ONLY)
        size = param.dtype.size
        if size and len(data) != size:
            code = AbortCode.LENGTH_TOO_HIGH if len(data) > size else AbortCode.LENGTH_TOO_LOW
            raise abort(param.key, code)
        try:
            value = param.dtype.decode(bytes(data))
        except (struct.error, UnicodeDecodeError) as exc:
            raise abort(param.key, AbortCode.WRONG_LENGTH) from exc
        self._write(param, value)


_Written = tuple[int, int, int, tuple[Parameter, Callable[[bytes], tuple[int, ...]]] | None]


def _write_plan(param: Parameter | None, index: int, sub: int, bits: int) -> _Written:
    """How :meth:`ObjectDictionary.write_mapped` writes an entry: decoded by its struct right
    away when :meth:`~ObjectDictionary.write_bytes` would only check what holds for every frame
    (it exists, is writable, a number of exactly this size), else through ``write_bytes``."""
    size = bits // 8
    codec = None if param is None else param.dtype.codec
    if param is None or codec is None or not param.writable or codec.size != size:
        return index, sub, size, None
    return index, sub, size, (param, codec.unpack)


def validate(param: Parameter, value: Value) -> None:
    """Raise the CiA 301 abort a valve answers for ``value`` outside the catalogue limits."""
    key = param.key
    if param.is_string:
        if not isinstance(value, str):
            raise abort(key, AbortCode.WRONG_LENGTH)
        return
    if isinstance(value, bool) or not isinstance(value, int):
        raise abort(key, AbortCode.WRONG_LENGTH)
    if key in ZERO_CLEARS and value != 0:
        raise abort(key, AbortCode.INVALID_VALUE)
    if value < param.raw_min:
        raise abort(key, AbortCode.VALUE_TOO_LOW)
    if value > param.raw_max:
        raise abort(key, AbortCode.VALUE_TOO_HIGH)
    if param.choices and value not in {code for code, _ in param.choices}:
        raise abort(key, AbortCode.INVALID_VALUE)

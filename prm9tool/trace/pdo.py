"""The PDO mappings in force on a bus, node by node, as the trace changes them: each node starts
with its defaults (a PRM9: manual table 7-13 from the catalogue; another node: its EDS), and
SDO writes to the communication (0x1400/0x1800) and mapping (0x1600/0x1A00) objects change
them from the frame they complete on. No Qt."""

from __future__ import annotations

from dataclasses import dataclass, field

from prm9tool.trace.dictionary import NodeDictionary, Reading

INVALID = 0x80000000  # COB-ID bit 31: PDO not valid (CiA 301)


@dataclass
class Pdo:
    """One PDO of one node: its COB-ID entry and its mapping (subindex 0 and the entries)."""

    node: int
    receive: bool
    number: int
    cob_entry: int
    count: int
    entries: list[int] = field(default_factory=lambda: [0] * 64)
    _fields: list[tuple[int, int, int, int, int]] | None = None  # shift, mask, bytes, index, sub
    decoded: dict[bytes, object] = field(default_factory=dict)  # the decoder's cache by data
    _length: int | None = None

    @property
    def name(self) -> str:
        """``RPDO1`` / ``TPDO2``."""
        return f"{'RPDO' if self.receive else 'TPDO'}{self.number}"

    @property
    def cob(self) -> int | None:
        """The 11-bit COB-ID when the PDO is valid, else None."""
        if self.cob_entry & INVALID or self.cob_entry & 0x20000000:
            return None
        return self.cob_entry & 0x7FF

    def fields(self) -> list[tuple[int, int, int, int, int]]:
        """The mapped objects as (bit shift, mask, bytes, index, subindex)."""
        if self._fields is None:
            result, shift = [], 0
            for entry in self.entries[: self.count]:
                bits = entry & 0xFF
                result.append(
                    (shift, (1 << bits) - 1, (bits + 7) // 8, entry >> 16, (entry >> 8) & 0xFF)
                )
                shift += bits
            self._fields = result
        return self._fields

    def length(self) -> int:
        """The bytes its mapping fills."""
        if self._length is None:
            self._length = (sum(entry & 0xFF for entry in self.entries[: self.count]) + 7) // 8
        return self._length

    def set_mapping(self, subindex: int, value: int) -> None:
        """An SDO write to the mapping object."""
        if subindex == 0:
            self.count = min(value & 0xFF, 64)
        elif subindex <= 64:
            self.entries[subindex - 1] = value & 0xFFFFFFFF
        self._fields = self._length = None
        self.decoded.clear()

    def decode(self, data: bytes, od: NodeDictionary) -> list[tuple[int, int, Reading | None]]:
        """The mapped objects' values in ``data``: (index, subindex, reading or None)."""
        word = int.from_bytes(data, "little")
        return [
            (index, sub, od.read(index, sub, ((word >> shift) & mask).to_bytes(size, "little")))
            for shift, mask, size, index, sub in self.fields()
        ]


class PdoMaps:
    """Every node's PDOs, and which COB-ID is whose."""

    def __init__(self) -> None:
        self._pdos: dict[tuple[int, bool, int], Pdo] = {}
        self._by_cob: dict[int, Pdo] | None = None

    def add_defaults(self, node: int, od: NodeDictionary, control_mode: int) -> None:
        """The node's PDOs at power-up (again after a reset of it)."""
        for receive in (True, False):
            for cob, number, entries in od.pdo_defaults(node, receive, control_mode):
                pdo = Pdo(node, receive, number, cob, len(entries))
                pdo.entries[: len(entries)] = entries
                self._pdos[(node, receive, number)] = pdo
        self._by_cob = None

    def forget(self, node: int) -> None:
        """A node gets another dictionary: its PDOs anew."""
        for key in [k for k in self._pdos if k[0] == node]:
            del self._pdos[key]
        self._by_cob = None

    def by_cob(self, cob: int) -> Pdo | None:
        """The valid PDO sent on ``cob`` (None: none)."""
        if self._by_cob is None:
            self._by_cob = {}
            for pdo in self._pdos.values():
                if pdo.cob is not None:
                    self._by_cob.setdefault(pdo.cob, pdo)
        return self._by_cob.get(cob)

    def written(self, node: int, index: int, subindex: int, value: int) -> bool:
        """Apply an SDO write (or a value read back) to a PDO object; True if it was one."""
        for receive, comm, maps in ((True, 0x1400, 0x1600), (False, 0x1800, 0x1A00)):
            if comm <= index < comm + 0x200 and subindex == 1:
                pdo = self._pdo(node, receive, index - comm + 1)
                pdo.cob_entry = value & 0xFFFFFFFF
                self._by_cob = None
                return True
            if maps <= index < maps + 0x200:
                self._pdo(node, receive, index - maps + 1).set_mapping(subindex, value)
                return True
        return False

    def _pdo(self, node: int, receive: bool, number: int) -> Pdo:
        key = (node, receive, number)
        if key not in self._pdos:
            self._pdos[key] = Pdo(node, receive, number, INVALID, 0)
        return self._pdos[key]

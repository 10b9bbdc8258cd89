"""Builders of the catalogue's communication profile objects (CiA 301, manual table 7-13): one
object, a PDO's communication and mapping parameters, the PDO event timers."""

from __future__ import annotations

from prm9tool.catalogue._vocabulary import CA_ONLY, RO, U8, U16, U32, T
from prm9tool.catalogue.schema import Access, DataType, ObjAccess, Parameter, Texts

WO = ObjAccess.WO


def comm_object(
    mnemonic: str,
    index: int,
    sub: int,
    dtype: DataType,
    default: int | str,
    text: Texts,
    obj: ObjAccess = RO,
    lo: int | None = None,
    hi: int | None = None,
    node_relative: bool = False,
    applies: object = CA_ONLY,
    source: str = "table 7-13",
    unit: str = "",
) -> Parameter:
    """One object of the communication profile area (configured by the master, not in the file)."""
    nat_lo, nat_hi = dtype.natural_range
    return Parameter(
        mnemonic,
        index,
        sub,
        dtype,
        nat_lo if lo is None else lo,
        nat_hi if hi is None else hi,
        default,
        group="canopen_comm",
        access=Access.EXPERT if obj in (ObjAccess.RW, WO) else Access.READ_ONLY,
        obj_access=obj,
        in_file=False,
        node_relative=node_relative,
        text=text,
        applies=applies,  # type: ignore[arg-type]
        source=source,
        unit=unit,
    )


def pdo_objects(
    kind: str, n: int, comm: int, mapping: tuple[int, ...], cob: int
) -> list[Parameter]:
    """PDO ``n`` (``kind`` RPDO or TPDO): its communication parameters at ``comm`` and its
    mapping (``comm`` + 0x200) with the ``mapping`` entries; ``cob`` the COB-ID without node ID."""
    rx = kind == "RPDO"
    result = [
        comm_object(
            f"{kind}{n}SUBS",
            comm,
            0,
            U8,
            5,
            T(
                f"{kind}{n} communication: highest subindex",
                f"{kind}{n} Kommunikation: höchster Subindex",
                f"{kind}{n} komunikace: nejvyšší subindex",
            ),
        ),
        comm_object(
            f"{kind}{n}COBID",
            comm,
            1,
            U32,
            cob,
            T(f"{kind}{n} COB-ID", f"{kind}{n} COB-ID", f"{kind}{n} COB-ID"),
            ObjAccess.RW,
            node_relative=True,
        ),
        comm_object(
            f"{kind}{n}TYPE",
            comm,
            2,
            U8,
            0xFF,
            T(
                f"{kind}{n} transmission type",
                f"{kind}{n} Übertragungsart",
                f"{kind}{n} typ přenosu",
            ),
            ObjAccess.RW,
            source="table 7-13, 7-12 (RPDO type writable as §7.6 writes it: decision)",
        ),
    ]
    result.append(rpdo_timer(n, comm) if rx else tpdo_timer(n, comm))
    map_index = (0x1600 if rx else 0x1A00) + n - 1
    result.append(
        comm_object(
            f"{kind}{n}MAPN",
            map_index,
            0,
            U8,
            len(mapping),
            T(
                f"{kind}{n} mapping: number of entries",
                f"{kind}{n} Mapping: Anzahl Einträge",
                f"{kind}{n} mapování: počet položek",
            ),
        )
    )
    for sub, entry in enumerate(mapping, start=1):
        result.append(
            comm_object(
                f"{kind}{n}MAP{sub}",
                map_index,
                sub,
                U32,
                entry,
                T(
                    f"{kind}{n} mapping entry {sub}",
                    f"{kind}{n} Mapping-Eintrag {sub}",
                    f"{kind}{n} mapovaný objekt {sub}",
                ),
            )
        )
    return result


def tpdo_timer(n: int, comm: int) -> Parameter:
    """TPDO ``n``'s event timer."""
    return comm_object(
        f"TPDO{n}TIMER",
        comm,
        5,
        U16,
        0x1388,
        T(f"TPDO{n} event timer", f"TPDO{n} Ereignis-Timer", f"TPDO{n} časovač událostí"),
        ObjAccess.RW,
        unit="ms",
    )


def rpdo_timer(n: int, comm: int) -> Parameter:
    """RPDO ``n``'s event timer: the reception deadline."""
    return comm_object(
        f"RPDO{n}TIMER",
        comm,
        5,
        U16,
        0,
        T(
            f"RPDO{n} event timer (reception deadline, 0 = off)",
            f"RPDO{n} Ereignis-Timer (Empfangsfrist, 0 = aus)",
            f"RPDO{n} časovač událostí (lhůta příjmu, 0 = vypnuto)",
        ),
        ObjAccess.RW,
        unit="ms",
        source="CiA 301 deadline monitoring for table 7-18 'Event-Timer Error' (not in 7-13: decision)",
    )

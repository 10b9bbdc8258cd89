"""Catalogue data: the CiA 301 communication profile area of a -CA valve (manual table 7-13).

These objects are configured by the CANopen master and kept by the valve with 0x1010; they are
not part of the *.prm parameter set (``in_file=False``), because COB-IDs depend on the node ID
of each valve on a production line (decision).
"""

from __future__ import annotations

import dataclasses

from prm9tool.catalogue._comm_objects import comm_object, pdo_objects
from prm9tool.catalogue._vocabulary import FIRMWARE_VERSION, STR, U8, U16, U32, T
from prm9tool.catalogue.schema import (
    EVERY_VARIANT as ALL,
)
from prm9tool.catalogue.schema import ObjAccess, Parameter

WO = ObjAccess.WO
CONST = ObjAccess.CONST
ERROR_HISTORY_DEPTH = 8  # 0x1003 keeps the 8 newest errors (decision)
SAVE_SIGNATURE = 0x65766173  # "save" little-endian (CiA 301)
LOAD_SIGNATURE = 0x64616F6C  # "load" little-endian (CiA 301)


def revision_number(version: str) -> int:
    """0x1018/3 from a ``major.minor.patch`` version text (decision: major<<16|minor<<8|patch)."""
    parts = [int(p) if p.isdigit() else 0 for p in version.split(".")[:3]]
    parts += [0] * (3 - len(parts))
    return (parts[0] & 0xFFFF) << 16 | (parts[1] & 0xFF) << 8 | (parts[2] & 0xFF)


COMMUNICATION: list[Parameter] = [
    comm_object(
        "DEVTYPE",
        0x1000,
        0,
        U32,
        0x198,
        T("Device type", "Gerätetyp", "Typ zařízení"),
        CONST,
        applies=ALL,
    ),
    comm_object(
        "ERRREG", 0x1001, 0, U8, 0, T("Error register", "Fehlerregister", "Chybový registr")
    ),
    comm_object(
        "ERRCOUNT",
        0x1003,
        0,
        U8,
        0,
        T(
            "Pre-defined error field: number of errors",
            "Fehlerspeicher: Anzahl Fehler",
            "Předdefinované chybové pole: počet položek",
        ),
        ObjAccess.RW,
        0,
        0,
        source="table 7-13 (only 0 may be written: clears the history, CiA 301)",
    ),
    *[
        comm_object(
            f"ERRHIST{k}",
            0x1003,
            k,
            U32,
            0,
            T(
                f"Error history entry {k}",
                f"Fehlerspeicher Eintrag {k}",
                f"Položka chybového pole {k}",
            ),
        )
        for k in range(1, ERROR_HISTORY_DEPTH + 1)
    ],
    comm_object(
        "COBIDSYNC",
        0x1005,
        0,
        U32,
        0x80,
        T("COB-ID SYNC", "COB-ID SYNC", "COB-ID zprávy SYNC"),
        ObjAccess.RW,
    ),
    comm_object(
        "CYCLEPERIOD",
        0x1006,
        0,
        U32,
        0,
        T("Communication cycle period", "Kommunikationszykluszeit", "Perioda komunikačního cyklu"),
        ObjAccess.RW,
        unit="µs",
    ),
    comm_object(
        "DEVNAME",
        0x1008,
        0,
        STR,
        "PRM9",
        T("Manufacturer device name", "Gerätename des Herstellers", "Název zařízení výrobce"),
        CONST,
    ),
    comm_object(
        "HWVER",
        0x1009,
        0,
        STR,
        "1.00",
        T("Manufacturer hardware version", "Hardware-Version", "Verze HW výrobce"),
        CONST,
    ),
    comm_object(
        "STORESUBS",
        0x1010,
        0,
        U8,
        1,
        T(
            "Store parameters: highest subindex",
            "Parameter speichern: höchster Subindex",
            "Uložení parametrů: nejvyšší subindex",
        ),
        source="CiA 301 (0x1010: seed 003)",
    ),
    comm_object(
        "STOREALL",
        0x1010,
        1,
        U32,
        1,
        T(
            'Store all parameters (write "save")',
            'Alle Parameter speichern ("save")',
            'Uložit všechny parametry ("save")',
        ),
        ObjAccess.RW,
        source="CiA 301 (reads 1: stores on command)",
    ),
    comm_object(
        "RESTORESUBS",
        0x1011,
        0,
        U8,
        1,
        T(
            "Restore defaults: highest subindex",
            "Werkseinstellung: höchster Subindex",
            "Obnovení výchozích hodnot: nejvyšší subindex",
        ),
        source="CiA 301",
    ),
    comm_object(
        "RESTOREALL",
        0x1011,
        1,
        U32,
        1,
        T(
            'Restore all default parameters (write "load")',
            'Alle Werkseinstellungen laden ("load")',
            'Obnovit všechny výchozí parametry ("load")',
        ),
        ObjAccess.RW,
        source="CiA 301",
    ),
    comm_object(
        "COBIDEMCY",
        0x1014,
        0,
        U32,
        0x80,
        T("COB-ID emergency message", "COB-ID Emergency", "COB-ID emergency zpráv"),
        ObjAccess.RW,
        node_relative=True,
        source="table 7-13 (U32 as §7.6 writes 4 bytes; default 0x80+node: decision)",
    ),
    comm_object(
        "HEARTBEAT",
        0x1017,
        0,
        U16,
        1000,
        T("Producer heartbeat time", "Heartbeat-Zeit", "Doba heartbeat odesílatele"),
        ObjAccess.RW,
        unit="ms",
    ),
    comm_object(
        "IDSUBS",
        0x1018,
        0,
        U8,
        4,
        T("Identity: highest subindex", "Identität: höchster Subindex", "Identita: počet položek"),
    ),
    comm_object(
        "VENDORID", 0x1018, 1, U32, 0xE6, T("Vendor ID", "Hersteller-ID", "Vendor ID"), CONST
    ),
    comm_object(
        "PRODCODE",
        0x1018,
        2,
        U32,
        0x0009,
        T("Product code", "Produktcode", "Produktový klíč"),
        source="table 7-13 (value: decision)",
    ),
    comm_object(
        "REVISION",
        0x1018,
        3,
        U32,
        revision_number(FIRMWARE_VERSION),
        T(
            "Revision number (firmware major<<16 | minor<<8 | patch)",
            "Revisionsnummer",
            "Číslo revize",
        ),
        source="table 7-13 (encoding: decision)",
    ),
    comm_object(
        "NMTSTARTUP",
        0x1F80,
        0,
        U32,
        2,
        T(
            "NMT startup (0 = start automatically)",
            "NMT-Start (0 = automatisch)",
            "Spuštění NMT (0 = automaticky)",
        ),
        ObjAccess.RW,
        0,
        2,
    ),
    *pdo_objects("RPDO", 1, 0x1400, (0x60400010, 0x63000110), 0x40000200),
    *pdo_objects("RPDO", 2, 0x1401, (0x21000210,), 0x40000300),
    *pdo_objects("TPDO", 1, 0x1800, (0x60410010, 0x63010110), 0x180),
    *pdo_objects("TPDO", 2, 0x1801, (0x21000110, 0x21000610), 0x280),
]


_EVERY_VALVE = {
    "DEVTYPE",
    "ERRREG",
    "ERRCOUNT",
    "DEVNAME",
    "HWVER",
    "STORESUBS",
    "STOREALL",
    "RESTORESUBS",
    "RESTOREALL",
    "IDSUBS",
    "VENDORID",
    "PRODCODE",
    "REVISION",
    *(f"ERRHIST{k}" for k in range(1, ERROR_HISTORY_DEPTH + 1)),
}
COMMUNICATION = [
    dataclasses.replace(p, applies=ALL) if p.mnemonic in _EVERY_VALVE else p for p in COMMUNICATION
]

# Table 7-13: RPDO1/TPDO1 entry 2 follow the control mode 0x6043. ``default`` is the control
# mode 2 mapping, ``default_e04`` the control mode 4 one (4 is the E04 default of CTRLMODE).
_CONTROL_MODE_4_MAPPING = {"RPDO1MAP2": 0x63800110, "TPDO1MAP2": 0x63810110}
COMMUNICATION = [
    dataclasses.replace(p, default_e04=_CONTROL_MODE_4_MAPPING[p.mnemonic])
    if p.mnemonic in _CONTROL_MODE_4_MAPPING
    else p
    for p in COMMUNICATION
]

# Table 7-13 maps the external sensor 0x2100 into RPDO2 (0x1601: one entry) and TPDO2 (0x1A01:
# two entries) for every -CA valve, and table 7-14 makes 0x2100 an object of all valves: on an
# E02 -CA (no sensor input) TPDO2 is sent by its defaults and carries zeros, and RPDO2 writes
# 0x2100/2 without effect (decision, docs/canopen.md).

# Table 7-13 gives TPDO2 entry 2 as 0x21000510 but calls it "after linearization" (0x2100/6).
_DECISIONS = {"TPDO2MAP2": "table 7-13 (entry 2 after linearization: decision, docs/canopen.md)"}
COMMUNICATION = [
    dataclasses.replace(p, source=_DECISIONS[p.mnemonic]) if p.mnemonic in _DECISIONS else p
    for p in COMMUNICATION
]

"""Catalogue data: the external sensor of E04 valves (signal type, range, linearization) and
its data objects 0x2100. Manual table 7-14 lists these objects among those of all valves, so
an E02 -CA has them too (``SENSOR_OBJECTS``), though they are not part of its parameter set."""

from __future__ import annotations

from prm9tool.catalogue._vocabulary import (
    OFF_ON,
    PERCENT,
    POLARITY,
    RO,
    S16,
    SENSOR_OBJECTS,
    SIGNAL_TYPES,
    U8,
    U16,
    T,
    linearization,
    process_value,
)
from prm9tool.catalogue.scale import FULL_SCALE, GAIN
from prm9tool.catalogue.schema import ObjAccess, Parameter

_SENSOR_LIN = T(
    "External sensor linearization",
    "Linearisierung externer Sensor",
    "Linearizace externího snímače",
)
EXTERNAL_SENSOR: list[Parameter] = [
    Parameter(
        "SENSTYPE",
        0x2005,
        1,
        U16,
        0,
        14,
        9,
        group="ext_sensor",
        applies=SENSOR_OBJECTS,
        choices=SIGNAL_TYPES,
        text=T(
            "External sensor: signal type",
            "Externer Sensor: Signaltyp",
            "Externí snímač: typ signálu",
        ),
        source="table 7-14, 7-15, 7-22",
    ),
    Parameter(
        "SENSINV",
        0x2005,
        2,
        U8,
        0,
        1,
        0,
        group="ext_sensor",
        applies=SENSOR_OBJECTS,
        choices=POLARITY,
        text=T(
            "External sensor: polarity", "Externer Sensor: Polarität", "Externí snímač: polarita"
        ),
        source="table 7-14",
    ),
    Parameter(
        "SENSOFFS",
        0x2005,
        3,
        S16,
        -FULL_SCALE,
        FULL_SCALE,
        0,
        group="ext_sensor",
        applies=SENSOR_OBJECTS,
        unit="%",
        scale=PERCENT,
        decimals=1,
        text=T(
            "External sensor: zero offset",
            "Externer Sensor: Nullpunktverschiebung",
            "Externí snímač: posunutí nuly",
        ),
        source="table 7-14",
    ),
    Parameter(
        "SENSGAIN",
        0x2005,
        4,
        U16,
        16383,
        65535,
        FULL_SCALE,
        group="ext_sensor",
        applies=SENSOR_OBJECTS,
        scale=GAIN,
        decimals=3,
        text=T("External sensor: gain", "Externer Sensor: Verstärkung", "Externí snímač: zesílení"),
        source="table 7-14 (16384 = 1.0: inference from the range 16383…65535)",
    ),
    *linearization(
        "SENSLIN",
        0x2006,
        "X",
        "ext_sensor_linearization",
        _SENSOR_LIN,
        SENSOR_OBJECTS,
        "table 7-14",
    ),
    *linearization(
        "SENSLIN",
        0x2007,
        "Y",
        "ext_sensor_linearization",
        _SENSOR_LIN,
        SENSOR_OBJECTS,
        "table 7-14",
    ),
    Parameter(
        "SENSLINON",
        0x2008,
        0,
        U8,
        0,
        1,
        0,
        group="ext_sensor_linearization",
        applies=SENSOR_OBJECTS,
        choices=OFF_ON,
        text=T(
            "External sensor linearization on/off",
            "Linearisierung externer Sensor ein/aus",
            "Linearizace externího snímače zapnuto/vypnuto",
        ),
        source="table 7-14",
    ),
]

EXTERNAL_SENSOR_DATA: list[Parameter] = [
    process_value(
        mn,
        0x2100,
        sub,
        text,
        group="ext_sensor_data",
        source="table 7-14",
        obj=obj,
        applies=SENSOR_OBJECTS,
    )
    for mn, sub, obj, text in (
        (
            "SENSVAL",
            1,
            RO,
            T("External sensor value", "Wert externer Sensor", "Hodnota signálu snímače"),
        ),
        (
            "SENSIN",
            2,
            ObjAccess.WO,
            T(
                "External sensor value received over CANopen",
                "Sensorwert über CANopen",
                "Vstup signálu snímače",
            ),
        ),
        (
            "SENSAFTINV",
            3,
            RO,
            T("Sensor after inversion", "Sensor nach Invertierung", "Snímač po inverzi"),
        ),
        (
            "SENSAFTOFFS",
            4,
            RO,
            T("Sensor after zero offset", "Sensor nach Nullpunkt", "Snímač po posunutí nuly"),
        ),
        (
            "SENSAFTGAIN",
            5,
            RO,
            T("Sensor after gain", "Sensor nach Verstärkung", "Snímač po zesílení"),
        ),
        (
            "SENSAFTLIN",
            6,
            RO,
            T("Sensor after linearization", "Sensor nach Linearisierung", "Snímač po linearizaci"),
        ),
    )
]

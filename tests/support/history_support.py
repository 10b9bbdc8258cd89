"""Shared pieces of the history tests: a valve identity and filling a database."""

from __future__ import annotations

from dataclasses import dataclass

from prm9tool.catalogue.typekey import TypeKey
from prm9tool.files.prmfile import PrmContents
from prm9tool.history.recorder import make_entry
from prm9tool.history.store import HistoryStore

E04 = "PRM9-06.3Z11/30-24E04S02-CA"


@dataclass
class Valve:
    """What the recorder needs to know about a valve (as a session's DeviceInfo)."""

    serial: int
    type_key: str = E04
    firmware: str = "V0.35.16"
    device_id: str = "usb:/dev/hidraw3"


def factory_values(type_key: str = E04) -> dict[str, int | str]:
    """The factory parameter set of ``type_key``."""
    return PrmContents.factory(TypeKey.parse(type_key)).values


def fill(store: HistoryStore, serial: int, count: int) -> None:
    """Append ``count`` upload records for ``serial`` (LIMTA counts up)."""
    values = factory_values()
    for number in range(count):
        entry = make_entry(Valve(serial), "upload", "ok", values | {"LIMTA": 1000 + number})
        store.append(entry)

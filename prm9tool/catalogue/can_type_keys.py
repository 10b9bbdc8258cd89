"""Type keys the user gave for valves that do not tell their own over CANopen, by serial number.

A real PRM9 has no object holding its type key (0x2041 is this project's decision, see
docs/can-link.md); what the user reads off the valve's label is kept in
``<user data dir>/can-type-keys.json`` (``{"4711": "PRM9-06.3Z11/30-24E04S02-CA"}``), written
atomically, and used whenever that serial number is seen again.
"""

from __future__ import annotations

import json
from pathlib import Path

from prm9tool.atomicfile import atomic_write
from prm9tool.catalogue.typekey import TypeKey

FILE_NAME = "can-type-keys.json"


def _path(data_dir: Path) -> Path:
    return data_dir / FILE_NAME


def _load(data_dir: Path) -> dict[str, object]:
    try:
        keys = json.loads(_path(data_dir).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return {}
    return keys if isinstance(keys, dict) else {}


def remembered(data_dir: Path, serial: int) -> str | None:
    """The type key given for ``serial`` before (None: none, or the file is broken)."""
    value = _load(data_dir).get(str(serial))
    return value if isinstance(value, str) else None


def remember(data_dir: Path, serial: int, type_key: str) -> None:
    """Remember ``type_key`` for ``serial`` (validated first: TypeKeyError if invalid)."""
    keys = _load(data_dir)
    keys[str(serial)] = str(TypeKey.parse(type_key))
    _save(data_dir, keys)


def forget(data_dir: Path, serial: int, type_key: str) -> None:
    """Forget the key remembered for ``serial`` if it is ``type_key`` (the valve contradicted
    it); another key remembered since stays."""
    keys = _load(data_dir)
    if keys.get(str(serial)) == type_key:
        del keys[str(serial)]
        _save(data_dir, keys)


def _save(data_dir: Path, keys: dict[str, object]) -> None:
    path = _path(data_dir)
    path.parent.mkdir(parents=True, exist_ok=True)
    text = json.dumps(keys, indent=1, sort_keys=True) + "\n"
    atomic_write(path, text.encode("utf-8"), backup=False)

"""The type key of a valve over CANopen.

The manual documents no object holding the type key; 0x2041 (PCODE) is this project's decision,
which the emulated valve has and a real valve will not. Without it the object dictionary tells
only part of the key: -CA (by definition: it speaks CANopen) and E02 or E04 (an E04 valve has
the external-sensor objects 0x2005–0x2100, manual table 7-14). The user gives the rest from the
valve's label; prm9tool remembers it per serial number in
``<user data dir>/can-type-keys.json``.
"""

from __future__ import annotations

import json
import logging
from dataclasses import dataclass
from pathlib import Path

from prm9tool.catalogue.typekey import TypeKey
from prm9tool.catalogue.variant import Config
from prm9tool.errors import TypeKeyError

log = logging.getLogger(__name__)
FILE_NAME = "can-type-keys.json"


@dataclass(frozen=True)
class Derived:
    """What the object dictionary tells about the type key."""

    config: Config
    canopen: bool = True

    def describe(self) -> str:
        """E.g. ``E04 -CA``."""
        return f"{self.config.value} -CA"

    def problem(self, key: TypeKey) -> str | None:
        """Why ``key`` cannot be this valve's (None: it fits every part the OD tells)."""
        if not key.canopen:
            return f"{key} has no -CA, but the valve speaks CANopen"
        if key.config is not self.config:
            return (
                f"{key} is an {key.config.value} valve, the valve's objects say {self.config.value}"
            )
        return None


class TypeKeyNeededError(TypeKeyError):
    """The valve does not tell its full type key and none was given or remembered."""

    def __init__(self, serial: int, derived: Derived) -> None:
        self.serial, self.derived = serial, derived
        super().__init__(
            f"the valve (serial {serial}) has no type-key object 0x2041; its objects tell "
            f"{derived.describe()}: give the type key on its label "
            "(command line: the file's key is used; GUI: asked once, then remembered)"
        )


def _path(data_dir: Path) -> Path:
    return data_dir / FILE_NAME


def remembered(data_dir: Path, serial: int) -> str | None:
    """The type key the user gave for ``serial`` before (None: none, or the file is broken)."""
    try:
        keys = json.loads(_path(data_dir).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    value = keys.get(str(serial)) if isinstance(keys, dict) else None
    return value if isinstance(value, str) else None


def remember(data_dir: Path, serial: int, type_key: str) -> None:
    """Remember ``type_key`` for ``serial`` (validated first; TypeKeyError if invalid)."""
    key = str(TypeKey.parse(type_key))
    path = _path(data_dir)
    try:
        keys = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        keys = {}
    if not isinstance(keys, dict):
        keys = {}
    keys[str(serial)] = key
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_suffix(".tmp")
    tmp.write_text(json.dumps(keys, indent=1, sort_keys=True), encoding="utf-8")
    tmp.replace(path)


def resolve(serial: int, derived: Derived, hint: str | None, data_dir: Path) -> str:
    """The type key of a valve without 0x2041: ``hint`` (the batch file's key, the user's
    answer) or the one remembered for ``serial``, checked against what the OD tells."""
    candidate = hint or remembered(data_dir, serial)
    if candidate is None:
        raise TypeKeyNeededError(serial, derived)
    key = TypeKey.parse(candidate)
    problem = derived.problem(key)
    if problem:
        raise TypeKeyError(f"valve serial {serial}: {problem}")
    return str(key)

"""The type key of a valve over CANopen.

The manual documents no object holding the type key; 0x2041 (PCODE) is this project's decision,
which the emulated valve has and a real valve will not. Without it the object dictionary tells
only part of the key: -CA (by definition: it speaks CANopen) and, only where it really tells,
E04: the control mode 0x6043 reads 4 (process control), which exists on E04 valves only (table
7-16 and this project's catalogue). The external-sensor objects 0x2005–0x2100 tell nothing:
table 7-14 lists them among the objects of all valves. A valve in control mode 2 leaves E02/E04
open. The user gives the rest from the valve's label; prm9tool remembers it per serial number
in ``<user data dir>/can-type-keys.json``.
"""

from __future__ import annotations

import logging
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path

from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.can_type_keys import forget, remember, remembered
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.catalogue.variant import Config
from prm9tool.errors import TypeKeyError

__all__ = [
    "Derived",
    "TypeKeyNeededError",
    "forget",
    "lacking_objects",
    "remember",
    "remembered",
    "resolve",
]

log = logging.getLogger(__name__)


@dataclass(frozen=True)
class Derived:
    """What the object dictionary tells about the type key."""

    config: Config | None  # None: the objects do not tell E02 from E04
    canopen: bool = True

    def describe(self) -> str:
        """E.g. ``E04 -CA``, or ``-CA (E02 or E04: its objects do not tell)``."""
        if self.config is None:
            return "-CA (E02 or E04: its objects do not tell)"
        return f"{self.config.value} -CA"

    def problem(self, key: TypeKey) -> str | None:
        """Why ``key`` cannot be this valve's (None: it fits every part the OD tells)."""
        if not key.canopen:
            return f"{key} has no -CA, but the valve speaks CANopen"
        if self.config is not None and key.config is not self.config:
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
            "(command line: --type-key KEY, or a batch file's key; GUI: asked once; "
            "then remembered)"
        )


def resolve(
    serial: int,
    derived: Derived,
    hint: str | None,
    data_dir: Path,
    label: str | None = None,
) -> str:
    """The type key of a valve without 0x2041, checked against what the OD tells.

    The user's word goes first: ``label`` (the key read off the valve's label now,
    ``--type-key``, the GUI's question), then the key remembered for ``serial`` (the label's,
    given before), and only then ``hint`` (a batch file's key: what the file was made for, not
    what the valve is; a file of another parameter set is then refused by the type check)."""
    remembered_key = remembered(data_dir, serial)
    candidate = label or remembered_key or hint
    if candidate is None:
        raise TypeKeyNeededError(serial, derived)
    key = TypeKey.parse(candidate)
    problem = derived.problem(key)
    if problem:
        raise TypeKeyError(f"valve serial {serial}: {problem}")
    if derived.config is None:
        source = "its label" if label or remembered_key else "the file"
        log.warning(
            "valve serial %s: %s taken from %s; its objects cannot confirm %s",
            serial,
            key,
            source,
            key.config.value,
        )
    return str(key)


def lacking_objects(serial: int, key: TypeKey, values: Mapping[str, object]) -> TypeKeyError | None:
    """The refusal when a valve read under ``key`` lacks objects the manual lists for it
    (``values``: what it gave; an object only this project has may be missing on any valve)."""
    lacking = [
        p.mnemonic
        for p in CATALOGUE.file_parameters(key.variant)
        if p.address_from_manual and p.mnemonic not in values
    ]
    if not lacking:
        return None
    names = ", ".join(lacking[:4]) + (f" and {len(lacking) - 4} more" if len(lacking) > 4 else "")
    return TypeKeyError(
        f"valve serial {serial} has no object for {names}, which every {key} has "
        f"(manual chapter 7): {key} is not its type key; give the one on its label "
        "(--type-key KEY)"
    )


class GivenKey:
    """The type key of one session's valve where the valve does not tell it (no 0x2041): the
    key given with the session (a file's, ``hint``) or read off the valve's label (``label``,
    which goes first and is remembered for its serial at once), resolved against what the
    objects tell; remembered once a set was stored under it, forgotten when the valve turns
    out to lack objects the key needs. A part of the CANopen session."""

    def __init__(self, hint: str | None, label: str | None) -> None:
        self._hint, self._label = hint, label
        self.given = False  # True: the valve has no 0x2041, the key was given

    def key_of(self, serial: int, told: str | None, derived: Derived | None) -> str:
        """The valve's key: the one it ``told`` (0x2041), else the given one (TypeKeyError
        when none fits what its objects tell, ``derived``)."""
        self.given = told is None
        if told is not None:
            return told
        assert derived is not None
        key = resolve(serial, derived, self._hint, _folder(), label=self._label)
        if self._label:
            remember(_folder(), serial, key)
        return key

    def stored(self, serial: int, key: str) -> None:
        """A set was stored under the given key: it stays remembered for ``serial``."""
        if self.given:
            remember(_folder(), serial, key)

    def check_download(self, serial: int, key: str, values: Mapping[str, object]) -> None:
        """A given key whose objects the download found missing is refused (TypeKeyError)
        and no longer remembered for ``serial``."""
        refusal = self.refusal(serial, key, values)
        if refusal is not None:
            forget(_folder(), serial, key)
            raise refusal

    def refusal(self, serial: int, key: str, values: Mapping[str, object]) -> TypeKeyError | None:
        """:func:`lacking_objects` for a given key (None for a key the valve told)."""
        return lacking_objects(serial, TypeKey.parse(key), values) if self.given else None


def _folder() -> Path:
    from prm9tool.paths import user_data_dir

    return user_data_dir()

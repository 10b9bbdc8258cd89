"""The twin file: a valve's fitted plant constants as versioned TOML (issue 31 items 2–3), and
the emulated valve of a twin file.

It lives with the emulator, below the device factory, so that ``emulator:twin:FILE``,
``--emulator twin:FILE`` and ``--serve-emulator twin:FILE`` open a twin without the factory
importing the identification above it (``prm9tool.twin``, which fits what is written here;
:mod:`prm9tool.twin.twinfile` keeps the old import path).

::

    format = "prm9tool twin"
    version = 1
    serial = 4101
    type_key = "PRM9-06.3Z11/30-24E02S02"
    firmware = "1.0.0"
    date = "2026-12-02T01:00:00+00:00"
    source = "position-loop steps 0 → ±5/25/90 %, 5000 Hz"

    [plant]              # every constant of the emulator's plant (fitted or kept)
    spool_mass_kg = 0.086
    ...

    [parameters]         # the valve's parameter set (raw values) the steps ran with
    POSKP = 40
    ...

    [fit]
    rms_pct = 0.18
    max_pct = 0.67
    start_rms_pct = 1.42
    evaluations = 26

    [fit.constants.spool_mass_kg]
    start = 0.06
    value = 0.086
    relative_se = 0.003
    determined = true

    [fit.constants.actuator_full_speed_s]   # an E04 characterized on its position loop
    start = 0.5
    value = 0.5
    relative_se = inf
    determined = false
    reason = "a position-loop run does not record the process value: …"

A file that cannot be used raises :class:`TwinFileError` naming the file and the key.
"""

from __future__ import annotations

import json
import math
import os
import tomllib
from collections.abc import Sequence
from dataclasses import dataclass, fields
from datetime import UTC, datetime
from pathlib import Path
from typing import TYPE_CHECKING, Any, Protocol

from prm9tool.atomicfile import atomic_write
from prm9tool.catalogue import CATALOGUE
from prm9tool.errors import Prm9Error

if TYPE_CHECKING:
    from prm9tool.device.emulator import EmulatedValve
    from prm9tool.device.emulator.constants import PlantConstants

FORMAT = "prm9tool twin"
VERSION = 1


class TwinFileError(Prm9Error):
    """A twin file cannot be read or used; the message names the file and the key."""


class FittedConstant(Protocol):
    """One fitted constant, as :class:`prm9tool.twin.identify.FittedConstant` has it."""

    @property
    def name(self) -> str: ...
    @property
    def start(self) -> float: ...
    @property
    def value(self) -> float: ...
    @property
    def relative_se(self) -> float: ...
    @property
    def determined(self) -> bool: ...
    @property
    def correlated_with(self) -> str | None: ...


class Fit(Protocol):
    """What the twin file keeps of a fit (:class:`prm9tool.twin.identify.Fit`)."""

    @property
    def plant(self) -> PlantConstants: ...
    @property
    def rms_pct(self) -> float: ...
    @property
    def max_pct(self) -> float: ...
    @property
    def start_rms_pct(self) -> float: ...
    @property
    def evaluations(self) -> int: ...
    @property
    def constants(self) -> Sequence[FittedConstant]: ...


@dataclass(frozen=True)
class Twin:
    """A twin file's content."""

    serial: int
    type_key: str
    firmware: str
    date: str
    source: str
    plant: PlantConstants
    fit: dict[str, Any]
    parameters: dict[str, int]


def write_twin(
    path: str | os.PathLike[str],
    fit: Fit,
    serial: int,
    type_key: str,
    firmware: str,
    source: str,
    parameters: dict[str, int] | None = None,
    date: datetime | None = None,
) -> None:
    """Write the twin of ``fit`` and the valve's ``parameters`` to ``path`` (atomically)."""
    when = (date or datetime.now(UTC)).isoformat(timespec="seconds")
    lines = [
        f"format = {_text(FORMAT)}",
        f"version = {VERSION}",
        f"serial = {int(serial)}",
        f"type_key = {_text(type_key)}",
        f"firmware = {_text(firmware)}",
        f"date = {_text(when)}",
        f"source = {_text(source)}",
        "",
        "[plant]",
    ]
    lines += [f"{f.name} = {_value(getattr(fit.plant, f.name))}" for f in fields(fit.plant)]
    lines += ["", "[parameters]"]
    lines += [f"{name} = {int(raw)}" for name, raw in (parameters or {}).items()]
    lines += [
        "",
        "[fit]",
        f"rms_pct = {_value(fit.rms_pct)}",
        f"max_pct = {_value(fit.max_pct)}",
        f"start_rms_pct = {_value(fit.start_rms_pct)}",
        f"evaluations = {fit.evaluations}",
    ]
    for c in fit.constants:
        lines += [
            "",
            f"[fit.constants.{c.name}]",
            f"start = {_value(c.start)}",
            f"value = {_value(c.value)}",
            f"relative_se = {_value(c.relative_se)}",
            f"determined = {_value(c.determined)}",
        ]
        if c.correlated_with is not None:
            lines.append(f"correlated_with = {_text(c.correlated_with)}")
        reason = getattr(c, "reason", None)  # why it is not determined (kept), where said
        if reason:
            lines.append(f"reason = {_text(reason)}")
    atomic_write(Path(path), ("\n".join(lines) + "\n").encode("utf-8"), backup=False)


def read_twin(path: str | Path) -> Twin:
    """Read a twin file; :class:`TwinFileError` says what is wrong with it."""
    from prm9tool.device.emulator.constants import PLANT, PlantConstants

    where = str(path)
    try:
        data = tomllib.loads(Path(path).read_text(encoding="utf-8"))
    except OSError as exc:
        raise TwinFileError(f"cannot read the twin file {where}: {exc.strerror or exc}") from None
    except tomllib.TOMLDecodeError as exc:
        raise TwinFileError(f"{where}: not valid TOML: {exc}") from None
    if data.get("format") != FORMAT:
        raise TwinFileError(f"{where}: not a twin file (format = {FORMAT!r} is missing)")
    version = data.get("version")
    if not isinstance(version, int) or version > VERSION or version < 1:
        raise TwinFileError(
            f"{where}: twin file version {version!r}; this prm9tool reads version {VERSION}"
        )
    head: dict[str, Any] = {}
    for key, kind in (
        ("serial", int),
        ("type_key", str),
        ("firmware", str),
        ("date", str),
        ("source", str),
    ):
        if not isinstance(data.get(key), kind):
            raise TwinFileError(f"{where}: {key} is missing or not a {kind.__name__}")
        head[key] = data[key]
    table = data.get("plant")
    if not isinstance(table, dict):
        raise TwinFileError(f"{where}: the [plant] table is missing")
    known = {f.name: f for f in fields(PlantConstants)}
    unknown = sorted(set(table) - set(known))
    if unknown:
        raise TwinFileError(f"{where}: [plant] has no constant {unknown[0]!r}")
    values: dict[str, Any] = {}
    for name, value in table.items():
        default = getattr(PLANT, name)
        if isinstance(value, bool) or not isinstance(value, int | float):
            raise TwinFileError(f"{where}: [plant] {name} must be a number")
        if isinstance(default, int):
            if value != int(value):
                raise TwinFileError(f"{where}: [plant] {name} must be a whole number")
            values[name] = int(value)
        else:
            if not math.isfinite(value) or value < 0:
                raise TwinFileError(f"{where}: [plant] {name} must be a number ≥ 0")
            values[name] = float(value)
    fit = data.get("fit", {})
    if not isinstance(fit, dict):
        raise TwinFileError(f"{where}: [fit] must be a table")
    parameters = data.get("parameters", {})
    if not isinstance(parameters, dict):
        raise TwinFileError(f"{where}: [parameters] must be a table")
    for name, raw in parameters.items():
        if name not in CATALOGUE:
            raise TwinFileError(f"{where}: [parameters] has no parameter {name!r}")
        if isinstance(raw, bool) or not isinstance(raw, int):
            raise TwinFileError(f"{where}: [parameters] {name} must be a whole number (raw)")
    return Twin(
        plant=PlantConstants(**{**_defaults(), **values}),
        fit=fit,
        parameters=dict(parameters),
        **head,
    )


def _defaults() -> dict[str, Any]:
    from prm9tool.device.emulator.constants import PLANT

    return {f.name: getattr(PLANT, f.name) for f in fields(PLANT)}


def _text(value: str) -> str:
    return json.dumps(value, ensure_ascii=False)  # a TOML basic string


def _value(value: float | int | bool) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if math.isinf(value):
        return "inf" if value > 0 else "-inf"
    if math.isnan(value):
        return "nan"
    return repr(float(value))


def emulated_twin(
    twin: Twin | str | Path,
    serial: int | None = None,
    nv_path: str | Path | None = None,
    od: str = "full",
) -> EmulatedValve:
    """An emulated valve built from ``twin`` (a :class:`Twin` or a twin file's path); its
    parameter set is written into the working memory as the valve had it when measured.
    ``serial`` overrides the file's (two emulated twins of one valve on one bus); ``nv_path``
    and ``od`` as :class:`~prm9tool.device.emulator.EmulatedValve` takes them."""
    from prm9tool.device.emulator import EmulatedValve

    data = twin if isinstance(twin, Twin) else read_twin(twin)
    try:
        valve = EmulatedValve(
            data.type_key,
            serial=data.serial if serial is None else serial,
            firmware_version=data.firmware,
            plant=data.plant,
            nv_path=nv_path,
            od=od,
        )
    except (Prm9Error, ValueError) as exc:
        raise TwinFileError(f"the twin of serial {data.serial} cannot be emulated: {exc}") from None
    for mnemonic, raw in data.parameters.items():
        param = CATALOGUE[mnemonic]
        try:
            valve.write(param.index, param.subindex, raw)
        except Prm9Error:  # not on this variant's dictionary, or refused: the default stays
            continue
    return valve

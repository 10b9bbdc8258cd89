"""Emulate a twin (issue 31 item 3, start): the emulated valve of a twin file, with its plant
constants, serial, type key, firmware version and parameter set."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from prm9tool.errors import Prm9Error
from prm9tool.twin.twinfile import Twin, TwinFileError, read_twin

if TYPE_CHECKING:
    from prm9tool.device.emulator import EmulatedValve


def emulated_twin(twin: Twin | str | Path, serial: int | None = None) -> EmulatedValve:
    """An emulated valve built from ``twin`` (a :class:`Twin` or a twin file's path); its
    parameter set is written into the working memory as the valve had it when measured.
    ``serial`` overrides the file's (two emulated twins of one valve on one bus)."""
    from prm9tool.catalogue import CATALOGUE
    from prm9tool.device.emulator import EmulatedValve

    data = twin if isinstance(twin, Twin) else read_twin(twin)
    try:
        valve = EmulatedValve(
            data.type_key,
            serial=data.serial if serial is None else serial,
            firmware_version=data.firmware,
            plant=data.plant,
        )
    except Prm9Error as exc:
        raise TwinFileError(f"the twin of serial {data.serial} cannot be emulated: {exc}") from None
    for mnemonic, raw in data.parameters.items():
        param = CATALOGUE[mnemonic]
        try:
            valve.write(param.index, param.subindex, raw)
        except Prm9Error:  # not on this variant's dictionary, or refused: the default stays
            continue
    return valve

"""EDS and DCF export of a valve or a parameter set, once for every door.

The window's File → Export DCF (``views/files/dcf_export.py``), ``--export-dcf`` on the command line
and :meth:`Valve.export_dcf <prm9tool.api.valve.Valve.export_dcf>` write the same file: the
CiA 306 DCF of :mod:`prm9tool.files.dcf` with the node ID and bit rate the valve runs with
after power-up (its rotary switches and NODEID/BITRATE, manual table 7-17). ``--export-eds
TYPEKEY -o FILE.eds`` and :meth:`Valve.export_eds <prm9tool.api.valve.Valve.export_eds>` write
the same EDS (:func:`write_eds`). No Qt.
"""

from __future__ import annotations

import os
from collections.abc import Mapping
from pathlib import Path

from prm9tool.catalogue.canopen_switches import effective
from prm9tool.catalogue.typekey import TypeKey

__all__ = ["SETTINGS", "dcf_text", "eds_text", "node_and_rate", "write_dcf", "write_eds"]

# the objects that decide node ID and bit rate after power-up (manual table 7-17)
SETTINGS = ("SWBAUD", "SWNODE", "NODEID", "BITRATE", "CANTERM")


def node_and_rate(values: Mapping[str, int | str]) -> tuple[int, int]:
    """Node ID and bit rate (kbit/s) a valve with these raw values runs with after power-up
    (a value it lacks counts as the factory setting: switches at 0, NODEID, 500 kbit/s)."""
    raw = {m: int(values.get(m, 0) or 0) for m in SETTINGS}
    settings = effective(*(raw[m] for m in SETTINGS))
    return settings.node_id or raw["NODEID"], settings.bitrate_kbit or 500


def dcf_text(
    type_key: str | TypeKey,
    values: Mapping[str, int | str],
    settings: Mapping[str, int | str] | None = None,
) -> tuple[str, int]:
    """The DCF of a ``type_key`` valve configured with the raw ``values``, and its node ID;
    ``settings``: the raw :data:`SETTINGS` (default: from ``values``). TypeKeyError for a key
    without -CA."""
    from prm9tool.files.dcf import export_dcf

    node, rate = node_and_rate(values if settings is None else settings)
    return export_dcf(type_key, values, node, rate), node


def write_dcf(
    path: str | os.PathLike[str],
    type_key: str | TypeKey,
    values: Mapping[str, int | str],
    settings: Mapping[str, int | str] | None = None,
) -> int:
    """Write the DCF (atomically, ASCII); returns the node ID it names. OSError: not written."""
    from prm9tool.files.atomicfile import atomic_write

    text, node = dcf_text(type_key, values, settings)
    atomic_write(Path(path), text.encode("ascii", errors="replace"), backup=False)
    return node


def eds_text(type_key: str | TypeKey) -> str:
    """The CiA 306 EDS of a ``type_key`` valve, lines ending in CR LF as CiA 306 files do;
    TypeKeyError for a key without -CA."""
    from prm9tool.files.eds import export_eds

    return export_eds(type_key).replace("\n", "\r\n")


def write_eds(path: str | os.PathLike[str], type_key: str | TypeKey) -> None:
    """Write the EDS (atomically, ASCII). OSError: not written; TypeKeyError: no -CA."""
    from prm9tool.files.atomicfile import atomic_write

    atomic_write(Path(path), eds_text(type_key).encode("ascii"), backup=False)

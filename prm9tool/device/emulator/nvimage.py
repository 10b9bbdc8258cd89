"""The emulated valve's non-volatile memory (EEPROM image), optionally kept in a file.

The image holds every catalogue parameter with object access RW that belongs to the *.prm
parameter set, plus the CANopen communication objects the master configures (0x1005, 0x1006,
0x1014, 0x1017, the PDO communication parameters 0x1400-0x1801, 0x1F80). A node-relative
COB-ID that still has its default is not stored, so it follows the node ID at power-up as on a
real CANopen device. The file is JSON, written atomically (temporary file + rename).

Beside the parameters the image keeps the LSS configuration (CiA 305 "store configuration":
node ID and bit-rate code, ``lss``), which a valve at node-ID switch 1 uses at power-up
(manual table 7-17). It is the LSS slave's own record: storing or restoring the parameter set
(0x1010/0x1011) leaves it alone, as on a CiA 305 device.
"""

from __future__ import annotations

import json
import os
import tempfile
from pathlib import Path

from prm9tool.catalogue import ObjAccess, Parameter
from prm9tool.errors import FileFormatError, FileProblem
from prm9tool.messages import QT_TRANSLATE_NOOP

_UNREADABLE = QT_TRANSLATE_NOOP("Problems", "unreadable EEPROM image of an emulated valve: {0}")
_NOT_AN_IMAGE = QT_TRANSLATE_NOOP("Problems", "not an emulator EEPROM image (format {0})")
_VERSION = QT_TRANSLATE_NOOP("Problems", "unsupported EEPROM image version {0}")
_OTHER_TYPE = QT_TRANSLATE_NOOP(
    "Problems",
    "the image belongs to a {0} valve, not to {1}: give the emulated valve another serial "
    "(TYPEKEY:SERIAL) or delete the file",
)
_NO_VALUES = QT_TRANSLATE_NOOP("Problems", "the EEPROM image has no 'values' table")

FORMAT = "prm9tool-emulator-eeprom"
VERSION = 1
_COMM_INDICES = (0x1005, 0x1006, 0x1014, 0x1017, 0x1F80)
NEVER_STORED = frozenset({0x2050})  # setpoint override (service objects)


def is_nonvolatile(param: Parameter) -> bool:
    """True if ``param`` lives in the EEPROM image."""
    if param.obj_access is not ObjAccess.RW or param.index in NEVER_STORED:
        return False
    if param.in_file:
        return True
    return param.index in _COMM_INDICES or 0x1400 <= param.index <= 0x1801


def stored_type_key(path: str | os.PathLike[str]) -> str | None:
    """The type key an image file at ``path`` belongs to; None when there is no readable one."""
    try:
        data = json.loads(Path(path).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    key = data.get("type_key") if isinstance(data, dict) else None
    return key if isinstance(key, str) else None


class NvImage:
    """The stored values by mnemonic; missing entries mean the factory default."""

    def __init__(self, type_key: str, serial: int, path: str | os.PathLike[str] | None) -> None:
        self.type_key = type_key
        self.serial = serial
        self.path = Path(path) if path is not None else None
        self.values: dict[str, int | str] = {}
        self.lss: dict[str, int] = {}  # "node_id", "bit_timing" (CiA 305 table 0) once stored
        if self.path is not None and self.path.exists():
            self.values = self._load(self.path)

    def replace_lss(self, lss: dict[str, int]) -> None:
        """Store the LSS configuration (file first, then memory; a failed write raises)."""
        new = dict(lss)
        if self.path is not None:
            self._save(self.path, self.values, new)
        self.lss = new

    def replace(self, values: dict[str, int | str]) -> None:
        """Write ``values`` to the file (if any), then make them the image in memory.

        A failed write raises and leaves memory and file on the old image, so a restart in the
        process and a restart of the process find the same stored set.
        """
        new = dict(values)
        if self.path is not None:
            self._save(self.path, new, self.lss)
        self.values = new

    def _load(self, path: Path) -> dict[str, int | str]:
        try:
            data = json.loads(path.read_text(encoding="utf-8"))
        except (OSError, ValueError) as exc:
            problem = FileProblem(0, _UNREADABLE(str(exc)))
            raise FileFormatError(str(path), [problem]) from exc
        problems = []
        if not isinstance(data, dict) or data.get("format") != FORMAT:
            problems.append(FileProblem(0, _NOT_AN_IMAGE(repr(FORMAT))))
        elif data.get("version") != VERSION:
            problems.append(FileProblem(0, _VERSION(repr(data.get("version")))))
        elif data.get("type_key") != self.type_key:
            problems.append(
                FileProblem(0, _OTHER_TYPE(str(data.get("type_key")), str(self.type_key)))
            )
        elif not isinstance(data.get("values"), dict):
            problems.append(FileProblem(0, _NO_VALUES()))
        if problems:
            raise FileFormatError(str(path), problems)
        lss = data.get("lss")
        if isinstance(lss, dict):
            self.lss = {str(k): v for k, v in lss.items() if isinstance(v, int)}
        return {str(k): v for k, v in data["values"].items() if isinstance(v, (int, str))}

    def _save(self, path: Path, values: dict[str, int | str], lss: dict[str, int]) -> None:
        payload: dict[str, object] = {
            "format": FORMAT,
            "version": VERSION,
            "type_key": self.type_key,
            "serial": self.serial,
            "values": dict(sorted(values.items())),
        }
        if lss:
            payload["lss"] = dict(sorted(lss.items()))
        path.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(prefix=path.name, suffix=".tmp", dir=path.parent)
        try:
            with os.fdopen(fd, "w", encoding="utf-8") as handle:
                json.dump(payload, handle, indent=1)
                handle.write("\n")
                handle.flush()
                os.fsync(handle.fileno())
            os.replace(tmp, path)
        except BaseException:
            Path(tmp).unlink(missing_ok=True)
            raise

"""The one exception tree of prm9tool, and the CiA 301 SDO abort codes.

Every error a user can meet derives from :class:`Prm9Error`, so a caller (the GUI, the
batch mode) can catch one type and show ``str(error)``, which is always a complete sentence.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import IntEnum
from typing import ClassVar

from prm9tool.messages import QT_TRANSLATE_NOOP, Message, Template


class AbortCode(IntEnum):
    """CiA 301 SDO abort codes (the subset a PRM9 answers with)."""

    TOGGLE_BIT = 0x05030000
    SDO_TIMEOUT = 0x05040000
    INVALID_COMMAND = 0x05040001
    OUT_OF_MEMORY = 0x05040005
    UNSUPPORTED_ACCESS = 0x06010000
    WRITE_ONLY = 0x06010001
    READ_ONLY = 0x06010002
    NO_SUCH_OBJECT = 0x06020000
    NOT_MAPPABLE = 0x06040041
    PDO_TOO_LONG = 0x06040042
    PARAMETER_INCOMPATIBLE = 0x06040043
    HARDWARE_ERROR = 0x06060000
    WRONG_LENGTH = 0x06070010
    LENGTH_TOO_HIGH = 0x06070012
    LENGTH_TOO_LOW = 0x06070013
    NO_SUCH_SUBINDEX = 0x06090011
    INVALID_VALUE = 0x06090030
    VALUE_TOO_HIGH = 0x06090031
    VALUE_TOO_LOW = 0x06090032
    MAX_BELOW_MIN = 0x06090036
    GENERAL_ERROR = 0x08000000
    CANNOT_STORE = 0x08000020
    CANNOT_STORE_LOCAL_CONTROL = 0x08000021
    CANNOT_STORE_DEVICE_STATE = 0x08000022
    NO_DATA = 0x08000024

    @property
    def text(self) -> str:
        """A short English explanation of the abort code."""
        return _ABORT_TEXTS.get(self, self.name.replace("_", " ").lower())


_ABORT_TEXTS: dict[AbortCode, str] = {
    AbortCode.TOGGLE_BIT: "toggle bit not alternated",
    AbortCode.SDO_TIMEOUT: "SDO protocol timed out",
    AbortCode.INVALID_COMMAND: "command specifier not valid or unknown",
    AbortCode.UNSUPPORTED_ACCESS: "unsupported access to an object",
    AbortCode.WRITE_ONLY: "attempt to read a write-only object",
    AbortCode.READ_ONLY: "attempt to write a read-only object",
    AbortCode.NO_SUCH_OBJECT: "object does not exist in the object dictionary",
    AbortCode.WRONG_LENGTH: "data type does not match, length of service parameter does not match",
    AbortCode.LENGTH_TOO_HIGH: "data type does not match, length too high",
    AbortCode.LENGTH_TOO_LOW: "data type does not match, length too low",
    AbortCode.NO_SUCH_SUBINDEX: "sub-index does not exist",
    AbortCode.INVALID_VALUE: "invalid value for parameter",
    AbortCode.VALUE_TOO_HIGH: "value of parameter written too high",
    AbortCode.VALUE_TOO_LOW: "value of parameter written too low",
    AbortCode.GENERAL_ERROR: "general error",
    AbortCode.CANNOT_STORE: "data cannot be transferred or stored to the application",
    AbortCode.CANNOT_STORE_DEVICE_STATE: (
        "data cannot be transferred or stored because of the present device state"
    ),
}


class Prm9Error(Exception):
    """Base of every error prm9tool raises on purpose.

    ``summary`` is a translatable lead sentence for errors whose own text is technical English
    (the device layer's); a view shows it in the program language with the text as the detail.
    """

    summary: ClassVar[Template | None] = None


class CommunicationError(Prm9Error):
    """The valve could not be reached, or the link broke."""

    summary = QT_TRANSLATE_NOOP("Errors", "The valve could not be reached.")


class DeviceTimeoutError(CommunicationError):
    """The valve did not answer in time."""

    summary = QT_TRANSLATE_NOOP("Errors", "The valve did not answer in time.")


class ProtocolError(CommunicationError):
    """The valve answered something that is not a valid answer."""

    summary = QT_TRANSLATE_NOOP(
        "Errors", "The valve answered something prm9tool does not understand."
    )


class DeviceDisconnectedError(CommunicationError):
    """The valve (or its USB cable) went away."""

    summary = QT_TRANSLATE_NOOP("Errors", "The connection to the valve is broken.")


class CanBusOffError(DeviceDisconnectedError):
    """The tool's CAN adapter went bus-off: it stopped sending after too many bus errors."""

    summary = QT_TRANSLATE_NOOP(
        "Errors",
        "The CAN adapter went bus-off: check the wiring, termination and bit rate.",
    )


class CanBusError(Prm9Error):
    """An emulated -CA valve could not join its CAN bus (its USB link is not affected)."""

    summary = QT_TRANSLATE_NOOP(
        "Errors", "The emulated valve could not join the CAN bus; it works over USB without CAN."
    )


class CanAdapterError(CommunicationError):
    """The CAN interface (adapter, driver, permission) could not be opened for the tool."""

    summary = QT_TRANSLATE_NOOP("Errors", "The CAN interface could not be opened.")


class AccessDeniedError(Prm9Error):
    """The operation is not allowed at the current access level or device state."""


class ValueRangeError(Prm9Error):
    """A value is outside the limits the catalogue allows."""


class TypeKeyError(Prm9Error):
    """A type key is malformed; the message names the wrong part."""


@dataclass(frozen=True, eq=False)
class FileProblem:
    """One problem found in a *.prm file, with its 1-based line number (0 = whole file).

    ``text`` is translatable (``prm9tool.translate.translated``), ``message`` is English.
    Problems compare by line, English message and severity, so a plain string matches the
    message built from a template.
    """

    line: int
    text: Message | str
    severity: str = "error"  # "error" or "warning"

    @property
    def message(self) -> str:
        """The problem in English (``--check``, logs)."""
        return str(self.text)

    def located(self, path: str) -> Message:
        """The problem as ``FILE:LINE: message``, a warning marked so (translatable)."""
        template = _LOCATED_WARNING if self.severity == "warning" else _LOCATED
        return template(path, self.line, self.text)

    def format(self, path: str) -> str:
        """Return the problem as ``FILE:LINE: message`` (the compiler convention), in English."""
        return str(self.located(path))

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, FileProblem):
            return NotImplemented
        return self._key() == other._key()

    def __hash__(self) -> int:
        return hash(self._key())

    def _key(self) -> tuple[int, str, str]:
        return (self.line, self.message, self.severity)


_LOCATED = Template("Problems", "{0}:{1}: {2}")  # nothing to translate: not marked for lupdate
_LOCATED_WARNING = QT_TRANSLATE_NOOP("Problems", "{0}:{1}: warning: {2}")


class FileFormatError(Prm9Error):
    """A *.prm file cannot be used; ``problems`` lists every problem with its line."""

    def __init__(self, path: str, problems: list[FileProblem]) -> None:
        self.path = path
        self.problems = problems
        lines = [p.format(path) for p in problems]
        super().__init__("\n".join(lines) if lines else f"{path}: invalid file")


class SdoAbortError(Prm9Error):
    """The valve refused an object-dictionary access with a CiA 301 abort code."""

    summary = QT_TRANSLATE_NOOP("Errors", "The valve refused the access.")

    def __init__(self, index: int, subindex: int, code: int) -> None:
        self.index = index
        self.subindex = subindex
        self.code = code
        try:
            text = AbortCode(code).text
        except ValueError:
            text = "unknown abort code"
        super().__init__(f"0x{index:04X}/{subindex}: abort 0x{code:08X} ({text})")


class ExitCode(IntEnum):
    """Documented exit codes (``--help``, README "Headless production mode", docs/batch.md)."""

    OK = 0
    VERIFY_FAILED = 1
    USAGE = 2
    INVALID_FILE = 3
    NO_DEVICE = 4
    TYPE_MISMATCH = 5
    COMMUNICATION = 6
    HISTORY = 7
    OUT_OF_LIMITS = 8  # --characterize: a figure outside the acceptance profile's limits


class HistoryError(Prm9Error):
    """The history database cannot be used (unreachable, damaged, newer, full); ``kind``
    says which: ``unreachable``, ``corrupt``, ``newer``, ``full``."""

    summary = QT_TRANSLATE_NOOP("Errors", "The history database cannot be used.")

    def __init__(self, message: str, kind: str = "unreachable") -> None:
        super().__init__(message)
        self.kind = kind

"""The access level (Basic / Expert) as an observable model shared by every view."""

from __future__ import annotations

from PySide6.QtCore import QObject, Signal

from prm9tool.catalogue import Access, Parameter
from prm9tool.messages import QT_TRANSLATE_NOOP, Message
from prm9tool.translate import translated


class AccessModel(QObject):
    """Current access level; views grey out or hide what the level may not change."""

    level_changed = Signal(object)  # Access

    def __init__(self, level: Access = Access.BASIC, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self._level = level

    @property
    def level(self) -> Access:
        """Access.BASIC or Access.EXPERT."""
        return self._level

    def set_level(self, level: Access) -> None:
        """Change the level (the password check happens before, in the application layer)."""
        if level is Access.READ_ONLY:
            raise ValueError("READ_ONLY is a parameter property, not an access level")
        if level != self._level:
            self._level = level
            self.level_changed.emit(level)

    def may_edit(self, param: Parameter) -> bool:
        """True if a user at the current level may change ``param``."""
        if param.access is Access.READ_ONLY or not param.writable:
            return False
        return param.access is Access.BASIC or self._level is Access.EXPERT

    def lock_reason(self, param: Parameter) -> Message | None:
        """Why ``param`` cannot be changed at the current level (None if it can)."""
        if param.access is Access.READ_ONLY or not param.writable:
            return QT_TRANSLATE_NOOP("Access", "{0} is a read-only value of the valve.")(
                param.mnemonic
            )
        if param.access is Access.EXPERT and self._level is Access.BASIC:
            return QT_TRANSLATE_NOOP("Access", "{0} can only be changed at Expert access level.")(
                param.mnemonic
            )
        return None

    def why_locked(self, param: Parameter) -> str:
        """A tooltip in the program language explaining why ``param`` is locked ('' if not)."""
        reason = self.lock_reason(param)
        return "" if reason is None else translated(reason)

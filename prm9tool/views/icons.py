"""Icons: the desktop theme's icon where there is one, else Qt's standard icon or ours (SVG).

Ours are in resources/icons/, compiled into the Qt resource module ``resources_rc`` (see
resources/README.md) and loaded from ``:/icons/``.
"""

from __future__ import annotations

from functools import cache

from PySide6.QtGui import QIcon
from PySide6.QtWidgets import QApplication, QStyle

from prm9tool.views import resources_rc  # noqa: F401  (registers the :/icons/ resources)

ICON_PREFIX = ":/icons/"

SP = QStyle.StandardPixmap
# name -> (freedesktop theme name, fallback: a standard pixmap or an SVG of ours)
_ICONS: dict[str, tuple[str, SP | str]] = {
    "open": ("document-open", SP.SP_DialogOpenButton),
    "save": ("document-save", SP.SP_DialogSaveButton),
    "save_as": ("document-save-as", SP.SP_DialogSaveButton),
    "print": ("document-print", "print.svg"),
    "pdf": ("application-pdf", "print.svg"),
    "exit": ("application-exit", SP.SP_DialogCloseButton),
    "undo": ("edit-undo", SP.SP_ArrowBack),
    "redo": ("edit-redo", SP.SP_ArrowForward),
    "online": ("network-connect", "online.svg"),
    "offline": ("network-disconnect", "offline.svg"),
    "download": ("", "download.svg"),
    "upload": ("", "upload.svg"),
    "restart": ("", "restart.svg"),
    "valve": ("", "valve.svg"),
    "status": ("", "status.svg"),
    "diagram": ("", "diagram.svg"),
    "parameters": ("", "parameters.svg"),
    "scope": ("", "scope.svg"),
    "canopen": ("", "canopen.svg"),
    "factory": ("", SP.SP_DialogResetButton),
    "hid": ("", SP.SP_DriveNetIcon),
    "help": ("help-contents", SP.SP_DialogHelpButton),
    "homepage": ("go-home", SP.SP_DirHomeIcon),
    "about": ("help-about", SP.SP_MessageBoxInformation),
    "app": ("", "app.svg"),
}


@cache
def icon(name: str) -> QIcon:
    """The icon called ``name`` (see ``_ICONS``); an empty icon for unknown names."""
    theme, fallback = _ICONS.get(name, ("", ""))
    if isinstance(fallback, str):
        backup = QIcon(ICON_PREFIX + fallback) if fallback else QIcon()
    else:
        backup = QApplication.style().standardIcon(fallback)
    if theme and QIcon.hasThemeIcon(theme):
        return QIcon.fromTheme(theme)
    return backup

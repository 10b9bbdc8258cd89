"""Can Qt open windows on this X11 desktop? Checked before Qt starts, without Qt.

Qt's xcb platform plugin needs X11 libraries that a fresh Debian or Ubuntu desktop may lack;
Qt then aborts with "could not load the Qt platform plugin xcb" and names a library that is
not the missing one. ``missing_x11_packages`` names the Debian/Ubuntu packages to install.
"""

from __future__ import annotations

import ctypes
import os
import sys
from collections.abc import Callable, Mapping

# Libraries Qt 6's xcb plugin loads (Qt's "Qt for X11 Requirements"), with their package.
X11_LIBRARIES: dict[str, str] = {
    "libxcb-cursor.so.0": "libxcb-cursor0",
    "libxcb-icccm.so.4": "libxcb-icccm4",
    "libxcb-keysyms.so.1": "libxcb-keysyms1",
    "libxcb-image.so.0": "libxcb-image0",
    "libxcb-render-util.so.0": "libxcb-render-util0",
    "libxcb-shape.so.0": "libxcb-shape0",
    "libxcb-randr.so.0": "libxcb-randr0",
    "libxcb-xkb.so.1": "libxcb-xkb1",
    "libxkbcommon-x11.so.0": "libxkbcommon-x11-0",
    "libEGL.so.1": "libegl1",
}


def _loadable(name: str) -> bool:
    try:
        ctypes.CDLL(name)
    except OSError:
        return False
    return True


def uses_xcb(environ: Mapping[str, str], platform: str = sys.platform) -> bool:
    """True when Qt would show its windows through X11 (xcb) here."""
    if not platform.startswith("linux"):
        return False
    chosen = environ.get("QT_QPA_PLATFORM", "")
    if chosen:
        return chosen.split(":")[0].split(";")[0] == "xcb"
    wayland = environ.get("WAYLAND_DISPLAY") and environ.get("XDG_SESSION_TYPE") == "wayland"
    return bool(environ.get("DISPLAY")) and not wayland


def missing_x11_packages(
    environ: Mapping[str, str] | None = None,
    loadable: Callable[[str], bool] = _loadable,
    platform: str = sys.platform,
) -> list[str]:
    """The packages of the X11 libraries Qt needs here and cannot load ([] if none or no X11)."""
    if not uses_xcb(os.environ if environ is None else environ, platform):
        return []
    return [package for library, package in X11_LIBRARIES.items() if not loadable(library)]


def missing_x11_message(packages: list[str]) -> str:
    """What to tell the user (on standard error: there is no window yet)."""
    return (
        "prm9tool: Qt cannot open windows on this X11 desktop: the libraries of "
        f"{', '.join(packages)} are missing.\n"
        "On Debian or Ubuntu install them once with:\n"
        f"    sudo apt-get install {' '.join(packages)}\n"
        "(without a screen, QT_QPA_PLATFORM=offscreen runs the program without windows)\n"
    )

"""The X11 check before Qt starts: the packages a fresh desktop lacks are named (issue 14, 13)."""

from __future__ import annotations

import argparse

import pytest

from prm9tool import app, display
from prm9tool.errors import ExitCode

X11 = {"DISPLAY": ":0"}


def test_the_missing_libraries_are_named_by_their_package():
    present = {"libxcb-cursor.so.0", "libxcb-image.so.0", "libEGL.so.1"}
    missing = display.missing_x11_packages(
        X11,
        lambda name: name in present or ("icccm" not in name and "keysyms" not in name),
        "linux",
    )
    assert missing == ["libxcb-icccm4", "libxcb-keysyms1"]
    message = display.missing_x11_message(missing)
    assert "sudo apt-get install libxcb-icccm4 libxcb-keysyms1" in message


@pytest.mark.parametrize(
    ("environ", "platform", "xcb"),
    [
        ({"DISPLAY": ":0"}, "linux", True),
        ({"DISPLAY": ":0", "QT_QPA_PLATFORM": "offscreen"}, "linux", False),
        ({"QT_QPA_PLATFORM": "xcb"}, "linux", True),
        (
            {"DISPLAY": ":0", "WAYLAND_DISPLAY": "wayland-0", "XDG_SESSION_TYPE": "wayland"},
            "linux",
            False,
        ),
        ({}, "linux", False),  # no screen at all: Qt says so itself
        ({"DISPLAY": ":0"}, "win32", False),
    ],
)
def test_only_an_x11_session_is_checked(environ, platform, xcb):
    assert display.uses_xcb(environ, platform) is xcb
    assert display.missing_x11_packages(environ, lambda _name: False, platform) == (
        list(display.X11_LIBRARIES.values()) if xcb else []
    )


def test_the_gui_does_not_start_qt_without_them(monkeypatch, capsys):
    monkeypatch.setattr(display, "missing_x11_packages", lambda: ["libxcb-icccm4"])
    monkeypatch.setattr(app, "create_application", lambda: pytest.fail("Qt started"))
    assert app.run(argparse.Namespace()) == ExitCode.USAGE
    assert "sudo apt-get install libxcb-icccm4" in capsys.readouterr().err

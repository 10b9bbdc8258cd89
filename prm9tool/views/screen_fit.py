"""A window's first size, never larger than the screen it opens on."""

from __future__ import annotations

from PySide6.QtWidgets import QWidget

FRAME_WIDTH = 16  # the window manager's border, left and right
FRAME_HEIGHT = 48  # its title bar and border (the screen's panel is outside availableGeometry)


def fit_to_screen(window: QWidget, width: int, height: int) -> None:
    """Resize *window* to width × height, smaller where the screen's free area is smaller.

    A 1366 × 768 laptop otherwise shows a 1200 × 800 window with its status bar below the
    screen's edge.
    """
    free = window.screen().availableGeometry()
    window.resize(
        max(1, min(width, free.width() - FRAME_WIDTH)),
        max(1, min(height, free.height() - FRAME_HEIGHT)),
    )

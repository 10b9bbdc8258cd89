"""The signal-flow diagram view, its block dialogs and its graphics items."""

from prm9tool.views.diagram.view import DiagramView, format_signal

__all__ = ["DiagramView", "format_signal"]

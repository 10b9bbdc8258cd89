"""Layering rules that import-linter cannot express: model modules use QtCore only."""

from __future__ import annotations

import ast
from pathlib import Path

import prm9tool

PACKAGE = Path(prm9tool.__file__).parent
GUI_MODULES = ("PySide6.QtWidgets", "PySide6.QtGui", "PySide6.QtPrintSupport", "pyqtgraph")
# Modules allowed to use Qt GUI classes: the views and the application shell.
GUI_ALLOWED = ("views", "app.py", "model/undo.py")


def _imports(path: Path) -> set[str]:
    tree = ast.parse(path.read_text(encoding="utf-8"))
    names: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom) and node.module:
            names.add(node.module)
    return names


def test_model_and_device_modules_import_no_gui_toolkit():
    offenders = []
    for path in PACKAGE.rglob("*.py"):
        relative = path.relative_to(PACKAGE).as_posix()
        if relative.startswith(GUI_ALLOWED):
            continue
        for name in _imports(path):
            if name.startswith(GUI_MODULES):
                offenders.append(f"{relative}: {name}")
    assert offenders == []


def test_views_do_not_import_the_device_layer():
    offenders = [
        f"{path.name}: {name}"
        for path in (PACKAGE / "views").rglob("*.py")
        for name in _imports(path)
        if name.startswith("prm9tool.device")
    ]
    assert offenders == []

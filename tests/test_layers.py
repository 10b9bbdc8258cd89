"""Layering rules that import-linter cannot express: model modules use QtCore only."""

from __future__ import annotations

import ast
from pathlib import Path

import prm9tool

PACKAGE = Path(prm9tool.__file__).parent
GUI_MODULES = ("PySide6.QtWidgets", "PySide6.QtGui", "PySide6.QtPrintSupport", "pyqtgraph")
# Modules allowed to use Qt GUI classes: the views and the application shell.
GUI_ALLOWED = ("views", "app/", "model/undo.py")


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


def test_no_layer_imports_the_package_root():
    # issue 28: prm9tool/__init__ is the Python API's door (it reaches the device layer); the
    # views reached the device through it (help_dialog -> prm9tool -> api -> device.records),
    # which import-linter does not see behind the lazy __getattr__. __version__ comes from the
    # leaf module prm9tool._version.
    offenders = [
        f"{path.relative_to(PACKAGE).as_posix()}: {name}"
        for path in PACKAGE.rglob("*.py")
        for name in _names_from_the_root(path)
    ]
    assert offenders == []


def _names_from_the_root(path: Path) -> list[str]:
    """What ``path`` takes from ``prm9tool/__init__`` itself (``import prm9tool``, ``from
    prm9tool import X`` for an X that is not a subpackage or module of its own)."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    names = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names += [a.name for a in node.names if a.name == "prm9tool"]
        elif isinstance(node, ast.ImportFrom) and node.module == "prm9tool" and not node.level:
            names += [
                a.name
                for a in node.names
                if not (PACKAGE / a.name).is_dir() and not (PACKAGE / f"{a.name}.py").exists()
            ]
    return names


def test_views_hold_no_session():
    # views get service calls through the connection, never a device session (issue 28)
    offenders = [
        f"{path.relative_to(PACKAGE).as_posix()}: {line.strip()}"
        for path in (PACKAGE / "views").rglob("*.py")
        for line in path.read_text(encoding="utf-8").splitlines()
        if "session: Any" in line or "ValveSession" in line
    ]
    assert offenders == []
